// The analytic model of Sect. 4.3 against the paper's Table 1 (mu = 1e-3 Pa*s,
// g = 9.81 m/s^2, rho_p = 2500 kg/m^3, rho_f = 1000 kg/m^3).
#include <gtest/gtest.h>

#include "core/physics/stokes.h"

namespace sedem {
namespace {

struct Row {
  double diameter_um, response_1e5_s, velocity_1e5_m_s, fraction;
};

// Table 1 does not use one criterion for t_tr: its 70 um row is the time to 99 % of u_tr,
// the other rows the time to 95 % (docs/physics.md, "Drag (Eqs. 7-9)"). Each row is checked
// with its own.
const Row kTable1[] = {
    {70, 313.4, 400.5, 0.99}, {50, 104.0, 204.3, 0.95}, {25, 26.0, 51.09, 0.95},
    {10, 4.16, 8.17, 0.95},   {5, 1.04, 2.04, 0.95},    {2.5, 0.26, 0.51, 0.95},
};

TEST(Stokes, TerminalVelocityMatchesTable1) {
  const Fluid water;
  for (const auto& row : kTable1) {
    const double u = stokes::terminal_velocity(row.diameter_um * 1e-6, 2500, water);
    // Table 1 prints 3-4 significant figures.
    EXPECT_NEAR(u / 1e-5, row.velocity_1e5_m_s, 0.006 * row.velocity_1e5_m_s)
        << row.diameter_um << " um";
  }
}

TEST(Stokes, ResponseTimeMatchesTable1WithItsOwnCriterion) {
  const Fluid water;
  for (const auto& row : kTable1) {
    const double t = stokes::response_time(row.diameter_um * 1e-6, 2500, water, row.fraction);
    EXPECT_NEAR(t / 1e-5, row.response_1e5_s, 0.01 * row.response_1e5_s)
        << row.diameter_um << " um";
  }
}

TEST(Stokes, DiameterFromVelocityInvertsTerminalVelocity) {
  const Fluid water;
  for (double d : {2.5e-6, 10e-6, 70e-6}) {
    const double u = stokes::terminal_velocity(d, 2650, water);
    EXPECT_NEAR(stokes::diameter_from_velocity(u, 2650, water), d, 1e-12);
  }
}

TEST(Stokes, LimitingDiameterIsTheSizeThatFallsDepthInTime) {
  const Fluid water;
  // A 40 um grain falls u_tr * t; Eq. 16 at that depth and time must give back 40 um.
  const double d = 40e-6, t = 120;
  const double depth = stokes::terminal_velocity(d, 2500, water) * t;
  EXPECT_NEAR(stokes::limiting_diameter(depth, t, 2500, water), d, 1e-12);
}

}  // namespace
}  // namespace sedem
