// The Di Felice drag (Eqs. 7-9) against its closed-form limits.
#include <gtest/gtest.h>

#include <cmath>

#include "core/physics/drag.h"
#include "core/physics/stokes.h"

namespace sedem {
namespace {

TEST(DiFelice, LowReynoldsDiluteLimitIs096Stokes) {
  const Fluid water;
  for (double d : {2.5e-6, 10e-6, 70e-6}) {
    const double u = 1e-9;  // Re ~ 1e-10
    const double ratio = drag::di_felice_force(d, u, 1.0, water) / stokes::drag_force(d, u, water);
    EXPECT_NEAR(ratio, 0.96, 1e-4) << d;
  }
}

TEST(DiFelice, DragGrowsAsVoidageFalls) {
  const Fluid water;
  const double d = 30e-6, u = 1e-3;
  double previous = drag::di_felice_force(d, u, 1.0, water);
  for (double eps : {0.99, 0.95, 0.9, 0.8}) {
    const double f = drag::di_felice_force(d, u, eps, water);
    EXPECT_GT(f, previous) << eps;
    previous = f;
  }
  // Low Re: F ~ eps^(1 - chi) with chi -> 3.7 as Re -> 0; Re here is ~0.03, so chi is a
  // little below 3.7 and the growth a little below eps^-2.7.
  const double growth =
      drag::di_felice_force(d, u, 0.9, water) / drag::di_felice_force(d, u, 1.0, water);
  EXPECT_GT(growth, std::pow(0.9, -2.2));
  EXPECT_LT(growth, std::pow(0.9, -2.7));
}

TEST(DiFelice, TerminalVelocityBalancesNetWeight) {
  const Fluid water;
  for (double d : {2.5e-6, 25e-6, 70e-6}) {
    const double u = drag::di_felice_terminal_velocity(d, 2500, water);
    const double net = 1500 * 9.81 * 3.14159265358979 / 6 * d * d * d;
    EXPECT_NEAR(drag::di_felice_force(d, u, 1.0, water), net, 1e-9 * net);
    // Small grains: 1/0.96 of the Stokes velocity; the 70 um grain (Re ~ 0.3) slower.
    const double stokes_u = stokes::terminal_velocity(d, 2500, water);
    EXPECT_LE(u, stokes_u / 0.96 * (1 + 1e-9));
    if (d < 5e-6) {
      EXPECT_NEAR(u, stokes_u / 0.96, 1e-3 * u);
    }
  }
}

}  // namespace
}  // namespace sedem
