#include "core/sample/sample_checks.h"

#include <sstream>
#include <string>

#include "core/sample/placement.h"
#include "core/sample/sample_builder.h"

namespace sedem {

namespace {

std::string number(double v) {
  std::ostringstream os;
  os.precision(6);
  os << v;
  return os.str();
}

}  // namespace

void check_sample(const SampleSetup& setup) {
  const SampleConfig& s = setup.sample;
  const SamplePlan plan = plan_sample(setup);
  const std::string count_key =
      s.simulated_count > 0 ? "sample.simulated_count" : "sample.mass_fraction";
  const std::string sizes = std::to_string(plan.classes.size());
  if (plan.requested_total > kMaxSimulatedCount)
    throw SetupProblem(count_key, "asks for " + number(double(plan.requested_total)) +
                                      " particles; at most " + number(double(kMaxSimulatedCount)) +
                                      " are allowed: lower it");
  if (plan.requested_total < std::int64_t(plan.classes.size()))
    throw SetupProblem(
        count_key, "gives " + std::to_string(plan.requested_total) + " particles for the " + sizes +
                       " sizes of the grading curve, and each size needs at least one; raise "
                       "it or lower sample.size_count");

  const std::size_t n = std::size_t(plan.simulated_total);
  const std::int64_t auto_side = cells_per_side(PlacementConfig{}, n);
  if (s.placement.cells_per_side > auto_side)
    throw SetupProblem("sample.placement.cells_per_side",
                       "makes more cells than particles (" + std::to_string(n) + "); at most " +
                           std::to_string(auto_side) + " (0 picks that)");

  if (plan.area_fraction > s.placement.max_area_fraction) {
    const double area = plan.area_fraction * setup.cylinder.diameter * setup.cylinder.height;
    throw SetupProblem(count_key, "gives " + std::to_string(n) + " particles of total area " +
                                      number(area) +
                                      " m^2, which cannot be placed without overlap in the "
                                      "section: area fraction " +
                                      number(plan.area_fraction) + " > limit " +
                                      number(s.placement.max_area_fraction) +
                                      " (sample.placement.max_area_fraction); lower it");
  }
}

}  // namespace sedem
