#include <gtest/gtest.h>

#include <sstream>
#include <string>
#include <vector>

#include "core/scene/scene_loader.h"
#include "scene_test_support.h"

namespace sedem {
namespace {

std::string error_of(const std::string& toml, std::vector<std::string> overrides = {}) {
  return test::scene_error(toml, std::move(overrides));
}

#define EXPECT_MESSAGE(message, part) \
  EXPECT_NE(std::string(message).find(part), std::string::npos) << (message)

const std::string kTable = "[sample.grading]\nfamily = \"table\"\n";

TEST(SceneChecks, TableMustAscend) {
  const std::string e =
      error_of(kTable + "diameters_um = [2.5, 10, 5, 70]\npercent_finer = [0, 10, 20, 100]\n");
  EXPECT_MESSAGE(e, "bad.toml:3: sample.grading.diameters_um = [2.5, 10, 5, 70]");
  EXPECT_MESSAGE(e, "must be strictly ascending (5 follows 10)");
}

TEST(SceneChecks, PercentFinerMustNotDecreaseAndRunFrom0To100) {
  EXPECT_MESSAGE(
      error_of(kTable + "diameters_um = [2.5, 10, 70]\npercent_finer = [0, 60, 40]\n"),
      "bad.toml:4: sample.grading.percent_finer = [0, 60, 40] must not decrease (40 follows 60)");
  EXPECT_MESSAGE(error_of(kTable + "diameters_um = [2.5, 10, 70]\npercent_finer = [0, 40, 90]\n"),
                 "sample.grading.percent_finer = [0, 40, 90] must end at 100");
  EXPECT_MESSAGE(error_of(kTable + "diameters_um = [2.5, 10, 70]\npercent_finer = [5, 40, 100]\n"),
                 "sample.grading.percent_finer = [5, 40, 100] must start at 0");
  EXPECT_MESSAGE(error_of(kTable + "diameters_um = [2.5, 10, 70]\npercent_finer = [0, 100]\n"),
                 "has 2 values but sample.grading.diameters_um has 3");
  EXPECT_MESSAGE(error_of(kTable + "percent_finer = [0, 250]\n"),
                 "bad.toml:3: sample.grading.percent_finer = 250 (in [0, 250]) is out of range; "
                 "allowed: [0, 100] %");
}

TEST(SceneChecks, FamilyRangeAndParameters) {
  EXPECT_MESSAGE(error_of("[sample.grading]\nfamily = \"log_uniform\"\nmin_um = 70\nmax_um = 10\n"),
                 "bad.toml:3: sample.grading.min_um = 70 must be smaller than "
                 "sample.grading.max_um = 10");
  EXPECT_MESSAGE(
      error_of("[sample.grading]\nfamily = \"log_normal\"\nmedian_um = 5000\nspread = 0.1\n"),
      "leaves almost none");
  EXPECT_MESSAGE(error_of("[sample.grading]\nfamily = \"gaussian\"\n"),
                 "sample.grading.family = \"gaussian\" is not one of: table, log_uniform, "
                 "log_normal, rosin_rammler, single");
  EXPECT_MESSAGE(error_of("[sample.grading]\nfamily = \"single\"\ndiameter_um = 5000\n"
                          "[cylinder]\ndiameter_m = 0.004\n"),
                 "cylinder.diameter_m = 0.004 is smaller than the largest grain (5000 um)");
  EXPECT_MESSAGE(error_of("[sample]\nsize_count = 2.5\n"),
                 "bad.toml:2: sample.size_count = 2.5 must be a whole number");
}

TEST(SceneChecks, CountAndFractionAreAlternatives) {
  const std::string both = error_of("[sample]\nsimulated_count = 2000\nmass_fraction = 1e-4\n");
  EXPECT_MESSAGE(both,
                 "bad.toml:3: sample.mass_fraction = 0.0001 and bad.toml:2: "
                 "sample.simulated_count = 2000 are alternatives; give only one of them");
  EXPECT_MESSAGE(error_of("", {"sample.simulated_count=10", "sample.mass_fraction=0.1"}),
                 "--set: sample.mass_fraction = 0.1 and --set: sample.simulated_count = 10");
  EXPECT_MESSAGE(error_of("[sample]\nsimulated_count = 0\n"),
                 "bad.toml:2: sample.simulated_count = 0 and sample.mass_fraction = 0: give one");

  // The file's count gives way to a fraction set on the command line, and the other way round.
  Scene s =
      parse_scene("[sample]\nsimulated_count = 2000\n", "f.toml", {"sample.mass_fraction=0.01"});
  EXPECT_EQ(s.sample.simulated_count, 0);
  EXPECT_DOUBLE_EQ(s.sample.mass_fraction, 0.01);
  s = parse_scene("[sample]\nmass_fraction = 0.01\n", "f.toml", {"sample.simulated_count=300"});
  EXPECT_EQ(s.sample.simulated_count, 300);
  EXPECT_EQ(s.sample.mass_fraction, 0);
  // A fraction alone in the file replaces the default count.
  s = parse_scene("[sample]\nmass_fraction = 0.01\n", "f.toml");
  EXPECT_EQ(s.sample.simulated_count, 0);
}

// The resolved scene lists both keys, the unused one as 0: read back as overrides it must
// give the same scene.
TEST(SceneChecks, ResolvedSceneWithAFractionReadsBack) {
  Scene s = parse_scene("[sample]\nmass_fraction = 0.01\n", "f.toml");
  std::vector<std::string> sets;
  std::istringstream lines(resolved_toml(s));
  for (std::string line; std::getline(lines, line);) {
    line = line.substr(0, line.find("  #"));
    const auto eq = line.find(" = ");
    sets.push_back(line.substr(0, eq) + "=" + line.substr(eq + 3));
  }
  Scene back = parse_scene("", "b.toml", sets);
  EXPECT_EQ(back.sample.simulated_count, 0);
  EXPECT_DOUBLE_EQ(back.sample.mass_fraction, 0.01);
  EXPECT_EQ(resolved_toml(back), resolved_toml(s));
}

TEST(SceneChecks, EverySizeNeedsAParticle) {
  EXPECT_MESSAGE(error_of("[sample]\nsimulated_count = 100\n"),
                 "bad.toml:2: sample.simulated_count = 100 gives 100 particles for the 220 sizes "
                 "of the grading curve, and each size needs at least one");
  EXPECT_MESSAGE(error_of("[sample]\nmass_fraction = 1e-12\n"),
                 "bad.toml:2: sample.mass_fraction = 1e-12 gives 0 particles");
  EXPECT_MESSAGE(error_of("[sample]\nmass_fraction = 0.9\nweighting = \"uniform_count\"\n"),
                 "particles; at most 1e+08");
}

// An instrument whose sampled volume holds under one simulated particle reads noise alone:
// refused, naming the key that made it so (the count, or the instrument's own size).
TEST(SceneChecks, AnInstrumentWithUnderOneParticleInItsVolumeIsRefused) {
  const std::string two_sizes =
      "[sample]\nsize_count = 2\nsimulated_count = 1500\n[sample.grading]\nfamily = "
      "\"table\"\ndiameters_um = [10.0, 35.0, 60.0]\npercent_finer = [0.0, 50.0, 100.0]\n";
  EXPECT_EQ(error_of(two_sizes), "");
  const std::string few = error_of(two_sizes, {"sample.simulated_count=16"});
  EXPECT_MESSAGE(few, "sample.simulated_count = 16 leaves about");
  EXPECT_MESSAGE(few, "its readings would be noise alone");
  EXPECT_MESSAGE(few, "allowed for this scene: >= ");
  const std::string small = error_of(two_sizes, {"instruments.pipette.volume_ml=0.01"});
  EXPECT_MESSAGE(small, "instruments.pipette.volume_ml = 0.01 leaves about");
  EXPECT_MESSAGE(small, "in the pipette's sampled volume");
  EXPECT_MESSAGE(small, "mL (or instruments.pipette.enabled = false)");
  // The instrument off: nothing to refuse.
  EXPECT_EQ(error_of(two_sizes,
                     {"instruments.pipette.volume_ml=0.01", "instruments.pipette.enabled=false"}),
            "");
}

TEST(SceneChecks, UnplaceableSceneIsRefusedWithTheReason) {
  const std::string e = error_of(
      "[cylinder]\nheight_m = 0.01\ndiameter_m = 0.004\n[sample]\nsimulated_count = 20000\n"
      "[sample.grading]\nfamily = \"single\"\ndiameter_um = 40\n");
  EXPECT_MESSAGE(e,
                 "bad.toml:5: sample.simulated_count = 20000 gives 20000 particles of total "
                 "area 2.51327e-05 m^2, which cannot be placed without overlap in the "
                 "section: area fraction 0.628319 > limit 0.4");
  EXPECT_MESSAGE(error_of("[sample]\nsimulated_count = 1000\n[sample.placement]\n"
                          "cells_per_side = 40\n"),
                 "bad.toml:4: sample.placement.cells_per_side = 40 makes more cells than "
                 "particles (1000); at most 32");
}

TEST(SceneChecks, UnknownKeysInAnyTableGetTheNearestName) {
  EXPECT_MESSAGE(error_of("[sampel]\nseed = 3\n"),
                 "bad.toml:2: unknown key 'sampel.seed'; did you mean 'sample.seed'?");
  EXPECT_MESSAGE(error_of("[sample.grading]\ndiameter_um = [2.5, 70]\n"),
                 "sample.grading.diameter_um = [2.5, 70] must be a number");
  EXPECT_MESSAGE(error_of("[sample.grading]\ndiameters = [2.5, 70]\n"),
                 "did you mean 'sample.grading.diameters_um'?");
  EXPECT_MESSAGE(error_of("", {"sample.masss_fraction=0.1"}),
                 "--set: unknown key 'sample.masss_fraction'; did you mean 'sample.mass_fraction'");
  EXPECT_MESSAGE(error_of("[sample\nseed = 3\n"), "bad.toml:1: ");
}

// A member's box of less than 2 steps' travel would keep every later step from growing.
TEST(SceneChecks, MemberBoxStepsAreZeroOrAtLeastTwo) {
  const std::string e = test::scene_error("[integrator]\nmember_box_steps = 1.5\n", {});
  EXPECT_NE(e.find("bad.toml:2: integrator.member_box_steps = 1.5 must be 0"), std::string::npos)
      << e;
  EXPECT_NE(e.find("or at least 2"), std::string::npos) << e;
  EXPECT_EQ(test::scene_error("[integrator]\nmember_box_steps = 0\n", {}), "");
  EXPECT_EQ(test::scene_error("[integrator]\nmember_box_steps = 2\n", {}), "");
}

}  // namespace
}  // namespace sedem

