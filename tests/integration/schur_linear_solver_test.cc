#include "integration/schur_linear_solver.h"

#include <atomic>
#include <cmath>
#include <complex>
#include <limits>
#include <memory>
#include <random>
#include <thread>
#include <type_traits>
#include <vector>

#include <Eigen/Core>
#include <gtest/gtest.h>

#include "tests/integration/sundials_handles.h"

#include <cvode/cvode.h>
#include <nvector/nvector_serial.h>
#include <sundials/sundials_context.h>
#include <sundials/sundials_linearsolver.h>
#include <sunlinsol/sunlinsol_dense.h>
#include <sunmatrix/sunmatrix_dense.h>

namespace walkers {
namespace {

using Mat9 = Eigen::Matrix<double, kHalf, kHalf>;

// J = [[0, I], [A_q, A_v]]
Mat18 OdeJacobian(const Mat9& a_q, const Mat9& a_v) {
  Mat18 j = Mat18::Zero();
  j.topRightCorner<kHalf, kHalf>().setIdentity();
  j.bottomLeftCorner<kHalf, kHalf>() = a_q;
  j.bottomRightCorner<kHalf, kHalf>() = a_v;
  return j;
}

// M = I - gamma*J formed the way CVODE forms it: J stored in the dense
// matrix, then SUNMatScaleAddI(-gamma, A)
void FormNewtonMatrix(const Mat18& jacobian, double gamma, SUNMatrix a) {
  Store(jacobian, a);
  ASSERT_EQ(SUNMatScaleAddI(-gamma, a), 0);
}

// random blocks on the scales of a stiff mechanical system: A_q ~ stiffness
// over mass, A_v ~ damping over mass
struct RandomBlocks {
  Mat9 a_q, a_v;
};
RandomBlocks MakeBlocks(unsigned seed) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> unit(-1.0, 1.0);
  RandomBlocks r;
  for (int j = 0; j < kHalf; ++j) {
    for (int i = 0; i < kHalf; ++i) {
      r.a_q(i, j) = 100.0 * unit(rng);
      r.a_v(i, j) = 10.0 * unit(rng);
    }
  }
  return r;
}
Vec18 RandomVector(unsigned seed) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> unit(-1.0, 1.0);
  Vec18 v;
  for (int i = 0; i < kN; ++i) v(i) = unit(rng);
  return v;
}

double RelativeDifference(const Vec18& x, const Vec18& reference) {
  return (x - reference).lpNorm<Eigen::Infinity>() / reference.lpNorm<Eigen::Infinity>();
}

// one context, the matrix CVODE would fill, the two vectors and the solver
struct Fixture {
  ContextPtr context = NewContext();
  MatrixPtr a{SUNDenseMatrix(kN, kN, context.get())};
  VectorPtr x{N_VNew_Serial(kN, context.get())};
  VectorPtr b{N_VNew_Serial(kN, context.get())};
  SolverPtr schur{MakeSchurLinearSolver(x.get(), a.get(), context.get())};
};

// solves M x = b with SUNLinSol_Dense on a copy of M (it factors in place)
Vec18 DenseSolve(const Mat18& m, const Vec18& rhs, SUNContext context) {
  MatrixPtr a(SUNDenseMatrix(kN, kN, context));
  VectorPtr x(N_VNew_Serial(kN, context)), b(N_VNew_Serial(kN, context));
  SolverPtr dense(SUNLinSol_Dense(x.get(), a.get(), context));
  Store(m, a.get());
  Store(rhs, b.get());
  EXPECT_EQ(SUNLinSolInitialize(dense.get()), SUNLS_SUCCESS);
  EXPECT_EQ(SUNLinSolSetup(dense.get(), a.get()), SUNLS_SUCCESS);
  EXPECT_EQ(SUNLinSolSolve(dense.get(), a.get(), x.get(), b.get(), 0.0), SUNLS_SUCCESS);
  return Load(x.get());
}

