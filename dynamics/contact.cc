#include "dynamics/contact.h"

#include <algorithm>
#include <cassert>
#include <cmath>
#include <type_traits>

namespace walkers {
namespace {

// local corner offsets of a box of half sizes (hx, hy)
std::array<Vec2, 4> BoxCorners(double hx, double hy) {
  return {Vec2(-hx, -hy), Vec2(hx, -hy), Vec2(hx, hy), Vec2(-hx, hy)};
}

// The 4 corners of a box of half sizes (hx, hy), turned with the box's angle
// into world-frame offsets from its centre.
std::array<Vec2, 4> RotatedCorners(const AngleKinematics& body, double hx, double hy) {
  const std::array<Vec2, 4> local = BoxCorners(hx, hy);
  return {Rotate(body, local[0]), Rotate(body, local[1]), Rotate(body, local[2]), Rotate(body, local[3])};
}

// A leg as a type, std::integral_constant<int, leg>, so that a visitor of the
// contact points gets ColumnsOf(leg) as a compile-time constant.
template <int kLeg>
using LegTag = std::integral_constant<int, kLeg>;

// Visits every contact point in the order of ContactPoint (the order of the
// sums in each entry of Q): visit(point, leg, base, body, r) for a point at
// world offset r from the base point, turning with the body angle. `leg` is
// the .leg of base and body, whose columns they depend on: a foot's or knee's
// own leg, kLeft for the trunk (as ComputeKinematics sets it). ContactCarriers
// and AddGroundContactForces share this one list of the points.
template <typename Visit>
void ForEachContactCarrier(const Model& model, const Kinematics& kin, Visit&& visit) {
  const BodyParameters& b = model.body;
  const LegKinematics& left = kin.legs[kLeft];
  const LegKinematics& right = kin.legs[kRight];
  // box corners turn with their box; each box's four are computed before the
  // visits, which may store to memory the compiler cannot tell from kin's
  const auto trunk = RotatedCorners(kin.pitch, b.half_body_x, b.half_body_y);
  for (int i = 0; i < 4; ++i) visit(kTrunkCorner0 + i, LegTag<kLeft>{}, kin.trunk, kin.pitch, trunk[i]);
  const auto foot_l = RotatedCorners(left.foot, b.half_foot_x, b.half_foot_y);
  for (int i = 0; i < 4; ++i) visit(kFootCorner0L + i, LegTag<kLeft>{}, left.ankle, left.foot, foot_l[i]);
  const auto foot_r = RotatedCorners(right.foot, b.half_foot_x, b.half_foot_y);
  for (int i = 0; i < 4; ++i) visit(kFootCorner0R + i, LegTag<kRight>{}, right.ankle, right.foot, foot_r[i]);
  // a knee circle's lowest point sits straight below the knee (offset (0, -R))
  // and moves with the femur
  const Vec2 below_knee(0.0, -model.contact.knee_radius);
  visit(kKneeCircleL, LegTag<kLeft>{}, left.knee, left.femur, below_knee);
  visit(kKneeCircleR, LegTag<kRight>{}, right.knee, right.femur, below_knee);
}

// GroundForce of a point known to touch: depth > 0 (or NaN, which GroundForce
// lets through too)
Vec2 TouchingGroundForce(const ContactParameters& c, double depth, double depth_rate, double slip) {
  // Hunt–Crossley: the spring grows as d^1.5, so force and stiffness start at 0
  const double normal = c.stiffness * depth * std::sqrt(depth) * std::max(0.0, 1.0 + c.dissipation * depth_rate);
  // regularised Coulomb plus viscous friction, opposing the slip
  const double tangential = -normal * (c.friction * std::tanh(slip / c.slip_velocity) + c.viscous_friction * slip);
  return Vec2(tangential, normal);
}

// force f applied at world offset r from a base point on the body of angle
// `body`: Q += J^T f, then Q += j^T (r x f), the sums of AddTransposeProduct
// over ColumnsOf(kLeg), zeros included (adding +0 turns a -0 of Q into +0).
// The columns are compile-time constants, so every entry sits at a constant
// offset (read from ColumnsOf(leg) at run time, their addresses cost more than
// the products), and every load precedes the first store to Q, which the
// compiler must assume could alias kin: two columns then share SSE2 operations.
template <int kLeg>
void ApplyForce(const PointKinematics& base, const AngleKinematics& body, const Vec2& r, const Vec2& f, Vec9* Q) {
  static constexpr TreeColumns kCols = ColumnsOf(kLeg);
  constexpr int N = kCols.size();
  const double torque = r.x() * f.y() - r.y() * f.x();
  double jx[N], jy[N], jb[N];
  #pragma GCC unroll 6
  for (int a = 0; a < N; ++a) {
    jx[a] = base.J(0, kCols[a]);
    jy[a] = base.J(1, kCols[a]);
    jb[a] = body.j(kCols[a]);
  }
  #pragma GCC unroll 6
  for (int a = 0; a < N; ++a) {
    double& Qa = (*Q)(kCols[a]);
    Qa = (Qa + (jx[a] * f.x() + jy[a] * f.y())) + jb[a] * torque;
  }
}

// a point at offset r from the base: a box corner, or a knee circle's lowest
// point (offset (0, -R), moving with the femur)
ContactSample CornerSample(const PointKinematics& base, const AngleKinematics& body, const Vec2& r) {
  ContactSample s;
  s.p = base.p + r;
  s.v = base.v + Vec2(-r.y(), r.x()) * body.rate;
  s.depth = -s.p.y();
  s.depth_rate = -s.v.y();
  return s;
}

}  // namespace

std::array<ContactCarrier, kNumContactPoints> ContactCarriers(const Model& model, const Kinematics& kin) {
  std::array<ContactCarrier, kNumContactPoints> out;
  ForEachContactCarrier(model, kin, [&](int point, auto /*leg*/, const PointKinematics& base,
                                        const AngleKinematics& body, const Vec2& r) {
    out[point] = {&base, &body, r};
  });
  return out;
}

Vec2 GroundForce(const ContactParameters& c, double depth, double depth_rate, double slip) {
  if (depth <= 0.0) return Vec2::Zero();
  return TouchingGroundForce(c, depth, depth_rate, slip);
}

std::array<ContactSample, kNumContactPoints> SampleContacts(const Model& model, const Kinematics& kin) {
  std::array<ContactSample, kNumContactPoints> out;
  const auto carriers = ContactCarriers(model, kin);
  for (int i = 0; i < kNumContactPoints; ++i) {
    out[i] = CornerSample(*carriers[i].base, *carriers[i].body, carriers[i].r);
  }
  return out;
}

void AddGroundContactForces(const Model& model, const Kinematics& kin, Vec9* Q) {
  // the carriers visited directly, not through ContactCarriers' array: with
  // the leg a compile-time constant, and no pointers stored and read back
  ForEachContactCarrier(model, kin, [&](int /*point*/, auto leg, const PointKinematics& base,
                                        const AngleKinematics& body, const Vec2& r) {
    assert(base.leg == leg && body.leg == leg);
    if (base.p.y() + r.y() >= 0.0) return;  // above the ground
    // below: s.depth = -(base.p.y() + r.y()) > 0 (or NaN)
    const ContactSample s = CornerSample(base, body, r);
    const Vec2 f = TouchingGroundForce(model.contact, s.depth, s.depth_rate, s.v.x());
    ApplyForce<decltype(leg)::value>(base, body, r, f, Q);
  });
}

void AddWeldForces(const Model& model, const Kinematics& kin, const Welds& welds, Vec9* Q) {
  for (int leg = 0; leg < kNumLegs; ++leg) {
    if (!welds[leg].active) continue;
    const LegKinematics& l = kin.legs[leg];
    // spring-damper on the foot centre and on the foot angle
    const Vec2 f = -model.weld.stiffness * (l.ankle.p - welds[leg].anchor) - model.weld_damping * l.ankle.v;
    const double torque = -model.weld.angular_stiffness * (l.foot.angle - welds[leg].angle) -
                          model.weld_angular_damping * l.foot.rate;
    AddTransposeProduct(l.ankle, f, Q);
    AddTransposeProduct(l.foot, torque, Q);
  }
}

double JointStopTorque(const JointStop& stop, double angle, double rate) {
  // overrun x past the limit, pushing back with a Hunt–Crossley style damper
  if (angle > stop.limit) {
    const double x = angle - stop.limit;
    return -stop.stiffness * x * std::max(0.0, 1.0 + stop.damping * rate);
  }
  if (angle < -stop.limit) {
    const double x = -stop.limit - angle;
    return stop.stiffness * x * std::max(0.0, 1.0 - stop.damping * rate);
  }
  return 0.0;
}

void AddJointStopTorques(const Model& model, const Vec9& q, const Vec9& v, Vec9* Q) {
  for (int leg = 0; leg < kNumLegs; ++leg) {
    for (int joint = 0; joint < kNumJoints; ++joint) {
      const int i = JointIndex(leg, joint);
      (*Q)(i) += JointStopTorque(model.stops[joint], q(i), v(i));
    }
  }
}

double ElasticEnergy(const Model& model, const Kinematics& kin, const Welds& welds) {
  double e = 0.0;
  if (model.options.contact) {
    // integral of k d^1.5 is 0.4 k d^2.5
    for (const ContactSample& s : SampleContacts(model, kin)) {
      if (s.depth > 0.0) e += 0.4 * model.contact.stiffness * std::pow(s.depth, 2.5);
    }
  }
  for (int leg = 0; leg < kNumLegs; ++leg) {
    if (!welds[leg].active) continue;
    const LegKinematics& l = kin.legs[leg];
    e += 0.5 * model.weld.stiffness * (l.ankle.p - welds[leg].anchor).squaredNorm();
    const double da = l.foot.angle - welds[leg].angle;
    e += 0.5 * model.weld.angular_stiffness * da * da;
  }
  if (model.options.joint_stops) {
    for (int leg = 0; leg < kNumLegs; ++leg) {
      const LegKinematics& l = kin.legs[leg];
      // joint angles from the absolute ones: hip = pitch - femur, ...
      const double angles[kNumJoints] = {kin.pitch.angle - l.femur.angle, l.femur.angle - l.tibia.angle,
                                         l.tibia.angle - l.foot.angle};
      for (int joint = 0; joint < kNumJoints; ++joint) {
        const double x = std::max(0.0, std::abs(angles[joint]) - model.stops[joint].limit);
        e += 0.5 * model.stops[joint].stiffness * x * x;
      }
    }
  }
  return e;
}

double MaxPenetration(const Model& model, const Kinematics& kin) {
  double deepest = 0.0;
  for (const ContactSample& s : SampleContacts(model, kin)) deepest = std::max(deepest, s.depth);
  return deepest;
}

bool TrunkTouchesGround(const Model& model, const Kinematics& kin) {
  const auto samples = SampleContacts(model, kin);
  for (int i = 0; i < 4; ++i) {
    if (samples[kTrunkCorner0 + i].depth > 0.0) return true;
  }
  return false;
}

}  // namespace walkers
