// Penalty ground contact, the planted-foot weld and the joint stops
// (MODEL.md §2–§3): each as a force kernel, its generalized forces, and its
// stored elastic energy.
#pragma once

#include <array>

#include "dynamics/coords.h"
#include "dynamics/kinematics.h"
#include "dynamics/model.h"

namespace walkers {

// Contact points: the trunk box's 4 corners, each foot box's 4 corners, and a
// circle at each knee.
enum ContactPoint : int {
  kTrunkCorner0 = 0,
  kFootCorner0L = 4,
  kFootCorner0R = 8,
  kKneeCircleL = 12,
  kKneeCircleR = 13,
  kNumContactPoints = 14
};

// What carries a contact point: a point of the tree, the body angle the
// point turns with, and the world-frame offset from that point. A box corner
// turns with its box; a knee circle's lowest point sits straight below the
// knee (offset (0, -R)) and moves with the femur.
struct ContactCarrier {
  const PointKinematics* base;
  const AngleKinematics* body;
  Vec2 r;
};
std::array<ContactCarrier, kNumContactPoints> ContactCarriers(const Model& model, const Kinematics& kin);

inline bool IsKneeCircle(int contact_point) { return contact_point >= kKneeCircleL; }

// Where a contact point is and how fast it goes into the ground.
struct ContactSample {
  Vec2 p = Vec2::Zero();  // contact point (a corner, or the circle's lowest point)
  Vec2 v = Vec2::Zero();  // its velocity
  double depth = 0;       // penetration into the ground, > 0 when touching [m]
  double depth_rate = 0;  // d(depth)/dt [m/s]
};

// A foot held at a planting pose by the stiff weld.
struct Weld {
  bool active = false;
  Vec2 anchor = Vec2::Zero();  // where the foot's centre is held [m]
  double angle = 0;            // foot angle held [rad]
};
using Welds = std::array<Weld, kNumLegs>;

// Ground force on one contact point: (tangential, normal) [N].
// Normal, Hunt–Crossley: k d^1.5 max(0, 1 + c d'), smooth at first touch.
// Tangential: -F_n (mu tanh(s / s_0) + mu_v s) for slip speed s.
Vec2 GroundForce(const ContactParameters& c, double depth, double depth_rate, double slip);

// Every contact point's position, velocity and penetration.
std::array<ContactSample, kNumContactPoints> SampleContacts(const Model& model, const Kinematics& kin);

// Generalized forces of ground contact, welds and joint stops, added to Q.
void AddGroundContactForces(const Model& model, const Kinematics& kin, Vec9* Q);
void AddWeldForces(const Model& model, const Kinematics& kin, const Welds& welds, Vec9* Q);
void AddJointStopTorques(const Model& model, const Vec9& q, const Vec9& v, Vec9* Q);

// Torque of one joint stop at angle and rate.
double JointStopTorque(const JointStop& stop, double angle, double rate);

// Elastic energy stored in the contact springs, welds and joint stops [J].
double ElasticEnergy(const Model& model, const Kinematics& kin, const Welds& welds);

// Deepest penetration of any contact point [m] (0 when nothing touches).
double MaxPenetration(const Model& model, const Kinematics& kin);

// True when a trunk corner is below the ground.
bool TrunkTouchesGround(const Model& model, const Kinematics& kin);

}  // namespace walkers
