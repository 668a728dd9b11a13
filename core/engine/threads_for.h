#pragma once

#include <cstddef>

namespace sedem {

// Below this many grains a pass over them takes microseconds, about what waking a second
// thread costs, and runs on one. Where grains meet everywhere, the members' step passes over a
// few to a few thousand members: at 10^5 particles the whole test on two threads took 60.3 s
// with the threshold at 256, 64.3 at 128, 63.8 at 1024 and 69.8 never threaded
// (docs/results/engine.md, "Rows for joiners instead of rebuilds"). Which thread count a pass
// takes changes no result: each pass gives the same bits on one thread or more.
inline constexpr std::size_t kThreadedFrom = 256;

inline int threads_for(int threads, std::size_t grains) {
  return grains >= kThreadedFrom ? threads : 1;
}

}  // namespace sedem
