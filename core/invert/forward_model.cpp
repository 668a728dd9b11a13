#include "core/invert/forward_model.h"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <stdexcept>

#include "core/instruments/instrument_panel.h"
#include "core/physics/drag.h"
#include "core/physics/stokes.h"
#include "core/reference/reference_field.h"
#include "core/reference/reference_readings.h"

namespace sedem::invert {

Test parse_test(const std::string& name) {
  if (name == "hydrometer") return Test::hydrometer;
  if (name == "buoyancy") return Test::buoyancy;
  if (name == "pipette") return Test::pipette;
  throw std::invalid_argument("test '" + name + "': expected hydrometer, buoyancy or pipette");
}

std::string test_name(Test test) {
  switch (test) {
    case Test::hydrometer:
      return "hydrometer";
    case Test::buoyancy:
      return "buoyancy";
    case Test::pipette:
      return "pipette";
  }
  return "";
}

std::string reading_unit(Test test) {
  return test == Test::hydrometer ? "g/L" : "g";
}

Grid log_grid(double smallest, double largest, std::size_t count) {
  if (!(smallest > 0 && largest > smallest && count >= 2))
    throw std::invalid_argument("grid: needs 0 < smallest < largest and two nodes or more");
  Grid g;
  const double ratio = std::log(largest / smallest);
  for (std::size_t k = 0; k < count; ++k)
    g.nodes.push_back(smallest * std::exp(ratio * double(k) / double(count - 1)));
  return g;
}

Grid reading_grid(std::vector<double> diameters, int refine, const std::vector<double>& edges) {
  std::sort(diameters.begin(), diameters.end());
  std::vector<double> base;
  for (double d : diameters) {
    if (!(d > 0)) throw std::invalid_argument("grid: diameters must be positive");
    if (base.empty() || d > 1.02 * base.back()) base.push_back(d);
  }
  if (base.size() < 2) throw std::invalid_argument("grid: the readings resolve one diameter");
  std::vector<double> anchors;
  anchors.push_back(base.front() / 1.5);
  anchors.insert(anchors.end(), base.begin(), base.end());
  anchors.push_back(2.0 * base.back());
  Grid g;
  for (std::size_t k = 0; k + 1 < anchors.size(); ++k) {
    const double lo = anchors[k], hi = anchors[k + 1];
    // The margins get two intervals each; between readings, 1 + refine.
    const int parts = (k == 0 || k + 2 == anchors.size()) ? 2 : 1 + std::max(0, refine);
    for (int s = 0; s < parts; ++s) g.nodes.push_back(lo * std::pow(hi / lo, double(s) / parts));
  }
  g.nodes.push_back(anchors.back());
  for (double e : edges) {
    if (!(e > g.nodes.front() && e < g.nodes.back())) continue;
    const auto at = std::lower_bound(g.nodes.begin(), g.nodes.end(), e);
    if (e < 1.01 * *(at - 1) || e * 1.01 > *at) continue;
    g.nodes.insert(at, e);
  }
  return g;
}

Grid split_grid(const Grid& grid, int parts) {
  Grid g;
  for (std::size_t k = 0; k + 1 < grid.nodes.size(); ++k)
    for (int s = 0; s < parts; ++s)
      g.nodes.push_back(grid.nodes[k] *
                        std::pow(grid.nodes[k + 1] / grid.nodes[k], double(s) / parts));
  if (!grid.nodes.empty()) g.nodes.push_back(grid.nodes.back());
  return g;
}

Eigen::VectorXd split_shares(const Eigen::VectorXd& x, int parts) {
  if (x.size() < 2) return x;
  Eigen::VectorXd out(1 + (x.size() - 2) * parts + 1);
  out(0) = x(0);
  for (Eigen::Index k = 1; k + 1 < x.size(); ++k)
    out.segment((k - 1) * parts + 1, parts).setConstant(x(k) / parts);
  out(out.size() - 1) = x(x.size() - 1);
  return out;
}

std::vector<double> bin_widths(const Grid& grid) {
  const auto& d = grid.nodes;
  std::vector<double> w{std::log(10.0)};
  for (std::size_t k = 1; k < d.size(); ++k) w.push_back(std::log(d[k] / d[k - 1]));
  w.push_back(std::log(4.0));
  return w;
}

ForwardModel::ForwardModel(const TestSetup& setup, Test test, Grid grid, std::vector<double> times,
                           int subclasses)
    : setup_(setup),
      test_(test),
      grid_(std::move(grid)),
      times_(std::move(times)),
      subclasses_(subclasses),
      layers_(std::size_t(setup.instruments.layers)) {
  if (grid_.nodes.size() < 2) throw std::invalid_argument("forward model: two grid nodes or more");
  if (subclasses_ < 1) throw std::invalid_argument("forward model: one subclass per bin or more");
  suspension_.fluid = setup.fluid;
  suspension_.cylinder = setup.cylinder;
  suspension_.particle_density = setup.particle_density;
  suspension_.initial_concentration =
      setup.total_mass / (std::numbers::pi / 4.0 * setup.cylinder.diameter *
                          setup.cylinder.diameter * setup.cylinder.height);
  {  // the instruments as the simulation's panel builds them from the setup
    Sample geometry;
    geometry.particle_density = setup.particle_density;
    const InstrumentPanel panel(setup, geometry);
    hydrometer_ = panel.hydrometer();
    sphere_ = panel.sphere();
    pipette_ = panel.pipette();
  }
  clear_reading_ = hydrometer_.reading_at(tip_depth_in_uniform(hydrometer_, setup.fluid.density) -
                                          hydrometer_.bulb_length);

  // Each bin's size classes, evenly spaced in log d across it.
  const auto& cfg = setup.instruments;
  const auto& d = grid_.nodes;
  local_voidage_ = cfg.reference_settling == "local_voidage" && setup.drag == "di_felice";
  hindrance_ =
      cfg.reference_settling == "richardson_zaki"
          ? std::pow(1.0 - suspension_.initial_concentration / suspension_.particle_density,
                     cfg.reference_richardson_zaki_exponent)
          : 1.0;
  for (std::size_t b = 0; b < grid_.bins(); ++b) {
    const double lo = b == 0 ? d.front() / 10.0 : d[b - 1];
    const double hi = b == d.size() ? 4.0 * d.back() : d[b];
    for (int s = 0; s < subclasses_; ++s) {
      const double diameter = lo * std::pow(hi / lo, (s + 0.5) / subclasses_);
      class_diameter_.push_back(diameter);
      class_velocity_.push_back(
          hindrance_ * reference_terminal_velocity(setup.drag, diameter,
                                                   suspension_.particle_density, setup.fluid));
    }
  }
}

double ForwardModel::read_fields(const LayerFields& fields) const {
  switch (test_) {
    case Test::hydrometer: {
      const double tip = equilibrium_tip_depth(hydrometer_, fields);
      return hydrometer_.reading_at(tip - hydrometer_.bulb_length) - clear_reading_;
    }
    case Test::buoyancy:
      return (sphere_.mass - displaced_mass(sphere_, fields)) * 1e3;
    case Test::pipette:
      return read_pipette(pipette_, fields, 0.0, suspension_).dry_mass * 1e3;
  }
  return 0;
}

std::vector<SettlingClass> ForwardModel::classes_of(const Eigen::VectorXd& x) const {
  std::vector<SettlingClass> classes;
  classes.reserve(class_diameter_.size());
  const double c0 = suspension_.initial_concentration;
  for (std::size_t k = 0; k < class_diameter_.size(); ++k) {
    const double share = x(Eigen::Index(k / std::size_t(subclasses_))) / subclasses_;
    classes.push_back({class_diameter_[k], c0 * share, class_velocity_[k]});
  }
  return classes;
}

ReferenceSolution ForwardModel::reference(const Eigen::VectorXd& x) const {
  const auto classes = classes_of(x);
  const double rho_p = suspension_.particle_density;
  const double packing = setup_.instruments.reference_bed_packing;
  if (local_voidage_)
    return ReferenceSolution::from_fronts(
        held_.order.empty() ? local_voidage_fronts(classes, rho_p, setup_.fluid, setup_.drag)
                            : fronts_with_held_speeds(classes, held_),
        setup_.cylinder, rho_p, packing);
  return ReferenceSolution(classes, setup_.cylinder, rho_p, packing);
}

void ForwardModel::hold_speeds_at(const Eigen::VectorXd& x) {
  if (!local_voidage_) return;
  local_voidage_fronts(classes_of(x), suspension_.particle_density, setup_.fluid, setup_.drag,
                       &held_);
}

double ForwardModel::read(const Eigen::VectorXd& x, double time) const {
  return read_fields(reference(x).layer_fields(time, layers_, setup_.fluid));
}

Eigen::VectorXd ForwardModel::readings(const Eigen::VectorXd& x) const {
  if (std::size_t(x.size()) != grid_.bins())
    throw std::invalid_argument("forward model: " + std::to_string(x.size()) + " shares for " +
                                std::to_string(grid_.bins()) + " bins");
  const ReferenceSolution settled = reference(x);
  Eigen::VectorXd r(Eigen::Index(times_.size()));
  for (std::size_t i = 0; i < times_.size(); ++i)
    r(Eigen::Index(i)) = read_fields(settled.layer_fields(times_[i], layers_, setup_.fluid));
  return r;
}

Eigen::MatrixXd ForwardModel::jacobian(const Eigen::VectorXd& x, double step) const {
  std::vector<Eigen::Index> all(std::size_t(x.size()));
  for (std::size_t k = 0; k < all.size(); ++k) all[k] = Eigen::Index(k);
  return jacobian_columns(x, all, step);
}

Eigen::MatrixXd ForwardModel::jacobian_columns(const Eigen::VectorXd& x,
                                               const std::vector<Eigen::Index>& columns,
                                               double step) const {
  const Eigen::Index n = x.size();
  const Eigen::VectorXd base = readings(x);
  Eigen::MatrixXd j(base.size(), Eigen::Index(columns.size()));
  if (affine()) {
    // Affine: each column is the response to the bin alone, less the empty reading.
    const Eigen::VectorXd empty = readings(Eigen::VectorXd::Zero(n));
    for (std::size_t c = 0; c < columns.size(); ++c)
      j.col(Eigen::Index(c)) = readings(Eigen::VectorXd::Unit(n, columns[c])) - empty;
    return j;
  }
  for (std::size_t c = 0; c < columns.size(); ++c) {
    Eigen::VectorXd moved = x;
    moved(columns[c]) += step;
    j.col(Eigen::Index(c)) = (readings(moved) - base) / step;
  }
  return j;
}

double ForwardModel::empty_reading() const {
  switch (test_) {
    case Test::hydrometer:
      return 0.0;
    case Test::buoyancy:
      return (sphere_.mass - setup_.fluid.density * sphere_.volume()) * 1e3;
    case Test::pipette:
      return 0.0;
  }
  return 0;
}

double ForwardModel::full_reading() const {
  Eigen::VectorXd x = Eigen::VectorXd::Zero(Eigen::Index(grid_.bins()));
  x(0) = 1.0;
  return read(x, 0.0);
}

double ForwardModel::nominal_depth() const {
  switch (test_) {
    case Test::hydrometer:
      return tip_depth_in_uniform(hydrometer_, setup_.fluid.density) -
             0.5 * hydrometer_.bulb_length;
    case Test::buoyancy:
      return sphere_.centre_depth;
    case Test::pipette:
      return pipette_.depth;
  }
  return 0;
}

double ForwardModel::reading_depth(double value) const {
  if (test_ != Test::hydrometer) return nominal_depth();
  return std::max(0.5 * hydrometer_.bulb_length,
                  nominal_depth() - value * hydrometer_.mark_per_reading);
}

double ForwardModel::front_speed(double diameter) const {
  const double rho_p = suspension_.particle_density;
  if (local_voidage_)
    return drag::di_felice_terminal_velocity(diameter, rho_p, setup_.fluid,
                                             1.0 - suspension_.initial_concentration / rho_p);
  return hindrance_ * reference_terminal_velocity(setup_.drag, diameter, rho_p, setup_.fluid);
}

double ForwardModel::model_diameter(double time, double value) const {
  return diameter_at(reading_depth(value), time);
}

double ForwardModel::half_span() const {
  switch (test_) {
    case Test::hydrometer:
      return 0.5 * hydrometer_.bulb_length;
    case Test::buoyancy:
      return 0.5 * sphere_.diameter;
    case Test::pipette:
      return pipette_.radius(setup_.cylinder);
  }
  return 0;
}

std::pair<double, double> ForwardModel::reading_window(double time, double value) const {
  const double depth = reading_depth(value), half = half_span();
  // The top no higher than a hundredth of the depth: a front at the surface is d = 0.
  return {diameter_at(std::max(0.01 * depth, depth - half), time), diameter_at(depth + half, time)};
}

double ForwardModel::diameter_at(double depth, double time) const {
  const double speed = depth / time;
  // The speed grows with the diameter: bisection in log d from Stokes' estimate.
  const double stokes =
      stokes::limiting_diameter(depth, time, suspension_.particle_density, suspension_.fluid);
  double lo = stokes / 4.0, hi = stokes * 4.0;
  for (int it = 0; it < 100 && hi / lo > 1 + 1e-12; ++it) {
    const double mid = std::sqrt(lo * hi);
    (front_speed(mid) < speed ? lo : hi) = mid;
  }
  return std::sqrt(lo * hi);
}

double ForwardModel::stokes_diameter(double time, double value) const {
  return stokes::limiting_diameter(reading_depth(value), time, suspension_.particle_density,
                                   suspension_.fluid);
}

}  // namespace sedem::invert
