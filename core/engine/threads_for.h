#pragma once

#include <cstddef>

namespace sedem {

// Below this many grains a pass over them takes microseconds, about what waking a second
// thread costs, and runs on one. Where grains meet everywhere, the members' step passes over a
// few to a few thousand members: at 10^5 particles the whole test took the same time with the
// threshold at 128 or 256 and 5 % longer at 1024 (docs/results/engine.md, "Two threads where
// grains meet"). Which thread count a pass takes changes no result: each pass gives the same
// bits on one thread or more.
inline constexpr std::size_t kThreadedFrom = 256;

inline int threads_for(int threads, std::size_t grains) {
  return grains >= kThreadedFrom ? threads : 1;
}

}  // namespace sedem
