// The round trip on small cases: readings of a known sample from the reference solution,
// rounded to the instrument's resolution, inverted; the inverted curve against the true one
// and against the standard reduction of the same readings. And the band's coverage over
// noisy copies of the readings.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <random>

#include "core/invert/inversion.h"
#include "tests/invert/round_trip.h"

namespace sedem::invert {
namespace {

using test::classes_only;
using test::knee_scene;
using test::log_uniform_scene;
using test::recorded;
using test::simulate_test;

struct RoundTrip {
  double inverted = 0;  // largest |inverted - true| at the standard reduction's diameters, pp
  double standard = 0;  // largest |standard - true| there, pp
  InvertedCurve curve;
};

RoundTrip round_trip(const Scene& scene, Test test, const InversionOptions& options = {}) {
  const Sample sample = classes_only(scene);
  const auto sim = simulate_test(scene, sample, test);
  RoundTrip r;
  r.curve = invert_readings(test_setup(scene), test, recorded(scene, sim, test), options);
  for (const auto& row : sim.reference.rows) {
    const double truth = true_percent_finer(sample.classes, row.diameter);
    r.inverted = std::max(r.inverted, std::abs(r.curve.at(row.diameter) - truth));
    r.standard = std::max(r.standard, std::abs(row.percent_finer - truth));
    if (std::getenv("SEDEM_INVERT_DEBUG"))
      std::printf("  d %.2f um truth %.2f standard %.2f inverted %.2f\n", row.diameter * 1e6, truth,
                  row.percent_finer, r.curve.at(row.diameter));
  }
  std::printf("%-10s inverted %.2f pp, standard %.2f pp, lambda %.3g, chi2 %.2f (target %.2f)\n",
              test_name(test).c_str(), r.inverted, r.standard, r.curve.lambda, r.curve.chi2,
              r.curve.chi2_target);
  return r;
}

InversionOptions quick() {
  InversionOptions o;
  o.bootstrap = 0;
  o.bounds = false;
  return o;
}

TEST(RoundTrip, SmoothCurveEveryTest) {
  for (invert::Test t : {invert::Test::hydrometer, invert::Test::buoyancy, invert::Test::pipette}) {
    const auto r = round_trip(log_uniform_scene(), t, quick());
    EXPECT_LE(r.inverted, std::max(2.0, r.standard + 0.5)) << test_name(t);
    EXPECT_LE(r.curve.chi2, r.curve.chi2_target * 1.05 + 1e-9) << test_name(t);
  }
}

// The knee lies between the ranges of diameters two readings see (the sphere's and the
// pipette's circles span a few per cent in d around each pinned diameter), and the standard
// reduction's diameters (Stokes' law, 3-8 % finer than the hindered fronts the readings
// follow) fall at the lower edge of those ranges, where only the smoothing places the curve:
// the 152H halves its error, the sphere and the pipette improve on theirs without halving it
// (docs/invert.md, "Measured").
TEST(RoundTrip, SteepCurveEveryTest) {
  for (invert::Test t : {invert::Test::hydrometer, invert::Test::buoyancy, invert::Test::pipette}) {
    const auto r = round_trip(knee_scene(), t, quick());
    ASSERT_GT(r.standard, 2.0) << test_name(t);
    if (t == invert::Test::hydrometer)
      EXPECT_LE(r.inverted, 0.5 * r.standard) << test_name(t);
    else
      EXPECT_LT(r.inverted, r.standard) << test_name(t);
  }
}

// Rounding leaves every reading within half a resolution step of the truth's, so no fitted
// reading may miss its measured one by more than that beyond what the least smoothing misses
// it by (the model's floor: the grid's curves are not the sample's 220 classes).
TEST(RoundTrip, NoReadingMissesByMoreThanHalfAStep) {
  for (const Scene& scene : {log_uniform_scene(), knee_scene()})
    for (invert::Test t :
         {invert::Test::hydrometer, invert::Test::buoyancy, invert::Test::pipette}) {
      const auto r = round_trip(scene, t, quick());
      const double half = 0.5 * default_resolution(t);
      for (std::size_t i = 0; i < r.curve.measured.size(); ++i)
        EXPECT_LE(std::abs(r.curve.fitted[i] - r.curve.measured[i]),
                  std::abs(r.curve.floor_residual[i]) + 1.02 * half)
            << test_name(t) << " reading " << i;
    }
}

// Each reading pins the curve where the front of that size is at the instrument's depth:
// with the scene's Di Felice drag in the voidage around it, a grain is slower than in clear
// fluid, so the pinned diameter is larger than clear fluid's.
TEST(Pins, FollowTheHinderedFronts) {
  Scene hindered = knee_scene();
  hindered.forces.drag = "di_felice";
  hindered.instruments.reference_settling = "local_voidage";
  Scene free = hindered;
  free.instruments.reference_settling = "free";
  const ForwardModel a(test_setup(hindered), invert::Test::buoyancy, log_grid(1e-6, 1e-4, 2), {});
  const ForwardModel b(test_setup(free), invert::Test::buoyancy, log_grid(1e-6, 1e-4, 2), {});
  for (double t : {30.0, 900.0}) {
    const double d = a.model_diameter(t, 0.0), d_free = b.model_diameter(t, 0.0);
    EXPECT_NEAR(a.front_speed(d) * t, a.nominal_depth(), 1e-9);
    EXPECT_NEAR(b.front_speed(d_free) * t, b.nominal_depth(), 1e-9);
    EXPECT_GT(d, 1.005 * d_free);
    EXPECT_LT(d, 1.05 * d_free);
  }
}

// 100 noisy copies of the same readings (an error uniform over one resolution step added
// before rounding): the true curve, at the diameters the readings pin, lies inside the
// reported 90 % band in about 90 % of the cases.
// Where the band is scored: at the readings' diameters, or midway between two neighbouring
// ones (in log d), where a knee hides from every reading.
enum class Where { readings, between };

double coverage(const Scene& scene, invert::Test test, int copies, int replicas,
                Where where = Where::readings, bool bounds = false) {
  const Sample sample = classes_only(scene);
  const auto sim = simulate_test(scene, sample, test);
  std::mt19937_64 rng(11);
  const double res = default_resolution(test);
  std::uniform_real_distribution<double> noise(-0.5 * res, 0.5 * res);
  InversionOptions o;
  o.bootstrap = replicas;
  o.bounds = bounds;  // the band alone, or widened to the bounds where the readings cannot tell
  int inside = 0, total = 0;
  for (int c = 0; c < copies; ++c) {
    std::vector<double> shift;
    for (std::size_t i = 0; i < sim.raw.size(); ++i) shift.push_back(noise(rng));
    o.seed = std::uint64_t(c + 1);
    const auto curve =
        invert_readings(test_setup(scene), test, recorded(scene, sim, test, shift), o);
    for (double d : where == Where::readings ? curve.reading_diameter : curve.between_readings()) {
      const double truth = true_percent_finer(sample.classes, d);
      if (truth <= 0.5 || truth >= 99.5) continue;  // the ends say nothing about the band
      ++total;
      if (truth >= curve.lower_at(d) - 1e-9 && truth <= curve.upper_at(d) + 1e-9)
        ++inside;
      else if (std::getenv("SEDEM_INVERT_DEBUG"))
        std::printf("  miss d %.2f truth %.2f band %.2f %.2f at %.2f\n", d * 1e6, truth,
                    curve.lower_at(d), curve.upper_at(d), curve.at(d));
    }
  }
  const double share = double(inside) / double(total);
  std::printf("%-10s coverage %.3f (%d of %d)\n", test_name(test).c_str(), share, inside, total);
  return share;
}

// The sphere's and the pipette's readings pin averages over their circles so finely (1 mg,
// 0.1 mg) that, with the prior's spread at the chosen lambda, their 90 % bands covered the
// knee's truth at 0.67 and 0.50 of the points; with the spread calibrated to the fit's
// roughness, at 0.77 and 0.75 (the knee sits where the readings say nothing).
TEST(Band, CoversTheKneeForTheSphereAndThePipette) {
  for (invert::Test t : {invert::Test::buoyancy, invert::Test::pipette})
    EXPECT_GE(coverage(knee_scene(), t, 30, 60), 0.7) << test_name(t);
}

// Between two readings, at a knee neither sees, the smoothness prior alone narrows the band.
// With the grid's coarseness in the band and the bounds where the readings cannot tell, the
// 90 % band covers sample 4's knee midway between readings at 0.97 (sphere) and 0.86 (pipette;
// its misses are 0.5 pp at 98 %, above the knee), and the knee itself is said to be open.
TEST(Band, CoversTheKneeBetweenReadingsWhereTheReadingsCannotTell) {
  for (invert::Test t : {invert::Test::buoyancy, invert::Test::pipette})
    EXPECT_GE(coverage(knee_scene(), t, 10, 40, Where::between, true), 0.85) << test_name(t);
  const Scene scene = knee_scene();
  const Sample sample = classes_only(scene);
  const auto sim = simulate_test(scene, sample, invert::Test::buoyancy);
  InversionOptions o;
  o.bootstrap = 20;
  const auto curve = invert_readings(test_setup(scene), invert::Test::buoyancy,
                                     recorded(scene, sim, invert::Test::buoyancy), o);
  const auto ranges = curve.open_ranges();
  ASSERT_FALSE(ranges.empty());
  // The knee (92 % of the mass between 25 and 35 um) lies in a range said to be open.
  bool knee_open = false;
  for (const auto& [from, to] : ranges) knee_open |= from <= 30e-6 && to >= 30e-6;
  EXPECT_TRUE(knee_open);
  EXPECT_TRUE(curve.open_at(30e-6));
}

TEST(Band, CoversTheTruthOverNoisyCopies) {
  Scene s = log_uniform_scene();
  s.sample.size_count = 220;
  // 0.97 with the smoothing's bias and the calibrated prior in the band; 0.90 without the
  // calibration, 0.84 with the noise alone.
  EXPECT_GE(coverage(s, invert::Test::hydrometer, 100, 100), 0.88);
}

}  // namespace
}  // namespace sedem::invert
