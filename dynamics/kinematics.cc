#include "dynamics/kinematics.h"

#include <cmath>

namespace walkers {
namespace {

// The kinematics are written out per leg at compile time, as in MassMatrix:
// with the leg as a template argument every column of q below is a constant,
// so every entry sits at a constant offset. With the leg read at run time
// (a loop over the legs, ColumnsOf(leg) in a loop over the columns) every
// address was computed at run time, which cost more than the arithmetic.
// Every number is still the same products and sums in the same order.

// ---- absolute angles ----

// The row j of an absolute angle (angle = j q): +1 for the trunk pitch and -1
// for each joint of the leg down to the body, 0 elsewhere.
using AngleRow = std::array<double, kNumCoords>;
constexpr AngleRow BodyAngleRow(int leg, int num_joints) {
  AngleRow j{};
  j[kPitch] = 1.0;
  for (int k = 0; k < num_joints; ++k) j[JointIndex(leg, k)] = -1.0;
  return j;
}
constexpr AngleRow kPitchRow = BodyAngleRow(kLeft, 0);
template <int kLeg>
struct LegAngleRows {
  static constexpr AngleRow kFemur = BodyAngleRow(kLeg, 1);
  static constexpr AngleRow kTibia = BodyAngleRow(kLeg, 2);
  static constexpr AngleRow kFoot = BodyAngleRow(kLeg, 3);
};

// (q_i, v_i): an angle and its rate are the same sum over q and over v, so
// they are computed together, one in each lane of an SSE2 register.
using PositionVelocity = Eigen::Array2d;
using StatePairs = PositionVelocity[kNumCoords];

// (angle, rate) = (j q, j v) with the products and sums of the Eigen dot
// product this replaced (j.dot(q) of a run-time Row9 and a Vec9, vectorised
// for SSE2): with t_i = j_i x_i,
//   ((t0 + t2) + (t4 + t6)) + ((t1 + t3) + (t5 + t7)), then + t8.
// The zero terms stay: 0 x_i is -0 for a negative x_i, which can decide the
// sign of a zero angle. j known at compile time, the products by ±1 cost
// nothing, and since ComputeKinematics sets all seven angles in one function
// the compiler computes the products and partial sums they share only once.
template <const AngleRow& kJ>
void SetAngle(int leg, const StatePairs& x, AngleKinematics* a) {
  const auto t = [&x](int i) -> PositionVelocity { return kJ[i] * x[i]; };
  const PositionVelocity even = (t(0) + t(2)) + (t(4) + t(6));
  const PositionVelocity odd = (t(1) + t(3)) + (t(5) + t(7));
  const PositionVelocity sum = (even + odd) + t(8);
  a->angle = sum[0];
  a->rate = sum[1];
  a->c = std::cos(a->angle);
  a->s = std::sin(a->angle);
  a->j = Eigen::Map<const Row9>(kJ.data());
  a->leg = leg;
}

// ---- points ----

// The point at r from `base`, rigid with `body`, whose Jacobian is zero
// outside ColumnsOf(kLeg). Every field of `out` is written from `base` and the
// link, as a copy of `base` then updates would, but each once: the copy then
// update of the whole struct wrote p, v, a_bias and J twice. `inline` lets GCC
// inline its five calls into ComputeKinematics, whose hip, knee and ankle then
// pass from one to the next without a call.
template <int kLeg>
inline void OffsetPoint(const PointKinematics& base, const AngleKinematics& body, const Vec2& r, PointKinematics* out) {
  const int num_links = base.num_links;  // read before out, which may be base, changes
  // p = p_base + r(angle): dr/dangle = perp(r), d2r/dangle2 = -r
  const Vec2 perp = Perp(r);
  out->p = base.p + r;
  out->v = base.v + perp * body.rate;
  out->a_bias = base.a_bias - r * (body.rate * body.rate);
  // J = J_base + perp j over kLeg's columns, J_base over the other leg's. J
  // is column-major: a column's two rows are adjacent, one SSE2 operation.
  constexpr int kOtherLeg = 1 - kLeg;
  for (int i : ColumnsOf(kLeg)) out->J.col(i) = base.J.col(i) + perp * body.j(i);
  for (int k = 0; k < kNumJoints; ++k) out->J.col(JointIndex(kOtherLeg, k)) = base.J.col(JointIndex(kOtherLeg, k));
  out->leg = kLeg;  // the base's columns are the trunk's or the same leg's
  out->links = base.links;
  out->links[num_links] = {r, &body};
  out->num_links = num_links + 1;
}

// one leg's angles and points, down from the hip
template <int kLeg>
void ComputeLeg(const BodyParameters& b, const StatePairs& x, const PointKinematics& hip, LegKinematics* l) {
  // absolute angles down the chain: child = parent - joint angle
  using Rows = LegAngleRows<kLeg>;
  SetAngle<Rows::kFemur>(kLeg, x, &l->femur);
  SetAngle<Rows::kTibia>(kLeg, x, &l->tibia);
  SetAngle<Rows::kFoot>(kLeg, x, &l->foot);

  OffsetPoint<kLeg>(hip, l->femur, b.femur_length * SegmentDirection(l->femur), &l->knee);
  OffsetPoint<kLeg>(l->knee, l->tibia, b.tibia_length * SegmentDirection(l->tibia), &l->ankle);
}

}  // namespace

void OffsetPoint(const PointKinematics& base, const AngleKinematics& body, const Vec2& r, PointKinematics* out) {
  // the body's leg, known only here, picks the compile-time version
  if (body.leg == kLeft) {
    OffsetPoint<kLeft>(base, body, r, out);
  } else {
    OffsetPoint<kRight>(base, body, r, out);
  }
}

PointKinematics OffsetPoint(const PointKinematics& base, const AngleKinematics& body, const Vec2& r) {
  PointKinematics out;
  OffsetPoint(base, body, r, &out);
  return out;
}

void ComputeKinematics(const Model& model, const Vec9& q, const Vec9& v, Kinematics* kin) {
  const BodyParameters& b = model.body;

  // trunk centre: the floating base
  kin->trunk.p = q.segment<2>(kX);
  kin->trunk.v = v.segment<2>(kX);
  kin->trunk.a_bias.setZero();
  // d(x, y)/dq; assigned whole rather than zeroed then set, which GCC did
  // with a `rep stos`, slow to start for 144 bytes
  kin->trunk.J = Jac2x9::Identity();
  kin->trunk.num_links = 0;

  StatePairs x;
  for (int i = 0; i < kNumCoords; ++i) x[i] = PositionVelocity(q(i), v(i));
  SetAngle<kPitchRow>(kLeft, x, &kin->pitch);

  // hips at (0, -half_body_y) in the trunk frame; the pitch's row is the
  // trunk's, any leg's: its columns are taken to be the left leg's
  OffsetPoint<kLeft>(kin->trunk, kin->pitch, Rotate(kin->pitch, Vec2(0.0, -b.half_body_y)), &kin->hip);

  ComputeLeg<kLeft>(b, x, kin->hip, &kin->legs[kLeft]);
  ComputeLeg<kRight>(b, x, kin->hip, &kin->legs[kRight]);
}

}  // namespace walkers

namespace walkers {

State StandingState(const Model& model, double knee_flexion, double foot_x) {
  State s;
  for (int leg = 0; leg < kNumLegs; ++leg) {
    s.q(JointIndex(leg, kHip)) = -0.5 * knee_flexion;
    s.q(JointIndex(leg, kKnee)) = knee_flexion;
    s.q(JointIndex(leg, kAnkle)) = -0.5 * knee_flexion;
  }
  // place the trunk so that the feet's centres sit at (foot_x, half_foot_y)
  Kinematics kin;
  ComputeKinematics(model, s.q, s.v, &kin);
  const Vec2 ankle = kin.legs[kLeft].ankle.p;
  s.q(kX) = foot_x - ankle.x();
  s.q(kY) = model.body.half_foot_y - ankle.y();
  return s;
}

Jac2x9 PointVelocityJacobian(const PointKinematics& p) {
  Jac2x9 dv_dq = Jac2x9::Zero();
  for (int k = 0; k < p.num_links; ++k) {
    dv_dq.noalias() -= (p.links[k].body->rate * p.links[k].r) * p.links[k].body->j;
  }
  return dv_dq;
}

}  // namespace walkers