TEST(SchurLinearSolverTest, Describes) {
  Fixture f;
  ASSERT_NE(f.schur, nullptr);
  EXPECT_EQ(SUNLinSolGetType(f.schur.get()), SUNLINEARSOLVER_DIRECT);
  EXPECT_EQ(SUNLinSolGetID(f.schur.get()), SUNLINEARSOLVER_CUSTOM);
  long lenrw = -1, leniw = -1;
  EXPECT_EQ(SUNLinSolSpace(f.schur.get(), &lenrw, &leniw), SUNLS_SUCCESS);
  EXPECT_GT(lenrw, 0);
  EXPECT_GT(leniw, 0);
  EXPECT_EQ(SUNLinSolInitialize(f.schur.get()), SUNLS_SUCCESS);
  EXPECT_EQ(SUNLinSolLastFlag(f.schur.get()), 0);
}

TEST(SchurLinearSolverTest, RejectsBadInputAtConstruction) {
  ContextPtr context = NewContext();
  SUNContext c = context.get();
  MatrixPtr a(SUNDenseMatrix(kN, kN, c));
  MatrixPtr small(SUNDenseMatrix(kHalf, kHalf, c));
  MatrixPtr rectangular(SUNDenseMatrix(kN, kN - 1, c));
  VectorPtr y(N_VNew_Serial(kN, c));
  VectorPtr short_y(N_VNew_Serial(kN - 1, c));

  SolverPtr good(MakeSchurLinearSolver(y.get(), a.get(), c));
  EXPECT_NE(good, nullptr);
  EXPECT_EQ(MakeSchurLinearSolver(nullptr, a.get(), c), nullptr);
  EXPECT_EQ(MakeSchurLinearSolver(y.get(), nullptr, c), nullptr);
  EXPECT_EQ(MakeSchurLinearSolver(y.get(), a.get(), nullptr), nullptr);
  EXPECT_EQ(MakeSchurLinearSolver(short_y.get(), a.get(), c), nullptr);
  EXPECT_EQ(MakeSchurLinearSolver(y.get(), small.get(), c), nullptr);
  EXPECT_EQ(MakeSchurLinearSolver(y.get(), rectangular.get(), c), nullptr);
}

class SchurMatchesDenseTest : public ::testing::TestWithParam<double> {};

TEST_P(SchurMatchesDenseTest, SameSolutionAsDenseAndSmallResidual) {
  const double gamma = GetParam();
  Fixture f;
  ASSERT_NE(f.schur, nullptr);
  ASSERT_EQ(SUNLinSolInitialize(f.schur.get()), SUNLS_SUCCESS);
  for (unsigned seed = 1; seed <= 20; ++seed) {
    const RandomBlocks blocks = MakeBlocks(seed);
    FormNewtonMatrix(OdeJacobian(blocks.a_q, blocks.a_v), gamma, f.a.get());
    const Mat18 m = Load(f.a.get());
    const Vec18 rhs = RandomVector(1000 + seed);
    Store(rhs, f.b.get());
    N_VConst(std::numeric_limits<double>::quiet_NaN(), f.x.get());

    ASSERT_EQ(SUNLinSolSetup(f.schur.get(), f.a.get()), SUNLS_SUCCESS) << "seed " << seed;
    ASSERT_EQ(SUNLinSolSolve(f.schur.get(), f.a.get(), f.x.get(), f.b.get(), 0.0), SUNLS_SUCCESS);
    EXPECT_EQ(SUNLinSolLastFlag(f.schur.get()), 0);
    const Vec18 x = Load(f.x.get());

    // setup and solve leave A and b as they were
    EXPECT_EQ(Load(f.a.get()), m);
    EXPECT_EQ(Load(f.b.get()), rhs);

    const Vec18 dense = DenseSolve(m, rhs, f.context.get());
    EXPECT_LT(RelativeDifference(x, dense), 1e-10) << "seed " << seed << " gamma " << gamma;

    const double residual = (m * x - rhs).lpNorm<Eigen::Infinity>() /
                            (m.lpNorm<Eigen::Infinity>() * x.lpNorm<Eigen::Infinity>() + rhs.lpNorm<Eigen::Infinity>());
    EXPECT_LT(residual, 1e-14) << "seed " << seed << " gamma " << gamma;
  }
}

