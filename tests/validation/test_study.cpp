// The study over seeds: the rule on intervals computed by hand, and each effect on hand-made
// runs whose answer is known.
#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <sstream>

#include "bench/validation/markdown.h"
#include "bench/validation/study.h"
#include "bench/validation/study_report.h"
#include "tests/validation/validation_test_support.h"

namespace sedem::validation {
namespace {

using testing::curve;
using testing::run;
using testing::run_test;

Interval interval(std::size_t n, double mean, double sd, double low, double high) {
  Interval i;
  i.n = n;
  i.mean = mean;
  i.sd = sd;
  i.low = low;
  i.high = high;
  return i;
}

TEST(StudyRule, AnIntervalAboveZeroSupportsAndOneBelowContradicts) {
  EXPECT_EQ(decide(interval(5, 2, 1, 1, 3)).verdict, StudyVerdict::supports);
  EXPECT_EQ(decide(interval(4, -1, 0.5, -1.8, -0.2)).verdict, StudyVerdict::contradicts);
  // Excluding zero wins over the margin: a small but certain effect is still an effect, and
  // the text says it is too small to matter.
  EXPECT_EQ(decide(interval(40, 0.2, 0.1, 0.1, 0.3)).verdict, StudyVerdict::supports);
  EXPECT_EQ(decide(interval(40, 0.2, 0.1, 0.1, 0.3)).text(), "supports, inside ±0.5 pp");
  EXPECT_EQ(decide(interval(40, -0.2, 0.1, -0.3, -0.1)).text(), "contradicts, inside ±0.5 pp");
  EXPECT_EQ(decide(interval(40, 0.6, 0.1, 0.4, 0.8)).text(), "supports");
  // Touching zero does not exclude it.
  EXPECT_EQ(decide(interval(5, 1, 1, 0, 2)).verdict, StudyVerdict::inconclusive);
}

TEST(StudyRule, AnIntervalInsideTheMarginIsNoEffect) {
  EXPECT_EQ(decide(interval(10, 0.1, 0.2, -0.05, 0.25)).text(), "no effect");
  EXPECT_EQ(decide(interval(10, 0.1, 0.2, -0.05, 0.25), 0.2).verdict, StudyVerdict::inconclusive);
}

TEST(StudyRule, InconclusiveNamesTheSeedsThatWouldDecideIt) {
  // Seeds 1, 2, 3: mean 2, sd 1, half-width t(2) / sqrt(3) = 4.303 / 1.732 = 2.48, so the
  // interval holds zero. Four seeds: t(3) / 2 = 3.182 / 2 = 1.59 < 2 excludes zero; the margin
  // (0.5 < 2) cannot be reached.
  const Decision d = decide(mean_interval({1, 2, 3}));
  EXPECT_EQ(d.verdict, StudyVerdict::inconclusive);
  EXPECT_EQ(d.seeds_to_decide, 4u);
  EXPECT_EQ(d.text(), "inconclusive: ~4 seeds would decide it");
  // Mean 0.1, sd 1, ten seeds: [-0.62, 0.82]. Excluding zero needs t / sqrt(n) <= 0.1 (about
  // 387 seeds); fitting within 0.5 needs t / sqrt(n) <= 0.4: n = 26 gives 2.060 / 5.099 =
  // 0.404, n = 27 gives 2.056 / 5.196 = 0.396.
  const Decision m = decide(interval(10, 0.1, 1, -0.615, 0.815));
  EXPECT_EQ(m.verdict, StudyVerdict::inconclusive);
  EXPECT_EQ(m.seeds_to_decide, 27u);
  EXPECT_EQ(m.text(), "inconclusive: ~27 seeds would decide it");
}

TEST(StudyRule, OneSeedDecidesNothing) {
  const Decision d = decide(mean_interval({3.0}));
  EXPECT_EQ(d.verdict, StudyVerdict::inconclusive);
  EXPECT_EQ(d.text(), "inconclusive: needs at least 2 seeds");
  EXPECT_EQ(decide(mean_interval({NAN, NAN})).text(), "inconclusive: no seed has readings for it");
}

// The true curve of testing::linear_sample() at 50, 30 and 10 um (times 1, 2, 3 s), shifted.
TestReadings reading(const std::string& test, double at50, double at30, double at10) {
  return curve(test, {{1, 50, 100.0 * 50 / 70 + at50},
                      {2, 30, 100.0 * 30 / 70 + at30},
                      {3, 10, 100.0 * 10 / 70 + at10}});
}
TestReadings truth(const std::string& test) {
  return reading(test, 0, 0, 0);
}

// One sample read by the three tests: the hydrometer bent at 30 um, the sphere and the
// pipette off at the large sizes.
RunFolder sample(const std::string& name) {
  return run(name, {run_test(reading("hydrometer", 0, 3, 0), truth("hydrometer")),
                    run_test(reading("buoyancy", 2, -2, 0), truth("buoyancy")),
                    run_test(reading("pipette", 6, 4, 1), truth("pipette"))});
}

TEST(StudyEffects, EachEffectOnAHandMadeSample) {
  const std::vector<RunFolder> runs = {sample("s1")};
  // Large minus small |w - true|: hydrometer 1.5 - 0, buoyancy 2 - 0, pipette 5 - 1.
  EXPECT_NEAR(size_range_effect(runs), (1.5 + 2 + 4) / 3, 1e-9);
  // The truth is straight (roughness 0); the hydrometer's second difference is -6.
  EXPECT_NEAR(smoothing_effect(runs), -6, 1e-9);
  // RMS of DEM minus reference at 50 and 30 um: hydrometer 3 / sqrt(2), buoyancy 2,
  // pipette sqrt(26).
  EXPECT_NEAR(oscillation_effect(runs), 2 - 3 / std::sqrt(2.0), 1e-9);
  // Signed deviation at 50 and 30 um: 1.5, 0, 5 -> mean 6.5 / 3, found finer, not coarser.
  EXPECT_NEAR(large_size_effect(runs), -6.5 / 3, 1e-9);
  // All readings are early; the largest error is the pipette's 6 pp.
  EXPECT_NEAR(early_effect(runs, 3600), 5 - 6, 1e-9);
  EXPECT_TRUE(std::isnan(early_effect(runs, 0.5)));
}

TEST(StudyEffects, DeeperReadingsWorseIsPositive) {
  const std::vector<RunFolder> shallow = {
      run("s1", {run_test(reading("buoyancy", 1, 1, 1), truth("buoyancy")),
                 run_test(reading("pipette", 0, 0, 0), truth("pipette"))})};
  const std::vector<RunFolder> deep = {
      run("s1", {run_test(reading("buoyancy", 3, -3, 3), truth("buoyancy")),
                 run_test(reading("pipette", 0, 0, 3), truth("pipette"))})};
  EXPECT_NEAR(depth_effect(shallow, deep), (2 + 1) / 2.0, 1e-9);
  EXPECT_NEAR(depth_effect(deep, shallow), -1.5, 1e-9);
}

TEST(StudyEffects, TheReferenceHasNoScatterAndReadingsAbove100AreCounted) {
  RunFolder r = sample("s1");
  r.tests[2].dem.rows[0].percent_finer = 101;  // pipette
  r.tests[0].dem.rows[0].percent_finer = 102;  // the hydrometer's is not counted
  const SeedEffects e = seed_effects({7, {r}, {}, {}});
  EXPECT_DOUBLE_EQ(e.seed, 7);
  EXPECT_DOUBLE_EQ(e.above_100, 1);
  EXPECT_TRUE(std::isnan(e.dem[4]));  // no depth runs
  for (std::size_t k : {0u, 1u, 2u, 3u}) EXPECT_NEAR(e.reference[k], 0, 1e-9) << k;
  EXPECT_NEAR(e.reference[5], 5, 1e-9);  // reference against itself: no error at all
  // The largest early error is now the hydrometer's 102 against the reference 100 * 50 / 70.
  EXPECT_NEAR(e.dem[5], 5 - (102 - 500.0 / 7), 1e-9);
}

TEST(StudyEffects, ARegimeDecidesEachConclusionOverItsSeeds) {
  std::vector<SeedEffects> seeds(3);
  for (std::size_t s = 0; s < 3; ++s) {
    seeds[s].seed = double(s + 1);
    seeds[s].dem.fill(double(s + 1));  // 1, 2, 3
    seeds[s].reference.fill(0.5);
    seeds[s].above_100 = double(2 * s);
  }
  const StudyRegime r = study_regime("passing", seeds, false);
  const StudyConclusion& c = r.conclusions[0];
  EXPECT_EQ(c.number, 1u);
  EXPECT_NEAR(c.effect.mean, 2, 1e-12);
  EXPECT_NEAR(c.reference, 0.5, 1e-12);
  EXPECT_NEAR(c.scatter.mean, 1.5, 1e-12);
  EXPECT_NEAR(c.scatter.sd, 1, 1e-12);
  EXPECT_EQ(c.decision.seeds_to_decide, 4u);
  EXPECT_NEAR(r.above_100.mean, 2, 1e-12);
  EXPECT_EQ(r.conclusions[4].decision.text(), "not run");
  EXPECT_EQ(study_regime("passing", seeds, true).conclusions[4].decision.seeds_to_decide, 4u);
}

TEST(StudyReport, TheSectionStatesTheRuleAndFitsTheDocument) {
  std::vector<SeedEffects> seeds(3);
  for (std::size_t s = 0; s < 3; ++s) {
    seeds[s].dem.fill(double(s + 1));
    seeds[s].above_100 = double(2 * s);
  }
  StudyRegime r = study_regime("contacts", seeds, false);
  r.note = "3 seeds";
  const std::string section = study_markdown({r});
  for (const char* text :
       {"written before the runs", "within ±0.5 pp", "**contacts** (3 seeds)",
        "| 1 | Inside the range", "2.00 [-0.48, 4.48]",
        "**inconclusive: ~4 seeds would decide it**", "**not run**", "| 2.0 [-3.0, 7.0] |"})
    EXPECT_NE(section.find(text), std::string::npos) << text << "\n" << section;
  std::ifstream doc(std::string(SEDEM_SOURCE_DIR) + "/docs/validation.md");
  std::stringstream text;
  text << doc.rdbuf();
  const std::string updated = replace_generated(text.str(), "study", section);
  EXPECT_NE(updated.find(section), std::string::npos);
}

}  // namespace
}  // namespace sedem::validation
