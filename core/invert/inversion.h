#pragma once

#include <cstdint>
#include <functional>
#include <limits>
#include <string>
#include <utility>
#include <vector>

#include "core/invert/forward_model.h"

namespace sedem::invert {

// One reading as the laboratory took it, in the test's unit (reading_unit).
struct Measurement {
  double time = 0;   // s since the start of sedimentation
  double value = 0;  // 152H: R - composite correction, g/L; sphere: apparent mass, g;
                     // pipette: dry mass of the sample, g
  // 152H: the reading the bulb's depth comes from, R + meniscus correction, g/L (ASTM: the
  // composite correction is the concentration's, not the depth's); NaN: value plus the
  // model's own clear-liquid reading (a simulated test's).
  double depth_reading = std::numeric_limits<double>::quiet_NaN();
};

struct InversionOptions {
  int refine = 2;  // grid nodes between each two readings' diameters (reading_grid)
  // A node also at each edge of every reading's window (ForwardModel::reading_window), so that
  // the curve's slope at a knee just beside a reading does not leak into that reading.
  bool window_nodes = true;
  double resolution = 0;    // of a reading, in its unit; 0: the test's default
  int subclasses = 8;       // size classes per bin in the forward model
  int bootstrap = 200;      // replicas for the band (0: no band)
  double coverage = 0.90;   // of the band, pointwise
  double tau = 0.7;         // discrepancy factor: chi^2 target (tau sqrt(N) + sqrt(floor))^2
  std::uint64_t seed = 1;   // of the bootstrap's noise
  int max_iterations = 12;  // Gauss-Newton steps (the hydrometer)
  bool bounds = true;       // the readings' strict bounds (InvertedCurve::bound_*)
  // Called as the inversion goes: its stage ("fit", "bounds", "band") and the share of that
  // stage done (0-1). May throw to end the inversion.
  std::function<void(const char* stage, double fraction)> progress;
  int bound_split = 4;  // the bounds' grid: each interval of the fit's cut in this many
  // The band also spans how far the curve moves on a grid twice as fine (2 refine + 1 nodes
  // between two readings' diameters): the grid's own coarseness, which no replica shows.
  bool grid_bias = true;
  // Where the curve rises by more than this (pp) between two neighbouring readings' pinned
  // diameters, the readings cannot tell where in between the rise sits (a knee between two
  // readings): no value is claimed there or in the two readings' windows (InvertedCurve::
  // open_at), the band there is the strict bounds, and the output says so.
  double open_rise = 50;
  // ... unless the strict bounds there are no wider than this (pp): then the readings do hold
  // the curve, wherever the rise sits.
  double open_width = 10;
};

// The default reading resolutions: 152H 1 g/L (its graduation), the sphere's balance 1 mg,
// the pipette's analytical balance 0.1 mg.
double default_resolution(Test test);

// At least this many readings (resolving as many distinct diameters), at most kMaxReadings (a
// test has a few dozen; the fit's cost grows with their square and more); at most kMaxRefine
// nodes between each two.
inline constexpr std::size_t kMinReadings = 3;
inline constexpr std::size_t kMaxReadings = 200;
inline constexpr int kMaxRefine = 6;

struct InvertedCurve {
  std::vector<double> diameter;          // the grid's nodes, m
  std::vector<double> percent_finer;     // at the nodes, %
  std::vector<double> lower, upper;      // the band at `coverage`, % (empty without bootstrap)
  std::vector<double> shares;            // x: the bins' shares of the mass (finest first)
  std::vector<double> measured, fitted;  // per reading, in the test's unit
  double sigma = 0;                      // noise of one reading, resolution / sqrt(12)
  double lambda = 0;                     // the smoothing weight chosen (dimensionless)
  double chi2 = 0;                       // sum ((fitted - measured) / sigma)^2
  double chi2_target = 0;                // what the discrepancy principle aimed at
  double chi2_floor = 0;                 // the least chi^2 any curve on the grid reaches
  std::vector<double> floor_residual;    // per reading, fitted - measured at that floor
  int iterations = 0;                    // Gauss-Newton steps
  double coverage = 0;
  int replicas = 0;
  double prior_scale = 1;  // gamma: the band's prior spread, calibrated to the fit
  // The readings' strict bounds (reading_bounds), % finer at bound_diameter, the grid's
  // intervals each split in bound_split (every bound_split-th is a node of the curve): the
  // least and the most of any curve whatever (its mass anywhere inside the bins) whose
  // readings, linearised at the fit, stay within bound_tolerance of the measured ones.
  // Empty if the linear programme failed.
  std::vector<double> bound_diameter, bound_lower, bound_upper;
  std::vector<double> bound_tolerance;        // per reading, in its unit
  double resolved_min = 0, resolved_max = 0;  // reading_diameter's extremes
  std::vector<double> reading_diameter;  // where each reading pins the curve, m (model_diameter)
  // The sizes each reading averages over (ForwardModel::reading_window), m.
  std::vector<std::pair<double, double>> reading_window;
  // Where the curve rises by more than this (InversionOptions::open_rise, pp) between two
  // neighbouring readings' diameters, the readings cannot tell where the rise sits (open_at),
  // and the band there is the bounds.
  double open_rise = 0;
  double open_width = 0;  // InversionOptions::open_width

