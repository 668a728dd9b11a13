#pragma once

#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <vector>

#include "core/engine/engine.h"
#include "core/run/stage_setups.h"
#include "core/scene/scene.h"

namespace sedem::test {

struct Grain {
  double x, y, d;
  double vx = 0, vy = 0;
  double weight = 1;
};

inline Sample sample_of(const std::vector<Grain>& grains) {
  Sample s;
  s.particles.resize(grains.size());
  for (std::size_t i = 0; i < grains.size(); ++i) {
    auto& p = s.particles;
    p.x[i] = grains[i].x;
    p.y[i] = grains[i].y;
    p.vx[i] = grains[i].vx;
    p.vy[i] = grains[i].vy;
    p.diameter[i] = grains[i].d;
    p.weight[i] = grains[i].weight;
    p.id[i] = std::uint32_t(100 + i);
  }
  return s;
}

// `count` grains of the given sizes at random in a box, no two overlapping by more than a
// fraction `overlap` of the smaller diameter (deterministic).
template <class Size>
std::vector<Grain> scattered(int count, double x0, double x1, double y0, double y1, Size&& size,
                             unsigned seed, double overlap = 0.05) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> u(0, 1);
  std::vector<Grain> g;
  while (int(g.size()) < count) {
    const double d = size(int(g.size()));
    const Grain c{x0 + (x1 - x0) * u(rng), y0 + (y1 - y0) * u(rng), d};
    bool ok = c.y > 0.5 * d;
    for (const Grain& o : g)
      ok = ok && std::hypot(o.x - c.x, o.y - c.y) > 0.5 * (o.d + d) - overlap * std::min(o.d, d);
    if (ok) g.push_back(c);
  }
  return g;
}

// 1500 grains of 70, 30 and 5 um scattered in a box of the section.
inline std::vector<Grain> crowd(double x0, double x1, double y0, double y1) {
  return scattered(
      1500, x0, x1, y0, y1, [](int k) { return k % 4 == 0 ? 70e-6 : (k % 4 == 1 ? 30e-6 : 5e-6); },
      7, 0.0);
}

// A scene with the given drag and integrator, nothing frozen or retired, one thread unless told.
inline Scene scene_with(const std::string& drag, const std::string& method, int threads = 1) {
  Scene scene;
  scene.forces.drag = drag;
  scene.integrator.method = method;
  scene.integrator.freeze_settled = false;
  scene.integrator.retire_below = false;
  scene.integrator.threads = threads;
  return scene;
}

// The scene on `threads` threads.
inline Scene on_threads(Scene scene, int threads) {
  scene.integrator.threads = threads;
  return scene;
}

// Every grain where, and as fast, as in the reference run, to the bit.
inline void expect_same_bits(const Particles& reference, const Particles& other) {
  ASSERT_EQ(reference.size(), other.size());
  for (std::size_t i = 0; i < reference.size(); ++i) {
    ASSERT_EQ(reference.x[i], other.x[i]) << i;
    ASSERT_EQ(reference.y[i], other.y[i]) << i;
    ASSERT_EQ(reference.vy[i], other.vy[i]) << i;
  }
}

}  // namespace sedem::test
