#pragma once

#include "core/model/particles.h"

namespace sedem {

// An immutable copy of the particle state at one time, handed to observers. The one thing
// that crosses from the engine to what looks at it (instruments, writers, renderers).
struct Snapshot {
  double time = 0;
  Particles particles;
};

}  // namespace sedem
