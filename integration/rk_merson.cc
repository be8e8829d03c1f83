#include "integration/rk_merson.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>

namespace walkers {
namespace {

std::string At(double t) { return " at t=" + std::to_string(t); }

}  // namespace

RungeKuttaMerson::RungeKuttaMerson(SecondOrderSystem& system, const IntegratorSettings& settings)
    : system_(system), settings_(settings) {}

void RungeKuttaMerson::Reset(double t0, const SystemState& y0) {
  t_ = t0;
  h_ = kInitialStep;
  stats_ = IntegratorStats{};
  SetState(y0);
}

void RungeKuttaMerson::SetState(const SystemState& y) {
  y_ = y;
  for (int i = 0; i < kNumCoords; ++i) {
    if (system_.Locked(i)) y_.v(i) = 0.0;
  }
}

bool RungeKuttaMerson::Evaluate(const SystemState& y, Derivative* f) {
  ++stats_.rhs_evals;
  f->qd = y.v;
  return system_.Derivatives(y.q, y.v, &f->vd, &f->zd) && f->vd.allFinite();
}

RungeKuttaMerson::StepDecision RungeKuttaMerson::AdjustStepSize(double h, double error_norm, double accuracy,
                                                                bool cut_short) {
  constexpr double kSafety = 0.9, kMinShrink = 0.1, kMaxGrow = 5.0;
  constexpr double kHysteresisLow = 0.9, kHysteresisHigh = 1.2;
  double next;
  if (!std::isfinite(error_norm)) {
    next = kMinShrink * h;
  } else if (error_norm == 0.0) {
    next = kMaxGrow * h;
  } else {
    // the step that would just meet the accuracy
    next = kSafety * h * std::pow(accuracy / error_norm, 1.0 / kErrorOrder);
  }
  // grow only by a worthwhile amount, and not from a step a stop time cut short
  if (next > h && (cut_short || next < kHysteresisHigh * h)) next = h;
  // an accepted step never shrinks the next; a rejected one shrinks it by 10 % at least
  if (next < h) next = error_norm <= accuracy ? h : std::min(next, kHysteresisLow * h);
  next = std::clamp(next, kMinShrink * h, kMaxGrow * h);
  return {next, next >= h};
}

double RungeKuttaMerson::Attempt(const Derivative& f0, double h, SystemState* y1) {
  constexpr double kInfinity = std::numeric_limits<double>::infinity();
  const SystemState& y0 = y_;
  // Hairer, Norsett & Wanner, Solving ODEs I, table 4.1 (Merson), as
  // Simbody's RungeKuttaMersonIntegratorRep::attemptODEStep stages it
  const auto add = [](const SystemState& y, double c, const Derivative& f) {
    SystemState out = y;
    out.q += c * f.qd;
    out.v += c * f.vd;
    out.z += c * f.zd;
    return out;
  };
  const auto sum = [](double a, const Derivative& fa, double b, const Derivative& fb) {
    Derivative out;
    out.qd = a * fa.qd + b * fb.qd;
    out.vd = a * fa.vd + b * fb.vd;
    out.zd = a * fa.zd + b * fb.zd;
    return out;
  };
  Derivative f1, f2, f3, f4;
  if (!Evaluate(add(y0, h / 3, f0), &f1)) return kInfinity;
  if (!Evaluate(add(y0, h / 6, sum(1, f0, 1, f1)), &f2)) return kInfinity;
  if (!Evaluate(add(y0, h / 8, sum(1, f0, 3, f2)), &f3)) return kInfinity;
  Derivative d = sum(1, f0, -3, f2);
  d = sum(1, d, 4, f3);
  const SystemState y_check = add(y0, h / 2, d);  // f0 - 3 f2 + 4 f3
  if (!Evaluate(y_check, &f4)) return kInfinity;
  d = sum(1, f0, 4, f3);
  d = sum(1, d, 1, f4);
  *y1 = add(y0, h / 6, d);  // f0 + 4 f3 + f4

  // the third-order embedded solution's error, 0.2 |y1 - y_check|, in the system's coordinates
  LocalError error = system_.EstimateError(*y1, y_check, 0.2);
  const double unprojected = system_.ErrorNorm(error, y0);
  if (!std::isfinite(unprojected)) return kInfinity;
  // far off: a half step would not meet the accuracy, so projecting cannot save it
  if (unprojected > std::pow(2.0, kErrorOrder) * settings_.accuracy) return unprojected;
  // the constraints, unless they are off by more than sqrt of their tolerance
  // (or twice it): the step fails (AbstractIntegratorRep::attemptDAEStep)
  const double tolerance = settings_.constraint_tolerance;
  const double limit = std::max(2 * tolerance, std::sqrt(tolerance));
  if (system_.ProjectPositions(y1, &error, tolerance, limit) == Projection::kFailed ||
      system_.ProjectVelocities(y1, &error, tolerance, limit) == Projection::kFailed) {
    ++stats_.nonlinear_failures;
    return kInfinity;
  }
  return system_.ErrorNorm(error, y0);
}

IntegrationStatus RungeKuttaMerson::AdvanceTo(double t_stop) {
  IntegrationStatus status;
  while (t_ < t_stop) {
    if (stats_.steps >= settings_.step_budget) {
      status.failure = IntegrationFailure::kStepBudget;
      status.reason = "step budget of " + std::to_string(settings_.step_budget) + " steps exhausted" + At(t_);
      return status;
    }
    // the derivatives at the step's start, under what the system holds now
    Derivative f0;
    if (!Evaluate(y_, &f0)) {
      status.failure = IntegrationFailure::kNonFinite;
      status.reason = "non-finite accelerations" + At(t_);
      return status;
    }
    const long error_tests_before = stats_.error_test_failures, projections_before = stats_.nonlinear_failures;
    const double t0 = t_;
    SystemState y1;
    double t1 = t0;
    for (;;) {
      // end on the stop time when it is near, and note when that cuts the step short
      bool cut_short = false;
      if (t_stop < t0 + 0.95 * h_) {
        cut_short = true;
        t1 = t_stop;
      } else if (t_stop > t0 + 1.001 * h_) {
        t1 = t0 + h_;
      } else {
        t1 = t_stop;
      }
      if (!(t1 > t0)) {
        status.failure = IntegrationFailure::kSolver;
        status.reason = "the step size fell to " + std::to_string(h_) + " s: unable to advance time" + At(t0);
        return status;
      }
      const double error_norm = Attempt(f0, t1 - t0, &y1);
      const StepDecision decision = AdjustStepSize(h_, error_norm, settings_.accuracy, cut_short);
      h_ = decision.next_step;
      if (decision.accepted) break;
      ++stats_.error_test_failures;
    }
    t_ = t1;
    y_ = y1;
    ++stats_.steps;
    if (observer_) {
      StepInfo info;
      info.t = t_;
      info.step = t1 - t0;
      info.order = kErrorOrder;
      info.error_test_failures = stats_.error_test_failures - error_tests_before;
      info.nonlinear_failures = stats_.nonlinear_failures - projections_before;
      info.state = &y_;
      observer_(info);
    }
  }
  return status;
}

}  // namespace walkers
