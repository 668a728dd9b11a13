#include "core/invert/nnls.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

namespace sedem::invert {

namespace {

// The least-squares solution on the passive columns, zero elsewhere.
Eigen::VectorXd passive_solution(const Eigen::MatrixXd& a, const Eigen::VectorXd& b,
                                 const std::vector<bool>& passive) {
  std::vector<Eigen::Index> columns;
  for (Eigen::Index j = 0; j < a.cols(); ++j)
    if (passive[std::size_t(j)]) columns.push_back(j);
  Eigen::MatrixXd sub(a.rows(), Eigen::Index(columns.size()));
  for (std::size_t k = 0; k < columns.size(); ++k) sub.col(Eigen::Index(k)) = a.col(columns[k]);
  const Eigen::VectorXd z = sub.colPivHouseholderQr().solve(b);
  Eigen::VectorXd full = Eigen::VectorXd::Zero(a.cols());
  for (std::size_t k = 0; k < columns.size(); ++k) full(columns[k]) = z(Eigen::Index(k));
  return full;
}

}  // namespace

NnlsResult nnls(const Eigen::MatrixXd& a, const Eigen::VectorXd& b, const Eigen::VectorXd& start,
                int max_iterations) {
  const Eigen::Index n = a.cols();
  if (max_iterations <= 0) max_iterations = 3 * int(n) + 30;
  NnlsResult r;
  r.x = Eigen::VectorXd::Zero(n);
  std::vector<bool> passive(std::size_t(n), false);
  if (start.size() == n) {
    // Warm start: the guess's support, less whatever its least-squares solution makes
    // non-positive, until that solution is feasible; it is then a valid starting point.
    for (Eigen::Index j = 0; j < n; ++j) passive[std::size_t(j)] = start(j) > 0;
    for (Eigen::Index round = 0; round <= n; ++round) {
      const Eigen::VectorXd z = passive_solution(a, b, passive);
      bool feasible = true;
      for (Eigen::Index j = 0; j < n; ++j)
        if (passive[std::size_t(j)] && !(z(j) > 0)) {
          passive[std::size_t(j)] = false;
          feasible = false;
        }
      if (feasible) {
        r.x = z;
        break;
      }
    }
  }
  // Lawson-Hanson's tolerance on the gradient: relative to the scale of A^T b.
  const double tol = 10.0 * std::numeric_limits<double>::epsilon() * double(n) *
                     std::max(1.0, (a.transpose() * b).cwiseAbs().maxCoeff());
  for (r.iterations = 0; r.iterations < max_iterations; ++r.iterations) {
    const Eigen::VectorXd w = a.transpose() * (b - a * r.x);
    Eigen::Index best = -1;
    double best_w = tol;
    for (Eigen::Index j = 0; j < n; ++j)
      if (!passive[std::size_t(j)] && w(j) > best_w) {
        best_w = w(j);
        best = j;
      }
    if (best < 0) {
      r.converged = true;
      return r;
    }
    passive[std::size_t(best)] = true;
    for (int inner = 0; inner <= int(n); ++inner) {
      const Eigen::VectorXd z = passive_solution(a, b, passive);
      bool feasible = true;
      double alpha = 1.0;
      for (Eigen::Index j = 0; j < n; ++j)
        if (passive[std::size_t(j)] && z(j) <= 0) {
          feasible = false;
          const double step = r.x(j) / (r.x(j) - z(j));
          alpha = std::min(alpha, std::isfinite(step) ? step : 0.0);
        }
      if (feasible) {
        r.x = z;
        break;
      }
      r.x += alpha * (z - r.x);
      for (Eigen::Index j = 0; j < n; ++j)
        if (passive[std::size_t(j)] && r.x(j) <= 1e-14) {
          passive[std::size_t(j)] = false;
          r.x(j) = 0;
        }
    }
  }
  return r;
}

}  // namespace sedem::invert
