#pragma once

// What the local stepper does with each grain (schedule/local_stepper.h). The values are the
// codes saved in checkpoints and held by the box registry: do not renumber them.

#include <cstdint>

namespace sedem {

enum class GrainKind : std::uint8_t {
  coasting = 0,  // on its exact free trajectory over a window of its own
  moving = 1,    // a member of the common step, integrated with the others
  frozen = 2,    // a member resting in the bed, no longer integrated
  settled = 3,   // a frozen grain no member can reach, kept out of the state
  retired = 4,   // below every instrument, falling onto (or resting on) the coarse bed
};

// The members are the grains the common step holds in the engine state.
inline bool is_member(GrainKind k) {
  return k == GrainKind::moving || k == GrainKind::frozen;
}

// The kind as the box registry stores it (it reports it to queries).
inline std::uint8_t box_tag(GrainKind k) {
  return std::uint8_t(k);
}

inline const char* name_of(GrainKind k) {
  static const char* const names[] = {"coasting", "moving", "frozen", "settled", "retired"};
  return names[std::uint8_t(k)];
}

}  // namespace sedem
