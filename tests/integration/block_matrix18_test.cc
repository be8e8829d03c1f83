#include "integration/block_matrix18.h"

#include <cmath>
#include <cstring>
#include <limits>
#include <random>
#include <stdexcept>

#include <Eigen/Core>
#include <gtest/gtest.h>

#include "control/genome.h"
#include "control/start_pose.h"
#include "integration/fixed_size_ops.h"
#include "integration/integrator.h"
#include "dynamics/observation.h"
#include "integration/schur_linear_solver.h"
#include "tests/integration/sundials_handles.h"

#include <nvector/nvector_serial.h>
#include <sundials/sundials_linearsolver.h>
#include <sundials/sundials_matrix.h>
#include <sunmatrix/sunmatrix_dense.h>

namespace walkers {
namespace {

// the dense matrix a block matrix stands for
Mat18 Dense(const Blocks18& b) {
  Mat18 m = Mat18::Zero();
  m.topLeftCorner<kHalf, kHalf>().diagonal() = b.d11;
  m.topRightCorner<kHalf, kHalf>().diagonal() = b.d12;
  m.bottomLeftCorner<kHalf, kHalf>() = b.m21;
  m.bottomRightCorner<kHalf, kHalf>() = b.m22;
  return m;
}

// bit for bit, so that -0 and +0 or two NaNs with different payloads differ
bool SameBits(const Mat18& a, const Mat18& b) { return std::memcmp(a.data(), b.data(), sizeof(double) * kN * kN) == 0; }
bool SameBits(const Vec18& a, const Vec18& b) { return std::memcmp(a.data(), b.data(), sizeof(double) * kN) == 0; }

// the walker's Jacobian shape, [[0, I], [A_q, A_v]], with random lower
// blocks on the scales of a stiff mechanical system
Blocks18 RandomJacobian(unsigned seed) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> unit(-1.0, 1.0);
  Blocks18 b;
  b.d12.setOnes();
  for (int j = 0; j < kHalf; ++j) {
    for (int i = 0; i < kHalf; ++i) {
      b.m21(i, j) = 1e4 * unit(rng);
      b.m22(i, j) = 1e2 * unit(rng);
    }
  }
  return b;
}

struct Fixture {
  ContextPtr context = NewContext();
  MatrixPtr blocks{MakeBlockMatrix18(context.get())};
  MatrixPtr dense{SUNDenseMatrix(kN, kN, context.get())};
};

TEST(BlockMatrix18Test, DescribesItselfAndKnowsItsOwn) {
  Fixture f;
  ASSERT_NE(f.blocks, nullptr);
  EXPECT_EQ(SUNMatGetID(f.blocks.get()), SUNMATRIX_CUSTOM);
  long lenrw = -1, leniw = -1;
  EXPECT_EQ(SUNMatSpace(f.blocks.get(), &lenrw, &leniw), SUNMAT_SUCCESS);
  EXPECT_EQ(lenrw, 2 * kHalf + 2 * kHalf * kHalf);
  EXPECT_EQ(leniw, 0);
  // a new matrix is zero
  ASSERT_NE(BlocksOf(f.blocks.get()), nullptr);
  EXPECT_TRUE(Dense(*BlocksOf(f.blocks.get())).isZero(0.0));
  // any other matrix is not ours, custom or not
  EXPECT_EQ(BlocksOf(f.dense.get()), nullptr);
  EXPECT_EQ(BlocksOf(nullptr), nullptr);
  MatrixPtr other_custom{SUNMatNewEmpty(f.context.get())};
  other_custom->ops->getid = [](SUNMatrix) { return SUNMATRIX_CUSTOM; };
  EXPECT_EQ(BlocksOf(other_custom.get()), nullptr);
  EXPECT_EQ(MakeBlockMatrix18(nullptr), nullptr);
}

TEST(BlockMatrix18Test, OperationsRejectOtherMatrices) {
  Fixture f;
  EXPECT_EQ(SUNMatCopy(f.dense.get(), f.blocks.get()), SUNMAT_ILL_INPUT);
  EXPECT_EQ(SUNMatCopy(f.blocks.get(), f.dense.get()), SUNMAT_ILL_INPUT);
  VectorPtr x{N_VNew_Serial(kN, f.context.get())}, short_vector{N_VNew_Serial(kN - 1, f.context.get())};
  EXPECT_EQ(SUNMatMatvec(f.blocks.get(), x.get(), short_vector.get()), SUNMAT_ILL_INPUT);
  EXPECT_EQ(SUNMatMatvec(f.blocks.get(), x.get(), x.get()), SUNMAT_ILL_INPUT);  // y = A y cannot be in place
}

// CVODE forms its Newton matrix as c*J + I (c = -gamma) with SUNMatScaleAddI,
// keeps a saved J with SUNMatCopy and clears with SUNMatZero: each must give
// the dense matrix's bits, known zeros included
TEST(BlockMatrix18Test, ScaleAddIdentityCopyAndZeroGiveTheDenseMatrixsBits) {
  Fixture f;
  ASSERT_TRUE(UseFixedSizeMatrixOps(f.dense.get()));
  MatrixPtr library_dense{SUNDenseMatrix(kN, kN, f.context.get())};  // SUNDIALS' own operations
  for (unsigned seed = 1; seed <= 20; ++seed) {
    const Blocks18 jacobian = RandomJacobian(seed);
    const double c = -std::pow(10.0, -1.0 - 0.25 * seed);  // -gamma, 1e-1.25 .. 1e-6
    *BlocksOf(f.blocks.get()) = jacobian;
    Store(Dense(jacobian), f.dense.get());
    Store(Dense(jacobian), library_dense.get());

    // the saved Jacobian, a clone, then copied back (cvLsLinSys)
    MatrixPtr saved{SUNMatClone(f.blocks.get())};
    ASSERT_NE(BlocksOf(saved.get()), nullptr);
    ASSERT_EQ(SUNMatCopy(f.blocks.get(), saved.get()), SUNMAT_SUCCESS);
    ASSERT_EQ(SUNMatZero(f.blocks.get()), SUNMAT_SUCCESS);
    EXPECT_TRUE(Dense(*BlocksOf(f.blocks.get())).isZero(0.0));
    ASSERT_EQ(SUNMatCopy(saved.get(), f.blocks.get()), SUNMAT_SUCCESS);
    EXPECT_TRUE(SameBits(Dense(*BlocksOf(f.blocks.get())), Dense(jacobian)));

    ASSERT_EQ(SUNMatScaleAddI(c, f.blocks.get()), SUNMAT_SUCCESS);
    ASSERT_EQ(SUNMatScaleAddI(c, f.dense.get()), SUNMAT_SUCCESS);
    ASSERT_EQ(SUNMatScaleAddI(c, library_dense.get()), SUNMAT_SUCCESS);
    const Mat18 dense = Load(f.dense.get());
    EXPECT_TRUE(SameBits(dense, Load(library_dense.get()))) << "seed " << seed;
    // the stored entries bit for bit; the dense matrix holds c*0 = -0 where
    // the blocks store nothing
    Blocks18 stored;
    stored.d11 = dense.topLeftCorner<kHalf, kHalf>().diagonal();
    stored.d12 = dense.topRightCorner<kHalf, kHalf>().diagonal();
    stored.m21 = dense.bottomLeftCorner<kHalf, kHalf>();
    stored.m22 = dense.bottomRightCorner<kHalf, kHalf>();
    EXPECT_TRUE(SameBits(Dense(*BlocksOf(f.blocks.get())), Dense(stored))) << "seed " << seed;
    EXPECT_TRUE((dense - Dense(stored)).isZero(0.0)) << "seed " << seed;
  }
}

TEST(BlockMatrix18Test, MatrixVectorProductMatchesTheDenseMatrix) {
  Fixture f;
  const Blocks18 b = RandomJacobian(7);
  *BlocksOf(f.blocks.get()) = b;
  ASSERT_EQ(SUNMatScaleAddI(-1e-3, f.blocks.get()), SUNMAT_SUCCESS);
  VectorPtr x{N_VNew_Serial(kN, f.context.get())}, y{N_VNew_Serial(kN, f.context.get())};
  Vec18 xv = Vec18::LinSpaced(-1.0, 2.0);
  Store(xv, x.get());
  ASSERT_EQ(SUNMatMatvec(f.blocks.get(), x.get(), y.get()), SUNMAT_SUCCESS);
  const Vec18 expected = Dense(*BlocksOf(f.blocks.get())) * xv;
  const Vec18 got = Load(y.get());
  EXPECT_LT((got - expected).lpNorm<Eigen::Infinity>(), 1e-12 * expected.lpNorm<Eigen::Infinity>());
  EXPECT_GT(expected.lpNorm<Eigen::Infinity>(), 1.0);
}

// the Schur solver on the block matrix and on the dense one: the same
// factorisation and solutions, bit for bit
TEST(BlockMatrix18Test, SchurSolverGivesTheDenseMatrixsSolutionsBitForBit) {
  Fixture f;
  VectorPtr x{N_VNew_Serial(kN, f.context.get())}, b{N_VNew_Serial(kN, f.context.get())};
  SolverPtr on_blocks{MakeSchurLinearSolver(x.get(), f.blocks.get(), f.context.get())};
  SolverPtr on_dense{MakeSchurLinearSolver(x.get(), f.dense.get(), f.context.get())};
  ASSERT_NE(on_blocks, nullptr);
  ASSERT_NE(on_dense, nullptr);
  ASSERT_EQ(SUNLinSolInitialize(on_blocks.get()), SUNLS_SUCCESS);
  ASSERT_EQ(SUNLinSolInitialize(on_dense.get()), SUNLS_SUCCESS);
  std::mt19937 rng(11);
  std::uniform_real_distribution<double> unit(-1.0, 1.0);
  for (unsigned seed = 1; seed <= 20; ++seed) {
    const Blocks18 jacobian = RandomJacobian(100 + seed);
    const double c = -std::pow(10.0, -1.0 - 0.25 * seed);
    *BlocksOf(f.blocks.get()) = jacobian;
    Store(Dense(jacobian), f.dense.get());
    ASSERT_EQ(SUNMatScaleAddI(c, f.blocks.get()), SUNMAT_SUCCESS);
    ASSERT_EQ(SUNMatScaleAddI(c, f.dense.get()), SUNMAT_SUCCESS);
    ASSERT_EQ(SUNLinSolSetup(on_blocks.get(), f.blocks.get()), SUNLS_SUCCESS);
    ASSERT_EQ(SUNLinSolSetup(on_dense.get(), f.dense.get()), SUNLS_SUCCESS);

    Vec18 rhs;
    for (int i = 0; i < kN; ++i) rhs(i) = unit(rng);
    Store(rhs, b.get());
    ASSERT_EQ(SUNLinSolSolve(on_blocks.get(), f.blocks.get(), x.get(), b.get(), 0.0), SUNLS_SUCCESS);
    const Vec18 from_blocks = Load(x.get());
    ASSERT_EQ(SUNLinSolSolve(on_dense.get(), f.dense.get(), x.get(), b.get(), 0.0), SUNLS_SUCCESS);
    const Vec18 from_dense = Load(x.get());
    EXPECT_TRUE(SameBits(from_blocks, from_dense)) << "seed " << seed;
    // and it is a solution
    const Mat18 m = Dense(*BlocksOf(f.blocks.get()));
    EXPECT_LT((m * from_blocks - rhs).lpNorm<Eigen::Infinity>(), 1e-9) << "seed " << seed;
  }
}

TEST(BlockMatrix18Test, SchurSolverReportsANonFiniteBlockMatrixAsRecoverable) {
  Fixture f;
  VectorPtr x{N_VNew_Serial(kN, f.context.get())};
  SolverPtr solver{MakeSchurLinearSolver(x.get(), f.blocks.get(), f.context.get())};
  Blocks18 jacobian = RandomJacobian(3);
  jacobian.m21(4, 2) = std::numeric_limits<double>::quiet_NaN();
  *BlocksOf(f.blocks.get()) = jacobian;
  ASSERT_EQ(SUNMatScaleAddI(-1e-3, f.blocks.get()), SUNMAT_SUCCESS);
  EXPECT_EQ(SUNLinSolSetup(solver.get(), f.blocks.get()), SUNLS_PACKAGE_FAIL_REC);
  // and refuses to solve with the failed factorisation
  EXPECT_NE(SUNLinSolSolve(solver.get(), f.blocks.get(), x.get(), x.get(), 0.0), SUNLS_SUCCESS);
}

// the whole integration: 1.5 s of the limp walker on planted feet, then
// free, through contact, welds and a restart, bit for bit with either matrix
TEST(BlockMatrix18Test, IntegratorGivesTheDenseMatrixsTrajectoryBitForBit) {
  const Model m = BuildModel(BodyOf(DefaultGenome()));
  const State start = StartState(m);
  struct Run {
    IntegratorStats stats;
    State state;
  };
  auto run = [&](LinearSolver solver) {
    IntegratorSettings settings;
    settings.linear_solver = solver;
    Integrator integrator(m, settings);
    Inputs inputs;
    for (int leg = 0; leg < kNumLegs; ++leg) inputs.welds[leg] = PlantFoot(m, start, leg);
    integrator.Reset(0.0, start, inputs);
    EXPECT_TRUE(integrator.AdvanceTo(0.75).ok());
    inputs.welds[kLeft].active = false;
    inputs.joint_torque(kHipR) = 30.0;
    integrator.SetWelds(inputs.welds);
    integrator.SetTorques(inputs.joint_torque);
    EXPECT_TRUE(integrator.AdvanceTo(1.5).ok());
    return Run{integrator.stats(), integrator.state()};
  };
  const Run blocks = run(LinearSolver::kSchurBlocks);
  const Run dense = run(LinearSolver::kSchurComplement);
  EXPECT_GT(blocks.stats.jacobian_evals, 0);
  EXPECT_EQ(blocks.stats.restarts, 1);
  EXPECT_EQ(blocks.stats.steps, dense.stats.steps);
  EXPECT_EQ(blocks.stats.rhs_evals, dense.stats.rhs_evals);
  EXPECT_EQ(blocks.stats.jacobian_evals, dense.stats.jacobian_evals);
  EXPECT_EQ(blocks.state.q, dense.state.q);
  EXPECT_EQ(blocks.state.v, dense.state.v);
}

TEST(BlockMatrix18Test, IntegratorRefusesTheBlockMatrixWithDifferenceQuotients) {
  const Model m = BuildModel(BodyOf(DefaultGenome()));
  IntegratorSettings settings;
  settings.linear_solver = LinearSolver::kSchurBlocks;
  settings.jacobian = JacobianSource::kFiniteDifference;
  EXPECT_THROW(Integrator(m, settings), std::logic_error);  // a bug of the caller (WALKERS_CHECK)
  settings.linear_solver = LinearSolver::kSchurComplement;
  EXPECT_NO_THROW(Integrator(m, settings));
}

}  // namespace
}  // namespace walkers
