#pragma once

#include <Eigen/Dense>

namespace sedem::invert {

struct NnlsResult {
  Eigen::VectorXd x;
  int iterations = 0;
  bool converged = false;
};

// Non-negative least squares, min ||A x - b|| subject to x >= 0, by the active-set method of
// Lawson and Hanson ("Solving Least Squares Problems", 1974, ch. 23), each passive-set
// subproblem solved by Householder QR. Debian 12 packages no C/C++ NNLS (Eigen 3.4.0 has
// none; its unsupported NNLS module came after 3.4), and the problems here are small (tens of
// unknowns), so the textbook method is enough.
// `start`, if not empty, is a guess of the solution (its positive entries the passive set):
// the method then starts from the least-squares solution on that set, pruned until it is
// feasible, which saves most iterations when a close problem was solved just before.
NnlsResult nnls(const Eigen::MatrixXd& a, const Eigen::VectorXd& b,
                const Eigen::VectorXd& start = {}, int max_iterations = 0);

}  // namespace sedem::invert
