#pragma once

// Every particle takes the common step. One step: voidage grid (Di Felice only) -> candidate
// lists if stale (re-sorting the state first at most every ResortTask::kPeriod steps) -> force
// pass (if the integrator needs one) -> integrator; every FreezeTask::kPeriod steps resting
// particles below the lowest instrument are frozen.

#include "core/engine/schedule/engine_parts.h"

namespace sedem {

class GlobalStepper {
 public:
  // Takes a first look at the contacts, so that the first step is chosen knowing them.
  explicit GlobalStepper(EngineParts& parts);
  // One step of the integrator's choosing (the last one shortened to land on `limit`).
  void step(double limit);

 private:
  EngineParts& e_;
};

}  // namespace sedem
