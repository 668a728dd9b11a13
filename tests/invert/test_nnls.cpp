// The non-negative least-squares solver against problems with known solutions and against
// its optimality (KKT) conditions.
#include <gtest/gtest.h>

#include <random>

#include "core/invert/nnls.h"

namespace sedem::invert {
namespace {

TEST(Nnls, UnconstrainedSolutionWhenPositive) {
  Eigen::MatrixXd a(3, 2);
  a << 1, 0, 0, 1, 1, 1;
  const Eigen::VectorXd x_true = Eigen::Vector2d(2, 3);
  const auto r = nnls(a, a * x_true);
  ASSERT_TRUE(r.converged);
  EXPECT_NEAR(r.x(0), 2, 1e-12);
  EXPECT_NEAR(r.x(1), 3, 1e-12);
}

TEST(Nnls, ClampsANegativeComponent) {
  // min (x0 - 1)^2 + (x1 + 1)^2: x = (1, 0).
  const Eigen::MatrixXd a = Eigen::MatrixXd::Identity(2, 2);
  const auto r = nnls(a, Eigen::Vector2d(1, -1));
  EXPECT_NEAR(r.x(0), 1, 1e-12);
  EXPECT_EQ(r.x(1), 0);
}

TEST(Nnls, SatisfiesKktOnRandomProblems) {
  std::mt19937_64 rng(3);
  std::normal_distribution<double> g;
  for (int trial = 0; trial < 50; ++trial) {
    Eigen::MatrixXd a(12, 8);
    Eigen::VectorXd b(12);
    for (Eigen::Index i = 0; i < a.size(); ++i) a.data()[i] = g(rng);
    for (Eigen::Index i = 0; i < b.size(); ++i) b(i) = g(rng);
    const auto r = nnls(a, b);
    ASSERT_TRUE(r.converged) << trial;
    const Eigen::VectorXd w = a.transpose() * (b - a * r.x);
    for (Eigen::Index j = 0; j < 8; ++j) {
      EXPECT_GE(r.x(j), 0);
      EXPECT_LE(w(j), 1e-9) << trial;  // no descent direction left
      if (r.x(j) > 0) {
        EXPECT_NEAR(w(j), 0, 1e-9) << trial;  // stationary where free
      }
    }
  }
}

}  // namespace
}  // namespace sedem::invert
