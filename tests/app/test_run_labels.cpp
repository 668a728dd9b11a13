#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include "app/figure_inputs.h"

namespace sedem {
namespace {

nlohmann::json scene(const std::string& name, int count, const std::string& weighting) {
  return {{"name", name},
          {"sample.simulated_count", count},
          {"sample.weighting", weighting},
          {"cylinder.height_m", 0.457},
          {"instruments.hydrometer.times_min", {2, 5}}};
}

TEST(RunLabels, SceneNamesWhenTheyTellRunsApart) {
  EXPECT_EQ(
      app::run_labels({scene("sample1", 3000, "equal_mass"), scene("sample2", 3000, "equal_mass")}),
      (std::vector<std::string>{"sample1", "sample2"}));
}

TEST(RunLabels, TheSweptKeyAndValueWhenTheNameIsTheSame) {
  EXPECT_EQ(
      app::run_labels({scene("demo", 300, "equal_mass"), scene("demo", 1200, "equal_mass")}),
      (std::vector<std::string>{"sample.simulated_count=300", "sample.simulated_count=1200"}));
  auto a = scene("demo", 300, "equal_mass"), b = scene("demo", 300, "uniform_count");
  b["instruments.hydrometer.times_min"] = {0.5, 1.5};
  EXPECT_EQ(app::run_labels({a, b}),
            (std::vector<std::string>{
                "instruments.hydrometer.times_min=[2, 5], sample.weighting=equal_mass",
                "instruments.hydrometer.times_min=[0.5, 1.5], sample.weighting=uniform_count"}));
}

TEST(RunLabels, NamesWithTheKeysWhereNamesRepeatInPart) {
  const auto labels =
      app::run_labels({scene("demo", 300, "equal_mass"), scene("demo", 600, "equal_mass"),
                       scene("sample1", 300, "equal_mass")});
  EXPECT_EQ(labels[0], "demo, sample.simulated_count=300");
  EXPECT_EQ(labels[2], "sample1, sample.simulated_count=300");
}

TEST(RunLabels, IdenticalScenesAreNumbered) {
  EXPECT_EQ(app::run_labels({scene("demo", 300, "equal_mass"), scene("demo", 300, "equal_mass")}),
            (std::vector<std::string>{"demo (run 1)", "demo (run 2)"}));
}

}  // namespace
}  // namespace sedem
