#pragma once

#include "core/model/sample.h"

namespace sedem {

struct Scene;

// Discretises the scene's grading curve into size classes (Eq. 15), gives each simulated
// particle its statistical weight, and places the particles in the section (Fig. 6).
Sample build_sample(const Scene& scene);

}  // namespace sedem
