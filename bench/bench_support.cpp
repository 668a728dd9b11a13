#include "bench/bench_support.h"

#include <cmath>

namespace sedem::bench {

std::vector<std::string> no_output_keys() {
  return {"output.frames=false", "output.particles=false", "output.fields=false"};
}

std::vector<std::string> sample_scenes(const std::vector<int>& samples) {
  std::vector<std::string> scenes;
  for (int k : samples)
    scenes.push_back(std::string(SEDEM_SOURCE_DIR) + "/scenes/sample" + std::to_string(k) +
                     ".toml");
  return scenes;
}

double test_error(const TestResults& results, const std::string& test) {
  for (const auto& t : results.granulometry.tests)
    if (t.test == test && !t.dem.rows.empty()) return t.error;
  return NAN;
}

}  // namespace sedem::bench
