#include "core/sample/sample_builder.h"

#include <numbers>

#include "core/sample/grading_curve.h"
#include "core/sample/memory_order.h"
#include "core/sample/placement.h"
#include "core/sample/sample_checks.h"
#include "core/sample/size_classes.h"

namespace sedem {

SamplePlan plan_sample(const SampleSetup& setup) {
  const auto& cfg = setup.sample;
  SamplePlan plan;
  plan.section_mass = cfg.total_mass * setup.cylinder.section_fraction;
  plan.classes = discretise(GradingCurve(cfg.grading), cfg.size_count, plan.section_mass,
                            cfg.particle_density);
  if (plan.classes.empty()) return plan;
  const std::vector<double> shares = simulated_shares(plan.classes, cfg.weighting);
  plan.requested_total =
      cfg.simulated_count > 0
          ? cfg.simulated_count
          : count_for_mass_fraction(plan.classes, shares, cfg.mass_fraction, cfg.particle_density);
  // Counts are only planned for a total that could be simulated; check_sample refuses more.
  if (plan.requested_total > kMaxSimulatedCount) return plan;
  assign_counts(plan.classes, shares, plan.requested_total);
  double covered = 0;
  for (const auto& c : plan.classes) {
    plan.simulated_total += c.simulated_count;
    covered += double(c.simulated_count) * 0.25 * std::numbers::pi * c.diameter * c.diameter;
  }
  plan.area_fraction = covered / (setup.cylinder.diameter * setup.cylinder.height);
  return plan;
}

Sample build_sample(const SampleSetup& setup) {
  try {
    check_sample(setup);
  } catch (const SetupProblem& p) {
    throw SceneError(std::string("sample: ") + p.what());
  }
  SamplePlan plan = plan_sample(setup);
  Sample sample;
  sample.particle_density = setup.sample.particle_density;
  sample.section_mass = plan.section_mass;
  sample.classes = std::move(plan.classes);

  auto& p = sample.particles;
  p.resize(std::size_t(plan.simulated_total));
  std::size_t i = 0;
  for (std::size_t k = 0; k < sample.classes.size(); ++k) {
    const auto& c = sample.classes[k];
    for (long j = 0; j < c.simulated_count; ++j, ++i) {
      p.diameter[i] = c.diameter;
      p.weight[i] = c.weight;
      p.size_class[i] = std::int32_t(k);
      p.id[i] = std::uint32_t(i);
    }
  }
  place_particles(p, setup.cylinder, setup.sample.placement, std::uint64_t(setup.sample.seed));
  order_for_memory(p, setup.cylinder);
  sample.area_fraction = area_fraction(p, setup.cylinder);
  return sample;
}

}  // namespace sedem
