#include "core/invert/reading_bounds.h"

#include <ClpSimplex.hpp>
#include <algorithm>

namespace sedem::invert {

ReadingBounds reading_bounds(const Eigen::MatrixXd& j, const Eigen::VectorXd& offset,
                             const Eigen::VectorXd& measured, const Eigen::VectorXd& tolerance,
                             double total) {
  return reading_bounds(j, j, offset, measured, tolerance, total);
}

ReadingBounds reading_bounds(const Eigen::MatrixXd& j_low, const Eigen::MatrixXd& j_high,
                             const Eigen::VectorXd& offset, const Eigen::VectorXd& measured,
                             const Eigen::VectorXd& tolerance, double total) {
  const int m = int(j_low.rows()), n = int(j_low.cols());
  // Rows: per reading, the least response no more than the measured value plus the
  // tolerance and the most no less than it less the tolerance (one row where the two are
  // the same matrix); then the shares' sum. Columns dense.
  const bool same = &j_low == &j_high || j_low == j_high;
  const int rows = same ? m : 2 * m;
  std::vector<CoinBigIndex> start;
  std::vector<int> index;
  std::vector<double> value;
  for (int c = 0; c < n; ++c) {
    start.push_back(CoinBigIndex(index.size()));
    for (int r = 0; r < m; ++r) {
      index.push_back(r);
      value.push_back(j_low(r, c));
    }
    if (!same)
      for (int r = 0; r < m; ++r) {
        index.push_back(m + r);
        value.push_back(j_high(r, c));
      }
    index.push_back(rows);
    value.push_back(1.0);
  }
  start.push_back(CoinBigIndex(index.size()));
  std::vector<double> row_lo, row_hi;
  for (int r = 0; r < m; ++r) {
    row_lo.push_back(same ? measured(r) - offset(r) - tolerance(r) : -COIN_DBL_MAX);
    row_hi.push_back(measured(r) - offset(r) + tolerance(r));
  }
  if (!same)
    for (int r = 0; r < m; ++r) {
      row_lo.push_back(measured(r) - offset(r) - tolerance(r));
      row_hi.push_back(COIN_DBL_MAX);
    }
  row_lo.push_back(total);
  row_hi.push_back(total);
  const std::vector<double> col_lo(std::size_t(n), 0.0), col_hi(std::size_t(n), COIN_DBL_MAX);
  std::vector<double> objective(std::size_t(n), 0.0);

  ClpSimplex lp;
  lp.setLogLevel(0);
  lp.loadProblem(n, rows + 1, start.data(), index.data(), value.data(), col_lo.data(),
                 col_hi.data(), objective.data(), row_lo.data(), row_hi.data());
  ReadingBounds out;
  // The percent finer at node k is 100 times the shares of bins 0..k: minimise it, then
  // maximise it, one more bin in the objective at each node.
  for (int k = 0; k + 1 < n; ++k) {
    lp.setObjectiveCoefficient(k, 1.0);
    double bound[2];
    for (int sense = 0; sense < 2; ++sense) {
      lp.setOptimizationDirection(sense == 0 ? 1.0 : -1.0);
      lp.dual();
      if (lp.status() != 0) return {};
      bound[sense] = std::clamp(100.0 * lp.objectiveValue() / total, 0.0, 100.0);
    }
    out.lower.push_back(bound[0]);
    out.upper.push_back(bound[1]);
  }
  out.feasible = true;
  return out;
}

}  // namespace sedem::invert
