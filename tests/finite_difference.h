// The one finite-difference helper of the test suite (central differences,
// step cbrt(eps) max(1, |x|)) and a matrix comparison that names the entry.
#pragma once

#include <cmath>
#include <limits>
#include <random>
#include <sstream>
#include <string>

#include <Eigen/Core>
#include <gtest/gtest.h>

namespace walkers::testing {

// d f / d x at x by central differences; f maps an N-vector to an M-vector.
template <int M, int N, typename F>
Eigen::Matrix<double, M, N> NumericalJacobian(const F& f, const Eigen::Matrix<double, N, 1>& x) {
  const double eps = std::cbrt(std::numeric_limits<double>::epsilon());
  Eigen::Matrix<double, M, N> J;
  for (int j = 0; j < N; ++j) {
    const double h = eps * std::max(1.0, std::abs(x(j)));
    Eigen::Matrix<double, N, 1> xp = x, xm = x;
    xp(j) += h;
    xm(j) -= h;
    const Eigen::Matrix<double, M, 1> fp = f(xp), fm = f(xm);
    J.col(j) = (fp - fm) / (xp(j) - xm(j));
  }
  return J;
}

// Every entry |expected - actual| <= tol; a failure names the entry.
template <typename A, typename B>
::testing::AssertionResult MatricesNear(const A& expected, const B& actual, double tol) {
  if (expected.rows() != actual.rows() || expected.cols() != actual.cols()) {
    return ::testing::AssertionFailure() << "shapes differ";
  }
  for (int i = 0; i < expected.rows(); ++i) {
    for (int j = 0; j < expected.cols(); ++j) {
      const double e = expected(i, j), a = actual(i, j);
      if (!(std::abs(e - a) <= tol)) {
        return ::testing::AssertionFailure() << "entry (" << i << ", " << j << "): expected " << e << ", actual "
                                             << a << ", |diff| " << std::abs(e - a) << " > " << tol;
      }
    }
  }
  return ::testing::AssertionSuccess();
}

// Tolerance of a central-difference derivative of a smooth function of O(1) scale.
constexpr double kFiniteDifferenceTolerance = 1e-7;

// Random vector with entries uniform in [lo, hi].
template <int N>
Eigen::Matrix<double, N, 1> RandomVector(std::mt19937& rng, double lo, double hi) {
  std::uniform_real_distribution<double> u(lo, hi);
  Eigen::Matrix<double, N, 1> x;
  for (int i = 0; i < N; ++i) x(i) = u(rng);
  return x;
}

}  // namespace walkers::testing
