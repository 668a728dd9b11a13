#pragma once

#include <cstdint>

#include "core/engine/forces/force_model.h"
#include "core/engine/forces/voidage_grid.h"

namespace sedem {

// What a grain's last Di Felice coefficient found in its cell: its voidage without the grain,
// that voidage's log and eps^-1.7, and the cell's solid fraction then. While the cell's solid
// fraction is the same to the bit, so are they, and the next coefficient reads them instead of
// calling log and exp again: most members' cells do not change from one step to the next.
struct DragMemo {
  std::uint32_t grain = ~std::uint32_t(0);  // whose (sample index): the state is re-sorted
  std::uint32_t cell = 0;
  double solid = -1, eps = 0, log_eps = 0, power = 0;
};

// The drag as a linear coefficient c (F = -c v), for the integrators (the laws: docs/physics.md,
// "Drag (Eqs. 7-9)").
struct DragEvaluator {
  const ForceModel* model = nullptr;
  const VoidageGrid* voidage = nullptr;
  double tail_re = 0;  // below it the Di Felice exponent's Re term is lost to round-off
  // `weight`: the grain's statistical weight, left out of its voidage if the model says so.
  double coefficient(double d, double weight, double speed, double x, double y) const {
    return coefficient(d, weight, speed, x, y, nullptr, 0);
  }
  // The same, the same bits, with grain `grain`'s memo (or nullptr), which it reads and keeps.
  double coefficient(double d, double weight, double speed, double x, double y, DragMemo* memo,
                     std::uint32_t grain) const;
};

// The Reynolds number below which 0.65 exp(-(1.5 - log10 Re)^2 / 2) |ln eps| < 2^-54 for every
// voidage down to `min_voidage`, with a margin.
double di_felice_tail_re(double min_voidage);

}  // namespace sedem
