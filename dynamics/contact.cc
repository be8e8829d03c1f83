#include "dynamics/contact.h"

#include <algorithm>
#include <cmath>

namespace walkers {
namespace {

// local corner offsets of a box of half sizes (hx, hy)
std::array<Vec2, 4> BoxCorners(double hx, double hy) {
  return {Vec2(-hx, -hy), Vec2(hx, -hy), Vec2(hx, hy), Vec2(-hx, hy)};
}

// force f applied at world offset r from a base point on the body of angle `body`
void ApplyForce(const PointKinematics& base, const AngleKinematics& body, const Vec2& r, const Vec2& f,
                Vec9* Q) {
  AddTransposeProduct(base, f, Q);
  AddTransposeProduct(body, r.x() * f.y() - r.y() * f.x(), Q);
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
  const auto trunk = BoxCorners(model.body.half_body_x, model.body.half_body_y);
  const auto foot = BoxCorners(model.body.half_foot_x, model.body.half_foot_y);
  for (int i = 0; i < 4; ++i) {
    out[kTrunkCorner0 + i] = {&kin.trunk, &kin.pitch, Rotate(kin.pitch, trunk[i])};
    for (int leg = 0; leg < kNumLegs; ++leg) {
      const LegKinematics& l = kin.legs[leg];
      out[kFootCorner0L + 4 * leg + i] = {&l.ankle, &l.foot, Rotate(l.foot, foot[i])};
    }
  }
  for (int leg = 0; leg < kNumLegs; ++leg) {
    const LegKinematics& l = kin.legs[leg];
    out[kKneeCircleL + leg] = {&l.knee, &l.femur, Vec2(0.0, -model.contact.knee_radius)};
  }
  return out;
}

Vec2 GroundForce(const ContactParameters& c, double depth, double depth_rate, double slip) {
  if (depth <= 0.0) return Vec2::Zero();
  // Hunt–Crossley: the spring grows as d^1.5, so force and stiffness start at 0
  const double normal = c.stiffness * depth * std::sqrt(depth) * std::max(0.0, 1.0 + c.dissipation * depth_rate);
  // regularised Coulomb plus viscous friction, opposing the slip
  const double tangential = -normal * (c.friction * std::tanh(slip / c.slip_velocity) + c.viscous_friction * slip);
  return Vec2(tangential, normal);
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
  for (const ContactCarrier& carrier : ContactCarriers(model, kin)) {
    if (carrier.base->p.y() + carrier.r.y() >= 0.0) continue;  // above the ground
    const ContactSample s = CornerSample(*carrier.base, *carrier.body, carrier.r);
    const Vec2 f = GroundForce(model.contact, s.depth, s.depth_rate, s.v.x());
    ApplyForce(*carrier.base, *carrier.body, carrier.r, f, Q);
  }
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
