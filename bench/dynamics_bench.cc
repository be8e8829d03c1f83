// Kernels of the dynamics and a short planted simulation.
#include <benchmark/benchmark.h>

#include "control/genome.h"
#include "control/start_pose.h"
#include "dynamics/equations_of_motion.h"
#include "dynamics/integrator.h"
#include "dynamics/jacobian.h"
#include "dynamics/observation.h"

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
