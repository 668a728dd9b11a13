#include "core/scene/scene_checks.h"

#include <algorithm>
#include <cmath>
#include <sstream>

#include "core/sample/grading_curve.h"
#include "core/sample/placement.h"
#include "core/sample/sample_builder.h"
#include "core/scene/scene.h"
#include "core/scene/scene_loader.h"

namespace sedem {

std::string SceneOrigins::of(const std::string& key) const {
  auto it = at.find(key);
  return it != at.end() ? it->second : source + " (default)";
}

namespace {

class Checker {
 public:
  Checker(const Scene& scene, const SceneOrigins& origins)
      : copy_(scene), schema_(copy_.schema()), origins_(origins) {}

  // "<where>: <key> = <value> <what>"
  [[noreturn]] void fail(const std::string& key, const std::string& what) const {
    throw SceneError(origins_.of(key) + ": " + key + " = " + value(key) + " " + what);
  }
  std::string value(const std::string& key) const {
    const Param* p = schema_.find(key);
    return p ? format_user_value(*p) : "?";
  }

 private:
  Scene copy_;  // the schema binds to a scene it may point into; the checked one is const
  Schema schema_;
  const SceneOrigins& origins_;
};

std::string number(double v) {
  std::ostringstream os;
  os.precision(6);
  os << v;
  return os.str();
}

void check_table(const GradingConfig& g, const Checker& check) {
  const char* kD = "sample.grading.diameters_um";
  const char* kP = "sample.grading.percent_finer";
  if (g.diameters.size() < 2)
    check.fail(kD, "needs at least 2 diameters (the smallest and the largest of the sample)");
  if (g.diameters.size() != g.percent_finer.size())
    check.fail(kP, "has " + std::to_string(g.percent_finer.size()) + " values but " +
                       std::string(kD) + " has " + std::to_string(g.diameters.size()) +
                       "; give one percentage per diameter");
  for (std::size_t i = 1; i < g.diameters.size(); ++i) {
    if (!(g.diameters[i] > g.diameters[i - 1]))
      check.fail(kD, "must be strictly ascending (" + number(g.diameters[i] * 1e6) + " follows " +
                         number(g.diameters[i - 1] * 1e6) + ")");
    if (g.percent_finer[i] < g.percent_finer[i - 1])
      check.fail(kP, "must not decrease (" + number(g.percent_finer[i]) + " follows " +
                         number(g.percent_finer[i - 1]) + ")");
  }
  if (g.percent_finer.front() != 0)
    check.fail(kP, "must start at 0: nothing is finer than the smallest diameter");
  if (g.percent_finer.back() != 100)
    check.fail(kP, "must end at 100: everything is finer than the largest diameter");
}

void check_family(const GradingConfig& g, const Checker& check) {
  if (!(g.min_diameter < g.max_diameter))
    check.fail("sample.grading.min_um", "must be smaller than sample.grading.max_um = " +
                                            check.value("sample.grading.max_um"));
  const GradingCurve curve(g);
  if (!(curve.captured_share() >= 1e-6))
    check.fail("sample.grading.median_um",
               "with sample.grading.spread = " + check.value("sample.grading.spread") +
                   " leaves almost none (" + number(curve.captured_share()) + ") of the " +
                   g.family + " curve's mass between min_um and max_um; move median_um into " +
                   "the range or widen the spread");
}

}  // namespace

void check_scene(const Scene& scene, const SceneOrigins& origins) {
  const Checker check(scene, origins);
  const auto& s = scene.sample;
  if (s.particle_density <= scene.fluid.density)
    check.fail("sample.particle_density",
               "must exceed fluid.density = " + check.value("fluid.density") +
                   " kg/m^3, or nothing settles");

  const auto& g = s.grading;
  if (g.family == "table")
    check_table(g, check);
  else if (g.family != "single")
    check_family(g, check);

  const GradingCurve curve(g);
  const double room = std::min(scene.cylinder.diameter, scene.cylinder.height);
  if (curve.max_diameter() > room)
    check.fail("cylinder.diameter_m",
               "is smaller than the largest grain (" + number(curve.max_diameter() * 1e6) + " um)");

  if (s.simulated_count == 0 && s.mass_fraction == 0)
    check.fail("sample.simulated_count",
               "and sample.mass_fraction = 0: give one of them (a particle count, or the share "
               "of the section's soil to simulate)");

  const SamplePlan plan = plan_sample(scene);
  const std::string count_key =
      s.simulated_count > 0 ? "sample.simulated_count" : "sample.mass_fraction";
  const std::string sizes = std::to_string(plan.classes.size());
  if (plan.requested_total > kMaxSimulatedCount)
    check.fail(count_key, "asks for " + number(double(plan.requested_total)) +
                              " particles; at most " + number(double(kMaxSimulatedCount)) +
                              " are allowed: lower it");
  if (plan.requested_total < std::int64_t(plan.classes.size()))
    check.fail(count_key,
               "gives " + std::to_string(plan.requested_total) + " particles for the " + sizes +
                   " sizes of the grading curve, and each size needs at least one; raise it or "
                   "lower sample.size_count");

  const std::size_t n = std::size_t(plan.simulated_total);
  const std::int64_t auto_side = cells_per_side(PlacementConfig{}, n);
  if (s.placement.cells_per_side > auto_side)
    check.fail("sample.placement.cells_per_side",
               "makes more cells than particles (" + std::to_string(n) + "); at most " +
                   std::to_string(auto_side) + " (0 picks that)");

  if (plan.area_fraction > s.placement.max_area_fraction) {
    const double area = plan.area_fraction * scene.cylinder.diameter * scene.cylinder.height;
    check.fail(count_key, "gives " + std::to_string(n) + " particles of total area " +
                              number(area) + " m^2, which cannot be placed without overlap " +
                              "in the section: area fraction " + number(plan.area_fraction) +
                              " > limit " + number(s.placement.max_area_fraction) +
                              " (sample.placement.max_area_fraction); lower it");
  }
}

}  // namespace sedem
