#include "dynamics/kinematics.h"

#include <cmath>

namespace walkers {
namespace {

void SetAngle(const Row9& j, int leg, const Vec9& q, const Vec9& v, AngleKinematics* a) {
  a->j = j;
  a->leg = leg;
  a->angle = j.dot(q);
  a->rate = j.dot(v);
  a->c = std::cos(a->angle);
  a->s = std::sin(a->angle);
}

}  // namespace

void OffsetPoint(const PointKinematics& base, const AngleKinematics& body, const Vec2& r, PointKinematics* out) {
  // p = p_base + r(angle): dr/dangle = perp(r), d2r/dangle2 = -r
  const Vec2 perp = Perp(r);
  *out = base;
  out->p += r;
  out->v += perp * body.rate;
  out->a_bias -= r * (body.rate * body.rate);
  out->leg = body.leg;  // the base's columns are the trunk's or the same leg's
  for (int i : ColumnsOf(body.leg)) {
    out->J(0, i) += perp.x() * body.j(i);
    out->J(1, i) += perp.y() * body.j(i);
  }
  out->links[out->num_links++] = {r, &body};
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
  kin->trunk.J.setZero();
  kin->trunk.J(0, kX) = 1.0;
  kin->trunk.J(1, kY) = 1.0;

  Row9 j = Row9::Zero();
  j(kPitch) = 1.0;
  SetAngle(j, kLeft, q, v, &kin->pitch);

  // hips at (0, -half_body_y) in the trunk frame
  kin->trunk.num_links = 0;
  OffsetPoint(kin->trunk, kin->pitch, Rotate(kin->pitch, Vec2(0.0, -b.half_body_y)), &kin->hip);

  for (int leg = 0; leg < kNumLegs; ++leg) {
    LegKinematics& l = kin->legs[leg];
    // absolute angles down the chain: child = parent - joint angle
    Row9 j_femur = kin->pitch.j;
    j_femur(JointIndex(leg, kHip)) = -1.0;
    Row9 j_tibia = j_femur;
    j_tibia(JointIndex(leg, kKnee)) = -1.0;
    Row9 j_foot = j_tibia;
    j_foot(JointIndex(leg, kAnkle)) = -1.0;
    SetAngle(j_femur, leg, q, v, &l.femur);
    SetAngle(j_tibia, leg, q, v, &l.tibia);
    SetAngle(j_foot, leg, q, v, &l.foot);

    OffsetPoint(kin->hip, l.femur, b.femur_length * SegmentDirection(l.femur), &l.knee);
    OffsetPoint(l.knee, l.tibia, b.tibia_length * SegmentDirection(l.tibia), &l.ankle);
  }
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

}  // namespace walkers