namespace sedem {
namespace {

// Grains that pass each other must not build a contact bed: the option needs retirement.
TEST(SceneChecks, SuspensionContactsOffNeedsRetirement) {
  const std::string off = "[forces]\nsuspension_contacts = false\n";
  EXPECT_EQ(test::scene_error(off, {}), "");
  const std::string e = test::scene_error(
      off +
          "[instruments.hydrometer]\nenabled = false\n[instruments.buoyancy]\nenabled = "
          "false\n[instruments.pipette]\nenabled = false\n",
      {});
  EXPECT_NE(e.find("bad.toml:2: forces.suspension_contacts = false"), std::string::npos) << e;
  EXPECT_NE(e.find("= false needs grains to retire onto the coarse bed"), std::string::npos) << e;
  EXPECT_NE(test::scene_error(off, {"integrator.local_steps=false"}).find("local_steps"),
            std::string::npos);
}

// Carried sub-steps are taken within carried steps: without them the option would do nothing.
TEST(SceneChecks, CarriedSubstepsNeedCarriedSteps) {
  const std::string on = "[integrator]\ncarried_substeps = true\n";
  const std::string e = test::scene_error(on, {});
  EXPECT_NE(e.find("bad.toml:2: integrator.carried_substeps = true needs carried steps"),
            std::string::npos)
      << e;
  EXPECT_NE(e.find("integrator.carried_fraction in (0, 1]"), std::string::npos) << e;
  EXPECT_EQ(test::scene_error(on + "carried_fraction = 0.8\n", {}), "");
}

// Own steps are an alternative to carried steps, and need members that meet: refused with
// either of those missing, accepted alone.
TEST(SceneChecks, OwnStepsNeedContactsEverywhereAndNoCarriedSteps) {
  const std::string on = "[integrator]\nown_steps = true\n";
  EXPECT_EQ(test::scene_error(on, {}), "");
  const std::string e = test::scene_error(on + "carried_fraction = 0.8\n", {});
  EXPECT_NE(e.find("bad.toml:2: integrator.own_steps = true needs"), std::string::npos) << e;
  EXPECT_NE(e.find("integrator.carried_fraction = 0"), std::string::npos) << e;
  EXPECT_NE(test::scene_error(on, {"integrator.local_steps=false"}).find("integrator.own_steps"),
            std::string::npos);
}

}  // namespace
}  // namespace sedem

namespace sedem {
namespace {

// Coasting windows are counted while each grain is in suspension, not over the whole test: ten
// million 5 um grains fall the column in about 6 h and take some 3e9 windows of 60 s (counted
// over 24 h: 1.4e10, refused), while windows of 0.5 s would make 4e11.
TEST(SceneChecks, CoastingWindowsAreCountedWhileTheGrainsAreInSuspension) {
  const std::string fine =
      "[run]\nend_time_s = 86400\n[sample]\nsimulated_count = 10000000\n[sample.grading]\n"
      "family = \"single\"\ndiameter_um = 5\n";
  EXPECT_EQ(test::scene_error(fine, {}), "");
  const std::string e = test::scene_error(fine, {"integrator.max_coast_s=0.5"});
  EXPECT_NE(e.find("integrator.max_coast_s = 0.5 makes 1e+07 particles take about"),
            std::string::npos)
      << e;
  EXPECT_NE(e.find("allowed for this scene: >= "), std::string::npos) << e;
}

}  // namespace
}  // namespace sedem
