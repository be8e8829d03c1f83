// Kernels of the dynamics and a short planted simulation.
#include <benchmark/benchmark.h>
#include <cvode/cvode.h>
#include <nvector/nvector_serial.h>
#include <sundials/sundials_context.h>
#include <sunlinsol/sunlinsol_dense.h>
#include <sunmatrix/sunmatrix_dense.h>

#include <Eigen/Cholesky>

#include "control/genome.h"
#include "control/start_pose.h"
#include "integration/block_matrix18.h"
#include "dynamics/equations_of_motion.h"
#include "integration/fixed_size_ops.h"
#include "integration/integrator.h"
#include "dynamics/jacobian.h"
#include "integration/schur_linear_solver.h"
#include "dynamics/observation.h"
#include "dynamics/tree_ldlt9.h"

namespace walkers {
namespace {

// The default walker standing on planted feet, warmed up for 0.5 s so the
// feet are loaded and the legs are moving.
class PlantedWalker : public benchmark::Fixture {
 public:
  void SetUp(const benchmark::State&) override {
    model_ = BuildModel(BodyOf(DefaultGenome()));
    const State start = StartState(model_);
    for (int leg = 0; leg < kNumLegs; ++leg) inputs_.welds[leg] = PlantFoot(model_, start, leg);
    Integrator integrator(model_);
    integrator.Reset(0.0, start, inputs_);
    integrator.AdvanceTo(0.5);
    state_ = integrator.state();
  }

