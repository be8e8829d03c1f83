// Forward kinematics of the planar tree: position, velocity, Jacobian and
// velocity-product ("bias") acceleration of every point the dynamics uses.
#pragma once

#include <array>
#include <cmath>

#include "dynamics/coords.h"
#include "dynamics/model.h"

namespace walkers {

// The columns of q a point or an angle of the tree can depend on: the trunk's
// three and one leg's three. The rest of its Jacobian is zero.
using TreeColumns = std::array<int, 6>;
constexpr TreeColumns ColumnsOf(int leg) {
  return {kX, kY, kPitch, JointIndex(leg, kHip), JointIndex(leg, kKnee), JointIndex(leg, kAnkle)};
}

// An absolute body angle. Every angle is linear in q: angle = j q.
struct AngleKinematics {
  double angle = 0;
  double rate = 0;
  double c = 1, s = 0;  // cos and sin of the angle
  Row9 j = Row9::Zero();
  int leg = kLeft;  // j is zero outside ColumnsOf(leg) (a trunk angle: any leg)
};

// A point of the tree: p, v = J q', and a_bias = J' q' so that a = J q'' + a_bias.
// It is the trunk centre (x, y) plus a chain of links r_k, each rigid with one
// absolute angle (dr_k / dangle_k = perp(r_k)); the analytic Jacobian of the
// equations of motion reads the chain.
struct PointKinematics {
  static constexpr int kMaxLinks = 4;
  struct Link {
    Vec2 r = Vec2::Zero();                 // world-frame link vector
    const AngleKinematics* body = nullptr;  // the angle it turns with
  };

  Vec2 p = Vec2::Zero();
  Vec2 v = Vec2::Zero();
  Vec2 a_bias = Vec2::Zero();
  Jac2x9 J = Jac2x9::Zero();
  int leg = kLeft;  // J is zero outside ColumnsOf(leg) (a trunk point: any leg)
  int num_links = 0;
  std::array<Link, kMaxLinks> links{};
};

struct LegKinematics {
  PointKinematics knee;   // end of the femur
  PointKinematics ankle;  // end of the tibia = centre of the foot
  AngleKinematics femur;  // absolute angles; 0 = hanging straight down / flat
  AngleKinematics tibia;
  AngleKinematics foot;
};

struct Kinematics {
  PointKinematics trunk;  // trunk centre
  PointKinematics hip;    // both hips: bottom centre of the trunk
  AngleKinematics pitch;  // trunk pitch
  std::array<LegKinematics, kNumLegs> legs;
};

// Fills every point and angle for the state (q, v). Use v = 0 for positions only.
void ComputeKinematics(const Model& model, const Vec9& q, const Vec9& v, Kinematics* kin);

// A point rigidly attached at `r` (world frame) from `base` to the body of angle `body`:
// its position, velocity, Jacobian and bias acceleration.
PointKinematics OffsetPoint(const PointKinematics& base, const AngleKinematics& body, const Vec2& r);
void OffsetPoint(const PointKinematics& base, const AngleKinematics& body, const Vec2& r, PointKinematics* out);

// Unit vector of a segment of absolute angle a, pointing from its top end to
// its bottom end: (sin a, -cos a).
inline Vec2 SegmentDirection(double a) { return Vec2(std::sin(a), -std::cos(a)); }
inline Vec2 SegmentDirection(const AngleKinematics& body) { return Vec2(body.s, -body.c); }

// A body-fixed vector r_local rotated by the body's angle into the world frame.
inline Vec2 Rotate(const AngleKinematics& body, const Vec2& r_local) {
  return Vec2(body.c * r_local.x() - body.s * r_local.y(), body.s * r_local.x() + body.c * r_local.y());
}

// Q += J^T f and Q += j^T torque, over the columns that can be nonzero: the
// same sums as the dense products, whose other terms add zeros.
inline void AddTransposeProduct(const PointKinematics& p, const Vec2& f, Vec9* Q) {
  for (int i : ColumnsOf(p.leg)) (*Q)(i) += p.J(0, i) * f.x() + p.J(1, i) * f.y();
}
inline void AddTransposeProduct(const AngleKinematics& a, double torque, Vec9* Q) {
  for (int i : ColumnsOf(a.leg)) (*Q)(i) += a.j(i) * torque;
}

// d(J v)/dq of a point's velocity: sum_k -r_k w_k j_k.
Jac2x9 PointVelocityJacobian(const PointKinematics& p);

// perp(r) = (-r_y, r_x) = dr/dangle for a vector turning with an angle.
inline Vec2 Perp(const Vec2& r) { return Vec2(-r.y(), r.x()); }

}  // namespace walkers

namespace walkers {

// The walker standing with both feet flat at foot_x on the ground, trunk
// level, both knees flexed by knee_flexion (split equally between hip and
// ankle so the trunk stays level), at rest.
State StandingState(const Model& model, double knee_flexion, double foot_x = 0.0);

}  // namespace walkers
