#pragma once

// The motion of a grain that touches nothing: m dv/dt = F - c v with F (weight and buoyancy)
// and c (its drag coefficient) held constant, solved exactly. The exponential integrator takes
// one such update per step; a coasting grain (schedule/local_stepper.h) follows one over a whole
// window of its own and is evaluated at any time inside it. Both use these formulas, so a grain's
// position does not depend on which of the two moved it.

#include <algorithm>
#include <cmath>

namespace sedem {

struct FreeFlight {
  double x = 0, y = 0, vx = 0, vy = 0;  // at the start
  double rate = 0;                      // c / m; 0: no drag
  double ux = 0, uy = 0;                // F / c (the terminal velocity), or F / m when rate = 0

  struct Point {
    double x, y, vx, vy;
  };
  Point at(double s) const {
    if (rate > 0) {
      const double a = s * rate;
      // decay - 1 from one call; past 40 response times it is -1 to round-off.
      const double lost = a > 40 ? -1.0 : std::expm1(-a);
      const double relax = -lost / rate;  // integral of the decay over s
      return {x + ux * s + (vx - ux) * relax, y + uy * s + (vy - uy) * relax,
              ux + (vx - ux) * (1.0 + lost), uy + (vy - uy) * (1.0 + lost)};
    }
    return {x + s * (vx + 0.5 * s * ux), y + s * (vy + 0.5 * s * uy), vx + s * ux, vy + s * uy};
  }

  // The time in (0, s) at which the velocity component v0 -> u changes sign, or -1.
  double turn(double v0, double u, double s) const {
    if (rate > 0) {
      if (v0 == u || (v0 > 0) == (u > 0) || v0 == 0 || u == 0) return -1;
      const double t = -std::log(u / (u - v0)) / rate;
      return t > 0 && t < s ? t : -1;
    }
    if (u == 0 || (v0 > 0) == (u > 0) || v0 == 0) return -1;
    const double t = -v0 / u;
    return t > 0 && t < s ? t : -1;
  }

  // The box the centre sweeps over [0, s]: each velocity component changes sign at most once.
  struct Range {
    double x0, x1, y0, y1;
  };
  Range sweep(double s) const {
    const Point e = at(s);
    Range r{std::min(x, e.x), std::max(x, e.x), std::min(y, e.y), std::max(y, e.y)};
    if (const double t = turn(vx, ux, s); t > 0) {
      const double xt = at(t).x;
      r.x0 = std::min(r.x0, xt);
      r.x1 = std::max(r.x1, xt);
    }
    if (const double t = turn(vy, uy, s); t > 0) {
      const double yt = at(t).y;
      r.y0 = std::min(r.y0, yt);
      r.y1 = std::max(r.y1, yt);
    }
    return r;
  }
};

}  // namespace sedem
