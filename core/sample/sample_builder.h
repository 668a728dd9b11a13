#pragma once

#include <cstdint>
#include <vector>

#include "core/model/sample.h"
#include "core/sample/sample_setup.h"

namespace sedem {

// The sizes, counts and weights of a sample, before any particle is placed: cheap,
// so that a scene can be checked (particle count, area fraction) before anything runs.
struct SamplePlan {
  std::vector<SizeClass> classes;    // sizes with mass, counts and weights set
  double section_mass = 0;           // kg of soil in the section
  std::int64_t simulated_total = 0;  // sum of the classes' simulated counts
  std::int64_t requested_total = 0;  // the count asked for (or derived from the fraction)
  double area_fraction = 0;          // share of the section's plane the particles will cover
};
SamplePlan plan_sample(const SampleSetup& setup);

// Discretises the grading curve into size classes (Sect. 4.4, Eq. 15), gives each simulated
// particle its statistical weight, and places the particles in the section (Fig. 6).
// Particles come ordered by size class, ids 0..N-1. Throws SceneError when the setup breaks
// one of the sample's rules (check_sample) or its particles cannot be placed.
Sample build_sample(const SampleSetup& setup);

}  // namespace sedem
