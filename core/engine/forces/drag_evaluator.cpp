#include "core/engine/forces/drag_evaluator.h"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace sedem {

double DragEvaluator::coefficient(double d, double weight, double speed, double x, double y,
                                  DragMemo* memo, std::uint32_t grain) const {
  switch (model->drag) {
    case DragLaw::off:
      return 0;
    case DragLaw::stokes:
      return 3.0 * std::numbers::pi * model->viscosity * d;
    case DragLaw::di_felice: {
      // drag::di_felice_coefficient with eps^(2 - chi) = eps^-1.7 (per cell) eps^(0.65 g),
      // g = exp(-(1.5 - log10 Re)^2 / 2). Below tail_re the second factor is 1 to round-off
      // (its exponent is below 2^-54 for every voidage the floor allows): it is not computed.
      // The engine's terminal velocities are tested against drag::di_felice_terminal_velocity.
      const std::size_t cell = voidage->cell(x, y);
      double eps, log_eps, power;
      if (model->voidage_excludes_self && weight > 0) {
        const double solid = voidage->solid()[cell];
        if (memo && memo->grain == grain && memo->cell == cell && memo->solid == solid) {
          eps = memo->eps;
          log_eps = memo->log_eps;
          power = memo->power;
        } else {
          eps = voidage->excluding(cell, weight * model->volume(d));
          log_eps = std::log(eps);
          power = std::exp(-1.7 * log_eps);
          if (memo) *memo = {grain, std::uint32_t(cell), solid, eps, log_eps, power};
        }
      } else {
        eps = voidage->voidage(cell);
        log_eps = voidage->log_voidage(cell);
        power = voidage->hindrance(cell);
      }
      const double mu = model->viscosity;
      const double re = model->fluid_density * eps * speed * d / mu;
      const double root = 0.63 * std::sqrt(re) + 4.8;
      if (re > tail_re && log_eps != 0) {
        const double l = 1.5 - std::log10(re);
        power *= std::exp(0.65 * std::exp(-0.5 * l * l) * log_eps);
      }
      const double area = std::numbers::pi * d * d / 4.0;
      return 0.5 * root * root * mu / (eps * d) * area * power;
    }
  }
  return 0;
}

double di_felice_tail_re(double min_voidage) {
  const double worst_log = -std::log(std::min(1.0, std::max(min_voidage, 1e-300)));
  if (worst_log <= 0) return HUGE_VAL;
  // 0.65 exp(-l0^2 / 2) worst_log = 2^-54 at l0; half that Re keeps a wide margin (g is then
  // smaller by exp(-0.3 l0)) over the round-off of log10 and exp.
  const double l0 = std::sqrt(2 * std::log(0.65 * worst_log * std::ldexp(1.0, 54)));
  return 0.5 * std::pow(10.0, 1.5 - l0);
}

}  // namespace sedem
