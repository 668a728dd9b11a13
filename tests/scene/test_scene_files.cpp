#include <gtest/gtest.h>

#include <cstring>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

#include "core/run/stage_setups.h"
#include "core/sample/sample_builder.h"
#include "core/scene/scene_loader.h"
#include "core/scene/schema.h"
#include "core/scene/schema_doc.h"

namespace sedem {
namespace {

namespace fs = std::filesystem;

// Every scene shipped in scenes/ loads, and its sample can be built and placed.
TEST(SceneFiles, AllShippedScenesLoadAndPlace) {
  int count = 0;
  for (const auto& entry : fs::directory_iterator(fs::path(SEDEM_SOURCE_DIR) / "scenes")) {
    if (entry.path().extension() != ".toml") continue;
    SCOPED_TRACE(entry.path().string());
    ++count;
    Scene scene;
    ASSERT_NO_THROW(scene = load_scene(entry.path()));
    EXPECT_EQ(scene.name, entry.path().stem().string());
    const Sample sample = build_sample(sample_setup(scene));
    EXPECT_EQ(std::int64_t(sample.particles.size()), scene.sample.simulated_count);
    EXPECT_GT(sample.area_fraction, 0);
    EXPECT_LE(sample.area_fraction, scene.sample.placement.max_area_fraction);
  }
  EXPECT_GE(count, 9);
}

// Every value of a scene and its resolved TOML, bit for bit: the same bits, or the same text.
void expect_same_values(Scene& a, Scene& b) {
  Schema sa = a.schema(), sb = b.schema();
  ASSERT_EQ(sa.params().size(), sb.params().size());
  for (std::size_t i = 0; i < sa.params().size(); ++i) {
    const Param& pa = sa.params()[i];
    const Param& pb = sb.params()[i];
    SCOPED_TRACE(pa.key);
    if (const auto* v = std::get_if<double*>(&pa.target)) {
      const double x = **v, y = *std::get<double*>(pb.target);
      EXPECT_EQ(std::memcmp(&x, &y, sizeof x), 0) << std::hexfloat << x << " against " << y;
    } else if (const auto* v = std::get_if<std::vector<double>*>(&pa.target)) {
      const auto& x = **v;
      const auto& y = *std::get<std::vector<double>*>(pb.target);
      ASSERT_EQ(x.size(), y.size());
      EXPECT_EQ(std::memcmp(x.data(), y.data(), x.size() * sizeof(double)), 0);
    } else {
      EXPECT_EQ(format_user_value(pa), format_user_value(pb));
    }
  }
}

// The resolved scene is a scene file that loads back to the same scene bit for bit, for every
// shipped scene and with values no decimal in the user's unit holds exactly in SI (a batch's
// task runs it in place of the scene and its overrides: same run, same results).
TEST(SceneFiles, TheResolvedSceneLoadsBackBitForBit) {
  const std::vector<std::string> odd{"instruments.buoyancy.sphere_diameter_cm=3.33",
                                     "sample.mass_g=47.11", "forces.voidage_cell_mm=0.7",
                                     "instruments.hydrometer.times_min=[0.1, 0.7, 13.37]",
                                     "name=\"a \\\"quoted\\\" \\\\ name\""};
  int count = 0;
  for (const auto& entry : fs::directory_iterator(fs::path(SEDEM_SOURCE_DIR) / "scenes")) {
    if (entry.path().extension() != ".toml") continue;
    for (const bool with_odd : {false, true}) {
      SCOPED_TRACE(entry.path().string() + (with_odd ? " with odd values" : ""));
      Scene scene = load_scene(entry.path(), with_odd ? odd : std::vector<std::string>{});
      const std::string text = resolved_toml(scene);
      Scene back;
      ASSERT_NO_THROW(back = parse_scene(text, "resolved.toml")) << text;
      expect_same_values(scene, back);
      EXPECT_EQ(resolved_toml(back), text);
      ++count;
    }
  }
  EXPECT_GE(count, 18);
}

// The paper's five samples: 60 g, 220 sizes from 2.5 to 70 um, the full 24 h test.
TEST(SceneFiles, PaperSamplesUseThePapersSettings) {
  for (int k = 1; k <= 5; ++k) {
    const Scene s = load_scene(fs::path(SEDEM_SOURCE_DIR) / "scenes" /
                               ("sample" + std::to_string(k) + ".toml"));
    EXPECT_DOUBLE_EQ(s.sample.total_mass, 60e-3);
    EXPECT_EQ(s.sample.size_count, 220);
    EXPECT_NEAR(s.sample.grading.diameters.front(), 2.5e-6, 1e-18);
    EXPECT_NEAR(s.sample.grading.diameters.back(), 70e-6, 1e-18);
    EXPECT_DOUBLE_EQ(s.end_time, 1440 * 60.0);
  }
}

std::string read(const fs::path& file) {
  std::ifstream in(file);
  std::stringstream text;
  text << in.rdbuf();
  return text.str();
}

// docs/scenes.md carries the key table generated from the Schema. With SEDEM_UPDATE_DOCS=1
// this test rewrites it instead of comparing.
TEST(SceneFiles, DocsKeyTableMatchesTheSchema) {
  const fs::path doc = fs::path(SEDEM_SOURCE_DIR) / "docs" / "scenes.md";
  std::string text = read(doc);
  const auto begin = text.find(kKeysBeginMarker);
  const auto end = text.find(kKeysEndMarker);
  ASSERT_NE(begin, std::string::npos) << doc << " lacks the marker " << kKeysBeginMarker;
  ASSERT_NE(end, std::string::npos) << doc << " lacks the marker " << kKeysEndMarker;
  const auto from = begin + std::string(kKeysBeginMarker).size() + 1;
  Scene defaults;
  const std::string table = schema_markdown(defaults);
  if (std::getenv("SEDEM_UPDATE_DOCS")) {
    text.replace(from, end - from, table);
    std::ofstream(doc) << text;
    GTEST_SKIP() << "rewrote the key table of " << doc;
  }
  EXPECT_EQ(text.substr(from, end - from), table)
      << "docs/scenes.md's key table differs from the scene keys declared in the code. "
         "Regenerate it: SEDEM_UPDATE_DOCS=1 build/tests/scene/test_scene "
         "--gtest_filter=SceneFiles.DocsKeyTableMatchesTheSchema";
}

}  // namespace
}  // namespace sedem