  // Linear in log d between nodes; 0 below a decade under the first node, 100 above 4x the
  // last (the finest and coarsest bins' spans).
  double at(double diameter) const;
  double lower_at(double diameter) const;
  double upper_at(double diameter) const;
  // The bounds at any diameter, taken conservatively from the nearest bound nodes (the lower
  // at the node below, the upper at the node above: every curve is monotone); NaN without
  // bounds.
  double bound_lower_at(double diameter) const;
  double bound_upper_at(double diameter) const;
  // The bound node within the resolved diameters where the bounds are furthest apart (width 0
  // without bounds): where the curve is most the smoothing's choice.
  struct OpenInterval {
    double width = 0;     // pp
    double diameter = 0;  // m
  };
  OpenInterval widest_open() const;
  // Whether the readings cannot tell the curve at `diameter`: the curve rises by more than
  // open_rise between the two readings' diameters around it (0 % below the finest, 100 %
  // above the coarsest), or `diameter` lies in a reading's window (the sizes it averages over)
  // and the curve rises by more than that on either side of the reading's own diameter; and
  // the strict bounds there (if computed) are wider than open_width.
  bool open_at(double diameter) const;
  // Midway (in log d) between each two neighbouring readings' diameters more than 5 % apart:
  // where a knee hides from every reading (to score the band there).
  std::vector<double> between_readings() const;
  // The runs of open nodes within the resolved diameters, as (smallest, largest) diameter, m.
  std::vector<std::pair<double, double>> open_ranges() const;
};

// Invalid input for the inversion: names the row (0-based, or kNoRow), the field, the value
// and the allowed range.
class InvalidInversionInput : public std::invalid_argument {
 public:
  static constexpr std::size_t kNoRow = static_cast<std::size_t>(-1);
  InvalidInversionInput(std::size_t row, const std::string& field, double value,
                        const std::string& why);
  std::size_t row() const { return row_; }

 private:
  std::size_t row_;
};

// Checks the readings against the test's set-up: positive, increasing times, kMinReadings to
// kMaxReadings of them, values between -10 % and 110 % finer as readings (the 152H's raw reading is
// checked on its -5..60 scale by validate_lab_readings), refine within [0, kMaxRefine]. Throws
// InvalidInversionInput.
void validate_measurements(const TestSetup& setup, Test test, const std::vector<Measurement>& data,
                           const InversionOptions& options);

// The grading curve whose forward-modelled readings match `data`: non-negative least
// squares of the whitened misfit plus lambda times the squared first differences of the
// bins' mass per log d (zero for a curve linear in log d), with the shares summing to 1;
// lambda by the discrepancy principle; Gauss-Newton for the hydrometer; the band by a
// parametric bootstrap of the reading noise. docs/invert.md has the details.
InvertedCurve invert_readings(const TestSetup& setup, Test test,
                              const std::vector<Measurement>& data,
                              const InversionOptions& options = {});

}  // namespace sedem::invert
