#pragma once

#include <Eigen/Dense>
#include <vector>

namespace sedem::invert {

// What the readings alone say about the curve: at each grid node, the least and the most
// percent finer of any non-negative set of bin shares summing to `total` whose readings, modelled
// as offset + J x, stay within `tolerance` of the measured ones (strict bounds: no prior, no
// smoothing). Where the two are far apart the readings cannot tell the curves between them
// apart, and any inverted curve there is its prior's choice. Each bound is a linear programme
// (COIN-OR Clp's dual simplex, warm-started from the previous node's).
struct ReadingBounds {
  std::vector<double> lower, upper;  // % finer at the nodes (bins - 1 of them)
  bool feasible = false;             // false: no curve meets the tolerance; lower/upper empty
};

ReadingBounds reading_bounds(const Eigen::MatrixXd& j, const Eigen::VectorXd& offset,
                             const Eigen::VectorXd& measured, const Eigen::VectorXd& tolerance,
                             double total = 1.0);

// The same where a bin's response is known only to lie between two values, as when its mass
// may sit anywhere inside it: reading i of bin shares x may be anything from offset + j_low x
// to offset + j_high x (row by row), and a curve is kept when that range comes within the
// tolerance of the measured reading. Every curve whose bins' responses do lie between the
// two is kept, wherever inside its bins its mass sits.
ReadingBounds reading_bounds(const Eigen::MatrixXd& j_low, const Eigen::MatrixXd& j_high,
                             const Eigen::VectorXd& offset, const Eigen::VectorXd& measured,
                             const Eigen::VectorXd& tolerance, double total = 1.0);

}  // namespace sedem::invert
