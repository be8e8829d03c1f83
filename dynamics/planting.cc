#include "dynamics/planting.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include <Eigen/Cholesky>

#include "dynamics/kinematics.h"

namespace walkers {
namespace {

constexpr int kMaxConstraints = 12;  // two hip welds and two foot welds, three equations each
using ConstraintVector = Eigen::Matrix<double, Eigen::Dynamic, 1, 0, kMaxConstraints, 1>;
using ConstraintJacobian = Eigen::Matrix<double, Eigen::Dynamic, kNumFreeBodyCoords, 0, kMaxConstraints, kNumFreeBodyCoords>;

// up a segment of absolute angle a from its lower end: (-sin a, cos a), and its derivative
Vec2 Up(double a) { return Vec2(-std::sin(a), std::cos(a)); }
Vec2 UpPrime(double a) { return Vec2(-std::cos(a), -std::sin(a)); }

// The errors of the hip welds and of the active foot welds, and their
// Jacobian with respect to the free-body coordinates.
void Constraints(const Model& model, const Welds& welds, const FreeBodyVector& z, ConstraintVector* c,
                 ConstraintJacobian* J) {
  const BodyParameters& b = model.body;
  int rows = kNumLegs * 3;
  for (const Weld& w : welds) rows += w.active ? 3 : 0;
  c->setZero(rows);
  J->setZero(rows, kNumFreeBodyCoords);
  const double pitch = z(kTrunkX + 2);
  int row = 0;
  for (int leg = 0; leg < kNumLegs; ++leg) {
    const int f = FootCoord(leg);
    const int a = PinCoord(leg, kAnkle), k = PinCoord(leg, kKnee), h = PinCoord(leg, kHip);
    const double tibia = z(f + 2) + z(a), femur = tibia + z(k);
    // hip weld: the top of the chain from the foot at the trunk's bottom centre, turned with it
    const Vec2 hip_chain = z.segment<2>(f) + b.tibia_length * Up(tibia) + b.femur_length * Up(femur);
    const Vec2 hip_trunk = z.segment<2>(kTrunkX) + b.half_body_y * Vec2(std::sin(pitch), -std::cos(pitch));
    c->segment<2>(row) = hip_chain - hip_trunk;
    // Simbody's weld measures a turn by the sine of its angle
    (*c)(row + 2) = std::sin(femur + z(h) - pitch);
    const Vec2 d_tibia = b.tibia_length * UpPrime(tibia) + b.femur_length * UpPrime(femur);
    J->block<2, 2>(row, f).setIdentity();
    J->block<2, 1>(row, f + 2) = d_tibia;
    J->block<2, 1>(row, a) = d_tibia;
    J->block<2, 1>(row, k) = b.femur_length * UpPrime(femur);
    // Simbody differentiates the weld's position error by the velocity of the
    // trunk's material point where the chain's top is, not where its own
    // point is: a different lever arm while the weld is open (docs/model.md)
    J->block<2, 2>(row, kTrunkX) = -Eigen::Matrix2d::Identity();
    J->block<2, 1>(row, kTrunkX + 2) = -Perp(hip_chain - z.segment<2>(kTrunkX));
    const double turn = std::cos(femur + z(h) - pitch);
    (*J)(row + 2, f + 2) = (*J)(row + 2, a) = (*J)(row + 2, k) = (*J)(row + 2, h) = turn;
    (*J)(row + 2, kTrunkX + 2) = -turn;
    row += 3;
  }
  for (int leg = 0; leg < kNumLegs; ++leg) {
    if (!welds[leg].active) continue;
    const int f = FootCoord(leg);
    // the welded point of the foot is held where it is when the foot's
    // centre is at the anchor and its angle at the weld's
    const Vec2 w = WeldedFootPoint(model);
    const double angle = z(f + 2), ca = std::cos(angle), sa = std::sin(angle);
    const double cw = std::cos(welds[leg].angle), sw = std::sin(welds[leg].angle);
    const Vec2 point = z.segment<2>(f) + Vec2(ca * w.x() - sa * w.y(), sa * w.x() + ca * w.y());
    const Vec2 target = welds[leg].anchor + Vec2(cw * w.x() - sw * w.y(), sw * w.x() + cw * w.y());
    c->segment<2>(row) = point - target;
    (*c)(row + 2) = std::sin(angle - welds[leg].angle);
    J->block<2, 2>(row, f).setIdentity();
    J->block<2, 1>(row, f + 2) = Perp(target - z.segment<2>(f));  // the lever arm to the ground's point, as above
    (*J)(row + 2, f + 2) = std::cos(angle - welds[leg].angle);
    row += 3;
  }
}

// The x of least weighted norm sum x_i^2 / w_i with J x = r:
// W J^T (J W J^T)^-1 r, W = diag(w).
FreeBodyVector LeastNorm(const ConstraintJacobian& J, const FreeBodyVector& w, const ConstraintVector& r, bool* ok) {
  using Square = Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, 0, kMaxConstraints, kMaxConstraints>;
  const ConstraintJacobian JW = J * w.asDiagonal();
  const Eigen::LLT<Square> llt(JW * J.transpose());
  *ok = llt.info() == Eigen::Success;
  return JW.transpose() * llt.solve(r);
}

// Simbody's projection of positions takes the least-norm change of its q,
// and a free body's orientation is a unit quaternion, whose change is half
// its angle's: so in angles, a free body's turn weighs a quarter of a pin's
// or a translation's in the squared norm (the weights w here are the inverse).
FreeBodyVector PositionWeights() {
  FreeBodyVector w = FreeBodyVector::Ones();
  w(kTrunkX + 2) = 4.0;
  for (int leg = 0; leg < kNumLegs; ++leg) w(FootCoord(leg) + 2) = 4.0;
  return w;
}

}  // namespace

FreeBodyState ToFreeBodies(const Model& model, const State& state) {
  Kinematics kin;
  ComputeKinematics(model, state.q, state.v, &kin);
  FreeBodyState s;
  s.z.segment<3>(kTrunkX) = state.q.segment<3>(kX);
  s.u.segment<3>(kTrunkX) = state.v.segment<3>(kX);
  for (int leg = 0; leg < kNumLegs; ++leg) {
    const LegKinematics& l = kin.legs[leg];
    s.z.segment<2>(FootCoord(leg)) = l.ankle.p;
    s.z(FootCoord(leg) + 2) = l.foot.angle;
    s.u.segment<2>(FootCoord(leg)) = l.ankle.v;
    s.u(FootCoord(leg) + 2) = l.foot.rate;
    for (int joint = 0; joint < kNumJoints; ++joint) {
      s.z(PinCoord(leg, joint)) = state.q(JointIndex(leg, joint));
      s.u(PinCoord(leg, joint)) = state.v(JointIndex(leg, joint));
    }
  }
  return s;
}

State FromFreeBodies(const FreeBodyState& s) {
  State state;
  state.q.segment<3>(kX) = s.z.segment<3>(kTrunkX);
  state.v.segment<3>(kX) = s.u.segment<3>(kTrunkX);
  for (int leg = 0; leg < kNumLegs; ++leg) {
    for (int joint = 0; joint < kNumJoints; ++joint) {
      state.q(JointIndex(leg, joint)) = s.z(PinCoord(leg, joint));
      state.v(JointIndex(leg, joint)) = s.u(PinCoord(leg, joint));
    }
  }
  return state;
}

bool ProjectFreeBodies(const Model& model, const Welds& welds, FreeBodyState* s) {
  FreeBodyVector z = s->z;
  ConstraintVector c;
  ConstraintJacobian J;
  // positions: Gauss-Newton, each step the least-norm one
  bool converged = false;
  for (int iteration = 0; iteration < 20 && z.allFinite(); ++iteration) {
    Constraints(model, welds, z, &c, &J);
    if (c.norm() < 1e-12) {
      converged = true;
      break;
    }
    bool ok = false;
    z -= LeastNorm(J, PositionWeights(), c, &ok);
    if (!ok) return false;
  }
  if (!converged) return false;
  // velocities: one least-squares step, each rate's change measured
  // relative to the rate itself where that exceeds 1, sum (du_i / max(1, |u_i|))^2
  const FreeBodyVector scale = s->u.cwiseAbs().cwiseMax(1.0);
  bool ok = false;
  const FreeBodyVector u = s->u - LeastNorm(J, scale.cwiseProduct(scale), J * s->u, &ok);
  if (!ok || !u.allFinite()) return false;
  s->z = z;
  s->u = u;
  return true;
}

bool ProjectOntoWelds(const Model& model, const Welds& welds, State* state) {
  FreeBodyState s = ToFreeBodies(model, *state);
  if (!ProjectFreeBodies(model, welds, &s)) return false;
  *state = FromFreeBodies(s);
  return true;
}

int SimbodyConstraintEquations(const Welds& welds) {
  int welded = kNumLegs;  // the hips
  for (const Weld& w : welds) welded += w.active ? 1 : 0;
  return 6 * welded;
}

namespace {

// Simbody's RMS of the constraint errors: over its six equations per weld,
// three of which (out of the plane) hold exactly
double SimbodyRms(const ConstraintVector& c, const Welds& welds) {
  return std::sqrt(c.squaredNorm() / SimbodyConstraintEquations(welds));
}

// Simbody aims a tenth below the tolerance (ProjectOptions' overshoot factor)
double AimFor(double tolerance) { return std::max(0.1 * tolerance, std::numeric_limits<double>::epsilon()); }

// An integrator's error estimate without the part that the linearised welds
// J forbid (the vector of least weighted norm with the same image under J),
// as Simbody projects the error estimate with the state
void ProjectOut(const ConstraintJacobian& J, const FreeBodyVector& weights, FreeBodyVector* error) {
  bool ok = false;
  const FreeBodyVector correction = LeastNorm(J, weights, J * *error, &ok);
  if (ok) *error -= correction;
}

}  // namespace

ProjectionOutcome ProjectFreeBodyPositions(const Model& model, const Welds& welds, const SimbodyProjection& how,
                                           FreeBodyVector* z, FreeBodyVector* error) {
  ConstraintVector c;
  ConstraintJacobian J;
  Constraints(model, welds, *z, &c, &J);
  const double on_entry = SimbodyRms(c, welds);
  if (!(on_entry <= how.limit)) return ProjectionOutcome::kFailed;
  if (on_entry == 0.0 || on_entry <= how.tolerance) return ProjectionOutcome::kUnchanged;

  const FreeBodyVector saved = *z;
  const FreeBodyVector weights = PositionWeights();
  double achieved = on_entry, previous = on_entry;
  ConstraintJacobian J_used;  // the matrix of the last iteration, which projects the error estimate
  for (int iteration = 1; iteration <= 20; ++iteration) {
    J_used = J;
    bool ok = false;
    const FreeBodyVector dz = LeastNorm(J, weights, c, &ok);
    if (!ok) return ProjectionOutcome::kFailed;
    *z -= dz;
    Constraints(model, welds, *z, &c, &J);
    achieved = SimbodyRms(c, welds);
    if (how.local_only && iteration >= 2 && achieved > previous) {
      // growing: back to the previous iterate, and stop
      *z += dz;
      Constraints(model, welds, *z, &c, &J);
      achieved = SimbodyRms(c, welds);
      break;
    }
    previous = achieved;
    if (!(achieved > AimFor(how.tolerance))) break;
  }
  if (!(achieved <= how.tolerance)) {
    if (!(achieved < on_entry)) *z = saved;
    return ProjectionOutcome::kFailed;
  }
  if (error) ProjectOut(J_used, weights, error);
  return ProjectionOutcome::kProjected;
}

ProjectionOutcome ProjectFreeBodyRates(const Model& model, const Welds& welds, const SimbodyProjection& how,
                                       const FreeBodyVector& z, FreeBodyVector* u, FreeBodyVector* error) {
  ConstraintVector c;
  ConstraintJacobian J;
  Constraints(model, welds, z, &c, &J);
  ConstraintVector rate_errors = J * *u;
  const double on_entry = SimbodyRms(rate_errors, welds);
  if (!(on_entry <= how.limit)) return ProjectionOutcome::kFailed;
  if (on_entry == 0.0 || on_entry <= how.tolerance) return ProjectionOutcome::kUnchanged;

  // each rate's change measured relative to the rate where it exceeds 1,
  // at the rates on entry
  const FreeBodyVector scale = u->cwiseAbs().cwiseMax(1.0);
  const FreeBodyVector weights = scale.cwiseProduct(scale);
  const FreeBodyVector saved = *u;
  double achieved = on_entry, previous = on_entry;
  for (int iteration = 1; iteration <= 7; ++iteration) {
    bool ok = false;
    const FreeBodyVector du = LeastNorm(J, weights, rate_errors, &ok);
    if (!ok) return ProjectionOutcome::kFailed;
    *u -= du;
    rate_errors = J * *u;
    achieved = SimbodyRms(rate_errors, welds);
    if (how.local_only && iteration >= 2 && achieved > previous) {
      *u += du;
      rate_errors = J * *u;
      achieved = SimbodyRms(rate_errors, welds);
      break;
    }
    previous = achieved;
    if (!(achieved > AimFor(how.tolerance))) break;
  }
  if (!(achieved <= how.tolerance) || !u->allFinite()) {
    if (!(achieved < on_entry)) *u = saved;
    return ProjectionOutcome::kFailed;
  }
  if (error) ProjectOut(J, weights, error);
  return ProjectionOutcome::kProjected;
}

bool ProjectOntoWeldsAsSimbody(const Model& model, const Welds& welds, double tolerance, State* state) {
  SimbodyProjection how;
  how.tolerance = tolerance;
  FreeBodyState s = ToFreeBodies(model, *state);
  if (ProjectFreeBodyPositions(model, welds, how, &s.z) == ProjectionOutcome::kFailed) return false;
  // the rates at the projected positions: ours are the trunk's and the pins',
  // the feet's follow from them
  State moved = FromFreeBodies(s);
  moved.v = state->v;
  s = ToFreeBodies(model, moved);
  if (ProjectFreeBodyRates(model, welds, how, s.z, &s.u) == ProjectionOutcome::kFailed) return false;
  *state = FromFreeBodies(s);
  return true;
}

}  // namespace walkers
