// Contact as the authors' Simbody program computes it, in the plane
// (docs/model.md, "Contact"): the elastic
// foundation of the trunk's and feet's brick meshes against the ground and
// against each other, Hertz contact of the knee spheres with the ground, the
// knee spheres against the meshes, Simbody's friction law; and the joint
// stops. Each contact pair is one entry of ContactPairs().
#pragma once

#include <array>

#include "dynamics/coords.h"
#include "dynamics/kinematics.h"
#include "dynamics/model.h"
#include "dynamics/weld.h"

namespace walkers {

// The bodies that carry contact surfaces: the ground, the trunk, the feet and
// the femurs (each carries the sphere at its knee).
enum class ContactBody : int { kGround, kTrunk, kFootL, kFootR, kKneeL, kKneeR };

// How a pair's force is computed.
enum class ContactLaw : int {
  kMeshOnGround,    // elastic foundation of a brick mesh on the half-space
  kSphereOnGround,  // Hertz contact of a knee sphere with the half-space
  kMeshOnMesh,      // elastic foundation between two brick meshes
  kMeshOnSphere,    // elastic foundation of a brick mesh on a knee sphere
};

// Every pair of surfaces that can meet in the plane: the authors' program
// sets no collision groups, so surfaces on different bodies collide; these
// are the pairs whose z extents overlap (docs/model.md). Forces are reported
// on body b; body a gets the opposite force at the same point.
enum ContactPair : int {
  kGroundTrunk,
  kGroundFootL,
  kGroundFootR,
  kGroundKneeL,
  kGroundKneeR,
  kTrunkFootL,
  kTrunkFootR,
  kTrunkKneeL,
  kTrunkKneeR,
  kFootKneeL,
  kFootKneeR,
  kNumContactPairs
};

struct ContactPairSpec {
  const char* name;
  ContactBody a, b;
  ContactLaw law;
  int leg;             // the leg whose surfaces meet (kLeft for the ground and the trunk alone)
  bool trunk_support;  // the trunk leaning on the ground or on its own feet (the gait class)
  bool self_contact;   // between two of the walker's own bodies
};
const std::array<ContactPairSpec, kNumContactPairs>& ContactPairs();

// What a pair does at one instant.
struct ContactReport {
  bool touching = false;         // some element pushes
  Vec2 force = Vec2::Zero();     // [N] total force on body b
  double energy = 0;             // [J] elastic energy stored
  // [W] the power its damping and friction take, and a spring that would
  // pull gives up (Simbody's power loss, which its dissipated energy
  // integrates); counted only when asked (counts_dissipation), as
  // AddContactForces asks when its caller wants it
  double dissipation = 0;
  bool counts_dissipation = false;
  int elements = 0;              // springs (or Hertz contacts) pushing
};
using ContactReports = std::array<ContactReport, kNumContactPairs>;

// Every pair's forces at the state of `kin` (the force on body b, summed).
ContactReports ReportContacts(const Model& model, const Kinematics& kin);

// A welded foot's ground contact is not applied (docs/model.md, "Planted-foot
// weld"): the authors' weld is exact and takes up whatever pushes the foot.
bool HeldByWeld(const ContactPairSpec& pair, const Welds& welds);

// Generalized forces of every enabled contact pair, added to Q; and, if
// asked, the power they dissipate (the pairs' ContactReport::dissipation).
void AddContactForces(const Model& model, const Kinematics& kin, const Welds& welds, Vec9* Q,
                      double* dissipation = nullptr);

// Simbody's friction coefficient per unit slip speed, g(s) = mu(s) / s, as a
// function of the squared slip speed: the friction force is -f_n g v_slip.
double FrictionPerSlip(const FrictionLaw& law, double slip_squared);

// Generalized forces of the joint stops, added to Q.
void AddJointStopTorques(const Model& model, const Vec9& q, const Vec9& v, Vec9* Q);

// Torque of one joint stop at angle and rate.
double JointStopTorque(const JointStop& stop, double angle, double rate);

// Where the contact forces switch law, as functions of the state that cross
// zero there (for an integrator that locates such events): per pair, the
// signed depth [m] of its deepest spring site (or knee sphere) in the other
// surface, positive while some site is inside, so zero where the pair starts
// or stops touching. A site's depth is the one its law pushes with (for a box,
// the smaller of its margins to the x and y faces). Continuous in q; -1 for a
// pair that is off (disabled, or held by a weld) or whose surfaces cannot
// meet (MayTouch), which keeps its sign. A spring that would pull, inside,
// is counted as touching: its switch is not located.
using ContactSwitches = std::array<double, kNumContactPairs>;
ContactSwitches ContactSwitchDepths(const Model& model, const Kinematics& kin, const Welds& welds);

// Per joint (JointIndex order) how far past its stop it is, |angle| - limit
// [rad]: zero where the stop engages or lets go; -1 without joint stops.
using JointStopSwitches = std::array<double, kNumLegs * kNumJoints>;
JointStopSwitches JointStopMargins(const Model& model, const Vec9& q);

// Elastic energy stored in the contact springs and joint stops [J].
double ElasticEnergy(const Model& model, const Kinematics& kin);

// How far the lowest spring site or knee sphere is below the ground [m]
// (negative: the whole walker is above it).
double LowestPointDepth(const Model& model, const Kinematics& kin);

// Deepest penetration of any surface into the ground [m] (0 when nothing touches).
double MaxGroundPenetration(const Model& model, const Kinematics& kin);

// The trunk leans on the ground or on its own feet (a pair with trunk_support touches).
bool TrunkSupported(const Model& model, const Kinematics& kin);

}  // namespace walkers
