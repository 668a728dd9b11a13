#include "core/invert/inversion.h"

#include <algorithm>
#include <cmath>
#include <random>
#include <sstream>

#include "core/invert/nnls.h"
#include "core/invert/reading_bounds.h"

namespace sedem::invert {

namespace {

std::string describe(std::size_t row, const std::string& field, double value,
                     const std::string& why) {
  std::ostringstream s;
  if (row != InvalidInversionInput::kNoRow) s << "row " << row + 1 << ", ";
  s << field << " = " << value << ": " << why;
  return s.str();
}

std::string fixed(double v, int digits) {
  std::ostringstream s;
  s.setf(std::ios::fixed);
  s.precision(digits);
  s << v;
  return s.str();
}

double quantile(std::vector<double> v, double q) {
  std::sort(v.begin(), v.end());
  const double pos = q * double(v.size() - 1);
  const auto lo = std::size_t(std::floor(pos));
  const auto hi = std::min(lo + 1, v.size() - 1);
  return v[lo] + (pos - double(lo)) * (v[hi] - v[lo]);
}

// Linear in log d through (nodes, values), extended as InvertedCurve::at says.
double interpolate(const std::vector<double>& d, const std::vector<double>& p, double x) {
  if (d.empty()) return 0;
  auto lerp = [](double x0, double y0, double x1, double y1, double v) {
    const double t = std::log(v / x0) / std::log(x1 / x0);
    return y0 + std::clamp(t, 0.0, 1.0) * (y1 - y0);
  };
  if (x <= d.front())
    return x <= d.front() / 10.0 ? 0.0 : lerp(d.front() / 10.0, 0, d.front(), p.front(), x);
  if (x >= d.back()) return lerp(d.back(), p.back(), 4.0 * d.back(), 100.0, x);
  const auto it = std::upper_bound(d.begin(), d.end(), x);
  const std::size_t k = std::size_t(it - d.begin());
  return lerp(d[k - 1], p[k - 1], d[k], p[k], x);
}

// The regularised, constrained least squares at one linearisation: the readings are
// modelled as base + J (x - x0).
class Problem {
 public:
  Problem(const Eigen::MatrixXd& j, const Eigen::VectorXd& base, const Eigen::VectorXd& x0,
          double sigma, const std::vector<double>& widths)
      : j_(j), offset_(base - j * x0), sigma_(sigma) {
    const Eigen::Index n = j.cols();
    // The roughness: the integral over ln d of the squared slope of the mass per ln d,
    // rho_k = x_k / w_k, i.e. the sum of (rho_{k+1} - rho_k)^2 / h_k with h_k the distance of
    // the two bins' centres. Zero for a curve linear in log d. Interior bins only: the finest
    // and the coarsest are open-ended.
    const Eigen::Index rows = std::max<Eigen::Index>(0, n - 3);
    l_ = Eigen::MatrixXd::Zero(rows, n);
    for (Eigen::Index k = 0; k < rows; ++k) {
      const double w0 = widths[std::size_t(k + 1)], w1 = widths[std::size_t(k + 2)];
      const double h = std::sqrt(0.5 * (w0 + w1));
      l_(k, k + 1) = -1.0 / (w0 * h);
      l_(k, k + 2) = 1.0 / (w1 * h);
    }
    const double misfit_scale = (j / sigma).squaredNorm();
    scale_ = rows > 0 ? misfit_scale / l_.squaredNorm() : 0.0;
    // The sum of the shares is 1: a row weighted well above the misfit (30 times the
    // largest column's norm holds the sum to about 1e-3 without spoiling the QR's accuracy).
    omega_ = 30.0 * std::max(1.0, (j / sigma).colwise().norm().maxCoeff());
  }

  // `prior`, if given, shifts the smoothing term to ||sqrt(lambda) L x - prior||^2.
  Eigen::VectorXd solve(const Eigen::VectorXd& measured, double mu,
                        const Eigen::VectorXd& start = {},
                        const Eigen::VectorXd& prior = {}) const {
    const Eigen::Index m = j_.rows(), r = l_.rows(), n = j_.cols();
    Eigen::MatrixXd a(m + r + 1, n);
    Eigen::VectorXd b(m + r + 1);
    a.topRows(m) = j_ / sigma_;
    b.head(m) = (measured - offset_) / sigma_;
    a.middleRows(m, r) = std::sqrt(mu * scale_) * l_;
    if (prior.size() == r)
      b.segment(m, r) = prior;
    else
      b.segment(m, r).setZero();
    a.row(m + r).setConstant(omega_);
    b(m + r) = omega_;
    return nnls(a, b, start).x;
  }

