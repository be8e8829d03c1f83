#include "integration/walker_system.h"

#include <algorithm>
#include <cmath>
#include <tuple>

#include "dynamics/contact.h"
#include "dynamics/jacobian.h"
#include "dynamics/kinematics.h"
#include "dynamics/planting.h"

namespace walkers {
namespace {

// Simbody's coordinates of the authors' model: three free bodies (a unit
// quaternion and a position each: 7 q's, 6 u's) and six pins
constexpr int kSimbodyQs = 3 * 7 + 6;
constexpr int kSimbodyUs = 3 * 6 + 6;
static_assert(kNumFreeBodyCoords <= LocalError::kMaxSize);

// the free bodies' angles among the planar coordinates
constexpr bool IsTurn(int i) { return i == kTrunkX + 2 || i == FootCoord(kLeft) + 2 || i == FootCoord(kRight) + 2; }

Projection Outcome(ProjectionOutcome outcome) {
  switch (outcome) {
    case ProjectionOutcome::kUnchanged:
      return Projection::kUnchanged;
    case ProjectionOutcome::kProjected:
      return Projection::kProjected;
    case ProjectionOutcome::kFailed:
      break;
  }
  return Projection::kFailed;
}

}  // namespace

WalkerSystem::WalkerSystem(const Model& model) : model_(model) {}

bool WalkerSystem::Accelerations(const Vec9& q, const Vec9& v, Vec9* a) {
  workspace_.count_dissipation = false;
  return ForwardDynamics(model_, inputs_, q, v, &workspace_, a);
}

bool WalkerSystem::AccelerationJacobian(const Vec9& q, const Vec9& v, Mat9* da_dq, Mat9* da_dv) {
  return walkers::AccelerationJacobian(model_, inputs_, q, v, &workspace_, da_dq, da_dv);
}

int WalkerSystem::NumSwitchFunctions() const {
  return std::tuple_size_v<ContactSwitches> + std::tuple_size_v<JointStopSwitches>;
}

void WalkerSystem::SwitchFunctions(const Vec9& q, const Vec9& /*v*/, double* g) {
  // positions alone decide where a contact or a stop switches
  ComputeKinematics(model_, q, Vec9::Zero(), &switch_kinematics_);
  const ContactSwitches contacts = ContactSwitchDepths(model_, switch_kinematics_, inputs_.welds);
  const JointStopSwitches stops = JointStopMargins(model_, q);
  std::copy(contacts.begin(), contacts.end(), g);
  std::copy(stops.begin(), stops.end(), g + contacts.size());
}

bool WalkerSystem::Derivatives(const Vec9& q, const Vec9& v, Vec9* a, double* z_rate) {
  workspace_.count_dissipation = true;
  if (!ForwardDynamics(model_, inputs_, q, v, &workspace_, a)) return false;
  *z_rate = workspace_.contact_dissipation;
  return std::isfinite(*z_rate);
}

LocalError WalkerSystem::EstimateError(const SystemState& y1, const SystemState& y_check, double factor) const {
  const FreeBodyState a = free_bodies_.Get(model_, y1), b = free_bodies_.Get(model_, y_check);
  LocalError e;
  e.q_size = kSimbodyQs;
  e.u_size = kSimbodyUs;
  e.z_size = 1;
  for (int i = 0; i < kNumFreeBodyCoords; ++i) {
    if (IsTurn(i)) {
      // the quaternion (cos th/2, 0, 0, sin th/2): its components' errors,
      // of which the part along the sphere at y1 is the turn's (N N^+ in
      // Simbody's scaleDQ), as the angle it stands for
      const double c_err = factor * std::abs(std::cos(0.5 * a.z(i)) - std::cos(0.5 * b.z(i)));
      const double s_err = factor * std::abs(std::sin(0.5 * a.z(i)) - std::sin(0.5 * b.z(i)));
      e.q(i) = 2.0 * (-std::sin(0.5 * a.z(i)) * c_err + std::cos(0.5 * a.z(i)) * s_err);
    } else {
      e.q(i) = factor * std::abs(a.z(i) - b.z(i));
    }
    e.u(i) = factor * std::abs(a.u(i) - b.u(i));
  }
  e.z = factor * std::abs(y1.z - y_check.z);
  return e;
}

double WalkerSystem::ErrorNorm(const LocalError& error, const SystemState& y0) const {
  const FreeBodyState start = free_bodies_.Get(model_, y0);
  double q_sum = 0, u_sum = 0;
  for (int i = 0; i < kNumFreeBodyCoords; ++i) {
    // a unit quaternion's change is half its turn's angle
    const double q = IsTurn(i) ? 0.5 * error.q(i) : error.q(i);
    q_sum += q * q;
    const double u = error.u(i) / std::max(1.0, std::abs(start.u(i)));
    u_sum += u * u;
  }
  return std::max({std::sqrt(q_sum / error.q_size), std::sqrt(u_sum / error.u_size),
                   error.z / std::max(1.0, std::abs(y0.z))});
}

Projection WalkerSystem::ProjectPositions(SystemState* y, LocalError* error, double tolerance, double limit) {
  FreeBodyState s = free_bodies_.Get(model_, *y);
  FreeBodyVector e = error->q.head<kNumFreeBodyCoords>();
  const SimbodyProjection how{tolerance, limit, true};
  const ProjectionOutcome outcome = ProjectFreeBodyPositions(model_, inputs_.welds, how, &s.z, &e);
  if (outcome == ProjectionOutcome::kProjected) {
    y->q = FromFreeBodies(s).q;
    error->q.head<kNumFreeBodyCoords>() = e;
  }
  return Outcome(outcome);
}

Projection WalkerSystem::ProjectVelocities(SystemState* y, LocalError* error, double tolerance, double limit) {
  FreeBodyState s = free_bodies_.Get(model_, *y);
  FreeBodyVector e = error->u.head<kNumFreeBodyCoords>();
  const SimbodyProjection how{tolerance, limit, true};
  const ProjectionOutcome outcome = ProjectFreeBodyRates(model_, inputs_.welds, how, s.z, &s.u, &e);
  if (outcome == ProjectionOutcome::kProjected) {
    y->v = FromFreeBodies(s).v;
    error->u.head<kNumFreeBodyCoords>() = e;
  }
  return Outcome(outcome);
}

}  // namespace walkers
