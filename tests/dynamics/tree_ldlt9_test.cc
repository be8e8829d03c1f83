#include "dynamics/tree_ldlt9.h"

#include <cmath>
#include <cstring>
#include <limits>
#include <random>

#include <Eigen/Cholesky>
#include <gtest/gtest.h>

#include "control/genome.h"
#include "dynamics/equations_of_motion.h"
#include "tests/dynamics/default_walker_test.h"
#include "tests/finite_difference.h"

namespace walkers {
namespace {

class TreeLdlt9Test : public testing::DefaultWalkerTest {
 protected:
  TreeLdlt9Test() : DefaultWalkerTest(7) {}

  Vec9 RandomB() { return testing::RandomVector<kNumCoords>(rng_, -100.0, 100.0); }
};

// the factorisation leaves out the left-leg/right-leg block: it must be zero
TEST_F(TreeLdlt9Test, MassMatrixDoesNotCoupleTheLegs) {
  for (int trial = 0; trial < 20; ++trial) {
    const Mat9 M = MassMatrix(model_, RandomQ());
    for (int a = 0; a < kNumJoints; ++a) {
      for (int b = 0; b < kNumJoints; ++b) {
        ASSERT_EQ(M(JointIndex(kLeft, a), JointIndex(kRight, b)), 0.0) << "trial " << trial;
        ASSERT_EQ(M(JointIndex(kRight, b), JointIndex(kLeft, a)), 0.0) << "trial " << trial;
      }
    }
  }
}

TEST_F(TreeLdlt9Test, SolvesMassMatrixSystemsLikeEigen) {
  for (int trial = 0; trial < 200; ++trial) {
    Mat9 M = MassMatrix(model_, RandomQ());
    if (trial % 4 == 0) {  // a locked coordinate, as ForwardDynamics masks it
      const int i = trial % kNumCoords;
      M.row(i).setZero();
      M.col(i).setZero();
      M(i, i) = 1.0;
    }
    const Vec9 b = RandomB();
    TreeLdlt9 ours;
    ASSERT_TRUE(ours.Compute(M)) << "trial " << trial;
    Vec9 x = b;
    ours.SolveInPlace(&x);
    const Vec9 expected = Eigen::LDLT<Mat9>(M).solve(b);
    ASSERT_LE((x - expected).norm(), 1e-10 * expected.norm()) << "trial " << trial << "\n"
                                                              << x.transpose() << "\n"
                                                              << expected.transpose();
    ASSERT_LE((M * x - b).norm(), 1e-12 * (M.norm() * x.norm() + b.norm())) << "trial " << trial;
  }
}

// the Jacobian's matrix solve does the vector solve's arithmetic, column by column
TEST_F(TreeLdlt9Test, MatrixSolveIsTheVectorSolveOfEachColumnBitForBit) {
  for (int trial = 0; trial < 20; ++trial) {
    TreeLdlt9 ldlt;
    ASSERT_TRUE(ldlt.Compute(MassMatrix(model_, RandomQ())));
    Mat9 B;
    for (int j = 0; j < kNumCoords; ++j) B.col(j) = RandomB();
    Mat9 X = B;
    ldlt.SolveInPlace(&X);
    for (int j = 0; j < kNumCoords; ++j) {
      Vec9 x = B.col(j);
      ldlt.SolveInPlace(&x);
      const Vec9 xj = X.col(j);
      ASSERT_EQ(std::memcmp(x.data(), xj.data(), sizeof(Vec9)), 0) << "trial " << trial << " column " << j;
    }
  }
}

TEST_F(TreeLdlt9Test, RejectsMatricesThatAreNotPositiveDefinite) {
  const Mat9 M = MassMatrix(model_, RandomQ());
  TreeLdlt9 ldlt;
  ASSERT_TRUE(ldlt.Compute(M));
  EXPECT_TRUE(ldlt.ok());

  for (int i = 0; i < kNumCoords; ++i) {
    Mat9 negative = M;
    negative(i, i) = -1.0;
    EXPECT_FALSE(ldlt.Compute(negative)) << "coordinate " << i;
    EXPECT_FALSE(ldlt.ok());
  }

  // positive diagonal, but a trunk pivot goes negative once the legs are eliminated
  Mat9 indefinite = M;
  indefinite(kHipL, kX) = indefinite(kX, kHipL) = 10.0 * std::sqrt(M(kHipL, kHipL) * M(kX, kX));
  EXPECT_FALSE(ldlt.Compute(indefinite));

  Mat9 not_finite = M;
  not_finite(kKneeR, kKneeR) = std::numeric_limits<double>::quiet_NaN();
  EXPECT_FALSE(ldlt.Compute(not_finite));
}

}  // namespace
}  // namespace walkers
