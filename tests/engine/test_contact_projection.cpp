// The contact projection's islands: particles linked by constraints move only each other, so an
// island comes out of a step exactly as it would alone, however long a far-away pile keeps its
// own island sweeping, and the pile as it would alone, though the sweeps then visit it only.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <vector>

#include "core/engine/contact/candidate_lists.h"
#include "core/engine/contact/neighbour_grid.h"
#include "core/engine/forces/force_model.h"
#include "core/engine/integrate/contact_projection.h"
#include "core/engine/state/engine_state.h"

namespace sedem {
namespace {

constexpr double kHalfWidth = 1e-3, kHeight = 2e-3, kDiameter = 20e-6;

struct Grains {
  std::vector<double> x, y;
  void add(double gx, double gy) {
    x.push_back(gx);
    y.push_back(gy);
  }
};

// A triangle of equal grains pressed into each other, well above the floor: each grain has two
// contacts, so the Jacobi sweeps reach its solution geometrically, never exactly.
Grains triangle() {
  Grains g;
  const double s = 0.8 * kDiameter, cx = -0.5e-3, cy = 1e-3;
  g.add(cx, cy);
  g.add(cx + s, cy);
  g.add(cx + 0.5 * s, cy + 0.5 * std::sqrt(3.0) * s);
  return g;
}

// A long chain of grains pressed deep into each other, far from the triangle: its forces need
// every sweep a step allows.
void add_chain(Grains& g) {
  for (int k = 0; k < 40; ++k) g.add(0.1e-3 + 0.6 * kDiameter * k, 1e-3);
}

// One projection of the grains from rest over a step of 1 ms; their positions after it.
Grains project(const Grains& g) {
  ForceModel model;
  model.half_width = kHalfWidth;
  model.friction = false;
  const std::size_t n = g.x.size();
  EngineState s;
  s.resize(n);
  for (std::size_t i = 0; i < n; ++i) {
    s.x[i] = g.x[i];
    s.y[i] = g.y[i];
    s.vx[i] = s.vy[i] = s.omega[i] = 0;
    s.diameter[i] = kDiameter;
    s.weight[i] = 1;
    s.origin[i] = std::uint32_t(i);
    s.frozen[i] = 0;
  }
  NeighbourGrid grid;
  grid.configure(2 * kDiameter, 2 * kDiameter, kHalfWidth, kHeight);
  CandidateLists lists;
  lists.configure(1);
  lists.search.assign(n, kDiameter);
  lists.rebuild(s, grid, true);
  ContactProjection projection;
  projection.configure(model, 1, 32, n);
  // Stokes drag of a 20 um grain in water.
  const std::vector<double> drag(n, 3 * std::numbers::pi * model.viscosity * kDiameter);
  projection.run(s, grid, lists, drag, 1e-3);
  Grains out;
  for (std::size_t i = 0; i < n; ++i) out.add(s.x[i], s.y[i]);
  return out;
}

TEST(ContactProjection, AnIslandComesOutAsItWouldAlone) {
  const Grains alone = project(triangle());
  Grains both = triangle();
  add_chain(both);
  const Grains together = project(both);
  for (std::size_t i = 0; i < 3; ++i) {
    EXPECT_EQ(alone.x[i], together.x[i]) << "grain " << i;
    EXPECT_EQ(alone.y[i], together.y[i]) << "grain " << i;
  }
  // The chain, swept on after the triangle converged (the sweeps then visit only its
  // constraints and grains), comes out as it would alone too.
  Grains chain;
  add_chain(chain);
  const Grains chain_alone = project(chain);
  for (std::size_t i = 0; i < chain.x.size(); ++i) {
    EXPECT_EQ(chain_alone.x[i], together.x[3 + i]) << "chain grain " << i;
    EXPECT_EQ(chain_alone.y[i], together.y[3 + i]) << "chain grain " << i;
  }
  // The triangle was pushed apart, and the chain too.
  const Grains start = triangle();
  EXPECT_GT(std::hypot(alone.x[1] - alone.x[0], alone.y[1] - alone.y[0]),
            std::hypot(start.x[1] - start.x[0], start.y[1] - start.y[0]));
  EXPECT_GT(together.x.back() - together.x[3], both.x.back() - both.x[3]);
}

}  // namespace
}  // namespace sedem
