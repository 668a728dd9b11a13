#include <gtest/gtest.h>

#include "core/scene/scene_loader.h"
#include "scene_test_support.h"

namespace sedem {
namespace {

std::string error_of(const std::string& toml, std::vector<std::string> overrides = {}) {
  return test::scene_error(toml, std::move(overrides));
}

TEST(SceneLoader, DefaultsAreThePapers) {
  Scene s = parse_scene("", "empty.toml");
  EXPECT_DOUBLE_EQ(s.fluid.viscosity, 1e-3);
  EXPECT_DOUBLE_EQ(s.cylinder.height, 0.457);
  EXPECT_DOUBLE_EQ(s.sample.total_mass, 60e-3);
  EXPECT_EQ(s.sample.size_count, 220);
  EXPECT_EQ(s.instruments.layers, 4000);
}

TEST(SceneLoader, ConvertsUserUnitsToSI) {
  Scene s = parse_scene(
      "[sample]\nmass_g = 30\n[sample.grading]\ndiameters_um = [2.5, 70]\n"
      "percent_finer = [0, 100]\n[instruments.hydrometer]\ntimes_min = [2, 5]\n",
      "units.toml");
  EXPECT_DOUBLE_EQ(s.sample.total_mass, 30e-3);
  EXPECT_DOUBLE_EQ(s.sample.grading.diameters[1], 70e-6);
  EXPECT_DOUBLE_EQ(s.instruments.hydrometer_times[1], 300.0);
}

TEST(SceneLoader, OutOfRangeNamesFileLineKeyValueAndRange) {
  const std::string e = error_of("name = \"x\"\n[fluid]\nviscosity = -1.0\n");
  EXPECT_NE(e.find("bad.toml:3"), std::string::npos) << e;
  EXPECT_NE(e.find("fluid.viscosity = -1"), std::string::npos) << e;
  EXPECT_NE(e.find("(1e-06, 10] Pa*s"), std::string::npos) << e;
}

TEST(SceneLoader, AMessageCutsALongValue) {
  // Ten thousand profile times, the last out of range: the message names the key, the bad
  // value and the length, not 70 kB of numbers.
  std::string list = "[";
  for (int k = 1; k < 10000; ++k) list += std::to_string(k) + ", ";
  list += "-1]";
  const std::string e = error_of("[instruments]\nprofile_times_min = " + list + "\n");
  EXPECT_LT(e.size(), 600u) << e.substr(0, 1000);
  EXPECT_NE(e.find("instruments.profile_times_min"), std::string::npos) << e;
  EXPECT_NE(e.find("-1"), std::string::npos) << e;
  EXPECT_NE(e.find("characters)"), std::string::npos) << e;
  EXPECT_EQ(shortened("short"), "short");
}

TEST(SceneLoader, FigureFormatsAreAnyOfPngSvgPdf) {
  // A TOML list or a comma-separated string, repeats dropped, order kept.
  EXPECT_EQ(parse_scene("[output]\nfigure_formats = [\"pdf\", \"png\", \"pdf\"]\n", "f.toml")
                .output.figure_formats,
            "pdf,png");
  EXPECT_EQ(parse_scene("", "f.toml", {"output.figure_formats=png, svg"}).output.figure_formats,
            "png,svg");
  const std::string e = error_of("[output]\nfigure_formats = [\"png\", \"jpeg\"]\n");
  EXPECT_NE(e.find("output.figure_formats"), std::string::npos) << e;
  EXPECT_NE(e.find("'jpeg' is not one of: png, svg, pdf"), std::string::npos) << e;
  EXPECT_NE(error_of("[output]\nfigure_formats = []\n").find("at least one of"), std::string::npos);
  EXPECT_NE(error_of("", {"output.figure_width_px=10"}).find("[200, 20000]"), std::string::npos);
}

TEST(SceneLoader, UnknownKeySuggestsTheNearest) {
  const std::string e = error_of("[fluid]\nviscosty = 1e-3\n");
  EXPECT_NE(e.find("unknown key 'fluid.viscosty'"), std::string::npos) << e;
  EXPECT_NE(e.find("did you mean 'fluid.viscosity'"), std::string::npos) << e;
}

TEST(SceneLoader, WrongTypeAndChoiceAreRejected) {
  EXPECT_NE(error_of("[forces]\ncontact = 3\n").find("must be true or false"), std::string::npos);
  EXPECT_NE(error_of("[forces]\ndrag = \"newton\"\n").find("is not one of: di_felice, stokes, off"),
            std::string::npos);
}

TEST(SceneLoader, SetOverridesTheFile) {
  Scene s = parse_scene("[fluid]\nviscosity = 2e-3\n", "f.toml",
                        {"fluid.viscosity=1.5e-3", "integrator.method=explicit"});
  EXPECT_DOUBLE_EQ(s.fluid.viscosity, 1.5e-3);
  EXPECT_EQ(s.integrator.method, "explicit");
  EXPECT_NE(error_of("", {"fluid.viscosity=abc"}).find("--set: fluid.viscosity"),
            std::string::npos);
}

// The explicit integrator's former name: old scenes and run records still load, as explicit.
TEST(SceneLoader, TheExplicitIntegratorsFormerNameStillLoads) {
  Scene s = parse_scene("[integrator]\nmethod = \"reference\"\n", "old.toml");
  EXPECT_EQ(integrator_method(s.integrator), IntegratorMethod::explicit_euler);
  EXPECT_NE(resolved_toml(s).find("integrator.method = \"explicit\""), std::string::npos);
  EXPECT_NE(
      error_of("[integrator]\nmethod = \"euler\"\n").find("is not one of: explicit, exponential"),
      std::string::npos);
}

TEST(SceneLoader, CrossChecksNameBothKeys) {
  const std::string e = error_of("[sample]\nparticle_density = 1001\n[fluid]\ndensity = 1500\n");
  EXPECT_NE(e.find("bad.toml:2: sample.particle_density = 1001 must exceed fluid.density = 1500"),
            std::string::npos)
      << e;
}

TEST(SceneLoader, ResolvedSceneReadsBackTheSame) {
  Scene s = parse_scene("[sample]\nmass_g = 30\n", "a.toml");
  std::string text = resolved_toml(s);
  // The resolved text is flat "key = value" lines: each must be accepted as an override.
  std::vector<std::string> sets;
  std::size_t pos = 0;
  while (pos < text.size()) {
    auto end = text.find('\n', pos);
    std::string line = text.substr(pos, end - pos);
    pos = end + 1;
    auto hash = line.find("  #");
    if (hash != std::string::npos) line.resize(hash);
    auto eq = line.find(" = ");
    sets.push_back(line.substr(0, eq) + "=" + line.substr(eq + 3));
  }
  Scene back = parse_scene("", "b.toml", sets);
  EXPECT_DOUBLE_EQ(back.sample.total_mass, 30e-3);
  EXPECT_EQ(resolved_toml(back), text);
}

}  // namespace
}  // namespace sedem
