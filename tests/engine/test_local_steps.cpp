// Local time stepping (integrator.local_steps): free grains coast on windows of their own.

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <numbers>
#include <random>
#include <sstream>
#include <tuple>
#include <vector>

#include "core/engine/contact/box_registry.h"
#include "core/engine/integrate/free_flight.h"
#include "core/engine/threads_for.h"
#include "core/physics/drag.h"
#include "core/physics/stokes.h"
#include "core/run/stage_setups.h"
#include "engine_test_support.h"

namespace sedem {
namespace {

using test::sample_of;
using test::scene_with;

// The box a free trajectory sweeps holds every point of it, including a velocity that turns
// (thrown up, then falling), and is no larger than the extremes it reaches.
TEST(FreeFlight, SweptBoxHoldsTheWholeTrajectory) {
  for (double rate : {0.0, 50.0, 5e4}) {
    const FreeFlight f{0.01, 0.2, 3e-3, 2e-3, rate, 0.0, rate > 0 ? -4e-3 : -9.81};
    const double window = 0.05;
    const FreeFlight::Range r = f.sweep(window);
    double lo = HUGE_VAL, hi = -HUGE_VAL;
    for (int k = 0; k <= 1000; ++k) {
      const FreeFlight::Point p = f.at(window * k / 1000);
      EXPECT_GE(p.x, r.x0 - 1e-15) << rate;
      EXPECT_LE(p.x, r.x1 + 1e-15) << rate;
      EXPECT_GE(p.y, r.y0 - 1e-15) << rate;
      EXPECT_LE(p.y, r.y1 + 1e-15) << rate;
      lo = std::min(lo, p.y);
      hi = std::max(hi, p.y);
    }
    // No larger than the extremes (sampled every 50 us: a turn within 20 us of the start, at
    // rate 5e4, peaks between two samples, ~4e-8 m above them).
    EXPECT_NEAR(r.y1, hi, 1e-7) << rate;
    EXPECT_NEAR(r.y0, lo, 1e-7) << rate;
  }
}

// A free grain's exact trajectory ends at its terminal velocity, Stokes' law.
TEST(FreeFlight, TendsToTheStokesVelocity) {
  const double d = 20e-6, mass = 2500 * std::numbers::pi / 6 * d * d * d;
  const double c = 3 * std::numbers::pi * 1e-3 * d;
  const double force = -(2500 - 1000) * 9.81 * std::numbers::pi / 6 * d * d * d;
  const FreeFlight f{0, 0.3, 0, 0, c / mass, 0, force / c};
  const double u = stokes::terminal_velocity(d, 2500, Fluid{});
  EXPECT_NEAR(f.at(1.0).vy, -u, 1e-9 * u);
  EXPECT_NEAR(f.at(1.0).y, 0.3 - u * (1.0 - mass / c), 1e-9 * u);
}

// Each overlapping box is reported once, whatever the number of cells the two share.
TEST(BoxRegistry, ReportsEachOverlapOnceAndForgetsClearedBoxes) {
  BoxRegistry r;
  r.configure(1e-3, 0.03, 0.4, 4);
  r.set(0, Box{-0.005, 0.005, 0.1, 0.11}, 0);  // spans 10 x 10 cells
  r.set(1, Box{0.0, 0.0001, 0.105, 0.1051}, 1);
  r.set(2, Box{0.02, 0.021, 0.3, 0.301}, 1);
  int count = 0;
  r.overlapping(Box{-0.004, 0.004, 0.102, 0.108}, 3, [&](std::uint32_t id) {
    EXPECT_TRUE(id == 0 || id == 1);
    ++count;
  });
  EXPECT_EQ(count, 2);
  r.clear(1);
  count = 0;
  r.overlapping(Box{-0.004, 0.004, 0.102, 0.108}, 3, [&](std::uint32_t) { ++count; });
  EXPECT_EQ(count, 1);
  r.set(0, Box{0.02, 0.0205, 0.3, 0.3005}, 0);  // moved next to grain 2
  count = 0;
  r.overlapping(Box{-0.004, 0.004, 0.102, 0.108}, 3, [&](std::uint32_t) { ++count; });
  EXPECT_EQ(count, 0);
}

// Sets and clears boxes of n grains at random (one move in `clear_one_in` a clear) over `rounds`
// moves, and after every `query_every`-th compares a random query's report with a brute-force
// look through the boxes held.
template <class RandomBox>
void expect_queries_as_brute_force(BoxRegistry& r, std::uint32_t n, int rounds, int clear_one_in,
                                   int query_every, std::mt19937& rng, RandomBox&& random_box) {
  std::vector<bool> held(n, false);
  for (int round = 0; round < rounds; ++round) {
    const std::uint32_t id = rng() % n;
    if (rng() % clear_one_in == 0) {
      r.clear(id);
      held[id] = false;
    } else {
      r.set(id, random_box(), 0);
      held[id] = true;
    }
    if (round % query_every != 0) continue;
    const Box q = random_box();
    std::vector<std::uint32_t> found, expected;
    r.overlapping(q, n, [&](std::uint32_t j) { found.push_back(j); });
    for (std::uint32_t j = 0; j < n; ++j)
      if (held[j] && r.box(j).overlaps(q)) expected.push_back(j);
    std::sort(found.begin(), found.end());
    ASSERT_EQ(found, expected) << "round " << round;
  }
}

// Many boxes in few cells (a cell keeps its first grains in itself, the rest apart): after
// random moves and clears every query reports exactly the boxes a brute-force look finds.
TEST(BoxRegistry, CrowdedCellsReportWhatABruteForceLookFinds) {
  constexpr std::uint32_t n = 200;
  BoxRegistry r;
  r.configure(1e-3, 2e-3, 3e-3, n);  // 4 x 3 cells
  std::mt19937 rng(3);
  std::uniform_real_distribution<double> x(-2e-3, 2e-3), y(0, 3e-3), size(1e-5, 8e-4);
  expect_queries_as_brute_force(r, n, 3000, 5, 10, rng, [&] {
    const double x0 = x(rng), y0 = y(rng);
    return Box{x0, x0 + size(rng), y0, y0 + size(rng)};
  });
}

// A tall registry whose boxes sit in a few rows (a query skips the rows holding none): after
// boxes move between rows, leave them and come back, every query reports exactly the boxes a
// brute-force look finds.
TEST(BoxRegistry, SparseRowsReportWhatABruteForceLookFinds) {
  constexpr std::uint32_t n = 40;
  BoxRegistry r;
  r.configure(1e-3, 2e-3, 0.1, n);  // 4 x 100 cells
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> x(-2e-3, 2e-3), size(1e-5, 1.5e-3);
  std::uniform_int_distribution<int> band(0, 3);
  expect_queries_as_brute_force(r, n, 4000, 3, 5, rng, [&] {
    const double x0 = x(rng), y0 = 0.02 * band(rng) + 1e-3 * x(rng) + 2e-3;
    return Box{x0, x0 + size(rng), y0, y0 + size(rng)};
  });
}

// Stokes drag and grains too far apart to meet: coasting is exact, so local steps put every
// grain where the global step does (to round-off), with far fewer particle-steps.
TEST(LocalSteps, FreeGrainsEndWhereTheGlobalStepPutsThem) {
  const auto grains = test::scattered(
      100, -0.03, 0.03, 0.1, 0.4, [](int k) { return 5e-6 + 2e-6 * (k % 30); }, 5);
  Scene global = scene_with("stokes", "exponential");
  global.integrator.local_steps = false;
  Scene local = scene_with("stokes", "exponential");
  local.integrator.local_steps = true;
  Engine a(engine_setup(global), sample_of(grains)), b(engine_setup(local), sample_of(grains));
  a.advance_to(20.0);
  b.advance_to(20.0);
  const double fall = stokes::terminal_velocity(65e-6, 2500, Fluid{}) * 20.0;
  double worst = 0;
  std::size_t at = 0;
  for (std::size_t i = 0; i < grains.size(); ++i)
    if (const double gap = std::hypot(a.particles().x[i] - b.particles().x[i],
                                      a.particles().y[i] - b.particles().y[i]);
        gap > worst) {
      worst = gap;
      at = i;
    }
  EXPECT_LT(worst, 1e-9 * fall) << at;
  EXPECT_LT(b.stats().particle_steps * 20, a.stats().particle_steps);
}

// A coarse grain falling straight onto a fine one: the two join the common step before they
// touch, and the fine one is pushed down ahead of the coarse (never passed through).
TEST(LocalSteps, ACoarseGrainNeverPassesThroughAFineOne) {
  Scene scene = scene_with("stokes", "exponential");
  scene.integrator.local_steps = true;
  const double coarse = 60e-6, fine = 10e-6;
  Engine engine(engine_setup(scene), sample_of({{0, 0.2, coarse}, {0, 0.19, fine}}));
  const double u = stokes::terminal_velocity(coarse, 2500, Fluid{});
  double worst = 0;
  for (int k = 1; k <= 200; ++k) {
    engine.advance_to(k * 0.02 / u / 100);  // 2 cm of the coarse grain's fall in all
    const auto& p = engine.particles();
    EXPECT_GT(p.y[0], p.y[1]) << k;
    const double gap = std::hypot(p.x[0] - p.x[1], p.y[0] - p.y[1]) - 0.5 * (coarse + fine);
    worst = std::min(worst, gap);
  }
  EXPECT_GT(worst, -0.3 * 0.5 * fine);  // overlaps stay a fraction of the fine radius
  EXPECT_GT(engine.stats().engaged, 0);
}

// Grains thrown apart side by side from slight overlaps come to rest half a radius or a radius
// apart, each inside its neighbours' member boxes and clear of their windows: none can leave the
// common step alone (two grains, or a row of three whose middle one holds both others), where they
// would fall side by side for ever, and all leave together.
TEST(LocalSteps, MembersHoldingEachOtherLeaveTogether) {
  Scene scene = scene_with("stokes", "exponential");
  scene.integrator.local_steps = true;
  const double d = 60e-6, r = 0.5 * d;
  // The drag stops a grain thrown at v0 within v0 tau.
  const double tau = 2500 * d * d / (18 * Fluid{}.viscosity);
  const double v0 = 0.5 * r / tau;
  const std::vector<std::vector<test::Grain>> rows = {
      {{-0.99 * r, 0.2, d, -v0, 0}, {0.99 * r, 0.2, d, v0, 0}},
      {{-1.98 * r, 0.2, d, -v0, 0}, {0, 0.2, d}, {1.98 * r, 0.2, d, v0, 0}}};
  for (const auto& row : rows) {
    SCOPED_TRACE(row.size());
    Engine engine(engine_setup(scene), sample_of(row));
    std::size_t most = 0;
    while (engine.time() < 0.5) {
      engine.step(0.5);
      ASSERT_EQ(engine.local_violation(), "") << engine.time();
      most = std::max(most, engine.stats().members);
    }
    const auto& p = engine.particles();
    for (std::size_t i = 1; i < row.size(); ++i)  // apart, each clear of its neighbour's window
      EXPECT_GT(p.x[i] - p.x[i - 1] - d, 0.2 * r) << i;
    EXPECT_EQ(most, row.size());
    EXPECT_EQ(engine.stats().released, std::int64_t(row.size()));
    EXPECT_EQ(engine.stats().members, 0u);
  }
}

// Without suspension contacts the coarse grain falls through the fine one: each ends where it
// would alone (Stokes drag: exact free paths), and neither ever joined the common step.
TEST(LocalSteps, WithoutSuspensionContactsACoarseGrainPassesAFineOne) {
  Scene scene = scene_with("stokes", "exponential");
  scene.integrator.local_steps = true;
  scene.forces.suspension_contacts = false;
  const double coarse = 60e-6, fine = 10e-6;
  Engine both(engine_setup(scene), sample_of({{0, 0.2, coarse}, {0, 0.19, fine}}));
  Engine coarse_alone(engine_setup(scene), sample_of({{0, 0.2, coarse}}));
  Engine fine_alone(engine_setup(scene), sample_of({{0, 0.19, fine}}));
  const double u = stokes::terminal_velocity(coarse, 2500, Fluid{});
  const double end = 0.02 / u;  // 2 cm of the coarse grain's fall
  for (Engine* e : {&both, &coarse_alone, &fine_alone}) e->advance_to(end);
  const auto& p = both.particles();
  EXPECT_LT(p.y[0], p.y[1] - 0.005);  // passed it by more than 5 mm
  EXPECT_NEAR(p.y[0], coarse_alone.particles().y[0], 1e-12);
  EXPECT_NEAR(p.y[1], fine_alone.particles().y[0], 1e-12);
  EXPECT_EQ(both.stats().engaged, 0);
}

// A crowded suspension of coarse and fine grains (many joining and leaving the common step):
// after every step each grain is inside its box, no window has ended unlooked-at and no two
// boxes overlap that must not. (A step that a joining grain shortened once let later windows
// end unlooked-at, and two grains met at 50 m/s.)
TEST(LocalSteps, KeepTheirPromiseInACrowdedSuspension) {
  Scene scene = scene_with("di_felice", "exponential");
  scene.integrator.local_steps = true;
  scene.integrator.freeze_settled = true;
  const double hw = scene.cylinder.half_width();
  // Own radii at the longest crossing lets a member travel the most of its box's allowance in
  // a step.
  struct Mode {
    const char* name;
    double carried_fraction;
    bool substeps;
    double crossing_fraction;
  };
  const double crossing = scene.integrator.crossing_fraction;
  for (const Mode& mode :
       {Mode{"own radii", 0.0, false, crossing}, Mode{"carried steps", 0.2, false, crossing},
        Mode{"carried sub-steps", 0.8, true, crossing},
        Mode{"own radii, crossing 1", 0.0, false, 1.0}}) {
    scene.integrator.carried_fraction = mode.carried_fraction;
    scene.integrator.carried_substeps = mode.substeps;
    scene.integrator.crossing_fraction = mode.crossing_fraction;
    Engine engine(engine_setup(scene), sample_of(test::crowd(-0.3 * hw, 0.3 * hw, 0.0005, 0.012)));
    std::int64_t engaged = 0;
    while (engine.time() < 0.5) {
      engine.step(0.5);
      const std::string broken = engine.local_violation();
      ASSERT_EQ(broken, "") << mode.name << " at t = " << engine.time() << " s, step "
                            << engine.stats().steps;
      engaged = engine.stats().engaged;
    }
    EXPECT_GT(engaged, 100) << mode.name << ": "
                            << engaged;  // the suspension did crowd the common step
  }
}

// Where grains crowd as at a million in the section (a mean spacing of 170 um), a coarse member's
// box of 2 radii reaches its neighbours' though the step the fine grains set moves it a fraction
// of a radius: boxes of a few steps' travel (integrator.member_box_steps) keep the promise after
// every step, hold fewer grains on the common step, let every size fall as with boxes of 2
// radii, and resume from a checkpoint to the bit, with carried sub-steps too.
TEST(LocalSteps, MembersBoxesByTheirTravelHoldFewerGrainsAndKeepThePromise) {
  Scene scene = scene_with("di_felice", "exponential");
  scene.integrator.local_steps = true;
  scene.cylinder.diameter = 0.004;
  scene.cylinder.height = 0.02;
  const double hw = scene.cylinder.half_width();
  const auto grains = test::crowd(-0.9 * hw, 0.9 * hw, 0.004, 0.016);
  auto size_of = [](double d) { return d > 50e-6 ? 0 : (d > 10e-6 ? 1 : 2); };
  for (bool substeps : {false, true}) {
    scene.integrator.carried_fraction = substeps ? 0.8 : 0.0;
    scene.integrator.carried_substeps = substeps;
    double members[2] = {0, 0}, fall[2][3] = {{0, 0, 0}, {0, 0, 0}};
    for (int by_travel : {0, 1}) {
      scene.integrator.member_box_steps = by_travel ? 4 : 0;
      Engine engine(engine_setup(scene), sample_of(grains));
      std::stringstream checkpoint;
      while (engine.time() < 0.2) {
        engine.step(0.2);
        members[by_travel] += double(engine.stats().members);
        if (by_travel) {
          ASSERT_EQ(engine.local_violation(), "")
              << "sub-steps " << substeps << ", at t = " << engine.time() << " s";
          if (engine.time() >= 0.1 && checkpoint.str().empty()) engine.save_checkpoint(checkpoint);
        }
      }
      if (by_travel) {  // the boxes' paces come back from the checkpoint to the bit
        Engine resumed(engine_setup(scene), sample_of(grains));
        resumed.load_checkpoint(checkpoint, "members' boxes");
        while (resumed.time() < 0.2) resumed.step(0.2);
        test::expect_same_bits(engine.particles(), resumed.particles());
      }
      members[by_travel] /= double(engine.stats().steps);
      for (const test::Grain& g : grains) fall[by_travel][size_of(g.d)] += g.y;
      const Particles& p = engine.particles();
      for (std::size_t i = 0; i < p.size(); ++i) fall[by_travel][size_of(p.diameter[i])] -= p.y[i];
    }
    // With sub-steps the coarse grains set the step, which moves them as far as their radii
    // allow: their boxes stay.
    if (!substeps) {
      EXPECT_LT(members[1], 0.9 * members[0]) << members[1] << " against " << members[0];
    }
    for (int size = 0; size < 3; ++size)
      EXPECT_NEAR(fall[1][size], fall[0][size], 0.005 * fall[0][size])
          << "sub-steps " << substeps << ", size " << size;
  }
}

// The same crowd without suspension contacts, across the whole width and retiring below the
// instruments: the promise holds for what still meets (the walls, and the members' contacts
// there), and grains join the common step only at the walls: far fewer than with contacts.
TEST(LocalSteps, KeepTheirPromiseWithoutSuspensionContacts) {
  Scene scene = scene_with("di_felice", "exponential");
  scene.integrator.local_steps = true;
  scene.integrator.retire_below = true;
  const double hw = scene.cylinder.half_width();
  const auto grains = test::crowd(-hw + 40e-6, hw - 40e-6, 0.25, 0.262);
  std::int64_t engaged[2] = {0, 0};
  for (bool contacts : {true, false}) {
    scene.forces.suspension_contacts = contacts;
    Engine engine(engine_setup(scene), sample_of(grains));
    while (engine.time() < 1.0) {
      engine.step(1.0);
      const std::string broken = engine.local_violation();
      ASSERT_EQ(broken, "") << contacts << " at t = " << engine.time() << " s";
    }
    engaged[contacts] = engine.stats().engaged;
  }
  EXPECT_LT(engaged[0] * 10, engaged[1]) << engaged[0] << " " << engaged[1];
}

// Local steps, Di Felice drag, grains that pass each other and retire below the instruments.
Scene passing_scene() {
  Scene scene = scene_with("di_felice", "exponential");
  scene.integrator.local_steps = true;
  scene.integrator.retire_below = true;
  scene.forces.suspension_contacts = false;
  return scene;
}

// Without suspension contacts a run resumes bit for bit too (free grains hold no box, so the
// checkpoint holds the members' and the walls' only), and grains still keep off the walls.
TEST(LocalSteps, WithoutSuspensionContactsResumesBitForBit) {
  Scene scene = passing_scene();
  const double hw = scene.cylinder.half_width();
  const auto grains = test::crowd(-hw + 40e-6, hw - 40e-6, 0.2, 0.3);
  const std::string checkpoint =
      (std::filesystem::temp_directory_path() / "sedem_passing_test.ckpt").string();
  Engine first(engine_setup(scene), sample_of(grains));
  for (int k = 1; k <= 20; ++k) {
    first.advance_to(k);
    ASSERT_EQ(first.local_violation(), "") << k;
    if (k == 10) first.save_checkpoint(checkpoint);
  }
  Engine resumed(engine_setup(scene), sample_of(grains));
  resumed.load_checkpoint(checkpoint);
  for (int k = 11; k <= 20; ++k) resumed.advance_to(k);
  const Particles& a = first.particles();
  const Particles& c = resumed.particles();
  for (std::size_t i = 0; i < grains.size(); ++i) {
    EXPECT_EQ(c.x[i], a.x[i]) << i;
    EXPECT_EQ(c.y[i], a.y[i]) << i;
    EXPECT_LE(std::abs(a.x[i]), hw - 0.5 * a.diameter[i] * 0.7) << i;
  }
  EXPECT_GT(first.stats().retired, 0u);  // 20 s: the coarse grains crossed the line
  std::filesystem::remove(checkpoint);
}

// Without suspension contacts the syncs are taken lane by lane (one lane a column of voidage
// cells) on the engine's threads: one thread and two give the same bits, with grains joining
// the members at the walls and retiring onto the shared bed. A checkpoint taken
// on two threads resumes on two, and on one, to the same bits too.
TEST(LocalSteps, WithoutSuspensionContactsLanesGiveTheSameBitsOnOneThreadOrTwo) {
  Scene scene = passing_scene();
  const double hw = scene.cylinder.half_width();
  auto size = [](int k) { return k % 3 == 0 ? 70e-6 : (k % 3 == 1 ? 25e-6 : 4e-6); };
  auto grains = test::scattered(4000, -hw + 30e-6, hw - 30e-6, 0.005, 0.3, size, 11, 0.0);
  for (double side : {-1.0, 1.0}) {  // crowds beside each wall, to join the members
    const auto wall = test::scattered(300, side * hw - 150e-6, side * hw + 150e-6, 0.31, 0.33, size,
                                      side > 0 ? 12 : 13, 0.0);
    for (const auto& g : wall)
      if (std::abs(g.x) < hw - 0.5 * g.d) grains.push_back(g);
  }
  const std::string checkpoint =
      (std::filesystem::temp_directory_path() / "sedem_lanes_test.ckpt").string();
  Engine one(engine_setup(test::on_threads(scene, 1)), sample_of(grains));
  Engine two(engine_setup(test::on_threads(scene, 2)), sample_of(grains));
  ASSERT_EQ(one.threads(), 1);
  ASSERT_EQ(two.threads(), 2);
  for (int k = 1; k <= 20; ++k) {
    one.advance_to(k);
    two.advance_to(k);
    if (k == 10) two.save_checkpoint(checkpoint);
  }
  Engine resumed(engine_setup(test::on_threads(scene, 2)), sample_of(grains));
  resumed.load_checkpoint(checkpoint);
  for (int k = 11; k <= 20; ++k) resumed.advance_to(k);
  Engine on_one(engine_setup(test::on_threads(scene, 1)), sample_of(grains));
  on_one.load_checkpoint(checkpoint);
  for (int k = 11; k <= 20; ++k) on_one.advance_to(k);
  for (const Engine* e : {&two, &resumed, &on_one}) {
    SCOPED_TRACE(e == &two ? "two threads" : (e == &resumed ? "resumed on two" : "resumed on one"));
    test::expect_same_bits(one.particles(), e->particles());
    EXPECT_EQ(e->stats().steps, one.stats().steps);
    EXPECT_EQ(e->stats().windows, one.stats().windows);
    EXPECT_EQ(e->stats().particle_steps, one.stats().particle_steps);
  }
  EXPECT_GT(one.stats().engaged, 0);  // at the walls
  EXPECT_GT(one.stats().retired, 100u);
  EXPECT_EQ(two.local_violation(), "");
  std::filesystem::remove(checkpoint);
}

// Where grains meet everywhere the members' step (lists, integration, projection, and with
// carried steps the step's choice) goes on the engine's threads when they are many
// (core/engine/threads_for.h): a crowd of 4000 grains gives the same bits on one thread and two,
// its members passing back and forth across the count where the second thread starts; a
// checkpoint taken on two threads resumes on one to the same bits.
TEST(LocalSteps, WithContactsEverywhereTheMembersStepGivesTheSameBitsOnOneThreadOrTwo) {
  for (const bool carried : {false, true}) {
    SCOPED_TRACE(carried ? "carried sub-steps" : "one rate");
    Scene scene = scene_with("di_felice", "exponential");
    scene.integrator.local_steps = true;
    if (carried) {
      scene.integrator.carried_fraction = 0.8;
      scene.integrator.carried_substeps = true;
    }
    const double hw = scene.cylinder.half_width();
    const auto grains = test::scattered(
        4000, -0.5 * hw, 0.5 * hw, 0.0005, 0.05,
        [](int k) { return k % 4 == 0 ? 70e-6 : (k % 4 == 1 ? 30e-6 : 5e-6); }, 5, 0.0);
    Engine one(engine_setup(test::on_threads(scene, 1)), sample_of(grains));
    Engine two(engine_setup(test::on_threads(scene, 2)), sample_of(grains));
    ASSERT_EQ(one.threads(), 1);
    ASSERT_EQ(two.threads(), 2);
    std::size_t most = 0, least = grains.size();
    std::stringstream checkpoint;  // taken on two threads while the second one works
    while (one.time() < 3) {
      one.step(3);
      two.step(3);
      ASSERT_EQ(one.time(), two.time()) << "step " << one.stats().steps;
      most = std::max(most, one.stats().members);
      least = std::min(least, one.stats().members);
      if (two.stats().members >= kThreadedFrom && checkpoint.str().empty())
        two.save_checkpoint(checkpoint);
    }
    test::expect_same_bits(one.particles(), two.particles());
    // A run stopped on two threads goes on on one (a machine with fewer cores) to the same bits.
    Engine resumed(engine_setup(test::on_threads(scene, 1)), sample_of(grains));
    resumed.load_checkpoint(checkpoint, "two threads' checkpoint");
    while (resumed.time() < 3) resumed.step(3);
    test::expect_same_bits(one.particles(), resumed.particles());
    EXPECT_EQ(two.stats().steps, one.stats().steps);
    EXPECT_EQ(two.stats().particle_steps, one.stats().particle_steps);
    EXPECT_GE(most, kThreadedFrom) << "the second thread never started";
    EXPECT_LT(least, kThreadedFrom) << "the second thread never stopped";
    if (carried) {
      EXPECT_GT(one.stats().widened_rows, 0) << "no grain was picked up";
    }
  }
}

// A run of `seconds` s with the scheme's promise checked after every second: its windows and
// where the grains end.
struct CheckedRun {
  std::int64_t windows = 0;
  Particles end;
};
CheckedRun run_checked(const Scene& scene, const std::vector<test::Grain>& grains, int seconds) {
  Engine engine(engine_setup(scene), sample_of(grains));
  for (int k = 1; k <= seconds; ++k) {
    engine.advance_to(k);
    const std::string broken = engine.local_violation();
    EXPECT_EQ(broken, "") << "t = " << k << " s";
    if (!broken.empty()) break;
  }
  return {engine.stats().windows, engine.particles()};
}

// A free grain's window may carry it integrator.coast_travel mean spacings: longer windows
// take fewer of them, keep the promise after every step (no box meets another), and move the
// grains that meet nothing along the same exact path, to round-off.
TEST(LocalSteps, LongerWindowsTakeFewerAndMoveTheFreeGrainsAlike) {
  Scene scene = scene_with("stokes", "exponential");
  scene.integrator.local_steps = true;
  scene.integrator.retire_below = false;
  const double hw = scene.cylinder.half_width();
  const auto grains = test::scattered(
      400, -0.9 * hw, 0.9 * hw, 0.05, 0.45, [](int k) { return k % 2 ? 70e-6 : 20e-6; }, 3, 0.0);
  std::int64_t windows[2] = {0, 0};
  Particles end[2];
  for (int longer : {0, 1}) {
    scene.integrator.coast_travel = longer ? 2.0 : 0.5;
    SCOPED_TRACE(longer ? "2 spacings" : "half a spacing");
    CheckedRun run = run_checked(scene, grains, 30);
    windows[longer] = run.windows;
    end[longer] = std::move(run.end);
  }
  EXPECT_LT(double(windows[1]), 0.5 * double(windows[0]))
      << windows[1] << " against " << windows[0];
  std::size_t alike = 0;
  for (std::size_t i = 0; i < grains.size(); ++i) {
    const double gap = std::hypot(end[1].x[i] - end[0].x[i], end[1].y[i] - end[0].y[i]);
    alike += gap < 1e-9;
  }
  EXPECT_GT(alike, grains.size() * 9 / 10) << alike << " of " << grains.size();
}

// A free grain far from its terminal velocity coasts a few response times and has its drag taken
// anew, unless its drag at the speed it relaxes to is within integrator.coast_drag_change of
// the one it holds: it then coasts on with that drag. Three lone grains started below their
// terminal speed: the fine one's drag hardly depends on its speed, and it coasts on; the
// coarser ones' first windows are cut as before. Each falls as with every such window cut, to
// a thousandth of its fall (1.4e-7, 1.4e-5 and 6.5e-5 of it here), in fewer windows (8 against
// 11). (At a tolerance of 0.5 the coarsest grain, whose drag moves most with its speed, coasted
// on from its start with a drag 5e-3 off and fell that much further: the test fails.)
TEST(LocalSteps, AGrainWhoseDragHoldsKeepsItsWindow) {
  Scene scene = scene_with("di_felice", "exponential");
  scene.integrator.local_steps = true;
  std::vector<test::Grain> grains;
  for (const auto& [d, x, start] :
       {std::tuple{5e-6, -0.01, 0.9}, std::tuple{60e-6, 0.0, 0.9}, std::tuple{200e-6, 0.01, 0.5}})
    grains.push_back(
        {x, 0.25, d, 0, -start * drag::di_felice_terminal_velocity(d, 2500, scene.fluid)});
  std::int64_t windows[2] = {0, 0};
  Particles end[2];
  for (int held : {0, 1}) {
    scene.integrator.coast_drag_change = held ? 1e-3 : 0.0;
    Engine engine(engine_setup(scene), sample_of(grains));
    engine.advance_to(5);
    windows[held] = engine.stats().windows;
    end[held] = engine.particles();
  }
  EXPECT_LT(windows[1], windows[0]);
  for (std::size_t k = 0; k < grains.size(); ++k) {
    const double fall = grains[k].y - end[0].y[k];
    EXPECT_GT(fall, 4 * -grains[k].vy);
    EXPECT_NEAR(end[1].y[k], end[0].y[k], 1e-3 * fall)
        << grains[k].d << " m " << (end[1].y[k] - end[0].y[k]) / fall;
  }
}

// The same in a hindered suspension of fine grains with a few coarse ones falling through, where
// the voidage a grain feels changes between its syncs as others cross the cells: with the
// tolerance far fewer windows (6 322 against 8 277), the promise kept after every second, and
// each fine size's mean fall as with every such window cut, to a thousandth (they differed by
// 3e-5 and 7e-5; the coarse grains' collisions make their falls differ by more from any change
// of the syncs' sequence).
TEST(LocalSteps, WindowsTheDragAllowsAreFewerInAHinderedSuspension) {
  Scene scene = scene_with("di_felice", "exponential");
  scene.integrator.local_steps = true;
  scene.integrator.max_coast = 5;
  const double hw = scene.cylinder.half_width();
  const double x0 = -0.3 * hw, x1 = 0.3 * hw, y0 = 0.25, y1 = 0.27;
  auto grains = test::scattered(
      800, x0, x1, y0, y1, [](int k) { return k % 20 == 0 ? 60e-6 : (k % 2 ? 8e-6 : 4e-6); }, 11,
      0.0);
  // One per cent solids by volume in the grains' region.
  double solid = 0;
  for (const auto& g : grains) solid += std::numbers::pi / 6 * g.d * g.d * g.d;
  const double weight = 0.01 * (x1 - x0) * (y1 - y0) * scene.cylinder.slab_thickness() / solid;
  for (auto& g : grains) g.weight = weight;
  std::int64_t windows[2] = {0, 0};
  Particles end[2];
  for (int held : {0, 1}) {
    scene.integrator.coast_drag_change = held ? 1e-3 : 0.0;
    SCOPED_TRACE(held ? "drag change 1e-3" : "every window cut");
    CheckedRun run = run_checked(scene, grains, 30);
    windows[held] = run.windows;
    end[held] = std::move(run.end);
  }
  EXPECT_LT(double(windows[1]), 0.85 * double(windows[0]))
      << windows[1] << " against " << windows[0];
  for (int size : {0, 1}) {  // 4 and 8 um
    double fall[2] = {0, 0};
    for (std::size_t i = size; i < grains.size(); i += 2)
      if (i % 20 != 0)
        for (int held : {0, 1}) fall[held] += grains[i].y - end[held].y[i];
    EXPECT_NEAR(fall[1], fall[0], 1e-3 * fall[0]) << (size ? "8 um" : "4 um");
  }
}

// Grains that fall below every instrument retire onto the coarse bed. Those that stay above are
// where they would be without retirement (Stokes drag: a free grain's path does not depend on
// its windows), the retired ones lie stacked on the bottom, and a checkpoint taken with
// retired grains resumes bit for bit.
TEST(LocalSteps, GrainsBelowEveryInstrumentRetireAndChangeNothingAbove) {
  Scene scene = scene_with("stokes", "exponential");
  scene.integrator.local_steps = true;
  // A grain retires at its window's end: windows of half a mean spacing (4 mm here, 12 s for a
  // fine grain) have all ended since the grains crossed the line that are below it at 60 s.
  scene.integrator.coast_travel = 0.5;
  const double hw = scene.cylinder.half_width();
  const auto grains = test::scattered(
      400, -0.9 * hw, 0.9 * hw, 0.001, 0.45, [](int k) { return k % 2 ? 70e-6 : 20e-6; }, 3, 0.0);
  Scene kept = scene;
  scene.integrator.retire_below = true;
  Engine retiring(engine_setup(scene), sample_of(grains)),
      keeping(engine_setup(kept), sample_of(grains));
  const double line = retiring.retire_height();
  const std::string checkpoint =
      (std::filesystem::temp_directory_path() / "sedem_retire_test.ckpt").string();
  ASSERT_GT(line, 0.1);
  EXPECT_EQ(keeping.retire_height(), 0.0);
  // 60 s: the coarse grains fall 26 cm, through the line and onto the bed.
  for (int k = 1; k <= 60; ++k) {
    retiring.advance_to(k);
    keeping.advance_to(k);
    ASSERT_EQ(keeping.local_violation(), "") << k;
    ASSERT_EQ(retiring.local_violation(), "") << k;
    if (k == 30) retiring.save_checkpoint(checkpoint);
  }
  const Particles& a = retiring.particles();
  const Particles& b = keeping.particles();
  std::size_t above = 0, same = 0, resting = 0;
  for (std::size_t i = 0; i < grains.size(); ++i) {
    const double r = 0.5 * a.diameter[i];
    if (b.y[i] - r > line + 1e-3) {
      // A collision's outcome depends on the members' step, which the grains that retired
      // (no longer on the common step) change: within a radius, and most exactly the same.
      ++above;
      const double gap = std::hypot(a.x[i] - b.x[i], a.y[i] - b.y[i]);
      EXPECT_LT(gap, r) << i;
      same += gap < 1e-9;
    } else {
      EXPECT_LT(a.y[i] + r, line) << i;
      EXPECT_GE(a.y[i], r * (1 - 1e-9)) << i;
      resting += a.vy[i] == 0;
    }
  }
  EXPECT_GT(above, 80u);
  EXPECT_GT(same, above * 9 / 10);
  EXPECT_GT(resting, 100u);
  EXPECT_EQ(retiring.stats().retired, grains.size() - above);
  // The bed spreads: the ~200 coarse grains that landed (one per 4.5 columns of 70 um) lie in
  // one layer, with no tower, each inside the cylinder.
  double top = 0;
  for (std::size_t i = 0; i < grains.size(); ++i)
    if (a.vy[i] == 0 && a.y[i] < 0.01) {
      const double r = 0.5 * a.diameter[i];
      top = std::max(top, a.y[i] + r);
      EXPECT_LE(std::abs(a.x[i]), hw - r) << i;
    }
  EXPECT_GE(top, 70e-6 * (1 - 1e-9));
  EXPECT_LT(top, 2 * 70e-6);

  Engine resumed(engine_setup(scene), sample_of(grains));
  resumed.load_checkpoint(checkpoint);
  for (int k = 31; k <= 60; ++k) resumed.advance_to(k);
  const Particles& c = resumed.particles();
  for (std::size_t i = 0; i < grains.size(); ++i) {
    EXPECT_EQ(c.x[i], a.x[i]) << i;
    EXPECT_EQ(c.y[i], a.y[i]) << i;
  }
  std::filesystem::remove(checkpoint);
}

}  // namespace
}  // namespace sedem
