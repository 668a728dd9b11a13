#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "core/run/stage_setups.h"
#include "core/sample/sample_builder.h"
#include "core/sample/size_classes.h"
#include "core/scene/scene_loader.h"

namespace sedem {
namespace {

Scene log_uniform_scene(const std::string& weighting, std::int64_t count) {
  return parse_scene(
      "[sample]\nsimulated_count = " + std::to_string(count) + "\nweighting = \"" + weighting +
          "\"\n[sample.grading]\nfamily = \"log_uniform\"\nmin_um = 2.5\nmax_um = 70\n",
      "weights.toml");
}

// Whatever the scheme, the simulated particles of a size, each standing for `weight` real
// grains, carry exactly that size's real mass in the section, and all sizes the whole 60 g/180.
TEST(Weights, EachSizeCarriesItsRealMass) {
  for (const char* scheme : {"equal_mass", "uniform_count", "equal_per_size"}) {
    const Scene scene = log_uniform_scene(scheme, 20000);
    const Sample sample = build_sample(sample_setup(scene));
    ASSERT_EQ(sample.particles.size(), 20000u) << scheme;
    std::vector<double> carried(sample.classes.size(), 0.0);
    const auto& p = sample.particles;
    for (std::size_t i = 0; i < p.size(); ++i)
      carried[std::size_t(p.size_class[i])] += p.weight[i] * grain_mass(p.diameter[i], 2500);
    double total = 0;
    for (std::size_t k = 0; k < carried.size(); ++k) {
      const double real = sample.classes[k].mass_fraction * sample.section_mass;
      EXPECT_NEAR(carried[k] / real, 1, 1e-12) << scheme << " size " << k;
      EXPECT_GE(sample.classes[k].simulated_count, 1);
      total += carried[k];
    }
    EXPECT_NEAR(total / (60e-3 / 180), 1, 1e-12) << scheme;
  }
}

TEST(Weights, SchemesShareTheParticlesAsDocumented) {
  {  // equal_mass: every particle stands for the same mass (up to rounding of the counts)
    const Sample s = build_sample(sample_setup(log_uniform_scene("equal_mass", 22000)));
    const double per_particle = s.section_mass / 22000;
    for (const auto& c : s.classes)
      EXPECT_NEAR(c.weight * grain_mass(c.diameter, 2500) / per_particle, 1,
                  1.0 / double(c.simulated_count));
  }
  {  // uniform_count: every particle stands for the same number of grains
    const SamplePlan s = plan_sample(sample_setup(log_uniform_scene("uniform_count", 1000000)));
    const double mean = [&] {
      double real = 0;
      for (const auto& c : s.classes) real += c.real_count;
      return real / 1e6;
    }();
    for (const auto& c : s.classes) {
      if (c.simulated_count > 1) {
        EXPECT_NEAR(c.weight / mean, 1, 1.0 / double(c.simulated_count));
      }
    }
  }
  {  // equal_per_size: 22000 particles over 220 sizes, 100 each
    const Sample s = build_sample(sample_setup(log_uniform_scene("equal_per_size", 22000)));
    for (const auto& c : s.classes) EXPECT_EQ(c.simulated_count, 100);
  }
}

// Largest remainders with at least one per size, by hand: shares 0.5, 0.3, 0.2, 1e-4 of 10
// particles. The last size gets its one; 9 remain: quotas 4.5, 2.7, 1.8 -> 4, 2, 1 and the
// two largest remainders (0.8, 0.7) one more each: 4, 3, 2, 1.
TEST(Weights, CountsByLargestRemainderWithOnePerSize) {
  std::vector<SizeClass> classes(4);
  for (auto& c : classes) c.real_count = 1000;
  const double sum = 0.5 + 0.3 + 0.2 + 1e-4;
  assign_counts(classes, {0.5 / sum, 0.3 / sum, 0.2 / sum, 1e-4 / sum}, 10);
  EXPECT_EQ(classes[0].simulated_count, 4);
  EXPECT_EQ(classes[1].simulated_count, 3);
  EXPECT_EQ(classes[2].simulated_count, 2);
  EXPECT_EQ(classes[3].simulated_count, 1);
  EXPECT_DOUBLE_EQ(classes[1].weight, 1000.0 / 3);
}

// A mass fraction f with uniform_count weighting simulates f of the real grains: every
// particle stands for 1/f grains, and the simulated grains weigh f x 60 g / 180.
TEST(Weights, MassFractionSetsTheCount) {
  const Scene scene = parse_scene(
      "[sample]\nsize_count = 10\nmass_fraction = 1e-4\nweighting = "
      "\"uniform_count\"\n[sample.grading]\n"
      "family = \"table\"\ndiameters_um = [20, 40]\npercent_finer = [0, 100]\n",
      "fraction.toml");
  EXPECT_EQ(scene.sample.simulated_count, 0);
  const SamplePlan plan = plan_sample(sample_setup(scene));
  double real = 0, simulated_mass = 0;
  for (const auto& c : plan.classes) {
    real += c.real_count;
    simulated_mass += double(c.simulated_count) * grain_mass(c.diameter, 2500);
    EXPECT_NEAR(c.weight / 1e4, 1, 1.0 / double(c.simulated_count));
  }
  EXPECT_EQ(plan.simulated_total, std::llround(real * 1e-4));
  EXPECT_NEAR(simulated_mass / (1e-4 * 60e-3 / 180), 1, 0.01);
}

}  // namespace
}  // namespace sedem