INSTANTIATE_TEST_SUITE_P(Gammas, SchurMatchesDenseTest, ::testing::Values(1e-6, 1e-3, 0.1));

// CVODE's difference-quotient Jacobian has relative errors ~1e-8 on the
// diagonal of J's identity block: the solver accepts them and solves the
// matrix it is given, not an idealized one
TEST(SchurLinearSolverTest, ExactForNoisyIdentityBlock) {
  Fixture f;
  ASSERT_NE(f.schur, nullptr);
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> noise(-3e-8, 3e-8);
  for (const double gamma : {1e-3, 0.1}) {
    const RandomBlocks blocks = MakeBlocks(42);
    Mat18 jacobian = OdeJacobian(blocks.a_q, blocks.a_v);
    for (int i = 0; i < kHalf; ++i) jacobian(i, kHalf + i) *= 1.0 + noise(rng);
    FormNewtonMatrix(jacobian, gamma, f.a.get());
    const Mat18 m = Load(f.a.get());
    const Vec18 rhs = RandomVector(3);
    Store(rhs, f.b.get());
    ASSERT_EQ(SUNLinSolSetup(f.schur.get(), f.a.get()), SUNLS_SUCCESS);
    ASSERT_EQ(SUNLinSolSolve(f.schur.get(), f.a.get(), f.x.get(), f.b.get(), 0.0), SUNLS_SUCCESS);
    EXPECT_LT(RelativeDifference(Load(f.x.get()), DenseSolve(m, rhs, f.context.get())), 1e-10) << gamma;
  }
}

TEST(SchurLinearSolverTest, SolvesInPlace) {
  Fixture f;
  ASSERT_NE(f.schur, nullptr);
  const RandomBlocks blocks = MakeBlocks(5);
  FormNewtonMatrix(OdeJacobian(blocks.a_q, blocks.a_v), 0.01, f.a.get());
  const Vec18 rhs = RandomVector(6);
  Store(rhs, f.b.get());
  ASSERT_EQ(SUNLinSolSetup(f.schur.get(), f.a.get()), SUNLS_SUCCESS);
  ASSERT_EQ(SUNLinSolSolve(f.schur.get(), f.a.get(), f.x.get(), f.b.get(), 0.0), SUNLS_SUCCESS);
  ASSERT_EQ(SUNLinSolSolve(f.schur.get(), f.a.get(), f.b.get(), f.b.get(), 0.0), SUNLS_SUCCESS);
  EXPECT_EQ(Load(f.b.get()), Load(f.x.get()));
}