  Eigen::VectorXd residual(const Eigen::VectorXd& measured, const Eigen::VectorXd& x) const {
    return j_ * x + offset_ - measured;
  }
  double chi2(const Eigen::VectorXd& measured, const Eigen::VectorXd& x) const {
    return (residual(measured, x) / sigma_).squaredNorm();
  }

  // The discrepancy principle: the largest mu whose chi^2 stays within the target
  // (tau sqrt(N) + sqrt(floor))^2, floor the chi^2 of the least smoothing, and whose every
  // residual stays within half a resolution step of the least smoothing's. Rounding leaves
  // each reading within half a step of the truth's, so a fit that spends the chi^2 budget on
  // one reading (the first sphere reading at 100 %, which alone says where the curve reaches
  // 100 %) contradicts the data even when the sum allows it. Bisection in log mu.
  struct Choice {
    Eigen::VectorXd x;
    Eigen::VectorXd floor_residual;  // per reading, of the least smoothing
    double mu = 0, chi2 = 0, target = 0, floor = 0;
  };
  Choice choose(const Eigen::VectorXd& measured, double tau,
                const Eigen::VectorXd& start = {}) const {
    constexpr double kMuMin = 1e-10, kMuMax = 1e6;
    Choice c;
    const Eigen::VectorXd rough = solve(measured, kMuMin, start);
    c.floor = chi2(measured, rough);
    c.target = std::pow(tau * std::sqrt(double(measured.size())) + std::sqrt(c.floor), 2);
    c.floor_residual = residual(measured, rough);
    const Eigen::ArrayXd bound = c.floor_residual.array().abs() + 0.5 * std::sqrt(12.0) * sigma_;
    auto within = [&](const Eigen::VectorXd& x) {
      return chi2(measured, x) <= c.target && (residual(measured, x).array().abs() <= bound).all();
    };
    const Eigen::VectorXd smooth = solve(measured, kMuMax, start);
    if (within(smooth)) {
      c.x = smooth;
      c.mu = kMuMax;
    } else {
      double lo = std::log(kMuMin), hi = std::log(kMuMax);
      c.x = rough;
      c.mu = kMuMin;
      for (int it = 0; it < 24; ++it) {
        const double mid = 0.5 * (lo + hi);
        const Eigen::VectorXd x = solve(measured, std::exp(mid), c.x);
        if (within(x)) {
          lo = mid;
          c.x = x;
          c.mu = std::exp(mid);
        } else {
          hi = mid;
        }
      }
    }
    c.chi2 = chi2(measured, c.x);
    return c;
  }

 public:
  Eigen::Index smoothing_rows() const { return l_.rows(); }
  // The smoothing term at x: ||sqrt(mu s) L x||^2.
  double roughness(const Eigen::VectorXd& x, double mu) const {
    return mu * scale_ * (l_ * x).squaredNorm();
  }
  // How many of the smoothing rows the prior rather than the readings decides at mu: the
  // trace of mu s L H^-1 L^T, H the normal matrix of the whole objective (without x >= 0).
  double prior_rows(double mu) const {
    const Eigen::Index n = j_.cols();
    Eigen::MatrixXd h = (j_ / sigma_).transpose() * (j_ / sigma_) +
                        mu * scale_ * l_.transpose() * l_ +
                        omega_ * omega_ * Eigen::MatrixXd::Ones(n, n);
    return mu * scale_ * (l_ * h.ldlt().solve(l_.transpose())).trace();
  }