 protected:
  Model model_;
  Inputs inputs_;
  State state_;
  Workspace workspace_;
};

BENCHMARK_F(PlantedWalker, Kinematics)(benchmark::State& st) {
  for (auto _ : st) {
    ComputeKinematics(model_, state_.q, state_.v, &workspace_.kin);
    benchmark::DoNotOptimize(workspace_.kin);
  }
  st.SetItemsProcessed(st.iterations());
}

BENCHMARK_F(PlantedWalker, MassMatrix)(benchmark::State& st) {
  ComputeKinematics(model_, state_.q, state_.v, &workspace_.kin);
  for (auto _ : st) {
    MassMatrix(model_, workspace_.kin, &workspace_.M);
    benchmark::DoNotOptimize(workspace_.M);
  }
  st.SetItemsProcessed(st.iterations());
}

BENCHMARK_F(PlantedWalker, GeneralizedForces)(benchmark::State& st) {
  ComputeKinematics(model_, state_.q, state_.v, &workspace_.kin);
  for (auto _ : st) {
    GeneralizedForces(model_, inputs_, workspace_.kin, state_.q, state_.v, &workspace_.Q);
    benchmark::DoNotOptimize(workspace_.Q);
  }
  st.SetItemsProcessed(st.iterations());
}

// the whole right-hand side: kinematics, M, Q, and the solve for q''
BENCHMARK_F(PlantedWalker, RightHandSide)(benchmark::State& st) {
  Vec9 qdd;
  for (auto _ : st) {
    benchmark::DoNotOptimize(ForwardDynamics(model_, inputs_, state_.q, state_.v, &workspace_, &qdd));
    benchmark::DoNotOptimize(qdd);
  }
  st.SetItemsProcessed(st.iterations());
}

// da/dq and da/dv, analytic (including the forward dynamics it starts from)
BENCHMARK_F(PlantedWalker, AccelerationJacobian)(benchmark::State& st) {
  Mat9 da_dq, da_dv;
  for (auto _ : st) {
    benchmark::DoNotOptimize(AccelerationJacobian(model_, inputs_, state_.q, state_.v, &workspace_, &da_dq, &da_dv));
    benchmark::DoNotOptimize(da_dq);
  }
  st.SetItemsProcessed(st.iterations());
}

// the mass matrix's factorisation and one solve: ours against Eigen's LLT and LDLT
BENCHMARK_F(PlantedWalker, MassMatrixSolve_TreeLdlt9)(benchmark::State& st) {
  const Mat9 M = MassMatrix(model_, state_.q);
  TreeLdlt9 ldlt;
  for (auto _ : st) {
    ldlt.Compute(M);
    Vec9 x = Vec9::Ones();
    ldlt.SolveInPlace(&x);
    benchmark::DoNotOptimize(x);
  }
  st.SetItemsProcessed(st.iterations());
}

template <typename EigenDecomposition>
void SolveWithEigen(const Mat9& M, benchmark::State& st) {
  EigenDecomposition decomposition(kNumCoords);
  for (auto _ : st) {
    decomposition.compute(M);
    Vec9 x = decomposition.solve(Vec9::Ones());
    benchmark::DoNotOptimize(x);
  }
  st.SetItemsProcessed(st.iterations());
}

BENCHMARK_F(PlantedWalker, MassMatrixSolve_EigenLLT)(benchmark::State& st) {
  SolveWithEigen<Eigen::LLT<Mat9>>(MassMatrix(model_, state_.q), st);
}

BENCHMARK_F(PlantedWalker, MassMatrixSolve_EigenLDLT)(benchmark::State& st) {
  SolveWithEigen<Eigen::LDLT<Mat9>>(MassMatrix(model_, state_.q), st);
}

// every contact pair, at a state where the trunk and feet touch the ground
BENCHMARK_F(PlantedWalker, ContactForces)(benchmark::State& st) {
  State lying = state_;
  Integrator integrator(model_);
  integrator.Reset(0.0, StartState(model_), inputs_);
  integrator.AdvanceTo(1.5);  // collapsed: the trunk lies on the ground
  lying = integrator.state();
  ComputeKinematics(model_, lying.q, lying.v, &workspace_.kin);
  int touching = 0;
  for (const ContactReport& r : ReportContacts(model_, workspace_.kin)) touching += r.elements;
  for (auto _ : st) {
    Vec9 Q = Vec9::Zero();
    AddContactForces(model_, workspace_.kin, Welds{}, &Q);
    benchmark::DoNotOptimize(Q);
  }
  st.SetItemsProcessed(st.iterations());
  st.counters["springs_pushing"] = touching;
}

// What CVODE does at each Newton-matrix setup (cvLsLinSys with a saved
// Jacobian), then one solve: A = saved J, A = I - gamma*A, factor, solve.
// The walker's analytic Jacobian; the three ways of IntegratorSettings'
// LinearSolver.
void NewtonSetupAndSolve(benchmark::State& st, LinearSolver kind) {
  const Model model = BuildModel(BodyOf(DefaultGenome()));
  const State start = StartState(model);
  Inputs inputs;
  for (int leg = 0; leg < kNumLegs; ++leg) inputs.welds[leg] = PlantFoot(model, start, leg);
  Workspace ws;
  Mat9 da_dq, da_dv;
  AccelerationJacobian(model, inputs, start.q, start.v, &ws, &da_dq, &da_dv);
  const double gamma = 1e-3;
  SUNContext context;
  SUNContext_Create(nullptr, &context);
  N_Vector x = N_VNew_Serial(18, context), b = N_VNew_Serial(18, context);
  SUNMatrix saved = nullptr;
  if (kind == LinearSolver::kSchurBlocks) {
    saved = MakeBlockMatrix18(context);
  } else {
    saved = SUNDenseMatrix(18, 18, context);
    UseFixedSizeMatrixOps(saved);  // as the integrator does
  }
  StoreWalkerJacobian(da_dq, da_dv, saved);
  SUNMatrix A = SUNMatClone(saved);
  SUNLinearSolver solver = kind == LinearSolver::kDense ? SUNLinSol_Dense(x, A, context)
                                                        : MakeSchurLinearSolver(x, A, context);
  SUNLinSolInitialize(solver);
  N_VConst(1.0, b);
  for (auto _ : st) {
    SUNMatCopy(saved, A);
    SUNMatScaleAddI(-gamma, A);
    SUNLinSolSetup(solver, A);
    SUNLinSolSolve(solver, A, x, b, 0.0);
    benchmark::DoNotOptimize(N_VGetArrayPointer(x)[0]);
  }
  st.SetItemsProcessed(st.iterations());
  SUNLinSolFree(solver);
  SUNMatDestroy(A);
  SUNMatDestroy(saved);
  N_VDestroy(x);
  N_VDestroy(b);
  SUNContext_Free(&context);
}
BENCHMARK_CAPTURE(NewtonSetupAndSolve, schur_blocks, LinearSolver::kSchurBlocks);
BENCHMARK_CAPTURE(NewtonSetupAndSolve, schur_dense, LinearSolver::kSchurComplement);
BENCHMARK_CAPTURE(NewtonSetupAndSolve, dense_lu, LinearSolver::kDense);

// 1 s of the limp walker on planted feet, reporting at 30 Hz
BENCHMARK_F(PlantedWalker, PlantedSimulation1s)(benchmark::State& st) {
  const State start = StartState(model_);
  IntegratorStats stats;
  for (auto _ : st) {
    Integrator integrator(model_);
    integrator.Reset(0.0, start, inputs_);
    for (int frame = 1; frame <= 30; ++frame) integrator.AdvanceTo(frame / kControlRate);
    stats = integrator.stats();
    benchmark::DoNotOptimize(integrator.state());
  }
  st.SetItemsProcessed(st.iterations());
  st.counters["cvode_steps"] = static_cast<double>(stats.steps);
  st.counters["rhs_evals"] = static_cast<double>(stats.rhs_evals);
}

}  // namespace
}  // namespace walkers
