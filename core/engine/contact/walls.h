#pragma once

// The column's walls: two sides at x = -half_width and x = +half_width and the floor at y = 0.
// The gaps are written once here so that the force pass and the contact projection measure a
// grain against the walls with the same operations, to the bit.

#include <cmath>

namespace sedem {

struct Walls {
  double half_width = 0;

  // How far a disc of radius r at (x, y) reaches into each wall (positive: overlap).
  struct Gaps {
    double left, right, bottom;
  };
  Gaps gaps(double x, double y, double r) const {
    return {-half_width - (x - r), x + r - half_width, r - y};
  }
  // The deeper of the two side overlaps, as |x| + r - half_width: the projection's report of the
  // overlaps left after a step (it rounds differently from max(left, right); kept as it was).
  double side_depth(double x, double r) const { return std::abs(x) + r - half_width; }
};

}  // namespace sedem
