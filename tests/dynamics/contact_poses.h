// Poses of the walker in the air in which one self-contact pair engages, for
// the contact and Jacobian tests: the trunk level at height 2 m, the legs
// folded by two-link inverse kinematics.
#pragma once

#include <cmath>

#include "dynamics/contact.h"
#include "dynamics/kinematics.h"
#include "dynamics/model.h"

namespace walkers::testing {

// The trunk at height y with the given pitch, both legs pointing straight up
// out of the way (their knees and feet far above the trunk), at rest.
inline State TrunkAt(double y, double pitch) {
  State s;
  s.q(kY) = y;
  s.q(kPitch) = pitch;
  for (int leg = 0; leg < kNumLegs; ++leg) s.q(JointIndex(leg, kHip)) = pitch - M_PI;
  return s;
}

// Joint angles of `leg` that put its ankle at `offset` from the hip, knee
// forward, foot flat, with the trunk level.
inline void PlaceAnkle(const Model& m, int leg, const Vec2& offset, State* s) {
  const double lf = m.body.femur_length, lt = m.body.tibia_length, d = offset.norm();
  const double femur = std::atan2(offset.x(), -offset.y()) + std::acos((lf * lf + d * d - lt * lt) / (2 * lf * d));
  const Vec2 knee = lf * SegmentDirection(femur);
  const double tibia = std::atan2((offset - knee).x(), -(offset - knee).y());
  s->q(JointIndex(leg, kHip)) = -femur;
  s->q(JointIndex(leg, kKnee)) = femur - tibia;
  s->q(JointIndex(leg, kAnkle)) = tibia;
}

// The site of `sites` on the face y = face_y nearest the sphere's plane
// (smallest dz2), the one farthest forward among those.
inline SphereSite SiteOnFace(const std::vector<SphereSite>& sites, double face_y) {
  SphereSite best;
  best.dz2 = 1e9;
  for (const SphereSite& s : sites) {
    if (std::abs(s.p.y() - face_y) > 1e-12) continue;
    if (s.dz2 < best.dz2 - 1e-12 || (std::abs(s.dz2 - best.dz2) <= 1e-12 && s.p.x() > best.p.x())) best = s;
  }
  return best;
}

// A walker whose femur is just long enough to reach, swung up, straight
// below a trunk bottom site of `leg`: its knee sphere `depth` into the trunk.
struct Posed {
  Model model;
  State state;
};
inline Posed KneeInTheTrunk(BodyParameters b, int leg, double depth) {
  const Model probe = BuildModel(b);
  const double radius = probe.contact.knee_radius;
  const SphereSite site = SiteOnFace(probe.sites.trunk_in_knee[leg], -b.half_body_y);
  const double below = std::sqrt((radius - depth) * (radius - depth) - site.dz2);  // knee centre below the site
  b.femur_length = std::hypot(site.p.x(), below);
  Posed out{BuildModel(b), TrunkAt(2.0, 0.0)};
  const double femur = std::atan2(site.p.x(), below);  // from straight down
  out.state.q(JointIndex(leg, kHip)) = -femur;
  out.state.q(JointIndex(leg, kKnee)) = femur;  // tibia hanging down
  return out;
}

// A walker whose tibia is just long enough to put its knee, leaning forward,
// straight above a foot top site: its knee sphere `depth` into its own foot.
inline Posed KneeOnItsFoot(BodyParameters b, int leg, double depth) {
  const Model probe = BuildModel(b);
  const double radius = probe.contact.knee_radius;
  const SphereSite site = SiteOnFace(probe.sites.foot_in_knee, b.half_foot_y);
  const double above = b.half_foot_y + std::sqrt((radius - depth) * (radius - depth) - site.dz2);  // over the ankle
  b.tibia_length = std::hypot(site.p.x(), above);
  Posed out{BuildModel(b), TrunkAt(2.0, 0.0)};
  const double tibia = -std::atan2(site.p.x(), above);  // absolute, knee ahead of the ankle
  out.state.q(JointIndex(leg, kHip)) = -tibia;  // femur along the tibia
  out.state.q(JointIndex(leg, kKnee)) = 0.0;
  out.state.q(JointIndex(leg, kAnkle)) = tibia;  // foot flat
  return out;
}

}  // namespace walkers::testing
