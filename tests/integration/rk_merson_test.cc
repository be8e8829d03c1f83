#include "integration/rk_merson.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <memory>
#include <tuple>
#include <utility>

#include <gtest/gtest.h>

#include "control/genome.h"
#include "control/start_pose.h"
#include "dynamics/kinematics.h"
#include "dynamics/planting.h"
#include "integration/cvode_integrator.h"
#include "integration/integrator.h"
#include "integration/walker_system.h"
#include "tests/integration/small_systems.h"

namespace walkers {
namespace {

IntegratorSettings Merson(double accuracy) {
  IntegratorSettings s;
  s.method = IntegrationMethod::kRkMerson;
  s.accuracy = accuracy;
  return s;
}

// A method on a small system: RK-Merson at `accuracy`, or CVODE at
// `tolerance` (relative and absolute alike) with difference-quotient Jacobians.
std::unique_ptr<TimeStepper> MethodOn(SecondOrderSystem& system, IntegrationMethod method, double accuracy,
                                      double tolerance) {
  IntegratorSettings settings = Merson(accuracy);
  settings.method = method;
  if (method == IntegrationMethod::kRkMerson) return std::make_unique<RungeKuttaMerson>(system, settings);
  settings.relative_tolerance = settings.absolute_tolerance_position = settings.absolute_tolerance_velocity = tolerance;
  settings.jacobian = JacobianSource::kFiniteDifference;
  settings.linear_solver = LinearSolver::kDense;
  return std::make_unique<CvodeIntegrator>(system, settings);
}

// ---- the step size control, decision by decision (AbstractIntegratorRep::adjustStepSize) ----

TEST(RungeKuttaMersonTest, AStepWithinTheAccuracyIsAcceptedAndGrowsTheNextByTheErrorsFourthRoot) {
  const auto d = RungeKuttaMerson::AdjustStepSize(0.01, 0.05 / 16, 0.05, false);
  EXPECT_TRUE(d.accepted);
  EXPECT_NEAR(d.next_step, 0.9 * 0.01 * 2.0, 1e-15);  // 0.9 h (16)^(1/4)
}

TEST(RungeKuttaMersonTest, GrowthIsCappedAtFiveTimes) {
  EXPECT_DOUBLE_EQ(RungeKuttaMerson::AdjustStepSize(0.01, 1e-12, 0.05, false).next_step, 0.05);
  EXPECT_DOUBLE_EQ(RungeKuttaMerson::AdjustStepSize(0.01, 0.0, 0.05, false).next_step, 0.05);
}

TEST(RungeKuttaMersonTest, ASmallGrowthOrOneAfterAStepCutShortKeepsTheStep) {
  // 0.9 (0.05 / e)^(1/4) = 1.1: under the 1.2 threshold
  const double e = 0.05 * std::pow(0.9 / 1.1, 4);
  const auto small = RungeKuttaMerson::AdjustStepSize(0.01, e, 0.05, false);
  EXPECT_TRUE(small.accepted);
  EXPECT_EQ(small.next_step, 0.01);
  const auto cut = RungeKuttaMerson::AdjustStepSize(0.01, 0.05 / 16, 0.05, true);
  EXPECT_TRUE(cut.accepted);
  EXPECT_EQ(cut.next_step, 0.01);
}

TEST(RungeKuttaMersonTest, AnAcceptedStepJustWithinTheAccuracyKeepsTheStep) {
  // 0.9 (1)^(1/4) h would shrink it, but the step met the accuracy
  const auto d = RungeKuttaMerson::AdjustStepSize(0.01, 0.05, 0.05, false);
  EXPECT_TRUE(d.accepted);
  EXPECT_EQ(d.next_step, 0.01);
}

TEST(RungeKuttaMersonTest, AStepBeyondTheAccuracyIsRejectedAndShrinksByTenPerCentAtLeastAndNinetyAtMost) {
  const auto slight = RungeKuttaMerson::AdjustStepSize(0.01, 0.051, 0.05, false);
  EXPECT_FALSE(slight.accepted);
  EXPECT_NEAR(slight.next_step, 0.9 * 0.01 * std::pow(0.05 / 0.051, 0.25), 1e-15);
  const auto far = RungeKuttaMerson::AdjustStepSize(0.01, 0.05 * 16, 0.05, false);
  EXPECT_FALSE(far.accepted);
  EXPECT_NEAR(far.next_step, 0.9 * 0.01 / 2.0, 1e-15);
  const auto very_far = RungeKuttaMerson::AdjustStepSize(0.01, 1e9, 0.05, false);
  EXPECT_FALSE(very_far.accepted);
  EXPECT_DOUBLE_EQ(very_far.next_step, 0.001);
}

TEST(RungeKuttaMersonTest, AFailedAttemptShrinksTheStepTenfold) {
  const auto d = RungeKuttaMerson::AdjustStepSize(0.01, std::numeric_limits<double>::infinity(), 0.05, false);
  EXPECT_FALSE(d.accepted);
  EXPECT_DOUBLE_EQ(d.next_step, 0.001);
  EXPECT_FALSE(RungeKuttaMerson::AdjustStepSize(0.01, std::nan(""), 0.05, false).accepted);
}

// ---- the method on small systems ----

TEST(RungeKuttaMersonTest, OneStepIsFourthOrder) {
  // one step of q'' = -q from (1, 0), cut short by the stop time to h: its
  // error against cos and -sin falls as h^5
  HarmonicOscillator system;
  const auto error_of_one_step = [&](double h) {
    RungeKuttaMerson rk(system, Merson(1.0));  // every step accepted
    SystemState y0;
    y0.q(0) = 1.0;
    rk.Reset(0.0, y0);
    EXPECT_TRUE(rk.AdvanceTo(h).ok());
    EXPECT_EQ(rk.stats().steps, 1);
    return std::hypot(rk.state().q(0) - std::cos(h), rk.state().v(0) + std::sin(h));
  };
  const double e1 = error_of_one_step(0.008), e2 = error_of_one_step(0.004);
  EXPECT_GT(e1, 0.0);
  EXPECT_NEAR(std::log2(e1 / e2), 5.0, 0.1);
}

TEST(RungeKuttaMersonTest, AStepCountsFourRightHandSidesPerAttemptAndOneAtItsStart) {
  HarmonicOscillator system;
  RungeKuttaMerson rk(system, Merson(1e-12));
  SystemState y0;
  y0.q(0) = 1.0;
  rk.Reset(0.0, y0);
  ASSERT_TRUE(rk.AdvanceTo(1.0).ok());
  const IntegratorStats s = rk.stats();
  EXPECT_GT(s.error_test_failures, 0);  // the first step, 0.01 s, is too long for 1e-12
  EXPECT_EQ(s.rhs_evals, 4 * (s.steps + s.error_test_failures) + s.steps);
}

TEST(RungeKuttaMersonTest, APendulumKeepsItsPeriod) {
  // a large swing (1 rad): period 4 sqrt(L/g) K(sin(1/2)) for L = g = 1,
  // timed by the zero crossings of the rate over ten periods at a tight
  // accuracy; K(k) = pi / (2 AGM(1, sqrt(1 - k^2)))
  Pendulum system;
  double a = 1.0, b = std::cos(0.5);
  for (int i = 0; i < 10; ++i) std::tie(a, b) = std::make_pair(0.5 * (a + b), std::sqrt(a * b));
  const double kExactPeriod = 4.0 * M_PI / (2.0 * a);
  for (const IntegrationMethod method : {IntegrationMethod::kRkMerson, IntegrationMethod::kCvode}) {
    const std::unique_ptr<TimeStepper> stepper = MethodOn(system, method, 1e-7, 1e-10);
    SystemState y0;
    y0.q(0) = 1.0;
    stepper->Reset(0.0, y0);
    // from the release the rate turns negative and comes back to 0 at each period's end
    double t_prev = 0.0, v_prev = 0.0, last_crossing = 0.0;
    int crossings = 0;
    for (int i = 1; i <= 72000 && crossings < 20; ++i) {
      const double t = 0.001 * i;
      ASSERT_TRUE(stepper->AdvanceTo(t).ok());
      const double v = stepper->state().v(0);
      if ((v_prev < 0) != (v < 0) && i > 1) {
        last_crossing = t_prev + (t - t_prev) * v_prev / (v_prev - v);
        ++crossings;
      }
      t_prev = t;
      v_prev = v;
    }
    ASSERT_EQ(crossings, 20) << IntegrationMethodName(method);
    EXPECT_NEAR(last_crossing / 10.0, kExactPeriod, 1e-5) << IntegrationMethodName(method);
  }
}

TEST(RungeKuttaMersonTest, AStiffSpringStaysBoundedAndEndsSmaller) {
  // k = 1e6, damped: an explicit method has to keep its steps below ~2.8/sqrt(k)
  StiffSpring system;
  RungeKuttaMerson rk(system, Merson(0.05));
  SystemState y0;
  y0.q(0) = 1e-3;
  rk.Reset(0.0, y0);
  double largest = 0;
  for (int i = 1; i <= 50; ++i) {
    ASSERT_TRUE(rk.AdvanceTo(0.01 * i).ok());
    largest = std::max(largest, std::abs(rk.state().q(0)));
  }
  // the loose accuracy lets the swing grow for a while (the exact one only
  // decays), but the error control keeps the steps within stability
  EXPECT_LT(largest, 3e-3);
  EXPECT_LT(std::abs(rk.state().q(0)), 0.5e-3);
  EXPECT_GT(rk.stats().steps, 100);  // stability, not the stop times 10 ms apart, sets the steps
}

TEST(RungeKuttaMersonTest, AJumpOfTheHeldForceIsFollowedExactly) {
  // q'' = u: a quadratic, which a fourth-order method integrates exactly
  // piece by piece; u jumps at t = 0.5, a stop time, and the step size carries over
  for (const IntegrationMethod method : {IntegrationMethod::kRkMerson, IntegrationMethod::kCvode}) {
    HeldForce system;
    const std::unique_ptr<TimeStepper> stepper = MethodOn(system, method, 0.05, 1e-7);
    system.force = 2.0;
    stepper->Reset(0.0, SystemState{});
    ASSERT_TRUE(stepper->AdvanceTo(0.5).ok());
    system.force = -4.0;
    stepper->MarkJump(Jump::kInputs);
    ASSERT_TRUE(stepper->AdvanceTo(1.0).ok());
    // q(0.5) = 0.25, v(0.5) = 1; then q = 0.25 + 0.5 - 2 (0.5)^2 = 0.25, v = 1 - 2 = -1
    const double tolerance = method == IntegrationMethod::kRkMerson ? 1e-12 : 1e-5;
    EXPECT_NEAR(stepper->state().q(0), 0.25, tolerance) << IntegrationMethodName(method);
    EXPECT_NEAR(stepper->state().v(0), -1.0, tolerance) << IntegrationMethodName(method);
  }
}

TEST(RungeKuttaMersonTest, AStepThatCannotAdvanceFails) {
  // accelerations that are never finite: every attempt fails and shrinks the
  // step tenfold until time cannot advance
  FiniteOnlyAtRest system;
  RungeKuttaMerson rk(system, Merson(0.05));
  rk.Reset(0.0, SystemState{});
  const IntegrationStatus status = rk.AdvanceTo(1.0);
  EXPECT_FALSE(status.ok());
  EXPECT_EQ(status.failure, IntegrationFailure::kSolver) << status.reason;
  EXPECT_NE(status.reason.find("unable to advance"), std::string::npos) << status.reason;
}

// ---- the walker's measure and projection (integration/walker_system.h) ----

TEST(WalkerSystemTest, ATurnCountsHalfItsAngleAndAllOfSimbodysCoordinatesCount) {
  const Model m = BuildModel(BodyOf(DefaultGenome()));
  const WalkerSystem system(m);
  SystemState y;
  static_cast<State&>(y) = StartState(m);
  y.q(kPitch) = 0.0;
  // a trunk that turns by d alone (and the feet with it, on their legs)
  SystemState turned = y;
  const double d = 1e-3;
  turned.q(kPitch) += d;
  turned.q(kHipL) += d;  // keep the legs' absolute angles, so only the trunk turns
  turned.q(kHipR) += d;
  const LocalError e = system.EstimateError(turned, y, 1.0);
  EXPECT_EQ(e.q_size, 27);
  EXPECT_EQ(e.u_size, 24);
  EXPECT_NEAR(e.q(kTrunkX + 2), d, 1e-9);
  // the norm: the turn at half its angle, with the translations its lever
  // arm makes of the trunk's position... here the trunk's centre stays, the
  // hips move, and with them the feet: the pins take up the rest
  double expected = 0;
  for (int i = 0; i < kNumFreeBodyCoords; ++i) {
    const double q = i == kTrunkX + 2 || i == FootCoord(kLeft) + 2 || i == FootCoord(kRight) + 2 ? 0.5 * e.q(i) : e.q(i);
    expected += q * q;
  }
  EXPECT_NEAR(system.ErrorNorm(e, y), std::sqrt(expected / 27.0), 1e-15);
}

TEST(WalkerSystemTest, RatesCountRelativeToTheirSizeAtTheStepsStart) {
  const Model m = BuildModel(BodyOf(DefaultGenome()));
  const WalkerSystem system(m);
  SystemState y;
  static_cast<State&>(y) = StartState(m);
  LocalError e;
  e.q_size = 27;
  e.u_size = 24;
  e.z_size = 1;
  e.u(kTrunkX) = 0.01;  // the trunk's x rate
  y.v(kX) = 0.5;        // below 1: absolute
  EXPECT_NEAR(system.ErrorNorm(e, y), 0.01 / std::sqrt(24.0), 1e-15);
  y.v(kX) = 4.0;  // above 1: relative
  EXPECT_NEAR(system.ErrorNorm(e, y), 0.0025 / std::sqrt(24.0), 1e-15);
  e.z = 2.0;  // dissipated energy: relative to what has been dissipated, where that is above 1 J
  y.z = 100.0;
  EXPECT_NEAR(system.ErrorNorm(e, y), 0.02, 1e-15);
}

TEST(WalkerSystemTest, ProjectionMovesAFootOntoItsWeldOnlyBeyondTheToleranceAndTakesTheErrorAlong) {
  const Model m = BuildModel(BodyOf(DefaultGenome()));
  WalkerSystem system(m);
  const State start = StartState(m);
  Inputs inputs;
  inputs.welds = StartWelds(m);
  system.SetInputs(inputs);
  // the trunk moved, the pins held: both feet leave their welds by 2 cm in x
  SystemState y;
  static_cast<State&>(y) = start;
  y.q(kX) += 0.02;
  LocalError error = system.EstimateError(y, y, 0.2);  // zero
  error.q(FootCoord(kLeft)) = 1e-3;   // along a weld's x: not allowed by it
  error.q(kPins) = 1e-3;              // a pin: allowed
  // RMS over 24 equations (two hips, two feet): 0.02 sqrt(2 / 24) = 5.8e-3
  SystemState unchanged = y;
  EXPECT_EQ(system.ProjectPositions(&unchanged, &error, 0.01, 0.1), Projection::kUnchanged);
  EXPECT_EQ(unchanged.q, y.q);
  SystemState projected = y;
  LocalError projected_error = error;
  ASSERT_EQ(system.ProjectPositions(&projected, &projected_error, 1e-3, 0.1), Projection::kProjected);
  Kinematics kin;
  ComputeKinematics(m, projected.q, projected.v, &kin);
  for (int leg = 0; leg < kNumLegs; ++leg) {
    EXPECT_LT((kin.legs[leg].ankle.p - inputs.welds[leg].anchor).norm(), 1e-3 * std::sqrt(24.0 / 2.0));
  }
  // the foot's x error is taken out (mostly), the rest stays an error
  EXPECT_LT(std::abs(projected_error.q(FootCoord(kLeft))), 0.5e-3);
  EXPECT_GT(projected_error.q.norm(), 0.0);
  // beyond the limit the projection fails and nothing moves
  SystemState far = y;
  far.q(kX) += 1.0;
  EXPECT_EQ(system.ProjectPositions(&far, &error, 0.01, 0.1), Projection::kFailed);
}

TEST(WalkerSystemTest, ZsRateIsTheDissipatedPowerAndNeverNegative) {
  const Model m = BuildModel(BodyOf(DefaultGenome()));
  WalkerSystem system(m);
  // no welds: the feet slide and sink on the ground
  State s = StartState(m);
  s.v(kX) = 0.3;
  s.v(kY) = -0.2;
  Vec9 a;
  double power = -1;
  ASSERT_TRUE(system.Derivatives(s.q, s.v, &a, &power));
  EXPECT_GT(power, 0.0);
  // at rest nothing dissipates
  s.v.setZero();
  ASSERT_TRUE(system.Derivatives(s.q, s.v, &a, &power));
  EXPECT_NEAR(power, 0.0, 1e-9);
}

}  // namespace
}  // namespace walkers
