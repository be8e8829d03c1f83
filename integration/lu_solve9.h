// The 9x9 LU factorisation with partial pivoting, its solve, and the 9x9
// matrix-vector update the Schur solver needs, in plain loops over
// compile-time sizes.
//
// Eigen sends 9x9 triangular solves and matrix-vector products through its
// general run-time-size kernels (it unrolls only up to 8), which made the
// linear solves a tenth of an evaluation, and its PartialPivLU also computes
// an L1 norm the solver never reads. These loops do the same arithmetic in the
// same order as Eigen 3.4's kernels on SSE2 doubles (no FMA), so the results
// are bit-identical and so are the walkers' trajectories:
// - PartialPivLU's unblocked factorisation, for each column k: the pivot is
//   the first entry of largest magnitude on or below the diagonal; unless it
//   is zero the rows are swapped and the column below it divided by it; then
//   the rank-1 update of the lower right block;
// - the column-major matrix-vector kernel accumulates each row as
//   c = 0, c += A(i,j) b(j) for j ascending, then res(i) += alpha c;
// - the triangular solver works in panels of EIGEN_TUNE_TRIANGULAR_PANEL_WIDTH
//   (8) rows: column updates inside a panel (skipped when the solved entry is
//   exactly zero), the matrix-vector kernel for the rows past it.
// tests/integration/lu_solve9_test.cc checks all three against Eigen bit for bit.
// The loops are fully unrolled (the pragmas), which GCC does not do by itself
// for loops this long.
#pragma once

#include <array>
#include <cmath>

#include <Eigen/Core>

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

// P A = L U with L unit lower and U upper, stored together as Eigen's
// PartialPivLU stores them; P is the row swaps k <-> swaps[k], k = 0..8 in turn.
struct Lu9 {
  Mat9 lu;
  std::array<int, kNumCoords> swaps{};
  int first_zero_pivot = -1;  // the first column with U(k, k) = 0, or -1
};

// Factors out->lu in place: the caller writes the matrix there (a 9x9 copy
// through Eigen is a loop behind a call, not unrolled).
inline void FactorLu9(Lu9* out) {
  Mat9& lu = out->lu;
  out->first_zero_pivot = -1;
  #pragma GCC unroll 8
  for (int k = 0; k < kNumCoords - 1; ++k) {
    int pivot = k;
    double biggest = std::fabs(lu(k, k));
    for (int i = k + 1; i < kNumCoords; ++i) {
      if (std::fabs(lu(i, k)) > biggest) {
        biggest = std::fabs(lu(i, k));
        pivot = i;
      }
    }
    out->swaps[k] = pivot;
    if (biggest != 0.0) {
      if (pivot != k) lu.row(k).swap(lu.row(pivot));
      const double diagonal = lu(k, k);
      for (int i = k + 1; i < kNumCoords; ++i) lu(i, k) /= diagonal;
    } else if (out->first_zero_pivot == -1) {
      out->first_zero_pivot = k;
    }
    for (int j = k + 1; j < kNumCoords; ++j) {
      for (int i = k + 1; i < kNumCoords; ++i) lu(i, j) -= lu(i, k) * lu(k, j);
    }
  }
  constexpr int kLast = kNumCoords - 1;
  out->swaps[kLast] = kLast;
  if (lu(kLast, kLast) == 0.0 && out->first_zero_pivot == -1) out->first_zero_pivot = kLast;
}

// A^{-1} b from the factors
inline Vec9 SolveLu9(const Lu9& factors, const Vec9& b) {
  static_assert(EIGEN_TUNE_TRIANGULAR_PANEL_WIDTH == 8, "the loops below follow Eigen's panels of 8");
  constexpr int kPanel = 8;
  const Mat9& m = factors.lu;
  Vec9 x = b;
  for (int k = 0; k < kNumCoords; ++k) std::swap(x(k), x(factors.swaps[k]));

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
