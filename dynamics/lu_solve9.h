// Solves with a 9x9 Eigen::PartialPivLU, and the 9x9 matrix-vector update
// the Schur solver needs, in plain loops over compile-time sizes.
//
// Eigen sends 9x9 triangular solves and matrix-vector products through its
// general run-time-size kernels (it unrolls only up to 8), which made the
// linear solves a tenth of an evaluation. These loops do the same arithmetic
// in the same order as Eigen 3.4's kernels on SSE2 doubles (no FMA), so the
// results are bit-identical and so are the walkers' trajectories:
// - the column-major matrix-vector kernel accumulates each row as
//   c = 0, c += A(i,j) b(j) for j ascending, then res(i) += alpha c;
// - the triangular solver works in panels of EIGEN_TUNE_TRIANGULAR_PANEL_WIDTH
//   (8) rows: column updates inside a panel (skipped when the solved entry is
//   exactly zero), the matrix-vector kernel for the rows past it.
// tests/dynamics/lu_solve9_test.cc checks both against Eigen bit for bit.
// The loops are fully unrolled (the pragmas), which GCC does not do by itself
// for loops this long.
#pragma once

#include <Eigen/Core>
#include <Eigen/LU>

#include "dynamics/coords.h"

namespace walkers {

// the term Eigen's column-major matrix-vector kernel adds to res(row) for
// alpha = -1: minus the sum of A(row, j) b(j), j = begin..end-1 ascending
inline double MinusRowProduct(const Mat9& A, int row, int begin, int end, const Vec9& b) {
  double c = 0.0;
  #pragma GCC unroll 9
  for (int j = begin; j < end; ++j) c += A(row, j) * b(j);
  return -1.0 * c;
}

// x -= A b
inline void SubtractProduct(const Mat9& A, const Vec9& b, Vec9* x) {
  #pragma GCC unroll 9
  for (int i = 0; i < kNumCoords; ++i) (*x)(i) += MinusRowProduct(A, i, 0, kNumCoords, b);
}

// P A = L U as Eigen's PartialPivLU stores it: returns A^{-1} b
inline Vec9 SolveLu9(const Eigen::PartialPivLU<Mat9>& lu, const Vec9& b) {
  static_assert(EIGEN_TUNE_TRIANGULAR_PANEL_WIDTH == 8, "the loops below follow Eigen's panels of 8");
  constexpr int kPanel = 8;
  const Mat9& m = lu.matrixLU();
  Vec9 x = lu.permutationP() * b;

  // L y = P b, L unit lower: the panel of rows 0..7, then row 8
  #pragma GCC unroll 9
  for (int i = 0; i < kPanel; ++i) {
    if (x(i) == 0.0) continue;
    #pragma GCC unroll 9
    for (int r = i + 1; r < kPanel; ++r) x(r) -= x(i) * m(r, i);
  }
  x(kPanel) += MinusRowProduct(m, kPanel, 0, kPanel, x);

  // U x = y: the panel of rows 8..1 from the bottom, then row 0
  #pragma GCC unroll 9
  for (int i = kPanel; i >= 1; --i) {
    if (x(i) == 0.0) continue;
    x(i) /= m(i, i);
    #pragma GCC unroll 9
    for (int r = 1; r < i; ++r) x(r) -= x(i) * m(r, i);
  }
  x(0) += MinusRowProduct(m, 0, 1, kPanel + 1, x);
  if (x(0) != 0.0) x(0) /= m(0, 0);
  return x;
}

}  // namespace walkers
