#include "control/step_profile.h"

#include <sstream>
#include <string>

#include <gtest/gtest.h>

#include "control/evaluation.h"
#include "control/start_pose.h"

namespace walkers {
namespace {

int CsvFields(const std::string& line) {
  int n = 1;
  for (char c : line) n += c == ',' ? 1 : 0;
  return n;
}

// Hand-made steps: the profile counts what it is fed, tick by tick.
TEST(StepProfileTest, CountsStepsLimitsAndSwitchesPerTick) {
  const Genome genome = DefaultGenome();
  const Model model = BuildModel(BodyOf(genome));
  WalkingController controller(genome, model, OriginalPreset());
  controller.Start(StartWelds(model));
  const Inputs free_inputs;  // no welds: every ground contact is applied

  // standing with its feet in the ground, lifted clear of it, and lifted
  // with the left knee past its stop
  const State standing = StartState(model);
  State lifted = standing;
  lifted.q(kY) += 1.0;
  State overrun = lifted;
  overrun.q(kKneeL) = model.stops[kKnee].limit + 0.1;
  const ContactSet on_ground = ContactSetAt(model, standing, free_inputs.welds);
  int pairs_on = 0;
  for (int e : on_ground.elements) pairs_on += e > 0 ? 1 : 0;
  ASSERT_GE(pairs_on, 2);  // both feet at least
  for (int e : ContactSetAt(model, lifted, free_inputs.welds).elements) ASSERT_EQ(e, 0);
  // a weld holds its foot's ground contact: not applied
  EXPECT_EQ(ContactSetAt(model, standing, StartWelds(model)).elements[kGroundFootL], 0);
  EXPECT_GT(on_ground.elements[kGroundFootL], 0);

  const auto step = [&](double t, double h, int order, const State& state, int limiting, long error_tests) {
    StepInfo s;
    s.t = t;
    s.step = h;
    s.order = order;
    s.error_test_failures = error_tests;
    s.nonlinear_failures = 1;
    s.weighted_error.setConstant(0.1);
    s.weighted_error(limiting) = 0.5;
    s.state = &state;
    s.inputs = &free_inputs;
    return s;
  };
  StepProfile profile(model);
  profile.OnTick(0.0, lifted, controller);  // the previous set: nothing pushes
  profile.OnStep(step(0.01, 0.01, 1, standing, kNumCoords + kKneeR, 0));  // the pairs on
  profile.OnStep(step(0.02, 0.01, 2, lifted, kNumCoords + kKneeR, 2));    // and off again
  profile.OnStep(step(0.03, 0.01, 3, overrun, kPitch, 0));             // the knee stop on
  profile.OnTick(0.03, overrun, controller);
  profile.OnStep(step(0.05, 0.02, 2, lifted, kPitch, 0));  // the knee stop off
  profile.OnTick(0.06, lifted, controller);                // no steps: left out

  const std::vector<TickProfile> ticks = profile.Ticks();
  ASSERT_EQ(ticks.size(), 2u);
  const TickProfile& a = ticks[0];
  EXPECT_EQ(a.steps, 3);
  EXPECT_EQ(a.error_test_failures, 2);
  EXPECT_EQ(a.nonlinear_failures, 3);
  EXPECT_DOUBLE_EQ(a.step_sum, 0.03);
  EXPECT_EQ(a.max_order, 3);
  EXPECT_EQ(a.limiting[kNumCoords + kKneeR], 2);
  EXPECT_EQ(a.limiting[kPitch], 1);
  EXPECT_EQ(a.PairSwitches(), 2 * pairs_on);
  int springs = 0;
  for (int e : on_ground.elements) springs += e;
  EXPECT_EQ(a.spring_switches, 2 * springs);
  EXPECT_EQ(a.StopSwitches(), 1);
  EXPECT_EQ(a.stop_switches[kLeft * kNumJoints + kKnee], 1);
  const TickProfile& b = ticks[1];
  EXPECT_DOUBLE_EQ(b.t, 0.03);
  EXPECT_EQ(b.steps, 1);
  EXPECT_DOUBLE_EQ(b.step_min, 0.02);
  EXPECT_EQ(b.PairSwitches(), 0);
  EXPECT_EQ(b.StopSwitches(), 1);
  EXPECT_TRUE(a.at_end.stops[kLeft * kNumJoints + kKnee]);
  EXPECT_FALSE(b.at_end.stops[kLeft * kNumJoints + kKnee]);

  // the CSV: a header and a row per tick with steps, all of one width
  std::ostringstream csv;
  profile.WriteCsv(csv);
  std::istringstream lines(csv.str());
  std::string header, row;
  std::getline(lines, header);
  EXPECT_EQ(header.rfind("t,state,steps,error_test_failures,nonlinear_failures,step_mean,step_min,step_max,", 0), 0u);
  EXPECT_NE(header.find(",limit_v_knee_r,"), std::string::npos);
  EXPECT_NE(header.find(",switch_ground-foot_l,"), std::string::npos);
  EXPECT_NE(header.find(",switch_stop_knee_l,"), std::string::npos);
  int rows = 0;
  while (std::getline(lines, row)) {
    ++rows;
    EXPECT_EQ(CsvFields(row), CsvFields(header)) << row;
    EXPECT_EQ(row.rfind(rows == 1 ? "0,DS,3,2,3," : "0.03,DS,1,0,1,", 0), 0u) << row;
    // nothing pushes at either tick's end but, after the first, the left knee's stop
    EXPECT_NE(row.find(rows == 1 ? ",,0,knee_l," : ",,0,,"), std::string::npos) << row;
  }
  EXPECT_EQ(rows, 2);

  // the summary: per walking state and over all
  const nlohmann::ordered_json summary = profile.Summary();
  EXPECT_EQ(summary["all"]["steps"], 4);
  EXPECT_EQ(summary["DS"]["ticks"], 2);
  EXPECT_EQ(summary["LS"]["ticks"], 0);
  EXPECT_EQ(summary["all"]["limiting"]["q_pitch"], 2);
  EXPECT_EQ(summary["all"]["limiting"]["v_knee_r"], 2);
  EXPECT_EQ(summary["all"]["stop_switches"]["by_stop"]["knee_l"], 2);
  EXPECT_EQ(summary["all"]["pair_switches"]["total"], 2 * pairs_on);
  EXPECT_DOUBLE_EQ(summary["all"]["steps_per_tick"]["mean"].get<double>(), 2.0);
}

// A whole evaluation: the profile accounts for every CVODE step and failure,
// a tick per controller tick, and profiling changes no bit of the result.
TEST(StepProfileTest, ProfilesAWalkWithoutChangingIt) {
  const Genome genome =
      LoadGenome(std::string(WALKERS_SOURCE_DIR) + "/data/genomes/bench/authors_case1_biped.json");
  const Model model = BuildModel(BodyOf(genome));
  StepProfile profile(model);
  const EvaluationResult plain = Evaluate(genome, OriginalPreset());
  const EvaluationResult profiled = Evaluate(
      genome, OriginalPreset(), {},
      [&](double t, const State& state, const WalkingController& c) { profile.OnTick(t, state, c); },
      [&](const StepInfo& step) { profile.OnStep(step); });
  EXPECT_EQ(plain.fitness, profiled.fitness);
  EXPECT_EQ(plain.distance, profiled.distance);
  EXPECT_EQ(plain.footsteps, profiled.footsteps);
  EXPECT_EQ(plain.integrator_stats.steps, profiled.integrator_stats.steps);
  EXPECT_EQ(plain.integrator_stats.rhs_evals, profiled.integrator_stats.rhs_evals);
  EXPECT_EQ(plain.integrator_stats.error_test_failures, profiled.integrator_stats.error_test_failures);
  ASSERT_EQ(plain.outcome, Outcome::kWalked) << plain.reason;
  ASSERT_GE(plain.footsteps, 10);  // it walks: the profile sees both single supports

  long steps = 0, error_tests = 0, nonlinear = 0, switches = 0;
  for (const TickProfile& t : profile.Ticks()) {
    steps += t.steps;
    error_tests += t.error_test_failures;
    nonlinear += t.nonlinear_failures;
    switches += t.PairSwitches();
  }
  EXPECT_EQ(steps, plain.integrator_stats.steps);
  EXPECT_EQ(error_tests, plain.integrator_stats.error_test_failures);
  EXPECT_EQ(nonlinear, plain.integrator_stats.nonlinear_failures);
  EXPECT_GT(switches, 0);  // a walk makes and breaks contacts
  EXPECT_EQ(profile.Ticks().size(), 450u);  // 15 s at 30 Hz
  const nlohmann::ordered_json summary = profile.Summary();
  EXPECT_GT(summary["LS"]["ticks"].get<int>(), 0);
  EXPECT_GT(summary["RS"]["ticks"].get<int>(), 0);
  EXPECT_EQ(summary["DS"]["steps"].get<long>() + summary["LS"]["steps"].get<long>() +
                summary["RS"]["steps"].get<long>(),
            plain.integrator_stats.steps);
}

}  // namespace
}  // namespace walkers
