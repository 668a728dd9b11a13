#include "core/reference/reference_field.h"

#include <algorithm>
#include <cmath>
#include <functional>
#include <limits>
#include <stdexcept>

#include "core/physics/drag.h"
#include "core/physics/stokes.h"

namespace sedem {
namespace {

// c_m' / c_m across a front falling at s, class m at v below and v' above (continuous flux).
// v' < s for every finer class unless two classes settle at nearly the same speed, where the
// ratio is held to [1/2, 2]: the voidage moves their speeds by well under their spacing.
double scale_through_front(double s, double v, double v_above) {
  if (v_above == v) return 1.0;  // the voidage did not change its speed
  return s - v_above > 0 ? std::clamp((s - v) / (s - v_above), 0.5, 2.0) : 2.0;
}

// The root of a function that falls from f(low) >= 0 to f(high) <= 0, to within `tolerance`:
// the Illinois variant of the false position, which keeps the bracket and converges
// superlinearly (a plain false position can stall at one end).
double bracketed_root(const std::function<double(double)>& f, double low, double high,
                      double tolerance) {
  double f_low = f(low), f_high = f(high);
  if (f_low <= 0) return low;
  if (f_high >= 0) return high;
  int kept = 0;  // which end stayed put last time: -1 low, +1 high
  for (int it = 0; it < 200 && high - low > tolerance; ++it) {
    double x = (low * f_high - high * f_low) / (f_high - f_low);
    if (!(x > low && x < high)) x = 0.5 * (low + high);
    const double fx = f(x);
    if (fx == 0) return x;
    if (fx > 0) {
      low = x;
      f_low = fx;
      if (kept == 1) f_high *= 0.5;
      kept = 1;
    } else {
      high = x;
      f_high = fx;
      if (kept == -1) f_low *= 0.5;
      kept = -1;
    }
  }
  return f_low < -f_high ? low : high;
}

std::vector<SettlingFront> fronts_of(const std::vector<SettlingClass>& classes) {
  std::vector<SettlingFront> fronts;
  fronts.reserve(classes.size());
  for (const auto& c : classes) fronts.push_back({c.diameter, c.velocity, c.concentration});
  return fronts;
}

}  // namespace

double reference_terminal_velocity(const std::string& drag, double diameter,
                                   double particle_density, const Fluid& fluid) {
  if (drag == "stokes") return stokes::terminal_velocity(diameter, particle_density, fluid);
  if (drag == "di_felice")
    return drag::di_felice_terminal_velocity(diameter, particle_density, fluid, 1.0);
  throw std::invalid_argument("reference solution: no terminal velocity for drag '" + drag + "'");
}

ReferenceSettling reference_settling(const std::string& name) {
  if (name == "free") return ReferenceSettling::free;
  if (name == "richardson_zaki") return ReferenceSettling::richardson_zaki;
  if (name == "local_voidage") return ReferenceSettling::local_voidage;
  throw std::invalid_argument("reference solution: unknown settling '" + name +
                              "' (free, richardson_zaki, local_voidage)");
}

std::vector<SettlingClass> settling_classes(const std::vector<SizeClass>& classes,
                                            double initial_concentration, double particle_density,
                                            const Fluid& fluid, const std::string& drag,
                                            const ReferenceOptions& options) {
  const double hindrance = options.settling == ReferenceSettling::richardson_zaki
                               ? std::pow(1.0 - initial_concentration / particle_density,
                                          options.richardson_zaki_exponent)
                               : 1.0;
  std::vector<SettlingClass> out;
  out.reserve(classes.size());
  for (const auto& c : classes) {
    SettlingClass s;
    s.diameter = c.diameter;
    s.concentration = initial_concentration * c.mass_fraction;
    s.velocity = hindrance * reference_terminal_velocity(drag, c.diameter, particle_density, fluid);
    out.push_back(s);
  }
  return out;
}

std::vector<SettlingFront> voidage_fronts(
    const std::vector<SettlingClass>& classes, double particle_density,
    const std::function<double(std::size_t, double)>& velocity, HeldFronts* held) {
  std::vector<std::size_t> order(classes.size());
  for (std::size_t k = 0; k < order.size(); ++k) order[k] = k;
  std::stable_sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) {
    return classes[a].velocity < classes[b].velocity;
  });
  // The region below every front: the initial suspension.
  std::vector<double> c(order.size()), v(order.size()), v_above(order.size());
  double solids = 0;
  for (std::size_t k = 0; k < order.size(); ++k) {
    c[k] = classes[order[k]].concentration;
    solids += c[k];
  }
  auto speeds = [&](std::size_t present, double total, std::vector<double>& out) {
    const double voidage = 1.0 - total / particle_density;
    for (std::size_t m = 0; m < present; ++m) out[m] = velocity(order[m], voidage);
  };
  speeds(order.size(), solids, v);
  std::vector<SettlingFront> fronts(order.size());
  if (held) {
    held->order = order;
    held->speed.assign(order.size(), 0.0);
    held->scale.assign(order.size(), {});
  }
  double previous_speed = std::numeric_limits<double>::infinity();
  for (std::size_t k = order.size(); k-- > 0;) {
    // Class k ends here; a front cannot overtake the one below it (equal speeds: a front
    // where both end together).
    const double s = std::min(v[k], previous_speed);
    previous_speed = s;
    // The finer classes' solids above the front, A: the root of
    //   F(A) = sum_m c_m (s - v_m) / (s - v_m'(A)) - A,
    // their flux through the front continuous at the voidage A leaves. Less solids above
    // means faster finer classes and a larger sum, so F falls as A grows: one root, bracketed
    // by the finer classes' solids below (F >= 0, their speeds can only grow) and all the
    // solids below (F = -c_k). A plain fixed point A <- F(A) + A diverges once F's slope
    // passes 1, at a few times the standard mass; this bracketing never does.
    auto excess = [&](double a) {
      speeds(k, a, v_above);
      double sum = 0;
      for (std::size_t m = 0; m < k; ++m) sum += c[m] * scale_through_front(s, v[m], v_above[m]);
      return sum - a;
    };
    const double above = bracketed_root(excess, solids - c[k], solids, 1e-14 * solids);
    speeds(k, above, v_above);
    if (held) {
      held->speed[k] = s;
      held->scale[k].resize(k);
    }
    for (std::size_t m = 0; m < k; ++m) {
      const double scale = scale_through_front(s, v[m], v_above[m]);
      if (held) held->scale[k][m] = scale;
      c[m] *= scale;
      v[m] = v_above[m];
    }
    fronts[k] = {classes[order[k]].diameter, s, solids - above};
    solids = above;
  }
  return fronts;
}

