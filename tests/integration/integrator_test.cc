#include "integration/integrator.h"

#include <cmath>
#include <random>
#include <vector>

#include <gtest/gtest.h>

#include "control/genome.h"
#include "control/start_pose.h"
#include "dynamics/energy.h"
#include "dynamics/observation.h"
#include "tests/finite_difference.h"

namespace walkers {
namespace {

// tight tolerances for the conservation and closed-form checks
IntegratorSettings Tight() {
  IntegratorSettings s;
  s.relative_tolerance = 1e-10;
  s.absolute_tolerance_position = 1e-11;
  s.absolute_tolerance_velocity = 1e-10;
  return s;
}

Model GravityOnly() {
  ModelOptions options;
  options.contact = false;
  options.joint_stops = false;
  return BuildModel(BodyOf(DefaultGenome()), options);
}

// Inputs with both feet planted where the state has them, no torques.
Inputs BothFeetPlanted(const Model& m, const State& s) {
  Inputs inputs;
  for (int leg = 0; leg < kNumLegs; ++leg) inputs.welds[leg] = PlantFoot(m, s, leg);
  return inputs;
}

double TotalEnergy(const Model& m, const State& s) {
  const Observation o = Observe(m, s);
  return o.kinetic + o.potential;
}

TEST(IntegratorTest, GravityOnlyConservesEnergyOfSwingingLegs) {
  // the trunk held fixed in the air; the two legs swing as chaotic triple
  // pendulums for 2 s
  Model m = GravityOnly();
  m.options.locked[kX] = m.options.locked[kY] = m.options.locked[kPitch] = true;
  std::mt19937 rng(7);
  State s;
  s.q = testing::RandomVector<kNumCoords>(rng, -1.0, 1.0);
  s.q(kY) = 3.0;
  s.v.tail<6>() = testing::RandomVector<6>(rng, -3.0, 3.0);
  Integrator integrator(m, Tight());
  integrator.Reset(0.0, s);
  const double e0 = TotalEnergy(m, integrator.state());
  double kinetic_seen = 0.0;
  for (int i = 1; i <= 200; ++i) {
    ASSERT_TRUE(integrator.AdvanceTo(0.01 * i).ok());
    const double e = TotalEnergy(m, integrator.state());
    kinetic_seen = std::max(kinetic_seen, Observe(m, integrator.state()).kinetic);
    ASSERT_NEAR(e, e0, 1e-7 * std::abs(e0)) << "t=" << integrator.time();
  }
  EXPECT_GT(kinetic_seen, 1.0);  // the legs really moved
}

TEST(IntegratorTest, GravityOnlyConservesEnergyOfTheFreeWalker) {
  // the whole walker thrown spinning into the air, joints free
  const Model m = GravityOnly();
  std::mt19937 rng(11);
  State s;
  s.q = testing::RandomVector<kNumCoords>(rng, -1.0, 1.0);
  s.v = testing::RandomVector<kNumCoords>(rng, -2.0, 2.0);
  Integrator integrator(m, Tight());
  integrator.Reset(0.0, s);
  const double e0 = TotalEnergy(m, s);
  for (int i = 1; i <= 20; ++i) {
    ASSERT_TRUE(integrator.AdvanceTo(0.1 * i).ok());
    ASSERT_NEAR(TotalEnergy(m, integrator.state()), e0, 1e-7 * std::abs(e0));
  }
  EXPECT_LT(integrator.state().q(kY), s.q(kY) - 5.0);  // it fell
}

TEST(IntegratorTest, SingleLinkPendulumHasItsClosedFormPeriod) {
  // everything locked but the left hip: the straight left leg is a compound
  // pendulum about the hip. T = 4 sqrt(I / (m g d)) K(sin(theta0 / 2)).
  Model m = GravityOnly();
  for (int i = 0; i < kNumCoords; ++i) m.options.locked[i] = i != kHipL;
  const double lf = m.body.femur_length, l = m.leg_length();
  const double inertia = m.knee_mass * lf * lf + m.ankle_mass * l * l + m.femur_inertia + m.tibia_inertia +
                         m.foot_inertia;
  const double mgd = m.options.gravity * (m.knee_mass * lf + m.ankle_mass * l);
  const double theta0 = 1.0;
  const double period = 4.0 * std::sqrt(inertia / mgd) * std::comp_ellint_1(std::sin(theta0 / 2.0));

  State s;
  s.q(kY) = 5.0;
  s.q(kHipL) = theta0;
  Integrator integrator(m, Tight());
  integrator.Reset(0.0, s);
  // times where the hip angle crosses zero going down, by linear interpolation
  std::vector<double> crossings;
  double t_prev = 0.0, q_prev = theta0;
  const double dt = 1e-4;
  while (crossings.size() < 3) {
    ASSERT_TRUE(integrator.AdvanceTo(t_prev + dt).ok());
    const double q = integrator.state().q(kHipL);
    if (q_prev > 0.0 && q <= 0.0) crossings.push_back(t_prev + dt * q_prev / (q_prev - q));
    t_prev = integrator.time();
    q_prev = q;
    ASSERT_LT(t_prev, 10 * period);
  }
  EXPECT_NEAR(crossings[1] - crossings[0], period, 1e-6 * period);
  EXPECT_NEAR(crossings[2] - crossings[1], period, 1e-6 * period);
  // the small-angle period differs by ~6 %: the test tells the two apart
  EXPECT_GT(std::abs(period - 2 * M_PI * std::sqrt(inertia / mgd)), 0.05 * period);
}

TEST(IntegratorTest, PassiveDropComesToRestOnTheGroundAndNeverGainsEnergy) {
  const Model m = BuildModel(BodyOf(DefaultGenome()));
  Integrator integrator(m);
  integrator.Reset(0.0, StartState(m));
  const double e0 = TotalEnergy(m, integrator.state());
  double e_max = -1e300;
  // the collapse settles within 10 s: with Simbody's friction, which has no
  // stiction, the limbs creep a while after the fall
  for (int i = 1; i <= 10000; ++i) {
    ASSERT_TRUE(integrator.AdvanceTo(0.001 * i).ok());
    e_max = std::max(e_max, TotalEnergy(m, integrator.state()));
  }
  // energy: never above its initial value (to the integration error)
  EXPECT_LE(e_max, e0 + 1e-6 * e0);
  // at rest on the ground: trunk lying on it, nearly no kinetic energy
  const Observation end = Observe(m, integrator.state());
  EXPECT_TRUE(end.trunk_contact);
  EXPECT_LT(end.kinetic, 0.01);
  EXPECT_LT(integrator.state().v.head<2>().norm(), 1e-3);
  // the ground carries the walker's weight on springs sunk by millimetres
  Kinematics kin;
  ComputeKinematics(m, integrator.state().q, integrator.state().v, &kin);
  double carried = 0.0;
  const ContactReports reports = ReportContacts(m, kin);
  for (int pair = 0; pair < kNumContactPairs; ++pair) {
    if (ContactPairs()[pair].a == ContactBody::kGround) carried += reports[pair].force.y();
  }
  EXPECT_NEAR(carried, m.total_mass * m.options.gravity, 1e-3 * m.total_mass * m.options.gravity);
  EXPECT_GT(end.max_penetration, 0.0);
  EXPECT_LE(end.max_penetration, 0.005);
  // and it lost most of the energy of its fall
  EXPECT_LT(end.kinetic + end.potential, 0.2 * e0);
}

// max foot displacement from its weld over a run
struct WeldDrift {
  double position = 0, angle = 0;
};

WeldDrift RunPlanted(const Model& m, double duration) {
  const State start = StartState(m);
  Inputs inputs = BothFeetPlanted(m, start);
  Integrator integrator(m);
  integrator.Reset(0.0, start, inputs);
  WeldDrift drift;
  for (int i = 1; i <= duration * 1000; ++i) {
    EXPECT_TRUE(integrator.AdvanceTo(0.001 * i).ok());
    Kinematics kin;
    ComputeKinematics(m, integrator.state().q, integrator.state().v, &kin);
    for (int leg = 0; leg < kNumLegs; ++leg) {
      drift.position = std::max(drift.position, (kin.legs[leg].ankle.p - inputs.welds[leg].anchor).norm());
      drift.angle = std::max(drift.angle, std::abs(kin.legs[leg].foot.angle));
    }
  }
  return drift;
}

TEST(IntegratorTest, PlantedFeetHoldTheStandingWalkersWeight) {
  // joints locked: the walker stands rigidly and its whole weight is on the welds
  Model m = BuildModel(BodyOf(DefaultGenome()));
  for (int i = kHipL; i < kNumCoords; ++i) m.options.locked[i] = true;
  const WeldDrift drift = RunPlanted(m, 2.0);
  EXPECT_LT(drift.position, 1e-3);
  EXPECT_LT(drift.angle, 0.01);
  EXPECT_GT(drift.position, 0.0);
}

TEST(IntegratorTest, PlantedFeetHoldWhileTheLimpWalkerCollapsesOnThem) {
  const Model m = BuildModel(BodyOf(DefaultGenome()));
  const WeldDrift drift = RunPlanted(m, 2.0);
  EXPECT_LT(drift.position, 1e-3);
  EXPECT_LT(drift.angle, 0.01);
}

TEST(IntegratorTest, StepBudgetExhaustionIsReportedNotFatal) {
  const Model m = BuildModel(BodyOf(DefaultGenome()));
  IntegratorSettings settings;
  settings.step_budget = 50;
  Integrator integrator(m, settings);
  integrator.Reset(0.0, StartState(m));
  const IntegrationStatus status = integrator.AdvanceTo(2.0);
  EXPECT_FALSE(status.ok());
  EXPECT_EQ(status.failure, IntegrationFailure::kStepBudget);
  EXPECT_NE(status.reason.find("step budget"), std::string::npos);
  EXPECT_LT(integrator.time(), 2.0);
}

TEST(IntegratorTest, NonFiniteStateIsReportedNotFatal) {
  const Model m = BuildModel(BodyOf(DefaultGenome()));
  Integrator integrator(m);
  State s = StartState(m);
  s.v(kHipL) = std::numeric_limits<double>::quiet_NaN();
  integrator.Reset(0.0, s);
  const IntegrationStatus status = integrator.AdvanceTo(0.1);
  EXPECT_FALSE(status.ok());
  EXPECT_EQ(status.failure, IntegrationFailure::kNonFinite);
}

TEST(IntegratorTest, CountsStepsAndRightHandSidesAcrossRestarts) {
  const Model m = BuildModel(BodyOf(DefaultGenome()));
  Integrator integrator(m);
  const State start = StartState(m);
  Inputs inputs = BothFeetPlanted(m, start);
  integrator.Reset(0.0, start, inputs);
  ASSERT_TRUE(integrator.AdvanceTo(0.5).ok());
  const IntegratorStats first = integrator.stats();
  inputs.welds[kLeft].active = false;
  integrator.SetWelds(inputs.welds);  // a weld switched: a restart
  ASSERT_TRUE(integrator.AdvanceTo(1.0).ok());
  const IntegratorStats second = integrator.stats();
  EXPECT_GT(first.steps, 0);
  EXPECT_GT(second.steps, first.steps);
  EXPECT_GT(second.rhs_evals, first.rhs_evals);
  EXPECT_GE(second.rhs_evals, second.steps);
  EXPECT_EQ(second.restarts, 1);
}

TEST(IntegratorTest, ANewStateIsTakenAtTheCurrentTimeWithARestart) {
  const Model m = BuildModel(BodyOf(DefaultGenome()));
  Integrator integrator(m);
  const State start = StartState(m);
  Inputs inputs = BothFeetPlanted(m, start);
  integrator.Reset(0.0, start, inputs);
  ASSERT_TRUE(integrator.AdvanceTo(0.2).ok());
  // a jump, as a projection at planting makes: the walker given a push
  State pushed = integrator.state();
  pushed.v(kX) += 0.5;
  integrator.SetState(pushed);
  EXPECT_EQ(integrator.state().v, pushed.v);
  EXPECT_EQ(integrator.time(), 0.2);
  ASSERT_TRUE(integrator.AdvanceTo(0.2 + 1e-9).ok());
  EXPECT_EQ(integrator.stats().restarts, 1);
  // CVODE went on from the new state, not from its old history
  EXPECT_NEAR(integrator.state().v(kX), pushed.v(kX), 1e-5);
}

TEST(IntegratorTest, RestartsAndRetriesWhenATorqueJumpDefeatsCvodesHistory) {
  // tight tolerances and large torque jumps at every 30 Hz tick: without a
  // restart CVODE's error test cannot pass right after a jump, so AdvanceTo
  // must restart there and carry on
  const Model m = BuildModel(BodyOf(DefaultGenome()));
  IntegratorSettings settings = Tight();
  settings.restart_at_ticks = false;
  Integrator integrator(m, settings);
  const State start = StartState(m);
  Inputs inputs = BothFeetPlanted(m, start);
  integrator.Reset(0.0, start, inputs);
  for (int tick = 0; tick < 30; ++tick) {
    for (int i = kHipL; i < kNumCoords; ++i) inputs.joint_torque(i) = (tick % 2 ? 4000.0 : -4000.0) * (i % 3 + 1);
    integrator.SetTorques(inputs.joint_torque);
    const IntegrationStatus status = integrator.AdvanceTo((tick + 1) / kControlRate);
    ASSERT_TRUE(status.ok()) << "tick " << tick << ": " << status.reason;
  }
  EXPECT_GE(integrator.stats().restarts, 1);
  EXPECT_NEAR(integrator.time(), 1.0, 1e-12);
}

// A step observer makes CVODE go one step at a time under the same stop
// times: the same steps, so the same bits, across weld switches (restarts)
// and torque jumps; it sees every step, with its failures, once.
TEST(IntegratorTest, AStepObserverSeesEveryStepAndChangesNoBit) {
  const Model m = BuildModel(BodyOf(DefaultGenome()));
  const State start = StartState(m);
  struct Run {
    State state;
    IntegratorStats stats;
    std::vector<StepInfo> steps;
  };
  const auto run = [&](bool observe) {
    Run out;
    Integrator integrator(m);
    if (observe) integrator.SetStepObserver([&](const StepInfo& step) { out.steps.push_back(step); });
    Inputs inputs = BothFeetPlanted(m, start);
    integrator.Reset(0.0, start, inputs);
    for (int tick = 0; tick < 30; ++tick) {
      if (tick == 10) {
        inputs.welds[kLeft].active = false;  // a restart
        integrator.SetWelds(inputs.welds);
      }
      inputs.joint_torque(kHipR) = tick % 2 ? 40.0 : -40.0;
      integrator.SetTorques(inputs.joint_torque);
      EXPECT_TRUE(integrator.AdvanceTo((tick + 1) / kControlRate).ok()) << "tick " << tick;
    }
    out.state = integrator.state();
    out.stats = integrator.stats();
    return out;
  };
  const Run plain = run(false), observed = run(true);
  EXPECT_EQ(plain.state.q, observed.state.q);
  EXPECT_EQ(plain.state.v, observed.state.v);
  EXPECT_EQ(plain.stats.steps, observed.stats.steps);
  EXPECT_EQ(plain.stats.rhs_evals, observed.stats.rhs_evals);
  EXPECT_EQ(plain.stats.error_test_failures, observed.stats.error_test_failures);
  EXPECT_EQ(plain.stats.nonlinear_failures, observed.stats.nonlinear_failures);
  EXPECT_EQ(plain.stats.restarts, observed.stats.restarts);
  EXPECT_TRUE(plain.steps.empty());

  ASSERT_EQ(static_cast<long>(observed.steps.size()), observed.stats.steps);
  long error_tests = 0, nonlinear = 0;
  double t = 0.0;
  for (const StepInfo& step : observed.steps) {
    EXPECT_GT(step.t, t);
    EXPECT_NEAR(step.t - t, step.step, 1e-12);  // each step starts where the last ended
    t = step.t;
    EXPECT_GE(step.order, 1);
    EXPECT_LE(step.order, 5);
    EXPECT_GT(step.weighted_error.maxCoeff(), 0.0);
    error_tests += step.error_test_failures;
    nonlinear += step.nonlinear_failures;
  }
  EXPECT_EQ(error_tests, observed.stats.error_test_failures);
  EXPECT_EQ(nonlinear, observed.stats.nonlinear_failures);
  EXPECT_NEAR(t, 1.0, 1e-12);
}

TEST(IntegratorTest, AStepObserverKeepsTheStepBudget) {
  const Model m = BuildModel(BodyOf(DefaultGenome()));
  IntegratorSettings settings;
  settings.step_budget = 50;
  long observed = 0;
  Integrator plain(m, settings), stepped(m, settings);
  stepped.SetStepObserver([&](const StepInfo&) { ++observed; });
  plain.Reset(0.0, StartState(m));
  stepped.Reset(0.0, StartState(m));
  const IntegrationStatus a = plain.AdvanceTo(2.0), b = stepped.AdvanceTo(2.0);
  EXPECT_EQ(b.failure, IntegrationFailure::kStepBudget);
  EXPECT_EQ(a.reason, b.reason);
  EXPECT_EQ(plain.time(), stepped.time());
  EXPECT_EQ(plain.state().q, stepped.state().q);
  EXPECT_EQ(observed, 50);
  EXPECT_EQ(stepped.stats().steps, 50);
}

TEST(IntegratorTest, IsDeterministic) {
  const Model m = BuildModel(BodyOf(DefaultGenome()));
  auto run = [&] {
    Integrator integrator(m);
    integrator.Reset(0.0, StartState(m));
    EXPECT_TRUE(integrator.AdvanceTo(1.5).ok());
    return integrator.state();
  };
  const State a = run(), b = run();
  EXPECT_EQ(a.q, b.q);
  EXPECT_EQ(a.v, b.v);
}

}  // namespace
}  // namespace walkers
