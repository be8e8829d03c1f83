// L D L^T factorisation and solves of the 9x9 mass matrix, in the order of the
// walker's tree: the left leg's three joints, the right leg's, then the trunk.
//
// The two legs are coupled only through the trunk, so the mass matrix's
// leg-left/leg-right block is zero. Eliminated leaves first, that zero block
// stays zero in L (no fill-in): the factorisation touches 45 - 9 = 36 of the
// 45 lower entries and needs no square root. In q's own order (trunk first) a
// Cholesky factor fills the block in. bench/dynamics_bench.cc, MassMatrixSolve
// compares this with Eigen's LLT and LDLT.
//
// The loops are written over the permuted indices and fully unrolled (GCC does
// not unroll nested loops of nine by itself); after unrolling, the `Coupled`
// tests are constants and the zero block's terms disappear.
#pragma once

#include "dynamics/coords.h"

namespace walkers {

class TreeLdlt9 {
 public:
  // Factors M = P L D L^T P^T. Returns false unless every pivot of D is
  // positive (M not positive definite, or not finite).
  bool Compute(const Mat9& M) {
    #pragma GCC unroll 9
    for (int j = 0; j < kNumCoords; ++j) {
      double d = M(kTreeOrder[j], kTreeOrder[j]);
      #pragma GCC unroll 9
      for (int k = 0; k < j; ++k) {
        if (Coupled(j, k)) d -= L_(j, k) * Ld_(j, k);
      }
      if (!(d > 0.0)) return ok_ = false;
      inv_d_(j) = 1.0 / d;
      #pragma GCC unroll 9
      for (int i = j + 1; i < kNumCoords; ++i) {
        if (!Coupled(i, j)) continue;
        double s = M(kTreeOrder[i], kTreeOrder[j]);
        #pragma GCC unroll 9
        for (int k = 0; k < j; ++k) {
          if (Coupled(i, k) && Coupled(j, k)) s -= L_(i, k) * Ld_(j, k);
        }
        Ld_(i, j) = s;  // L(i, j) d(j)
        L_(i, j) = s * inv_d_(j);
      }
    }
    return ok_ = true;
  }

  bool ok() const { return ok_; }

  // Solves M x = b in place.
  void SolveInPlace(Vec9* b) const {
    Vec9 y;
    #pragma GCC unroll 9
    for (int i = 0; i < kNumCoords; ++i) y(i) = (*b)(kTreeOrder[i]);
    // L z = y
    #pragma GCC unroll 9
    for (int i = 0; i < kNumCoords; ++i) {
      double s = y(i);
      #pragma GCC unroll 9
      for (int k = 0; k < i; ++k) {
        if (Coupled(i, k)) s -= L_(i, k) * y(k);
      }
      y(i) = s;
    }
    // D L^T x = z
    #pragma GCC unroll 9
    for (int i = kNumCoords - 1; i >= 0; --i) {
      double s = y(i) * inv_d_(i);
      #pragma GCC unroll 9
      for (int k = i + 1; k < kNumCoords; ++k) {
        if (Coupled(k, i)) s -= L_(k, i) * y(k);
      }
      y(i) = s;
    }
    #pragma GCC unroll 9
    for (int i = 0; i < kNumCoords; ++i) (*b)(kTreeOrder[i]) = y(i);
  }

  // Solves M X = B in place for a 9 x Cols B, one row of B at a time
  // (contiguous rows), with the same arithmetic per column as the vector solve.
  template <int Cols>
  void SolveInPlace(Eigen::Matrix<double, kNumCoords, Cols>* B) const {
    Eigen::Matrix<double, kNumCoords, Cols, Cols == 1 ? Eigen::ColMajor : Eigen::RowMajor> Y;
    #pragma GCC unroll 9
    for (int i = 0; i < kNumCoords; ++i) Y.row(i) = B->row(kTreeOrder[i]);
    #pragma GCC unroll 9
    for (int i = 0; i < kNumCoords; ++i) {
      #pragma GCC unroll 9
      for (int k = 0; k < i; ++k) {
        if (Coupled(i, k)) Y.row(i) -= L_(i, k) * Y.row(k);
      }
    }
    #pragma GCC unroll 9
    for (int i = kNumCoords - 1; i >= 0; --i) {
      Y.row(i) *= inv_d_(i);
      #pragma GCC unroll 9
      for (int k = i + 1; k < kNumCoords; ++k) {
        if (Coupled(k, i)) Y.row(i) -= L_(k, i) * Y.row(k);
      }
    }
    #pragma GCC unroll 9
    for (int i = 0; i < kNumCoords; ++i) B->row(kTreeOrder[i]) = Y.row(i);
  }

  // Position p of the elimination holds coordinate kTreeOrder[p].
  static constexpr int kTreeOrder[kNumCoords] = {kHipL, kKneeL, kAnkleL, kHipR,  kKneeR,
                                                 kAnkleR, kX,  kY,    kPitch};

 private:
  // Whether position `later` of the elimination order may share a nonzero
  // entry with the earlier position `earlier`: both in the same body group
  // (left leg, right leg, trunk), or the later one in the trunk (eliminated
  // last, coupled to everything).
  static constexpr bool Coupled(int later, int earlier) {
    constexpr int kTrunkGroup = 2;
    return later / 3 == earlier / 3 || later / 3 == kTrunkGroup;
  }

  Mat9 L_ = Mat9::Identity();   // unit lower triangle, in elimination order
  Mat9 Ld_ = Mat9::Zero();      // L(i, j) d(j), kept to save a product per term
  Vec9 inv_d_ = Vec9::Ones();  // 1 / D
  bool ok_ = false;
};

}  // namespace walkers
