// Cholesky factorisation and solves for the 9x9 mass matrix. Eigen's LLT
// routes fixed-size 9x9 problems through its general (blocked, dynamic-size)
// triangular kernels; these plain loops over compile-time sizes are several
// times faster at this size (bench/dynamics_bench.cc, MassMatrixSolve). GCC
// does not unroll the nested loops by itself; fully unrolled (the pragmas)
// the same arithmetic takes 122 ns instead of 215 ns per factorisation and
// solve, with bit-identical results.
#pragma once

#include <cmath>

#include "dynamics/coords.h"

namespace walkers {

class Cholesky9 {
 public:
  // Factors M = L L^T. Returns false if M is not positive definite.
  bool Compute(const Mat9& M) {
    L_ = M;
    #pragma GCC unroll 9
    for (int j = 0; j < kNumCoords; ++j) {
      double d = L_(j, j);
      #pragma GCC unroll 9
      for (int k = 0; k < j; ++k) d -= L_(j, k) * L_(j, k);
      if (!(d > 0.0)) return ok_ = false;
      const double ljj = std::sqrt(d);
      L_(j, j) = ljj;
      inv_diag_(j) = 1.0 / ljj;
      #pragma GCC unroll 9
      for (int i = j + 1; i < kNumCoords; ++i) {
        double s = L_(i, j);
        #pragma GCC unroll 9
        for (int k = 0; k < j; ++k) s -= L_(i, k) * L_(j, k);
        L_(i, j) = s * inv_diag_(j);
      }
    }
    return ok_ = true;
  }

  bool ok() const { return ok_; }

  // Solves M x = b in place.
  void SolveInPlace(Vec9* b) const {
    Vec9& x = *b;
    // forward: L y = b
    #pragma GCC unroll 9
    for (int i = 0; i < kNumCoords; ++i) {
      double s = x(i);
      #pragma GCC unroll 9
      for (int k = 0; k < i; ++k) s -= L_(i, k) * x(k);
      x(i) = s * inv_diag_(i);
    }
    // backward: L^T x = y
    #pragma GCC unroll 9
    for (int i = kNumCoords - 1; i >= 0; --i) {
      double s = x(i);
      #pragma GCC unroll 9
      for (int k = i + 1; k < kNumCoords; ++k) s -= L_(k, i) * x(k);
      x(i) = s * inv_diag_(i);
    }
  }

  // Solves M X = B in place for a 9x9 B, on contiguous rows.
  void SolveInPlace(Mat9* B) const {
    Eigen::Matrix<double, kNumCoords, kNumCoords, Eigen::RowMajor> X = *B;
    #pragma GCC unroll 9
    for (int i = 0; i < kNumCoords; ++i) {
      #pragma GCC unroll 9
      for (int k = 0; k < i; ++k) X.row(i) -= L_(i, k) * X.row(k);
      X.row(i) *= inv_diag_(i);
    }
    #pragma GCC unroll 9
    for (int i = kNumCoords - 1; i >= 0; --i) {
      #pragma GCC unroll 9
      for (int k = i + 1; k < kNumCoords; ++k) X.row(i) -= L_(k, i) * X.row(k);
      X.row(i) *= inv_diag_(i);
    }
    *B = X;
  }

 private:
  Mat9 L_ = Mat9::Identity();
  Vec9 inv_diag_ = Vec9::Ones();
  bool ok_ = false;
};

}  // namespace walkers