std::vector<SettlingFront> fronts_with_held_speeds(const std::vector<SettlingClass>& classes,
                                                   const HeldFronts& held) {
  if (held.order.size() != classes.size())
    throw std::invalid_argument("reference solution: held fronts of another set of classes");
  const std::size_t n = classes.size();
  std::vector<double> c(n);
  for (std::size_t k = 0; k < n; ++k) c[k] = classes[held.order[k]].concentration;
  std::vector<SettlingFront> fronts(n);
  for (std::size_t k = n; k-- > 0;) {
    double jump = c[k];
    for (std::size_t m = 0; m < k; ++m) {
      jump += c[m] * (1.0 - held.scale[k][m]);
      c[m] *= held.scale[k][m];
    }
    fronts[k] = {classes[held.order[k]].diameter, held.speed[k], jump};
  }
  return fronts;
}

std::vector<SettlingFront> local_voidage_fronts(const std::vector<SettlingClass>& classes,
                                                double particle_density, const Fluid& fluid,
                                                const std::string& drag, HeldFronts* held) {
  double solids = 0;
  for (const auto& c : classes) solids += c.concentration;
  const double initial_voidage = 1.0 - solids / particle_density;
  if (drag != "di_felice" || !(solids > 0)) {
    // No voidage in the speeds: each class's front at its own speed, nothing rescaled.
    if (held)
      voidage_fronts(
          classes, particle_density, [&](std::size_t n, double) { return classes[n].velocity; },
          held);
    return fronts_of(classes);
  }
  std::vector<double> exponent(classes.size());
  for (std::size_t n = 0; n < classes.size(); ++n)
    exponent[n] = std::log(drag::di_felice_terminal_velocity(classes[n].diameter, particle_density,
                                                             fluid, initial_voidage) /
                           drag::di_felice_terminal_velocity(classes[n].diameter, particle_density,
                                                             fluid, 1.0)) /
                  std::log(initial_voidage);
  return voidage_fronts(
      classes, particle_density,
      [&](std::size_t n, double voidage) {
        return classes[n].velocity * std::exp(exponent[n] * std::log(voidage));
      },
      held);
}

ReferenceSolution::ReferenceSolution(const std::vector<SettlingClass>& classes,
                                     const Cylinder& cylinder, double particle_density,
                                     double bed_packing)
    : ReferenceSolution(fronts_of(classes), cylinder, particle_density, bed_packing, 0) {}

ReferenceSolution ReferenceSolution::from_fronts(std::vector<SettlingFront> fronts,
                                                 const Cylinder& cylinder, double particle_density,
                                                 double bed_packing) {
  return ReferenceSolution(std::move(fronts), cylinder, particle_density, bed_packing, 0);
}

