// `sedem design`: bad input gets one line and exit 2; a small scene's design read back from
// design.json and design.csv.
#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <filesystem>
#include <fstream>
#include <sstream>

#include "tests/app/cli_runner.h"

namespace sedem {
namespace {

namespace fs = std::filesystem;

const fs::path kOut = fs::path(SEDEM_TEST_OUTPUT) / "design";
const std::string kScene = std::string(SEDEM_SOURCE_DIR) + "/scenes/sample4.toml";

TEST(DesignCommand, BadInputExitsTwoWithOneLine) {
  const std::string out = " --out " + (kOut / "bad").string();
  auto r = test::run_sedem("design " + kScene + " --test sieve" + out);
  EXPECT_EQ(r.status, 2);
  EXPECT_EQ(r.output, "sedem design: --test sieve: allowed hydrometer, buoyancy or pipette\n");
  r = test::run_sedem("design " + kScene + " --test hydrometer --readings 0" + out);
  EXPECT_EQ(r.status, 2);
  EXPECT_EQ(r.output, "sedem design: --readings 0: allowed 2 to 200\n");
  r = test::run_sedem("design " + kScene +
                      " --test buoyancy --set instruments.buoyancy.enabled=false" + out);
  EXPECT_EQ(r.status, 2);
  EXPECT_EQ(r.output,
            "sedem design: --test buoyancy: the scene disables it "
            "(instruments.buoyancy.enabled = false)\n");
  EXPECT_FALSE(fs::exists(kOut / "bad" / "design.json"));
}

TEST(DesignCommand, SampleFoursSphereDesignedAndConfirmed) {
  // Sample 4 (92 % of the mass between 25 and 35 um): the standard's sphere readings never
  // look inside the knee; a DEM run of 3000 particles confirms the design (60 s of the test,
  // the first readings, keep it quick).
  const fs::path dir = kOut / "sample4_buoyancy";
  fs::remove_all(dir);
  const auto r = test::run_sedem(
      "design " + kScene + " --test buoyancy --sizes 400 --dem-count 3000 --quiet --out " +
      dir.string() + " --set \"instruments.buoyancy.times_min=[0.5,1,2,4,8]\"");
  ASSERT_EQ(r.status, 0) << r.output;
  std::ifstream in(dir / "design.json");
  const auto j = nlohmann::json::parse(in);
  const double standard = j["standard"]["reference"]["worst_error_pp"];
  const double designed = j["designed"]["reference"]["worst_error_pp"];
  EXPECT_GT(standard, 2.0);
  EXPECT_LE(designed, standard / 2);
  EXPECT_EQ(j["designed"]["times_min"].size(), 5u);
  EXPECT_GE(j["designed"]["times_min"][0].get<double>(), 0.5);
  EXPECT_TRUE(j["designed"].contains("dem"));
  EXPECT_EQ(j["dem"]["particles"], 3000);
  // The DEM run of the same sample reads the designed schedule better too.
  EXPECT_LT(j["designed"]["dem"]["worst_error_pp"].get<double>(),
            j["standard"]["dem"]["worst_error_pp"].get<double>());
  // design.csv: the standard's reference rows are the json's times.
  std::ifstream csv(dir / "design.csv");
  std::string line;
  std::getline(csv, line);
  EXPECT_EQ(line,
            "schedule,source,time_min,depth_fraction,diameter_um,percent_finer,true_percent_finer");
  std::size_t standard_rows = 0, dem_rows = 0;
  while (std::getline(csv, line)) {
    if (line.rfind("standard,reference,", 0) == 0) ++standard_rows;
    if (line.find(",dem,") != std::string::npos) ++dem_rows;
  }
  EXPECT_EQ(standard_rows, 5u);
  EXPECT_EQ(dem_rows, 10u);
  EXPECT_TRUE(fs::exists(dir / "design_figure.png"));
}

}  // namespace
}  // namespace sedem
