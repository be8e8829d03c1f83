#include "dynamics/lu_solve9.h"

#include <cstring>
#include <random>

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

TEST(LuSolve9Test, MatchesEigenPartialPivLuBitForBit) {
  for (unsigned seed = 1; seed <= 500; ++seed) {
    const RandomSystem s = MakeSystem(seed);
    const Eigen::PartialPivLU<Mat9> lu(s.a);
    const Vec9 eigen = lu.solve(s.b);
    ASSERT_TRUE(SameBits(SolveLu9(lu, s.b), eigen)) << "seed " << seed;
  }
}

TEST(LuSolve9Test, SolvesTheSystem) {
  const RandomSystem s = MakeSystem(42);
  const Vec9 x = SolveLu9(Eigen::PartialPivLU<Mat9>(s.a), s.b);
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
