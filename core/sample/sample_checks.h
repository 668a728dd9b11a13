#pragma once

#include "core/model/scene_error.h"
#include "core/sample/sample_setup.h"

namespace sedem {

// The sample's own rules on its setup as a whole (each key's range is checked as it is read,
// the grading curve's shape by the scene's checks): a particle count that can be simulated,
// at least one particle a size, placement cells no more than particles, particles that fit
// in the section. Throws SetupProblem naming the key at fault.
void check_sample(const SampleSetup& setup);

}  // namespace sedem
