// The first engine slice: one grain settling in still water reaches the Stokes terminal
// velocity and covers the distance of Eq. 13 integrated in time.
#include <gtest/gtest.h>

#include <cmath>

#include "core/engine/engine.h"
#include "core/physics/stokes.h"

namespace sedem {
namespace {

Sample one_grain(double diameter, double y) {
  Sample s;
  s.classes.push_back(SizeClass{diameter, 1.0, 1.0, 1, 1.0});
  s.particles.resize(1);
  s.particles.y[0] = y;
  s.particles.diameter[0] = diameter;
  s.particles.weight[0] = 1;
  return s;
}

TEST(EngineSettling, FallsTheDistanceOfEq13) {
  Scene scene;
  scene.output.interval = 1e-4;
  const double d = 50e-6;
  Engine engine(scene, one_grain(d, 0.4));
  const double t = 0.01;
  engine.advance_to(t);
  const double ut = stokes::terminal_velocity(d, 2500, scene.fluid);
  const double tau = stokes::relaxation_time(d, 2500, scene.fluid);
  // Integral of Eq. 13 left from 0 to t.
  const double fallen = ut * (t - tau * (1 - std::exp(-t / tau)));
  EXPECT_NEAR(0.4 - engine.particles().y[0], fallen, 1e-9 * fallen);
  EXPECT_NEAR(-engine.particles().vy[0], ut * (1 - std::exp(-t / tau)), 1e-9 * ut);
}

TEST(EngineSettling, RestsOnTheBottom) {
  Scene scene;
  const double d = 70e-6;
  Engine engine(scene, one_grain(d, 0.001));
  engine.advance_to(10.0);
  EXPECT_DOUBLE_EQ(engine.particles().y[0], 0.5 * d);
  EXPECT_DOUBLE_EQ(engine.particles().vy[0], 0.0);
}

}  // namespace
}  // namespace sedem