 private:
  Eigen::MatrixXd j_, l_;
  Eigen::VectorXd offset_;
  double sigma_, scale_ = 0, omega_ = 1;
};

std::vector<double> curve_of(const Eigen::VectorXd& x) {
  // Percent finer at node k: the bins 0..k; the shares are rescaled to sum exactly to 1.
  const double total = x.sum();
  std::vector<double> p;
  double sum = 0;
  for (Eigen::Index k = 0; k + 1 < x.size(); ++k) {
    sum += x(k);
    p.push_back(std::clamp(100.0 * sum / total, 0.0, 100.0));
  }
  return p;
}

}  // namespace

double default_resolution(Test test) {
  switch (test) {
    case Test::hydrometer:
      return 1.0;
    case Test::buoyancy:
      return 1e-3;
    case Test::pipette:
      return 1e-4;
  }
  return 1.0;
}

double InvertedCurve::at(double d) const {
  return interpolate(diameter, percent_finer, d);
}
double InvertedCurve::lower_at(double d) const {
  return interpolate(diameter, lower.empty() ? percent_finer : lower, d);
}
double InvertedCurve::upper_at(double d) const {
  return interpolate(diameter, upper.empty() ? percent_finer : upper, d);
}

double InvertedCurve::bound_lower_at(double d) const {
  if (bound_lower.empty()) return std::nan("");
  const auto it = std::upper_bound(bound_diameter.begin(), bound_diameter.end(), d);
  return it == bound_diameter.begin() ? 0.0
                                      : bound_lower[std::size_t(it - bound_diameter.begin()) - 1];
}
double InvertedCurve::bound_upper_at(double d) const {
  if (bound_upper.empty()) return std::nan("");
  const auto it = std::lower_bound(bound_diameter.begin(), bound_diameter.end(), d);
  return it == bound_diameter.end() ? 100.0 : bound_upper[std::size_t(it - bound_diameter.begin())];
}
InvertedCurve::OpenInterval InvertedCurve::widest_open() const {
  OpenInterval w;
  for (std::size_t k = 0; k < bound_diameter.size(); ++k) {
    const double d = bound_diameter[k];
    if (d < resolved_min || d > resolved_max) continue;
    if (bound_upper[k] - bound_lower[k] > w.width) w = {bound_upper[k] - bound_lower[k], d};
  }
  return w;
}

bool InvertedCurve::open_at(double d) const {
  if (reading_diameter.empty() || open_rise <= 0) return false;
  if (!bound_lower.empty() && bound_upper_at(d) - bound_lower_at(d) <= open_width) return false;
  // The readings pin the curve at their diameters (averages over their windows); between two
  // pins they do not say where its rise sits. Intervals between sorted pins, with the curve's
  // ends (0 % below the finest pin, 100 % above the coarsest) as the outer ones.
  std::vector<double> pins = reading_diameter;
  std::sort(pins.begin(), pins.end());
  const auto rise_of_interval = [&](std::size_t i) {  // interval i: between pins i-1 and i
    const double below = i == 0 ? 0.0 : at(pins[i - 1]);
    const double above = i == pins.size() ? 100.0 : at(pins[i]);
    return above - below;
  };
  const auto interval_of = [&](double x) {
    return std::size_t(std::upper_bound(pins.begin(), pins.end(), x) - pins.begin());
  };
  if (rise_of_interval(interval_of(d)) > open_rise) return true;
  for (std::size_t r = 0; r < reading_window.size() && r < reading_diameter.size(); ++r) {
    const auto [lo, hi] = reading_window[r];
    if (d < lo || d > hi) continue;
    // The reading averages over sizes on both sides of its pin: a rise on either side it cannot
    // place reaches the whole window.
    const std::size_t i =
        std::size_t(std::lower_bound(pins.begin(), pins.end(), reading_diameter[r]) - pins.begin());
    if (rise_of_interval(i) > open_rise || rise_of_interval(i + 1) > open_rise) return true;
  }
  return false;
}

std::vector<double> InvertedCurve::between_readings() const {
  std::vector<double> d = reading_diameter;
  std::sort(d.begin(), d.end());
  std::vector<double> mid;
  for (std::size_t i = 1; i < d.size(); ++i)
    if (d[i] > 1.05 * d[i - 1]) mid.push_back(std::sqrt(d[i] * d[i - 1]));
  return mid;
}

std::vector<std::pair<double, double>> InvertedCurve::open_ranges() const {
  std::vector<std::pair<double, double>> ranges;
  bool in_run = false;
  for (const double d : diameter) {
    const bool counted =
        open_at(d) && d >= resolved_min * (1 - 1e-9) && d <= resolved_max * (1 + 1e-9);
    if (counted && in_run)
      ranges.back().second = d;
    else if (counted)
      ranges.emplace_back(d, d);
    in_run = counted;
  }
  return ranges;
}

InvalidInversionInput::InvalidInversionInput(std::size_t row, const std::string& field,
                                             double value, const std::string& why)
    : std::invalid_argument(describe(row, field, value, why)), row_(row) {}

void validate_measurements(const TestSetup& setup, Test test, const std::vector<Measurement>& data,
                           const InversionOptions& options) {
  constexpr auto kNoRow = InvalidInversionInput::kNoRow;
  const std::string unit = reading_unit(test);
  if (data.size() < kMinReadings)
    throw InvalidInversionInput(
        kNoRow, "readings", double(data.size()),
        "the inversion needs " + std::to_string(kMinReadings) + " readings or more");
  if (data.size() > kMaxReadings)
    throw InvalidInversionInput(
        kNoRow, "readings", double(data.size()),
        "the inversion takes at most " + std::to_string(kMaxReadings) +
            " readings (a test has a few dozen; the fit's time grows fast with their number): "
            "keep every few");
  if (options.refine < 0 || options.refine > kMaxRefine)
    throw InvalidInversionInput(
        kNoRow, "refine", options.refine,
        "allowed 0 to " + std::to_string(kMaxRefine) + " nodes between two readings' diameters");
  if (!(options.resolution >= 0) || !std::isfinite(options.resolution))
    throw InvalidInversionInput(kNoRow, "resolution", options.resolution,
                                "must be positive (" + unit + ")");
  if (!(options.coverage > 0 && options.coverage < 1))
    throw InvalidInversionInput(kNoRow, "coverage", options.coverage, "allowed (0, 1)");
  const ForwardModel model(setup, test, log_grid(1e-6, 1e-4, 2), {});
  const double empty = model.empty_reading(), full = model.full_reading();
  // Between -10 % and 110 % finer, as a reading.
  const double lo = std::min(empty - 0.1 * (full - empty), empty + 1.1 * (full - empty));
  const double hi = std::max(empty - 0.1 * (full - empty), empty + 1.1 * (full - empty));
  for (std::size_t i = 0; i < data.size(); ++i) {
    const auto& m = data[i];
    if (!(m.time > 0) || !std::isfinite(m.time))
      throw InvalidInversionInput(i, "time_min", m.time / 60.0, "times must be positive");
    if (i > 0 && !(m.time > data[i - 1].time))
      throw InvalidInversionInput(
          i, "time_min", m.time / 60.0,
          "times must increase (previous row: " + fixed(data[i - 1].time / 60.0, 3) + " min)");
    if (test == Test::hydrometer) continue;  // the 152H scale is checked on the raw reading
    const std::string field = test == Test::buoyancy ? "apparent_mass_g" : "dry_mass_g";
    if (!(m.value >= lo && m.value <= hi) || !std::isfinite(m.value))
      throw InvalidInversionInput(i, field, m.value,
                                  "outside " + fixed(lo, 4) + " to " + fixed(hi, 4) +
                                      " g, the readings of -10 % to 110 % finer for this set-up");
  }
}

namespace {

struct Fit {
  Eigen::VectorXd x;
  Problem::Choice choice;
  Eigen::MatrixXd jacobian;  // at x, the speeds held there
  int iterations = 0;
};

// Gauss-Newton from an even spread (one step for the affine tests), lambda by the discrepancy
// principle at each step. Speeds that depend on the voidage are held at each step's x (a fixed
// point in them): the data then pull the curve only through where the fronts are, not through
// how the total mass hinders them, which the readings resolve no better than their noise.
Fit fit_readings(ForwardModel& model, const Eigen::VectorXd& measured, double sigma,
                 const InversionOptions& options) {
  const Eigen::Index n = Eigen::Index(model.grid().bins());
  const std::vector<double> widths = bin_widths(model.grid());
  Fit fit;
  fit.x = Eigen::VectorXd::Constant(n, 1.0 / double(n));
  for (fit.iterations = 1; fit.iterations <= options.max_iterations; ++fit.iterations) {
    if (options.progress)
      options.progress("fit", double(fit.iterations - 1) / double(options.max_iterations));
    model.hold_speeds_at(fit.x);
    fit.jacobian = model.jacobian(fit.x);
    const Problem problem(fit.jacobian, model.readings(fit.x), fit.x, sigma, widths);
    fit.choice = problem.choose(measured, options.tau);
    const double change = (fit.choice.x - fit.x).cwiseAbs().maxCoeff();
    fit.x = fit.choice.x;
    if ((model.affine() && !model.speeds_depend_on_x()) || change < 1e-5) break;
  }
  fit.iterations = std::min(fit.iterations, options.max_iterations);
  model.hold_speeds_at(fit.x);
  if (!model.affine() || model.speeds_depend_on_x()) fit.jacobian = model.jacobian(fit.x);
  return fit;
}

}  // namespace

InvertedCurve invert_readings(const TestSetup& setup, Test test,
                              const std::vector<Measurement>& data,
                              const InversionOptions& options) {
  validate_measurements(setup, test, data, options);
  InvertedCurve out;
  const double resolution = options.resolution > 0 ? options.resolution : default_resolution(test);
  out.sigma = resolution / std::sqrt(12.0);

  std::vector<double> times;
  Eigen::VectorXd measured(Eigen::Index(data.size()));
  for (std::size_t i = 0; i < data.size(); ++i) {
    times.push_back(data[i].time);
    measured(Eigen::Index(i)) = data[i].value;
    out.measured.push_back(data[i].value);
  }
  // The grid: a node at each reading's pinned diameter, refined between them.
  {
    const ForwardModel probe(setup, test, log_grid(1e-6, 1e-4, 2), times);
    for (const auto& m : data) {
      const double depth_value =
          std::isnan(m.depth_reading) ? m.value : m.depth_reading - probe.clear_liquid_reading();
      out.reading_diameter.push_back(probe.model_diameter(m.time, depth_value));
      out.reading_window.push_back(probe.reading_window(m.time, depth_value));
    }
    out.resolved_max = *std::max_element(out.reading_diameter.begin(), out.reading_diameter.end());
    out.resolved_min = *std::min_element(out.reading_diameter.begin(), out.reading_diameter.end());
  }
  std::vector<double> edges;
  if (options.window_nodes)
    for (const auto& [lo, hi] : out.reading_window) edges.insert(edges.end(), {lo, hi});
  ForwardModel model(setup, test, reading_grid(out.reading_diameter, options.refine, edges), times,
                     options.subclasses);
  const std::vector<double> widths = bin_widths(model.grid());
  Fit fit = fit_readings(model, measured, out.sigma, options);
  const Eigen::VectorXd& x = fit.x;
  const Problem::Choice& choice = fit.choice;
  Eigen::MatrixXd j = fit.jacobian;
  out.iterations = fit.iterations;
  const Eigen::VectorXd fitted = model.readings(x);
  out.fitted.assign(fitted.data(), fitted.data() + fitted.size());
  out.chi2 = ((fitted - measured) / out.sigma).squaredNorm();
  out.chi2_target = choice.target;
  out.chi2_floor = choice.floor;
  out.floor_residual.assign(choice.floor_residual.data(),
                            choice.floor_residual.data() + choice.floor_residual.size());
  out.lambda = choice.mu;
  out.diameter = model.grid().nodes;
  out.shares.assign(x.data(), x.data() + x.size());
  out.percent_finer = curve_of(x);

  // The readings' own bounds, on a grid bound_split times finer. They must hold for any
  // curve, not only for curves linear in log d between the nodes of some grid (a knee inside
  // a bin would then be outside them, and the bounds would move as the grid is refined):
  // each bin's mass may sit anywhere inside it, so its response to a reading is taken as
  // anything between the least and the most of a unit mass's at the bin's two ends and its
  // middle (a size's response changes monotonically across a bin: its front passes the
  // instrument once). The finest bin reaches down to a tenth of the first node and the
  // coarsest up to four times the last, where a size's response no longer changes (it
  // stays, or has long gone). The response of a unit mass at one size is the model's for a
  // bin 2e-4 wide in log d around it, a single size class; the model is linearised at the
  // fit, its fine bins' shares each put at their middle. The tolerance is the one the lambda
  // rule keeps the fit within, half a resolution step (rounding) plus the least smoothing's
  // misfit (the grid's own), plus what putting the fit's shares at the middles changes in its
  // readings, so that the fit is always inside them.
  if (options.bounds) {
    if (options.progress) options.progress("bounds", 0);
    const int split = std::max(1, options.bound_split);
    const Grid fine = split_grid(model.grid(), split);
    const Eigen::VectorXd x_fine = split_shares(x, split);
    const auto& d = fine.nodes;
    const Eigen::Index bins = Eigen::Index(fine.bins());
    // Sizes probed: bin b's lower end is probe 2b, its middle 2b + 1, its upper end 2b + 2.
    std::vector<double> probes{d.front() / 10.0};
    for (Eigen::Index b = 0; b < bins; ++b) {
      const double lo = probes.back();
      const double hi = b + 1 == bins ? 4.0 * d.back() : d[std::size_t(b)];
      probes.push_back(std::sqrt(lo * hi));
      probes.push_back(hi);
    }
    constexpr double kProbeWidth = 1e-4;
    Grid probe_grid;
    for (double p : probes) {
      probe_grid.nodes.push_back(p * (1.0 - kProbeWidth));
      probe_grid.nodes.push_back(p * (1.0 + kProbeWidth));
    }
    std::vector<Eigen::Index> columns;  // probe q's bin in probe_grid: 1 + 2q
    for (std::size_t q = 0; q < probes.size(); ++q) columns.push_back(Eigen::Index(1 + 2 * q));
    ForwardModel probe_model(setup, test, probe_grid, times, 1);
    Eigen::VectorXd x_probe = Eigen::VectorXd::Zero(Eigen::Index(probe_grid.bins()));
    for (Eigen::Index b = 0; b < bins; ++b) x_probe(columns[std::size_t(2 * b + 1)]) = x_fine(b);
    probe_model.hold_speeds_at(x_probe);
    const Eigen::MatrixXd g = probe_model.jacobian_columns(x_probe, columns);
    const Eigen::VectorXd read_probe = probe_model.readings(x_probe);
    Eigen::MatrixXd j_low(g.rows(), bins), j_high(g.rows(), bins), j_mid(g.rows(), bins);
    for (Eigen::Index b = 0; b < bins; ++b) {
      j_mid.col(b) = g.col(2 * b + 1);
      j_low.col(b) = g.col(2 * b).cwiseMin(g.col(2 * b + 1)).cwiseMin(g.col(2 * b + 2));
      j_high.col(b) = g.col(2 * b).cwiseMax(g.col(2 * b + 1)).cwiseMax(g.col(2 * b + 2));
    }
    Eigen::VectorXd tolerance = choice.floor_residual.cwiseAbs().array() + 0.5 * resolution +
                                (read_probe - fitted).cwiseAbs().array();
    // The fit meets the tolerance up to the NNLS's rounding: widen by a hair so the linear
    // programme is feasible whenever the fit is. Its shares sum to 1 within the weight of
    // that row (about 1e-3); the bounds keep the fit's own sum so that it is one of their
    // curves.
    tolerance.array() += 1e-9 * (measured.cwiseAbs().maxCoeff() + resolution);
    const auto bounds =
        reading_bounds(j_low, j_high, read_probe - j_mid * x_fine, measured, tolerance, x.sum());
    if (bounds.feasible) {
      out.bound_diameter = fine.nodes;
      out.bound_lower = bounds.lower;
      out.bound_upper = bounds.upper;
    }
    out.bound_tolerance.assign(tolerance.data(), tolerance.data() + tolerance.size());
  }

  // The band: randomize-then-optimize sampling of the posterior that the objective stands
  // for (Gaussian reading noise of sigma, a Gaussian smoothness prior of weight lambda,
  // x >= 0), on the model linearised at the fit. Each replica perturbs the measured readings
  // by an error uniform over one resolution step (what rounding to the graduation leaves)
  // and the smoothing term by a standard normal vector, and is solved by NNLS at the chosen
  // lambda; the band is the pointwise quantiles of the replicas' curves. Unlike a bootstrap
  // around the fit, this also spreads the curve where only the smoothing fixes it.
  //
  // The discrepancy principle sets lambda, i.e. how much to smooth, not how rough the curve
  // may be: at that lambda the prior's variance can be far below the fitted curve's own
  // roughness (the pipette's readings pin a curve with knees a smooth prior would call
  // improbable), and the band would then be as narrow as the prior is wrong. The prior's
  // perturbation is therefore scaled by gamma, gamma^2 = (the fit's smoothing term) / (the
  // rows the readings decide), the residual-over-degrees-of-freedom estimate of the prior's
  // variance at the fit, when that exceeds 1.
  out.coverage = options.coverage;
  out.replicas = std::max(0, options.bootstrap);
  if (out.replicas > 0) {
    const Problem problem(j, fitted, x, out.sigma, widths);
    std::mt19937_64 rng(options.seed);
    std::uniform_real_distribution<double> noise(-0.5 * resolution, 0.5 * resolution);
    std::normal_distribution<double> gauss;
    std::vector<std::vector<double>> curves(out.percent_finer.size());
    const double decided = double(problem.smoothing_rows()) - problem.prior_rows(out.lambda);
    out.prior_scale =
        std::sqrt(std::max(1.0, problem.roughness(x, out.lambda) / std::max(1.0, decided)));
    for (int b = 0; b < out.replicas; ++b) {
      if (options.progress) options.progress("band", double(b) / double(out.replicas));
      Eigen::VectorXd replica = measured;
      for (Eigen::Index i = 0; i < replica.size(); ++i) replica(i) += noise(rng);
      Eigen::VectorXd prior(problem.smoothing_rows());
      for (Eigen::Index i = 0; i < prior.size(); ++i) prior(i) = out.prior_scale * gauss(rng);
      const auto p = curve_of(problem.solve(replica, out.lambda, x, prior));
      for (std::size_t k = 0; k < p.size(); ++k) curves[k].push_back(p[k]);
    }
    const double tail = 0.5 * (1.0 - options.coverage);
    // The smoothing's bias, which the replicas (all at the chosen lambda) cannot show: how far
    // the curve moves when the data are fitted with hardly any smoothing.
    const auto rough = curve_of(problem.solve(measured, 1e-6 * out.lambda, x));
    // The grid's coarseness, which every replica shares: the same readings fitted on a grid
    // twice as fine (its own lambda), read at this grid's nodes. Between two nodes the curve is
    // linear in log d, and a knee inside an interval bends the fit at the nodes around it
    // (the pipette's band missed the truth at 2 readings in 3 on curves with knees without it).
    std::vector<double> coarse(curves.size(), 0.0);
    if (options.grid_bias) {
      InversionOptions finer = options;
      finer.refine = std::min(2 * options.refine + 1, kMaxRefine);
      finer.bootstrap = 0;
      finer.bounds = false;
      finer.progress = nullptr;
      const InvertedCurve fine = invert_readings(setup, test, data, finer);
      for (std::size_t k = 0; k < coarse.size(); ++k)
        coarse[k] = std::abs(fine.at(out.diameter[k]) - out.percent_finer[k]);
    }
    for (std::size_t k = 0; k < curves.size(); ++k) {
      const double bias = std::abs(rough[k] - out.percent_finer[k]) + coarse[k];
      out.lower.push_back(std::max(0.0, quantile(curves[k], tail) - bias));
      out.upper.push_back(std::min(100.0, quantile(curves[k], 1.0 - tail) + bias));
    }
    // The bias is not monotone in d: the band's edges are made so again, outwards (each lower
    // edge no higher than any to its right, each upper no lower than any to its left).
    for (std::size_t k = out.lower.size(); k-- > 1;)
      out.lower[k - 1] = std::min(out.lower[k - 1], out.lower[k]);
    for (std::size_t k = 1; k < out.upper.size(); ++k)
      out.upper[k] = std::max(out.upper[k], out.upper[k - 1]);
  }
  // Where the readings cannot tell the curve, the smoothness prior alone narrows the band, and
  // at a knee it is wrong: the band is then what the readings allow. Both edges stay monotone
  // (each is the pointwise min or max of two monotone sequences).
  out.open_rise = options.open_rise;
  out.open_width = options.open_width;
  for (std::size_t k = 0; k < out.lower.size() && !out.bound_lower.empty(); ++k) {
    const double d = out.diameter[k];
    if (!out.open_at(d)) continue;
    out.lower[k] = std::min(out.lower[k], out.bound_lower_at(d));
    out.upper[k] = std::max(out.upper[k], out.bound_upper_at(d));
  }
  return out;
}

}  // namespace sedem::invert
