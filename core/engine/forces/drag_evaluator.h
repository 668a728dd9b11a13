#pragma once

#include "core/engine/forces/force_model.h"
#include "core/engine/forces/voidage_grid.h"

namespace sedem {

// The drag as a linear coefficient c (F = -c v), for the integrators (the laws: docs/physics.md,
// "Drag (Eqs. 7-9)").
struct DragEvaluator {
  const ForceModel* model = nullptr;
  const VoidageGrid* voidage = nullptr;
  double tail_re = 0;  // below it the Di Felice exponent's Re term is lost to round-off
  // `weight`: the grain's statistical weight, left out of its voidage if the model says so.
  double coefficient(double d, double weight, double speed, double x, double y) const;
};

// The Reynolds number below which 0.65 exp(-(1.5 - log10 Re)^2 / 2) |ln eps| < 2^-54 for every
// voidage down to `min_voidage`, with a margin.
double di_felice_tail_re(double min_voidage);

}  // namespace sedem