// a matrix that is not I - gamma*[[0, I], [A_q, A_v]] is refused: setup
// fails, and a solve after it fails too instead of using a stale factorization
TEST(SchurLinearSolverTest, RejectsMatrixWithoutBlockStructure) {
  const RandomBlocks blocks = MakeBlocks(11);
  const double gamma = 0.05;
  const Mat18 good = Mat18::Identity() - gamma * OdeJacobian(blocks.a_q, blocks.a_v);

  struct Case {
    const char* name;
    int row, col;
    double value;
  };
  const Case cases[] = {
      {"M11 off-diagonal", 2, 5, 1e-3},
      {"M11 diagonal", 4, 4, 1.01},
      {"M12 off-diagonal", 1, kHalf + 3, -1e-4},
      {"M12 diagonal not -gamma", 6, kHalf + 6, -2.0 * gamma},
      {"M12 diagonal of the wrong sign", 0, kHalf, gamma},
      {"NaN in M12", 3, kHalf + 3, std::numeric_limits<double>::quiet_NaN()},
  };
  for (const Case& c : cases) {
    Fixture f;
    ASSERT_NE(f.schur, nullptr);
    // a successful setup first, so that a stale factorization exists
    Store(good, f.a.get());
    ASSERT_EQ(SUNLinSolSetup(f.schur.get(), f.a.get()), SUNLS_SUCCESS) << c.name;

    Mat18 bad = good;
    bad(c.row, c.col) = c.value;
    Store(bad, f.a.get());
    const int flag = SUNLinSolSetup(f.schur.get(), f.a.get());
    EXPECT_NE(flag, SUNLS_SUCCESS) << c.name;
    EXPECT_EQ(flag, SUNLS_PACKAGE_FAIL_UNREC) << c.name;
    EXPECT_EQ(SUNLinSolLastFlag(f.schur.get()), SUNLS_PACKAGE_FAIL_UNREC) << c.name;

    Store(RandomVector(2), f.b.get());
    N_VConst(0.0, f.x.get());
    EXPECT_NE(SUNLinSolSolve(f.schur.get(), f.a.get(), f.x.get(), f.b.get(), 0.0), SUNLS_SUCCESS) << c.name;
    EXPECT_EQ(Load(f.x.get()), Vec18::Zero()) << c.name;
  }

  // and a general dense matrix
  Fixture f;
  ASSERT_NE(f.schur, nullptr);
  std::mt19937 rng(3);
  std::uniform_real_distribution<double> unit(-1.0, 1.0);
  Mat18 dense;
  for (int j = 0; j < kN; ++j)
    for (int i = 0; i < kN; ++i) dense(i, j) = unit(rng) + (i == j ? 5.0 : 0.0);
  Store(dense, f.a.get());
  EXPECT_EQ(SUNLinSolSetup(f.schur.get(), f.a.get()), SUNLS_PACKAGE_FAIL_UNREC);
}

// S = M22 + gamma*M21 with an exactly zero column: A_q's column k zero and
// A_v's column k = e_k / gamma make column k of S vanish, so M is singular
TEST(SchurLinearSolverTest, SingularSchurComplementFailsWithoutNaN) {
  const double gamma = 0.5;  // 1 / gamma exact
  for (const int k : {0, 4, 8}) {
    Fixture f;
    ASSERT_NE(f.schur, nullptr);
    RandomBlocks blocks = MakeBlocks(21);
    blocks.a_q.col(k).setZero();
    blocks.a_v.col(k).setZero();
    blocks.a_v(k, k) = 1.0 / gamma;
    FormNewtonMatrix(OdeJacobian(blocks.a_q, blocks.a_v), gamma, f.a.get());

    EXPECT_EQ(SUNLinSolSetup(f.schur.get(), f.a.get()), SUNLS_LUFACT_FAIL) << k;
    // like SUNLinSol_Dense, the last flag is the (1-based) column of the zero pivot
    EXPECT_EQ(SUNLinSolLastFlag(f.schur.get()), kHalf + k + 1) << k;

    // a solve anyway neither succeeds nor writes NaN into x
    Store(RandomVector(9), f.b.get());
    N_VConst(0.0, f.x.get());
    EXPECT_NE(SUNLinSolSolve(f.schur.get(), f.a.get(), f.x.get(), f.b.get(), 0.0), SUNLS_SUCCESS) << k;
    EXPECT_TRUE(Load(f.x.get()).allFinite()) << k;
  }
}

// an infinite acceleration derivative is reported as recoverable, not
// factored into NaN
TEST(SchurLinearSolverTest, NonFiniteJacobianIsRecoverableFailure) {
  Fixture f;
  ASSERT_NE(f.schur, nullptr);
  RandomBlocks blocks = MakeBlocks(8);
  blocks.a_v(2, 3) = std::numeric_limits<double>::infinity();
  FormNewtonMatrix(OdeJacobian(blocks.a_q, blocks.a_v), 0.01, f.a.get());
  const int flag = SUNLinSolSetup(f.schur.get(), f.a.get());
  EXPECT_GT(flag, 0);
  EXPECT_EQ(flag, SUNLS_PACKAGE_FAIL_REC);
}

