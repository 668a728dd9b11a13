// Single grains settling through the engine against the analytic model of Sect. 4.3 (Table 1)
// and the Di Felice drag's limits (Eqs. 7-9).
#include <gtest/gtest.h>

#include <cmath>

#include "core/physics/drag.h"
#include "core/physics/stokes.h"
#include "core/run/stage_setups.h"
#include "tests/engine/engine_test_support.h"

namespace sedem {
namespace {

using test::Grain;
using test::sample_of;
using test::scene_with;

struct Row {
  double d_um, t_tr_1e5, u_tr_1e5, fraction;
};
// Table 1 of the paper. Its 70 um row is the time to 99 % of u_tr, the others to 95 %.
const Row kTable1[] = {{70, 313.4, 400.5, 0.99}, {50, 104.0, 204.3, 0.95}, {25, 26.0, 51.09, 0.95},
                       {10, 4.16, 8.17, 0.95},   {5, 1.04, 2.04, 0.95},    {2.5, 0.26, 0.51, 0.95}};

// The time at which the engine's grain first reaches `fraction` of `speed`, by sampling
// `samples` output times up to `horizon` and interpolating linearly between them.
double time_to_reach(Engine& engine, double fraction, double speed, double horizon, int samples) {
  double t0 = 0, v0 = 0;
  for (int k = 1; k <= samples; ++k) {
    const double t = horizon * k / samples;
    engine.advance_to(t);
    const double v = -engine.particles().vy[0];
    if (v >= fraction * speed) return t0 + (t - t0) * (fraction * speed - v0) / (v - v0);
    t0 = t;
    v0 = v;
  }
  return -1;
}

void check_table1(const std::string& method, double step_factor, double tolerance) {
  for (const Row& row : kTable1) {
    Scene scene = scene_with("stokes", method);
    scene.forces.contact = false;
    scene.integrator.step_factor = step_factor;
    scene.integrator.fast_step_factor = step_factor;
    scene.integrator.adaptive = false;
    const double d = row.d_um * 1e-6;
    const double t_table = row.t_tr_1e5 * 1e-5, u_table = row.u_tr_1e5 * 1e-5;
    // The terminal velocity, to the table's 3-4 digits (half a unit of the last one).
    Engine settled(engine_setup(scene), sample_of({{0, 0.4, d}}));
    settled.advance_to(40 * t_table);
    const double u = -settled.particles().vy[0];
    EXPECT_NEAR(u, u_table, 0.0125 * u_table) << method << " " << row.d_um;
    // The response time, to the same digits plus the method's error.
    Engine engine(engine_setup(scene), sample_of({{0, 0.4, d}}));
    const double t = time_to_reach(engine, row.fraction, u, 2 * t_table, 400);
    EXPECT_NEAR(t, t_table, (0.005 + tolerance) * t_table) << method << " " << row.d_um;
  }
}

TEST(EngineSettling, Table1WithExponentialIntegrator) {
  check_table1("exponential", 1.0, 0);
}

TEST(EngineSettling, Table1WithExplicitIntegrator) {
  check_table1("explicit", 1e-3, 2e-3);
}

TEST(EngineSettling, TerminalVelocityIsStokesExactly) {
  for (const char* method : {"exponential", "explicit"}) {
    Scene scene = scene_with("stokes", method);
    scene.forces.contact = false;
    const double d = 25e-6;
    Engine engine(engine_setup(scene), sample_of({{0, 0.4, d}}));
    engine.advance_to(0.2);  // ~800 response times
    const double ut = stokes::terminal_velocity(d, 2500, scene.fluid);
    EXPECT_NEAR(-engine.particles().vy[0], ut, 1e-9 * ut) << method;
  }
}

TEST(EngineSettling, FallsTheDistanceOfEq13) {
  Scene scene = scene_with("stokes", "exponential");
  scene.forces.contact = false;
  const double d = 50e-6;
  Engine engine(engine_setup(scene), sample_of({{0, 0.4, d}}));
  const double t = 0.01;
  engine.advance_to(t);
  const double ut = stokes::terminal_velocity(d, 2500, scene.fluid);
  const double tau = stokes::relaxation_time(d, 2500, scene.fluid);
  const double fallen = ut * (t - tau * (1 - std::exp(-t / tau)));  // Eq. 13 integrated
  EXPECT_NEAR(0.4 - engine.particles().y[0], fallen, 1e-9 * fallen);
}

// As Re -> 0 and eps -> 1 the Di Felice drag is 0.96 Stokes: a 2.5 um grain (Re ~ 1e-5) in
// clear water settles at u_Stokes / 0.96.
TEST(EngineDiFelice, DiluteLowReynoldsLimitIs096Stokes) {
  Scene scene = scene_with("di_felice", "exponential");
  scene.forces.contact = false;
  const double d = 2.5e-6;
  Engine engine(engine_setup(scene), sample_of({{0, 0.4, d, 0, 0, 1.0}}));
  engine.advance_to(1e-3);  // ~1000 response times
  const double ut = stokes::terminal_velocity(d, 2500, scene.fluid);
  EXPECT_NEAR(-engine.particles().vy[0] * 0.96 / ut, 1.0, 2e-3);
}

// A grain alone, standing for so many real ones that its weight alone would make its cell half
// solids, still settles as in clear water: the voidage it feels is the others'.
TEST(EngineDiFelice, LoneHeavilyWeightedGrainDoesNotHinderItself) {
  Scene scene = scene_with("di_felice", "exponential");
  scene.forces.contact = false;
  const double d = 10e-6, cell = scene.forces.voidage_cell;
  const double weight =
      0.5 * cell * cell * scene.cylinder.slab_thickness() / (std::numbers::pi / 6 * d * d * d);
  Engine engine(engine_setup(scene), sample_of({{0.5 * cell, 0.2 + 0.5 * cell, d, 0, 0, weight}}));
  engine.advance_to(0.5);
  const double ut = drag::di_felice_terminal_velocity(d, 2500, scene.fluid, 1.0);
  EXPECT_NEAR(-engine.particles().vy[0], ut, 1e-6 * ut);
}

// Equal grains sharing one voidage cell, their statistical weights set for a cell voidage eps:
// each settles at the Di Felice terminal velocity at the voidage the other 19 make (its own
// weight left out), slower the more they pack; with its own weight counted, slower still.
TEST(EngineDiFelice, DragGrowsWithConcentration) {
  Scene scene = scene_with("di_felice", "exponential");
  scene.forces.contact = false;
  const double d = 10e-6, cell = scene.forces.voidage_cell;
  const int count = 20;
  const double cell_volume = cell * cell * scene.cylinder.slab_thickness();
  const double grain = std::numbers::pi / 6 * d * d * d;
  double previous = 0;
  for (double eps : {1.0 - 1e-9, 0.95, 0.9, 0.8}) {
    std::vector<Grain> grains;
    for (int k = 0; k < count; ++k)
      grains.push_back({0.2 * cell + k * 0.6 * cell / count, 0.4 * cell + 0.2, d, 0, 0,
                        (1 - eps) * cell_volume / (count * grain)});
    // Several steps: each takes its drag coefficient at the speed the previous one reached.
    Engine engine(engine_setup(scene), sample_of(grains));
    engine.advance_to(0.5);
    const double others = 1 - (1 - eps) * (count - 1) / count;
    const double expected = drag::di_felice_terminal_velocity(d, 2500, scene.fluid, others);
    const double u = -engine.particles().vy[count / 2];
    EXPECT_NEAR(u, expected, 1e-6 * expected) << eps;
    Scene counted = scene;
    counted.forces.voidage_excludes_self = false;
    Engine self(engine_setup(counted), sample_of(grains));
    self.advance_to(0.5);
    const double whole = drag::di_felice_terminal_velocity(d, 2500, scene.fluid, eps);
    EXPECT_NEAR(-self.particles().vy[count / 2], whole, 1e-6 * whole) << eps;
    if (previous > 0) {
      EXPECT_LT(u, previous) << eps;
    }
    previous = u;
  }
}

}  // namespace
}  // namespace sedem
