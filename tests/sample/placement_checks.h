#pragma once

// Checks shared by the placement tests of every method.
#include <gtest/gtest.h>

#include "core/model/cylinder.h"
#include "core/model/particles.h"

namespace sedem::test {

// A small section that 3000 particles of 12 and 40 um cover by a third: dense enough that
// placement has to move points aside, small enough to check every pair by brute force.
inline Cylinder small_dense_section() {
  Cylinder c;
  c.height = 0.003;
  c.diameter = 0.002;
  return c;
}

// Every particle inside the walls, above the bottom and below the surface, and no two
// overlapping (brute force over every pair).
inline void expect_inside_and_apart(const Particles& p, const Cylinder& c) {
  for (std::size_t i = 0; i < p.size(); ++i) {
    const double r = 0.5 * p.diameter[i];
    ASSERT_GE(p.x[i] - r, -c.half_width());
    ASSERT_LE(p.x[i] + r, c.half_width());
    ASSERT_GE(p.y[i] - r, 0.0);
    ASSERT_LE(p.y[i] + r, c.height);
    for (std::size_t j = 0; j < i; ++j) {
      const double dx = p.x[i] - p.x[j], dy = p.y[i] - p.y[j];
      const double touch = r + 0.5 * p.diameter[j];
      ASSERT_GE(dx * dx + dy * dy, touch * touch) << i << " overlaps " << j;
    }
  }
}

}  // namespace sedem::test