// two solvers, each with its own context, working through the same problems
// at the same time in opposite orders: every result must be bit for bit the
// one a lone solver gets, which fails if the solvers shared mutable state
TEST(SchurLinearSolverTest, SolversOnTwoThreadsAreIndependent) {
  constexpr int kProblems = 24;
  constexpr int kRepeats = 5000;
  const double gammas[] = {1e-6, 1e-3, 0.1};
  std::vector<Mat18> matrices;
  std::vector<Vec18> rhs, reference;
  {
    Fixture f;
    ASSERT_NE(f.schur, nullptr);
    for (int p = 0; p < kProblems; ++p) {
      const RandomBlocks blocks = MakeBlocks(100 + p);
      FormNewtonMatrix(OdeJacobian(blocks.a_q, blocks.a_v), gammas[p % 3], f.a.get());
      matrices.push_back(Load(f.a.get()));
      rhs.push_back(RandomVector(200 + p));
      Store(rhs.back(), f.b.get());
      ASSERT_EQ(SUNLinSolSetup(f.schur.get(), f.a.get()), SUNLS_SUCCESS);
      ASSERT_EQ(SUNLinSolSolve(f.schur.get(), f.a.get(), f.x.get(), f.b.get(), 0.0), SUNLS_SUCCESS);
      reference.push_back(Load(f.x.get()));
    }
  }

  std::atomic<int> ready{0};
  struct Outcome {
    bool created = false;
    int failures = 0;    // setup or solve not successful
    int mismatches = 0;  // results differing from the reference
    std::vector<Vec18> last;
  };
  auto work = [&](bool reverse, Outcome* out) {
    Fixture f;
    out->created = f.schur != nullptr;
    ready.fetch_add(1);
    while (ready.load() < 2) std::this_thread::yield();
    if (!out->created) return;
    out->last.assign(kProblems, Vec18::Zero());
    for (int r = 0; r < kRepeats; ++r) {
      for (int i = 0; i < kProblems; ++i) {
        const int p = reverse ? kProblems - 1 - i : i;
        Store(matrices[p], f.a.get());
        Store(rhs[p], f.b.get());
        if (SUNLinSolSetup(f.schur.get(), f.a.get()) != SUNLS_SUCCESS ||
            SUNLinSolSolve(f.schur.get(), f.a.get(), f.x.get(), f.b.get(), 0.0) != SUNLS_SUCCESS) {
          ++out->failures;
          continue;
        }
        const Vec18 x = Load(f.x.get());
        if (x != reference[p]) ++out->mismatches;
        out->last[p] = x;
      }
    }
  };
  Outcome forward, backward;
  std::thread t1(work, false, &forward);
  std::thread t2(work, true, &backward);
  t1.join();
  t2.join();

  ASSERT_TRUE(forward.created);
  ASSERT_TRUE(backward.created);
  EXPECT_EQ(forward.failures, 0);
  EXPECT_EQ(backward.failures, 0);
  EXPECT_EQ(forward.mismatches, 0);
  EXPECT_EQ(backward.mismatches, 0);
  for (int p = 0; p < kProblems; ++p) EXPECT_EQ(forward.last[p], backward.last[p]) << p;
}

// CVODE end to end: nine damped oscillators q'' = -k q - c v, some stiff,
// integrated by BDF with the Schur solver and with SUNLinSol_Dense (both on
// CVODE's own difference-quotient Jacobian)
struct OscillatorRun {
  int flag = 0;
  long steps = 0;
  Vec18 y;
};

constexpr double kStiffness[kHalf] = {1.0, 4.0, 10.0, 100.0, 1e3, 1e4, 1e4, 1e5, 2.0};
constexpr double kDamping[kHalf] = {0.1, 0.5, 1.0, 3.0, 50.0, 1e3, 250.0, 2e3, 0.0};