ReferenceSolution::ReferenceSolution(std::vector<SettlingFront> fronts, const Cylinder& cylinder,
                                     double particle_density, double bed_packing, int)
    : fronts_(std::move(fronts)),
      cylinder_(cylinder),
      particle_density_(particle_density),
      bed_packing_(bed_packing) {
  if (!(bed_packing_ > 0 && bed_packing_ <= 1))
    throw std::invalid_argument("reference solution: bed packing must be in (0, 1]");
  std::stable_sort(
      fronts_.begin(), fronts_.end(),
      [](const SettlingFront& a, const SettlingFront& b) { return a.speed < b.speed; });
}

double ReferenceSolution::bed_top(double time) const {
  const double height = cylinder_.height;
  const double bed_density = particle_density_ * bed_packing_;
  double total = 0;
  for (const auto& f : fronts_) total += f.jump * height;
  // Class n, uniform at first, has translated down by u_n t: it fills [u_n t, bed top) and
  // the rest of it is in the bed. The bed's top and the suspended mass depend on each other;
  // the map is a contraction (its slope is at most c_0 / (rho_p packing) < 1), so iterate.
  double top = height;
  for (int it = 0; it < 200; ++it) {
    double suspended = 0;  // kg/m^2
    for (const auto& f : fronts_) suspended += f.jump * std::max(0.0, top - f.speed * time);
    const double next = height - (total - suspended) / bed_density;
    if (std::abs(next - top) <= 1e-15 * height) return next;
    top = next;
  }
  return top;
}

double ReferenceSolution::concentration(double depth, double time) const {
  const double top = bed_top(time);
  if (depth >= top) return particle_density_ * bed_packing_;
  double c_sum = 0;
  for (const auto& f : fronts_)
    if (depth >= f.speed * time) c_sum += f.jump;
  return c_sum;
}

double ReferenceSolution::largest_diameter_above(double depth, double time) const {
  const double limit = std::min(depth, bed_top(time));
  double largest = 0;
  for (const auto& f : fronts_)
    if (f.speed * time < limit && f.jump > 0) largest = std::max(largest, f.diameter);
  return largest;
}

std::vector<double> ReferenceSolution::layer_solid_volume(double time, std::size_t layers) const {
  if (layers == 0) throw std::invalid_argument("reference solution: zero layers");
  const double top = bed_top(time);
  const double h = cylinder_.height / static_cast<double>(layers);
  const double area = cylinder_.diameter * cylinder_.slab_thickness();
  // The suspended mass above depth d (d <= bed top) is sum_{e_n <= d} J_n (d - e_n) with
  // e_n = s_n t the depth of front n and J_n its jump: swept down the layer boundaries, the
  // fronts being sorted.
  std::size_t k = 0;
  const auto& fronts = fronts_;
  double present = 0, moment = 0;  // sum c_n and sum c_n e_n of the fronts above d
  auto cumulative = [&](double d) {
    const double in_suspension = std::min(d, top);
    while (k < fronts.size() && fronts[k].speed * time <= in_suspension) {
      present += fronts[k].jump;
      moment += fronts[k].jump * fronts[k].speed * time;
      ++k;
    }
    double m = present * in_suspension - moment;
    if (d > top) m += particle_density_ * bed_packing_ * (d - top);
    return m;
  };
  std::vector<double> volume(layers);
  double previous = cumulative(0.0);
  for (std::size_t j = 0; j < layers; ++j) {
    const double next = cumulative(static_cast<double>(j + 1) * h);
    volume[j] = (next - previous) * area / particle_density_;
    previous = next;
  }
  return volume;
}

LayerFields ReferenceSolution::layer_fields(double time, std::size_t layers,
                                            const Fluid& fluid) const {
  return LayerFields(layer_solid_volume(time, layers), cylinder_, fluid, particle_density_);
}

ReferenceSolution make_reference(const TestSetup& setup, const Sample& sample,
                                 const ReferenceOptions& options) {
  const double c0 = sample.section_mass / setup.cylinder.section_volume();
  auto classes = settling_classes(sample.classes, c0, sample.particle_density, setup.fluid,
                                  setup.drag, options);
  if (options.settling == ReferenceSettling::local_voidage)
    return ReferenceSolution::from_fronts(
        local_voidage_fronts(classes, sample.particle_density, setup.fluid, setup.drag),
        setup.cylinder, sample.particle_density, options.bed_packing);
  return ReferenceSolution(classes, setup.cylinder, sample.particle_density, options.bed_packing);
}

}  // namespace sedem
