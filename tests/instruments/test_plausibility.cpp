#include <gtest/gtest.h>

#include <limits>
#include <string>
#include <vector>

#include "core/instruments/plausibility.h"

namespace sedem {
namespace {

const Doubt* find(const std::vector<Doubt>& doubts, const std::string& code) {
  for (const auto& d : doubts)
    if (d.code == code) return &d;
  return nullptr;
}

// One test's DEM and reference readings at the same times.
TestComparison comparison(const std::string& test, const std::vector<double>& dem,
                          const std::vector<double>& reference, double error) {
  TestComparison c;
  c.test = c.dem.test = c.reference.test = test;
  for (std::size_t i = 0; i < dem.size(); ++i) {
    c.dem.rows.push_back({60.0 * double(i + 1), 20e-6, dem[i], {}});
    c.reference.rows.push_back({60.0 * double(i + 1), 20e-6, reference[i], {}});
  }
  c.error = error;
  return c;
}

TEST(Plausibility, FewParticlesInAVolumeAreCountedAndNamed) {
  TestSetup setup;
  setup.instruments.buoyancy = setup.instruments.hydrometer = false;
  setup.instruments.pipette = true;
  // The pipette's circle is a small share of the section: a thousand particles put a few in it.
  const auto volumes = sampled_volumes(setup, 1000);
  ASSERT_EQ(volumes.size(), 1u);
  ASSERT_LT(volumes[0].particles, kDoubtfulSampled);
  const auto doubts = setup_doubts(setup, 1000);
  const Doubt* few = find(doubts, "few_particles");
  ASSERT_NE(few, nullptr);
  EXPECT_NE(few->message.find("pipette"), std::string::npos) << few->message;
  EXPECT_NE(few->message.find("of the 1000 simulated particles"), std::string::npos)
      << few->message;
  EXPECT_NE(few->message.find("instruments.pipette.volume_ml"), std::string::npos) << few->message;
  // Enough particles: no doubt.
  EXPECT_EQ(find(setup_doubts(setup, 1000 * kDoubtfulSampled / volumes[0].particles + 10),
                 "few_particles"),
            nullptr);
}

TEST(Plausibility, PercentFinerOutsideZeroToHundredBeyondTheNoiseIsADoubt) {
  TestSetup setup;
  const double many = 1e7;  // the noise floor of 1 pp holds
  Granulometry g;
  // 100.5 % is within the noise (at least 1 pp); 112 % is not.
  g.tests.push_back(comparison("hydrometer", {100.5, 60, 40}, {99, 60, 40}, 1.5));
  EXPECT_EQ(find(result_doubts(g, setup, many), "percent_finer_out_of_range"), nullptr);
  g.tests[0] = comparison("hydrometer", {112, 60, 40}, {99, 60, 40}, 13);
  const auto doubts = result_doubts(g, setup, many);
  const Doubt* out = find(doubts, "percent_finer_out_of_range");
  ASSERT_NE(out, nullptr);
  EXPECT_NE(out->message.find("hydrometer reads 112.0 % finer at 60.0 s"), std::string::npos)
      << out->message;
  // Below zero too.
  g.tests[0] = comparison("hydrometer", {90, 60, -8}, {90, 60, 1}, 9);
  EXPECT_NE(find(result_doubts(g, setup, many), "percent_finer_out_of_range"), nullptr);
  // The noise grows as the particles in the volume fall: 112 % with a few hundred particles
  // in all is within it.
  g.tests[0] = comparison("hydrometer", {112, 60, 40}, {99, 60, 40}, 13);
  EXPECT_EQ(find(result_doubts(g, setup, 300), "percent_finer_out_of_range"), nullptr);
}

TEST(Plausibility, AnErrorBeyondTheTestsSpanIsADoubt) {
  TestSetup setup;
  Granulometry g;
  // The reference spans 60-80 %: an error of 15 pp is inside that, 30 pp is not.
  g.tests.push_back(comparison("pipette", {75, 65}, {80, 60}, 15));
  EXPECT_EQ(find(result_doubts(g, setup, 1e7), "error_beyond_range"), nullptr);
  g.tests[0].error = 30;
  const auto doubts = result_doubts(g, setup, 1e7);
  const Doubt* beyond = find(doubts, "error_beyond_range");
  ASSERT_NE(beyond, nullptr);
  EXPECT_NE(beyond->message.find("pipette: its error (30.0 pp)"), std::string::npos)
      << beyond->message;
  EXPECT_NE(beyond->message.find("(20.0 pp of percent finer"), std::string::npos)
      << beyond->message;
  // A span narrower than 5 pp counts as 5: an error of 4 pp over a 1 pp span is no doubt.
  g.tests[0] = comparison("pipette", {75, 74}, {75, 74}, 4);
  EXPECT_EQ(find(result_doubts(g, setup, 1e7), "error_beyond_range"), nullptr);
  // No number (a test without readings): no doubt.
  g.tests[0] = comparison("pipette", {}, {}, std::numeric_limits<double>::quiet_NaN());
  EXPECT_TRUE(result_doubts(g, setup, 1e7).empty());
}

}  // namespace
}  // namespace sedem