int OscillatorRhs(sunrealtype /*t*/, N_Vector y, N_Vector ydot, void* /*data*/) {
  const double* in = N_VGetArrayPointer(y);
  double* out = N_VGetArrayPointer(ydot);
  for (int i = 0; i < kHalf; ++i) {
    out[i] = in[kHalf + i];
    out[kHalf + i] = -kStiffness[i] * in[i] - kDamping[i] * in[kHalf + i];
  }
  return 0;
}

Vec18 OscillatorStart() {
  Vec18 y;
  for (int i = 0; i < kHalf; ++i) {
    y(i) = 0.1 * (i + 1);
    y(kHalf + i) = -0.2 * i;
  }
  return y;
}

// closed form through the roots of s^2 + c s + k (all distinct here)
Vec18 OscillatorExact(double t) {
  const Vec18 y0 = OscillatorStart();
  Vec18 y;
  for (int i = 0; i < kHalf; ++i) {
    const std::complex<double> root = std::sqrt(std::complex<double>(kDamping[i] * kDamping[i] - 4.0 * kStiffness[i]));
    const std::complex<double> s1 = 0.5 * (-kDamping[i] + root), s2 = 0.5 * (-kDamping[i] - root);
    const std::complex<double> c1 = (y0(kHalf + i) - s2 * y0(i)) / (s1 - s2), c2 = y0(i) - c1;
    const std::complex<double> e1 = std::exp(s1 * t), e2 = std::exp(s2 * t);
    y(i) = (c1 * e1 + c2 * e2).real();
    y(kHalf + i) = (c1 * s1 * e1 + c2 * s2 * e2).real();
  }
  return y;
}

OscillatorRun RunOscillators(bool use_schur, double t_end) {
  OscillatorRun run;
  ContextPtr context = NewContext();
  VectorPtr y(N_VNew_Serial(kN, context.get()));
  Store(OscillatorStart(), y.get());
  MatrixPtr a(SUNDenseMatrix(kN, kN, context.get()));
  SolverPtr ls(use_schur ? MakeSchurLinearSolver(y.get(), a.get(), context.get())
                         : SUNLinSol_Dense(y.get(), a.get(), context.get()));
  void* mem = CVodeCreate(CV_BDF, context.get());
  if (!ls || !mem) {
    run.flag = -1;
    return run;
  }
  run.flag = CVodeInit(mem, OscillatorRhs, 0.0, y.get());
  if (run.flag == CV_SUCCESS) run.flag = CVodeSStolerances(mem, 1e-10, 1e-12);
  if (run.flag == CV_SUCCESS) run.flag = CVodeSetLinearSolver(mem, ls.get(), a.get());
  if (run.flag == CV_SUCCESS) run.flag = CVodeSetMaxNumSteps(mem, 100000);
  double t = 0.0;
  if (run.flag == CV_SUCCESS) run.flag = CVode(mem, t_end, y.get(), &t, CV_NORMAL);
  CVodeGetNumSteps(mem, &run.steps);
  run.y = Load(y.get());
  CVodeFree(&mem);
  return run;
}

TEST(SchurLinearSolverTest, CvodeBdfMatchesDenseSolver) {
  const double t_end = 2.0;
  const OscillatorRun schur = RunOscillators(true, t_end);
  const OscillatorRun dense = RunOscillators(false, t_end);
  ASSERT_EQ(schur.flag, CV_SUCCESS);
  ASSERT_EQ(dense.flag, CV_SUCCESS);
  EXPECT_GT(schur.steps, 0);
  // both solve the same Newton systems up to round-off
  EXPECT_LT((schur.y - dense.y).lpNorm<Eigen::Infinity>(), 1e-9);
  const Vec18 exact = OscillatorExact(t_end);
  EXPECT_LT((schur.y - exact).lpNorm<Eigen::Infinity>(), 1e-6);
  EXPECT_LT((dense.y - exact).lpNorm<Eigen::Infinity>(), 1e-6);
}

}  // namespace
}  // namespace walkers
