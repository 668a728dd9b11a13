// `sedem_validation_report study` on real seed batches: tiny runs of two samples over two
// seeds, read back from study.csv and study_seeds.csv.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <map>
#include <string>

#include "bench/validation/run_folder.h"
#include "bench/validation/study_report.h"

namespace sedem::validation {
namespace {

namespace fs = std::filesystem;

const fs::path kDir = fs::path(SEDEM_TEST_OUTPUT) / "validation" / "study";
// A few seconds per batch: 300 particles, 2 min, each test read three times.
const std::string kTiny =
    " --seeds 2 --jobs 2 --quiet --set sample.simulated_count=300 --set run.end_time_s=120"
    " --set output.frames=false --set output.fields=false --set output.particles=false"
    " --set instruments.hydrometer.times_min=[0.5,1,2]"
    " --set instruments.buoyancy.times_min=[0.5,1,2]"
    " --set instruments.pipette.times_min=[0.5,1,2]";

int shell(const std::string& command) {
  return std::system((command + " > " + (kDir / "log.txt").string() + " 2>&1").c_str());
}

int batch(const std::string& folder, const std::string& depth = "") {
  const std::string scenes = std::string(SEDEM_SOURCE_DIR) + "/scenes/sample1.toml " +
                             std::string(SEDEM_SOURCE_DIR) + "/scenes/sample2.toml";
  std::string sets;
  if (!depth.empty())
    sets = " --set instruments.buoyancy.depth_fraction=" + depth +
           " --set instruments.pipette.depth_fraction=" + depth +
           " --set instruments.hydrometer.enabled=false";
  return shell(std::string(SEDEM_EXE) + " batch " + scenes + " --out " + (kDir / folder).string() +
               kTiny + sets);
}

std::string field(const CsvTable& csv, std::size_t row, const std::string& column) {
  return csv.rows.at(row).at(csv.column(column));
}
double number(const CsvTable& csv, std::size_t row, const std::string& column) {
  const std::string text = field(csv, row, column);
  return text.empty() ? NAN : std::stod(text);
}

TEST(StudyPipeline, TwoSeedsOfTwoSamplesGiveEveryConclusionItsInterval) {
  fs::remove_all(kDir);
  fs::create_directories(kDir);
  ASSERT_EQ(batch("tiny/main"), 0);
  ASSERT_EQ(batch("tiny/shallow", "0.1"), 0);
  ASSERT_EQ(batch("tiny/deep", "0.7"), 0);
  ASSERT_EQ(shell(std::string(SEDEM_VALIDATION_REPORT) +
                  " study --regime tiny=" + (kDir / "tiny").string() + " --regime main-only=" +
                  (kDir / "tiny" / "main").string() + " --out " + (kDir / "report").string()),
            0);

  const CsvTable study = read_csv(kDir / "report" / "study.csv");
  ASSERT_EQ(study.rows.size(), 12u);  // two regimes x six conclusions
  for (std::size_t k = 0; k < 6; ++k) {
    EXPECT_EQ(field(study, k, "regime"), "tiny");
    EXPECT_EQ(field(study, k, "conclusion"), std::to_string(k + 1));
    EXPECT_EQ(field(study, 6 + k, "regime"), "main-only");
  }
  // Large sizes (4) and the early part (6) have readings in every run of two minutes.
  for (std::size_t row : {3u, 5u}) {
    EXPECT_EQ(field(study, row, "seeds"), "2");
    EXPECT_LE(number(study, row, "effect_low"), number(study, row, "effect_mean"));
    EXPECT_GE(number(study, row, "effect_high"), number(study, row, "effect_mean"));
  }
  EXPECT_EQ(field(study, 4, "seeds"), "2");  // the depth runs were read
  EXPECT_NE(field(study, 4, "verdict"), "not run");
  EXPECT_EQ(field(study, 10, "verdict"), "not run");

  // Each seed's effect is the one its own runs give, not a mixture of seeds.
  const CsvTable seeds = read_csv(kDir / "report" / "study_seeds.csv");
  ASSERT_EQ(seeds.rows.size(), 24u);
  std::map<std::string, std::vector<RunFolder>> by_seed;
  for (const auto& r : read_batch(kDir / "tiny" / "main"))
    by_seed[std::to_string(int(r.number("sample.seed")))].push_back(r);
  ASSERT_EQ(by_seed.size(), 2u);
  double sum = 0;
  for (std::size_t row = 0; row < 12; ++row) {
    if (field(seeds, row, "conclusion") != "4") continue;
    const auto& runs = by_seed.at(field(seeds, row, "seed"));
    EXPECT_EQ(runs.size(), 2u);
    EXPECT_NEAR(number(seeds, row, "effect"), large_size_effect(runs), 1e-6);
    sum += number(seeds, row, "effect");
  }
  EXPECT_NEAR(number(study, 3, "effect_mean"), sum / 2, 1e-6);
}

}  // namespace
}  // namespace sedem::validation
