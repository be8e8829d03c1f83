#include "control/evaluation.h"

#include <string>
#include <thread>

#include <gtest/gtest.h>

#include "control/accuracy.h"
#include "tests/input_error_message.h"

namespace walkers {
namespace {

// every field but the wall time, bit for bit
void ExpectIdentical(const EvaluationResult& a, const EvaluationResult& b) {
  EXPECT_EQ(a.outcome, b.outcome);
  EXPECT_EQ(a.reason, b.reason);
  EXPECT_EQ(a.fitness, b.fitness);
  EXPECT_EQ(a.distance, b.distance);
  EXPECT_EQ(a.footsteps, b.footsteps);
  EXPECT_EQ(a.trunk_contact_fraction, b.trunk_contact_fraction);
  EXPECT_EQ(a.gait, b.gait);
  EXPECT_EQ(a.sim_time, b.sim_time);
  EXPECT_EQ(a.integrator_stats.steps, b.integrator_stats.steps);
  EXPECT_EQ(a.integrator_stats.rhs_evals, b.integrator_stats.rhs_evals);
}

// An evaluation ended as `outcome`, with the fitness and gait that outcome
// gives and a reason only if it failed. Each outcome arises below: a walk (a
// tripod, a biped), falls, a failure and a cut-off.
void ExpectOutcome(const EvaluationResult& r, Outcome outcome) {
  EXPECT_EQ(r.outcome, outcome) << r.reason;
  EXPECT_EQ(r.reason.empty(), outcome != Outcome::kFailed) << r.reason;
  switch (outcome) {
    case Outcome::kWalked:
      EXPECT_EQ(r.fitness, r.distance / r.leg_length);  // paper eq. (6)
      EXPECT_EQ(r.gait, r.trunk_contact_fraction >= kTripodContactFraction ? Gait::kTripod : Gait::kBiped);
      break;
    case Outcome::kFell:
    case Outcome::kFailed:
      EXPECT_EQ(r.fitness, -1.0);
      EXPECT_EQ(r.gait, Gait::kNone);
      break;
    case Outcome::kCutOff:
      EXPECT_EQ(r.fitness, kCutOffFitness);
      EXPECT_EQ(r.gait, Gait::kNone);
      break;
  }
}

// The initial individual is a tripod: it leans its trunk on the ground and
// takes its first step (docs/fidelity.md: like the authors' program
// integrated accurately, it then stalls).
TEST(EvaluationTest, TheDefaultGenomeStepsAsATripod) {
  const EvaluationResult r = Evaluate(DefaultGenome(), OriginalPreset());
  ExpectOutcome(r, Outcome::kWalked);
  EXPECT_GE(r.footsteps, 1);
  EXPECT_GT(r.fitness, 0.0);
  EXPECT_EQ(r.gait, Gait::kTripod);
  EXPECT_DOUBLE_EQ(r.sim_time, 15.0);
  EXPECT_EQ(r.preset, "original");
  EXPECT_GT(r.integrator_stats.steps, 0);
  // its planted feet stay put under the VMC loads (docs/model.md, "Planted-foot weld")
  EXPECT_LT(r.max_weld_drift, 1e-3);
}

// One of the authors' evolved bipeds (their case 3) walks 15 s on regular steps.
TEST(EvaluationTest, AnEvolvedBipedWalksFar) {
  const Genome g = LoadGenome(std::string(WALKERS_SOURCE_DIR) +
                              "/data/genomes/authors/archive_case3_06_13_20_20_41_2.json");
  const EvaluationResult r = Evaluate(g, OriginalPreset());
  ExpectOutcome(r, Outcome::kWalked);
  EXPECT_EQ(r.gait, Gait::kBiped);
  EXPECT_GE(r.footsteps, 20);
  EXPECT_GT(r.fitness, 15.0);  // the authors' program: 18.73
  EXPECT_LT(r.max_weld_drift, 1e-3);
}

TEST(EvaluationTest, AWalkerThatFallsHasNoGaitClass) {
  const Genome g = LoadGenome(std::string(WALKERS_SOURCE_DIR) + "/data/genomes/bench/evolved_faller.json");
  const EvaluationResult r = Evaluate(g, OriginalPreset());
  ExpectOutcome(r, Outcome::kFell);
  EXPECT_STREQ(GaitName(r.gait), "none");
}

TEST(EvaluationTest, IsBitIdenticalTwiceAndOnAnotherThread) {
  const Genome g = DefaultGenome();
  const EvaluationResult first = Evaluate(g, OriginalPreset());
  const EvaluationResult second = Evaluate(g, OriginalPreset());
  EvaluationResult threaded;
  std::thread worker([&] { threaded = Evaluate(g, OriginalPreset()); });
  worker.join();
  ExpectIdentical(first, second);
  ExpectIdentical(first, threaded);
}

// dynamics/fixed_size_ops and dynamics/block_matrix18 promise SUNDIALS'
// arithmetic in SUNDIALS' order: a whole walk, ~10 k steps through every CVODE
// code path, must not move a bit with the dense Newton matrix, nor with
// SUNDIALS' own vector and matrix operations
TEST(EvaluationTest, FixedSizeOperationsAndTheBlockMatrixChangeNoBit) {
  EvaluationSettings dense;
  dense.integrator.linear_solver = LinearSolver::kSchurComplement;
  EvaluationSettings library = dense;
  library.integrator.fixed_size_ops = false;
  for (const Preset& preset : {OriginalPreset(), PaperPreset()}) {
    SCOPED_TRACE(preset.name);
    const EvaluationResult production = Evaluate(DefaultGenome(), preset);
    ExpectIdentical(production, Evaluate(DefaultGenome(), preset, dense));
    ExpectIdentical(production, Evaluate(DefaultGenome(), preset, library));
  }
}

TEST(EvaluationTest, AWalkerWithAWeakVerticalSpringFallsAndScoresMinusOne) {
  Genome g = DefaultGenome();
  g[kKy] = 3000.0;        // the floor: it cannot hold the trunk up...
  g[kHalfBodyX] = 0.1;    // ...and a short trunk cannot lean on the ground as a tripod
  for (const Preset& preset : {OriginalPreset(), PaperPreset()}) {
    SCOPED_TRACE(preset.name);
    const EvaluationResult r = Evaluate(g, preset);
    ExpectOutcome(r, Outcome::kFell);
    EXPECT_LT(r.sim_time, 15.0);
  }
}

TEST(EvaluationTest, ReportsAnIntegrationFailureAsMinusOneWithItsReason) {
  EvaluationSettings settings;
  settings.integrator.step_budget = 100;
  const EvaluationResult r = Evaluate(DefaultGenome(), OriginalPreset(), settings);
  ExpectOutcome(r, Outcome::kFailed);
  EXPECT_NE(r.reason.find("step budget"), std::string::npos) << r.reason;
  EXPECT_LT(r.sim_time, 15.0);
}

TEST(EvaluationTest, ObserverSeesEveryTickAndTheEnd) {
  int calls = 0;
  double last_t = -1.0;
  Evaluate(DefaultGenome(), OriginalPreset(), {}, [&](double t, const State&, const WalkingController&) {
    EXPECT_GE(t, last_t);
    last_t = t;
    ++calls;
  });
  EXPECT_EQ(calls, 451);  // ticks at 0, 1/30, ..., 449/30, and the end at 15 s
  EXPECT_DOUBLE_EQ(last_t, 15.0);
}


// ---- the walker under RK-Merson against the authors' program ----

TEST(RungeKuttaMersonTest, TheAuthorsCaseOneBipedTakesTheirProgramsSteps) {
  // their program, built with its integrator's statistics printed, took
  // 1,778 steps (2,795 attempts, 12,960 right-hand sides) on this genome
  // and scored 15.21 (docs/fidelity.md, "RK-Merson's steps")
  const Genome genome = LoadGenome(std::string(WALKERS_SOURCE_DIR) + "/data/genomes/bench/authors_case1_biped.json");
  EvaluationSettings settings;
  settings.integrator.method = IntegrationMethod::kRkMerson;
  const EvaluationResult r = Evaluate(genome, OriginalPreset(), settings);
  ExpectOutcome(r, Outcome::kWalked);
  EXPECT_GT(r.integrator_stats.steps, 0.7 * 1778);
  EXPECT_LT(r.integrator_stats.steps, 1.3 * 1778);
  EXPECT_GT(r.fitness, 10.0);
  EXPECT_EQ(r.gait, Gait::kBiped);
}

TEST(EvaluationTest, RkMersonIsBitIdenticalTwiceAndItsEnsembleMembersDiffer) {
  EvaluationSettings settings;
  settings.integrator.method = IntegrationMethod::kRkMerson;
  const Genome genome = LoadGenome(std::string(WALKERS_SOURCE_DIR) + "/data/genomes/bench/authors_case2_tripod.json");
  ExpectIdentical(Evaluate(genome, OriginalPreset(), settings), Evaluate(genome, OriginalPreset(), settings));
  // an ensemble's members perturb RK-Merson's accuracy (control/accuracy.h)
  const FitnessEnsemble ensemble = EvaluateEnsemble(genome, OriginalPreset(), settings, 3);
  EXPECT_NE(ensemble.fitness[0], ensemble.fitness[2]);
}

TEST(EvaluationTest, AnEvaluationPastTheCutOffScoresMinus124AndIsNoFall) {
  EvaluationSettings settings;
  settings.integrator.method = IntegrationMethod::kRkMerson;
  settings.cut_off_rhs = 5000;  // the initial individual takes tens of thousands
  const EvaluationResult r = Evaluate(DefaultGenome(), OriginalPreset(), settings);
  ExpectOutcome(r, Outcome::kCutOff);
  EXPECT_LT(r.sim_time, 15.0);  // it stops there
  EXPECT_LE(r.integrator_stats.rhs_evals, 5000 + 2000);  // within the tick that passed the budget
  // without it the same walker walks its 15 s
  settings.cut_off_rhs = 0;
  const EvaluationResult uncut = Evaluate(DefaultGenome(), OriginalPreset(), settings);
  ExpectOutcome(uncut, Outcome::kWalked);
  EXPECT_GT(uncut.fitness, 0.0);
  EXPECT_GT(uncut.integrator_stats.rhs_evals, 5000);
}

TEST(EvaluationTest, AnIntegratorChoiceThatIsNotAllowedNamesItsOption) {
  using testing::InputErrorMessage;
  const IntegrationChoiceNames cli{"--integrator", "--accuracy", "--cut-off"};
  EXPECT_NE(InputErrorMessage([&] { SettingsOfIntegrator("euler", std::nullopt, std::nullopt, cli); })
                .find("--integrator = \"euler\" is none of cvode, rk-merson"),
            std::string::npos);
  EXPECT_NE(InputErrorMessage([&] { SettingsOfIntegrator("cvode", 0.01, std::nullopt, cli); })
                .find("--accuracy applies to the rk-merson integrator only"),
            std::string::npos);
  EXPECT_NE(InputErrorMessage([&] { SettingsOfIntegrator("rk-merson", 2.0, std::nullopt, cli); }).find("(0, 1]"),
            std::string::npos);
  EXPECT_NE(InputErrorMessage([] { SettingsOfIntegrator("rk-merson", std::nullopt, -3); }).find("cut_off = -3"),
            std::string::npos);
  // the choices that are allowed, and their defaults
  EXPECT_EQ(SettingsOfIntegrator("rk-merson").cut_off_rhs, kAuthorsCutOffRhs);
  EXPECT_EQ(SettingsOfIntegrator("rk-merson", 0.01, 0).integrator.accuracy, 0.01);
  EXPECT_EQ(SettingsOfIntegrator("cvode").cut_off_rhs, 0);
}

}  // namespace
}  // namespace walkers
