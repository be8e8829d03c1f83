#include "integration/lu_solve9.h"

#include <cstring>
#include <random>

#include <Eigen/LU>
#include <gtest/gtest.h>

namespace walkers {
namespace {

::testing::AssertionResult SameBits(const Vec9& a, const Vec9& b) {
  if (std::memcmp(a.data(), b.data(), sizeof(double) * kNumCoords) == 0) return ::testing::AssertionSuccess();
  return ::testing::AssertionFailure() << "\n" << a.transpose() << "\nvs Eigen\n" << b.transpose();
}

// Newton-matrix-like systems: a unit diagonal plus entries from tiny to huge,
// some exact zeros in the right-hand side (the solver skips those columns)
struct RandomSystem {
  Mat9 a;
  Vec9 b;
};
RandomSystem MakeSystem(unsigned seed) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> unit(-1.0, 1.0);
  std::uniform_int_distribution<int> decade(-6, 6);
  RandomSystem s;
  for (int j = 0; j < kNumCoords; ++j) {
    for (int i = 0; i < kNumCoords; ++i) s.a(i, j) = unit(rng) * std::pow(10.0, decade(rng)) + (i == j ? 1.0 : 0.0);
    s.b(j) = seed % 3 == 0 && j % 4 == 1 ? 0.0 : unit(rng) * std::pow(10.0, decade(rng));
  }
  return s;
}

Lu9 Factor(const Mat9& a) {
  Lu9 f;
  f.lu = a;
  FactorLu9(&f);
  return f;
}

// the first zero on U's diagonal as Eigen leaves it, or -1
int FirstZeroPivot(const Eigen::PartialPivLU<Mat9>& lu) {
  for (int k = 0; k < kNumCoords; ++k) {
    if (lu.matrixLU()(k, k) == 0.0) return k;
  }
  return -1;
}

TEST(LuSolve9Test, FactorsLikeEigenPartialPivLuBitForBit) {
  for (unsigned seed = 1; seed <= 500; ++seed) {
    const RandomSystem s = MakeSystem(seed);
    const Eigen::PartialPivLU<Mat9> eigen(s.a);
    const Lu9 ours = Factor(s.a);
    ASSERT_EQ(std::memcmp(ours.lu.data(), eigen.matrixLU().data(), sizeof(Mat9)), 0) << "seed " << seed;
    // the same row permutation: it moves the rows of the identity alike
    Mat9 permuted = Mat9::Identity();
    for (int k = 0; k < kNumCoords; ++k) permuted.row(k).swap(permuted.row(ours.swaps[k]));
    ASSERT_EQ(permuted, eigen.permutationP() * Mat9::Identity()) << "seed " << seed;
    ASSERT_EQ(ours.first_zero_pivot, -1) << "seed " << seed;
  }
}

TEST(LuSolve9Test, ReportsTheFirstZeroPivotLikeEigen) {
  // a zero column, then also a zero last row: singular at column 3, Eigen
  // carries on past the zero pivot and so must the copy
  Mat9 a = MakeSystem(7).a;
  a.col(3).setZero();
  const Lu9 ours = Factor(a);
  const Eigen::PartialPivLU<Mat9> eigen(a);
  EXPECT_EQ(ours.first_zero_pivot, 3);
  EXPECT_EQ(FirstZeroPivot(eigen), 3);
  EXPECT_EQ(std::memcmp(ours.lu.data(), eigen.matrixLU().data(), sizeof(Mat9)), 0);

  Mat9 last = Mat9::Identity();
  last(kNumCoords - 1, kNumCoords - 1) = 0.0;
  EXPECT_EQ(Factor(last).first_zero_pivot, kNumCoords - 1);
}

TEST(LuSolve9Test, SolvesLikeEigenPartialPivLuBitForBit) {
  for (unsigned seed = 1; seed <= 500; ++seed) {
    const RandomSystem s = MakeSystem(seed);
    const Vec9 eigen = Eigen::PartialPivLU<Mat9>(s.a).solve(s.b);
    ASSERT_TRUE(SameBits(SolveLu9(Factor(s.a), s.b), eigen)) << "seed " << seed;
  }
}

TEST(LuSolve9Test, SolvesTheSystem) {
  const RandomSystem s = MakeSystem(42);
  const Vec9 x = SolveLu9(Factor(s.a), s.b);
  EXPECT_LT((s.a * x - s.b).norm(), 1e-9 * (s.a.norm() * x.norm() + s.b.norm()));
}

TEST(LuSolve9Test, SubtractProductMatchesEigenBitForBit) {
  for (unsigned seed = 1; seed <= 500; ++seed) {
    const RandomSystem s = MakeSystem(seed), t = MakeSystem(seed + 1000);
    Vec9 eigen = t.b, ours = t.b;
    eigen.noalias() -= s.a * s.b;
    SubtractProduct(s.a, s.b, &ours);
    ASSERT_TRUE(SameBits(ours, eigen)) << "seed " << seed;
  }
}

}  // namespace
}  // namespace walkers
