// The walker's constant model: masses, inertias, joint stops and contact
// constants, built once from the physical sizes a genome gives (MODEL.md §2–§3).
#pragma once

#include <array>

#include "dynamics/coords.h"

namespace walkers {

// The physical genes of a genome; everything else the dynamics needs is derived.
struct BodyParameters {
  double half_body_x = 0.8822120184545844;   // [m] trunk box, along x
  double half_body_y = 0.1353015130243578;   // [m] trunk box, along y
  double half_body_z = 0.329704208858325;    // [m] trunk box depth (mass only)
  double half_foot_x = 0.22018185203456214;  // [m]
  double half_foot_y = 0.05;                 // [m]
  double half_foot_z = 0.06957592968690621;  // [m] (mass only)
  double femur_length = 0.5301194705959408;  // [m] hip -> knee
  double tibia_length = 0.6845846448329076;  // [m] knee -> ankle
  double knee_mass = 0.7;                    // [kg] point mass at the femur's end
  double ankle_mass = 0.1;                   // [kg] point mass at the tibia's end
  double hip_mass = 0.1;                     // [kg] per hip, at the trunk's bottom centre
};

// Penalty ground contact (MODEL.md §3). The reasons for each value are in
// docs/model.md; tests/dynamics/contact_test.cc checks their consequences.
struct ContactParameters {
  double stiffness = 1.0e8;        // [N/m^1.5] Hunt–Crossley k in F = k d^1.5 (1 + c d')
  double dissipation = 1.0;        // [s/m] Hunt–Crossley c, the original's value
  double friction = 0.3;           // [-] Coulomb coefficient (static = dynamic)
  double viscous_friction = 0.3;   // [s/m] extra tangential force per normal force and slip speed
  double slip_velocity = 0.01;     // [m/s] tanh regularisation of Coulomb friction
  double knee_radius = 0.1;        // [m] contact circle at each knee
};

// The stiff spring-damper that holds a planted foot (MODEL.md §3).
struct WeldParameters {
  double stiffness = 1.0e9;          // [N/m] on the foot centre, x and y
  double angular_stiffness = 1.0e8;  // [N m/rad] on the foot angle
  double damping_ratio = 1.0;        // [-] of the foot alone on these springs
};

// Hunt–Crossley style joint limit: tau = -k x (1 + d x') past +-limit.
struct JointStop {
  double limit = 0;      // [rad]
  double stiffness = 0;  // [N m/rad]
  double damping = 0;    // [s/rad]
};

// Switches for fixtures: the tests turn contact, stops and gravity off and pin
// coordinates to build closed-form pendulums.
struct ModelOptions {
  bool contact = true;
  bool joint_stops = true;
  double gravity = 9.81;  // [m/s^2] along -y
  std::array<bool, kNumCoords> locked{};  // coordinates held fixed (q'' = 0)
};

constexpr double kBodyDensity = 1180.0;  // [kg/m^3] trunk and feet

struct Model {
  BodyParameters body;
  ContactParameters contact;
  WeldParameters weld;
  ModelOptions options;

  // derived mass model (MODEL.md §2)
  double trunk_mass = 0;        // [kg] box
  double hips_mass = 0;         // [kg] both hip point masses, at the hip
  double knee_mass = 0;         // [kg] per knee
  double ankle_mass = 0;        // [kg] per ankle: ankle point mass + foot box
  double foot_mass = 0;         // [kg] foot box alone
  double trunk_inertia = 0;     // [kg m^2] box + the two hips' quirk inertia
  double femur_inertia = 0;     // [kg m^2]
  double tibia_inertia = 0;     // [kg m^2] quirk: the foot box's inertia
  double foot_inertia = 0;      // [kg m^2]
  double total_mass = 0;        // [kg]

  // joint stops, per joint of a leg (kHip, kKnee, kAnkle)
  std::array<JointStop, kNumJoints> stops{};

  // weld damping, derived from the foot's mass and inertia
  double weld_damping = 0;          // [N s/m]
  double weld_angular_damping = 0;  // [N m s/rad]

  double leg_length() const { return body.femur_length + body.tibia_length; }
};

// Builds the constant model from the body's sizes.
Model BuildModel(const BodyParameters& body, const ModelOptions& options = {},
                 const ContactParameters& contact = {}, const WeldParameters& weld = {});

}  // namespace walkers
