#include "core/invert/reading_bounds.h"

#include <ClpSimplex.hpp>
#include <algorithm>

namespace sedem::invert {

ReadingBounds reading_bounds(const Eigen::MatrixXd& j, const Eigen::VectorXd& offset,
                             const Eigen::VectorXd& measured, const Eigen::VectorXd& tolerance,
                             double total) {
  const int m = int(j.rows()), n = int(j.cols());
  // Rows: each reading within its tolerance, then the shares' sum. Columns dense.
  std::vector<CoinBigIndex> start;
  std::vector<int> index;
  std::vector<double> value;
  for (int c = 0; c < n; ++c) {
    start.push_back(CoinBigIndex(index.size()));
    for (int r = 0; r < m; ++r) {
      index.push_back(r);
      value.push_back(j(r, c));
    }
    index.push_back(m);
    value.push_back(1.0);
  }
  start.push_back(CoinBigIndex(index.size()));
  std::vector<double> row_lo, row_hi;
  for (int r = 0; r < m; ++r) {
    row_lo.push_back(measured(r) - offset(r) - tolerance(r));
    row_hi.push_back(measured(r) - offset(r) + tolerance(r));
  }
  row_lo.push_back(total);
  row_hi.push_back(total);
  const std::vector<double> col_lo(std::size_t(n), 0.0), col_hi(std::size_t(n), COIN_DBL_MAX);
  std::vector<double> objective(std::size_t(n), 0.0);

  ClpSimplex lp;
  lp.setLogLevel(0);
  lp.loadProblem(n, m + 1, start.data(), index.data(), value.data(), col_lo.data(), col_hi.data(),
                 objective.data(), row_lo.data(), row_hi.data());
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
