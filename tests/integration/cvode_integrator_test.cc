#include "integration/cvode_integrator.h"

#include <cmath>
#include <vector>

#include <gtest/gtest.h>

#include "tests/integration/small_systems.h"

namespace walkers {
namespace {

// CVODE on a small system: difference-quotient Jacobians (it has no
// analytic one) on the dense matrix, relative and absolute tolerances alike
IntegratorSettings SmallSystemSettings(double tolerance, bool locate_switches) {
  IntegratorSettings s;
  s.relative_tolerance = s.absolute_tolerance_position = s.absolute_tolerance_velocity = tolerance;
  s.jacobian = JacobianSource::kFiniteDifference;
  s.linear_solver = LinearSolver::kDense;
  s.locate_contact_switches = locate_switches;
  return s;
}

struct Bounce {
  std::vector<double> step_ends;  // [s]
  IntegratorStats stats;
  SystemState end;
};

// the ball dropped from q = 1/2 at rest, to t = 2.5 (one landing, one
// lift-off, in flight again) in ticks of 1/30 s, as the walker is advanced
Bounce DropTheBall(bool locate_switches) {
  BallOnSpringGround ball;
  CvodeIntegrator cvode(ball, SmallSystemSettings(1e-8, locate_switches));
  Bounce bounce;
  cvode.SetStepObserver([&](const StepInfo& step) { bounce.step_ends.push_back(step.t); });
  SystemState start;
  start.q(0) = 0.5;
  cvode.Reset(0.0, start);
  for (int tick = 1; tick <= 75; ++tick) EXPECT_TRUE(cvode.AdvanceTo(tick / 30.0).ok()) << "tick " << tick;
  bounce.stats = cvode.stats();
  bounce.end = cvode.state();
  return bounce;
}

double NearestTo(const std::vector<double>& times, double t) {
  double nearest = times.front();
  for (double x : times) {
    if (std::abs(x - t) < std::abs(nearest - t)) nearest = x;
  }
  return nearest;
}

TEST(CvodeIntegratorTest, LocatesAContactSwitchAndRestartsThere) {
  const BallOnSpringGround ball;
  const double landing = 1.0, lift_off = ball.LiftOffTime();
  const Bounce located = DropTheBall(true);
  const Bounce stepped = DropTheBall(false);

  // the landing and the lift-off, each found and restarted at: a step ends there
  EXPECT_EQ(located.stats.switches_located, 2);
  EXPECT_EQ(located.stats.restarts, 2);
  EXPECT_NEAR(NearestTo(located.step_ends, landing), landing, 1e-7);
  EXPECT_NEAR(NearestTo(located.step_ends, lift_off), lift_off, 1e-7);
  EXPECT_EQ(stepped.stats.switches_located, 0);
  EXPECT_EQ(stepped.stats.restarts, 0);

  // both follow the exact flight after the lift-off: q' = +1 there
  const double s = 2.5 - lift_off;
  for (const Bounce* b : {&located, &stepped}) {
    EXPECT_NEAR(b->end.q(0), s - 0.5 * s * s, 1e-5);
    EXPECT_NEAR(b->end.v(0), 1.0 - s, 1e-5);
  }

  // the steps stay in proportion: no storm of restarts, and no more than
  // twice what stepping through the switches takes
  EXPECT_GT(located.stats.steps, 10);
  EXPECT_LT(located.stats.steps, 2 * stepped.stats.steps);
  RecordProperty("steps_located", static_cast<int>(located.stats.steps));
  RecordProperty("steps_stepped", static_cast<int>(stepped.stats.steps));
}

}  // namespace
}  // namespace walkers
