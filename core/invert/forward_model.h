#pragma once

#include <string>
#include <utility>
#include <vector>

#include <Eigen/Dense>

#include "core/instruments/buoyancy_sphere.h"
#include "core/instruments/hydrometer.h"
#include "core/instruments/pipette.h"
#include "core/instruments/suspension.h"
#include "core/instruments/test_setup.h"
#include "core/reference/reference_field.h"

namespace sedem::invert {

enum class Test { hydrometer, buoyancy, pipette };

// "hydrometer" | "buoyancy" | "pipette"; throws std::invalid_argument otherwise.
Test parse_test(const std::string& name);
std::string test_name(Test test);
// The unit of a test's reading as the laboratory records it: "g/L" (152H, R - C), "g"
// (sphere's apparent mass, pipette's dry mass).
std::string reading_unit(Test test);

// The unknown curve's grid: nodes d_0 < ... < d_{n-1} (m, evenly spaced in log d) cut the
// diameters into n + 1 bins: bin 0 is finer than d_0, bin k (1 <= k < n) is (d_{k-1}, d_k],
// bin n is coarser than d_{n-1}. The unknowns are the bins' shares x_k of the sample's mass,
// so the curve at the nodes, P(d_k) = 100 (x_0 + ... + x_k), is monotone by x >= 0.
struct Grid {
  std::vector<double> nodes;  // m
  std::size_t bins() const { return nodes.size() + 1; }
};

// `count` nodes evenly spaced in log d from `smallest` to `largest`.
Grid log_grid(double smallest, double largest, std::size_t count);

// The grid of a set of readings: a node at each reading's diameter (those closer than 2 %
// merged), `refine` more nodes evenly in log d between each two, and margins: two intervals
// down to the smallest / 1.5 and two up to twice the largest (coarser grains have left the
// instrument by the first reading). Then a node at each of `edges` inside the grid's range and
// more than 1 % from every node already there: the edges of the readings' windows
// (ForwardModel::reading_window), so that no interval straddles one. The curve is linear in
// log d inside an interval: one that reached from a reading's own sizes into a knee just
// beyond them would carry the knee's slope into that reading, and the fit would bend the
// curve at the reading to make up for it (1.6-2.2 pp on the benchmark's narrow curves).
Grid reading_grid(std::vector<double> diameters, int refine, const std::vector<double>& edges = {});

// Each interval between the grid's nodes cut into `parts` even in log d (the grid's nodes stay,
// node k at k * parts), and shares on it that give the same curve: each interior bin's share
// spread evenly over its parts, the open-ended bins as they are.
Grid split_grid(const Grid& grid, int parts);
Eigen::VectorXd split_shares(const Eigen::VectorXd& x, int parts);

// The widths of the bins in ln d: ln 10 for the finest, ln 4 for the coarsest.
std::vector<double> bin_widths(const Grid& grid);

// The continuum reference solution of the setup (core/reference) read by the setup's
// instrument for `test` at `times`, for a sample whose mass is spread over the grid's bins
// as `x` says. Each bin is `subclasses` size classes evenly spaced in log d across it (the
// curve linear in log d inside a bin, as a "table" grading is); the finest bin spans a
// decade below d_0 and the coarsest from d_{n-1} to 4 d_{n-1}. Drag law, hindrance, bed,
// cylinder, fluid, particle density, sample mass, layers and the instruments' geometry are
// the setup's.
//
// Readings are in the laboratory's units (reading_unit): the 152H's R minus its reading in
// the setup's clear liquid (what a laboratory's composite correction removes), the
// sphere's apparent mass, the pipette's dry mass. The sphere's and the pipette's are affine
// in x (while the bed stays below them); the hydrometer's is nearly so, through the bulb's
// equilibrium depth.
class ForwardModel {
 public:
  ForwardModel(const TestSetup& setup, Test test, Grid grid, std::vector<double> times,
               int subclasses = 8);

