#pragma once

#include <string>
#include <vector>

#include "bench/validation/curve_checks.h"
#include "bench/validation/run_folder.h"

namespace sedem::validation::testing {

// A curve from (time s, diameter um, percent finer) triples.
inline TestReadings curve(const std::string& test,
                          const std::vector<std::tuple<double, double, double>>& points) {
  TestReadings t;
  t.test = test;
  for (const auto& [time, diameter_um, finer] : points)
    t.rows.push_back({time, diameter_um * 1e-6, finer, {}});
  return t;
}

// A sample whose true curve is a straight line in diameter: w = 100 d / 70 um, in 1 um steps.
inline std::vector<SizeClass> linear_sample() {
  std::vector<GradingPoint> truth;
  for (int d = 1; d <= 70; ++d) truth.push_back({d * 1e-6, 100.0 * d / 70.0});
  return classes_from_true_curve(truth);
}

inline RunTest run_test(const TestReadings& dem, const TestReadings& reference) {
  RunTest t;
  t.test = dem.test;
  t.dem = dem;
  t.reference = reference;
  t.error_pp = max_abs(differences(dem, reference));
  return t;
}

inline RunFolder run(const std::string& name, std::vector<RunTest> tests) {
  RunFolder r;
  r.name = name;
  r.classes = linear_sample();
  r.tests = std::move(tests);
  r.scene = nlohmann::json::object();
  return r;
}

}  // namespace sedem::validation::testing