  Test test() const { return test_; }
  const Grid& grid() const { return grid_; }
  const std::vector<double>& times() const { return times_; }
  const Suspension& suspension() const { return suspension_; }
  // True when the readings are affine in x: the sphere's and the pipette's (with the speeds
  // held, below, when they depend on the voidage).
  bool affine() const { return test_ != Test::hydrometer; }
  // The settling speeds depend on the voidage, i.e. on x itself (local_voidage): an inversion
  // holds them at its current x (hold_speeds_at), which makes the readings of other x those of
  // the same fronts with other masses, and takes them anew at each of its steps.
  bool speeds_depend_on_x() const { return local_voidage_; }
  void hold_speeds_at(const Eigen::VectorXd& x);

  Eigen::VectorXd readings(const Eigen::VectorXd& x) const;
  // d readings / d x at x: exact columns for the affine tests, one-sided differences of
  // `step` (a share of the sample's mass) for the hydrometer.
  Eigen::MatrixXd jacobian(const Eigen::VectorXd& x, double step = 0.02) const;
  // The same for the bins in `columns` only, in that order (a column per entry).
  Eigen::MatrixXd jacobian_columns(const Eigen::VectorXd& x,
                                   const std::vector<Eigen::Index>& columns,
                                   double step = 0.02) const;

  // The reading with no soil in suspension (0 % finer) and with the whole sample uniformly
  // in suspension (100 % finer, time zero).
  double empty_reading() const;
  double full_reading() const;
  // The 152H's own reading R in the setup's clear liquid, g/L (readings are R less this).
  double clear_liquid_reading() const { return clear_reading_; }

  // Where the test reads (m below the surface): the sphere's and the pipette's centre, the
  // 152H's bulb centre in the clear liquid (it rises as the suspension gets denser).
  double nominal_depth() const;
  // The depth of the instrument for a reading of `value` (the 152H's bulb centre rises by
  // the mark spacing per g/L; the others do not move).
  double reading_depth(double value) const;
  // Stokes' diameter (Eq. 16) at reading_depth(value) and `time`, m.
  double stokes_diameter(double time, double value) const;
  // How fast the front of a size falls from the surface in the model: the setup's drag law
  // in the initial suspension's voidage (local_voidage: exactly the coarsest front's speed,
  // and within the few per cent of hindrance of every other's), slowed by Richardson-Zaki,
  // or in clear fluid, as instruments.reference.settling says.
  double front_speed(double diameter) const;
  // The diameter whose front front_speed brings from the surface to reading_depth(value) at
  // `time`, m: where the reading pins the curve.
  double model_diameter(double time, double value) const;
  // How far the instrument reaches above and below reading_depth, m: the sphere's radius, the
  // pipette's sampling circle's, half the 152H's bulb.
  double half_span() const;
  // The sizes a reading of `value` at `time` averages over: the diameters whose fronts are at
  // the instrument's bottom and at its top (the 152H's: not above the surface), m, smallest
  // first. Sizes between are partly inside; finer ones wholly, coarser ones not at all.
  std::pair<double, double> reading_window(double time, double value) const;

 private:
  std::vector<SettlingClass> classes_of(const Eigen::VectorXd& x) const;  // bins x subclasses
  ReferenceSolution reference(const Eigen::VectorXd& x) const;
  double read(const Eigen::VectorXd& x, double time) const;
  double read_fields(const LayerFields& fields) const;
  double diameter_at(double depth, double time) const;  // whose front is at depth at time

  TestSetup setup_;
  Test test_;
  Grid grid_;
  std::vector<double> times_;
  int subclasses_;
  std::size_t layers_;
  Suspension suspension_;
  HydrometerGeometry hydrometer_;
  BuoyancySphere sphere_;
  Pipette pipette_;
  double clear_reading_ = 0;    // 152H in the clear liquid, g/L
  double hindrance_ = 1;        // on every terminal velocity
  bool local_voidage_ = false;  // speeds set by the voidage
  HeldFronts held_;             // local_voidage: the speeds held (none: from each x's own voidage)
  std::vector<double> class_diameter_, class_velocity_;  // bins x subclasses
};

}  // namespace sedem::invert
