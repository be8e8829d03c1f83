// The walker's constant model: masses, inertias, joint stops and contact
// constants, built once from the physical sizes a genome gives (docs/model.md,
// "Mass model", "Joint stops" and "Contact").
#pragma once

#include <array>

#include "dynamics/contact_geometry.h"
#include "dynamics/coords.h"
#include "dynamics/weld.h"

namespace walkers {

// The physical genes of a genome; everything else the dynamics needs is
// derived. The values of a walker come from its genome (control/genome.h
// holds the default genome).
struct BodyParameters {
  double half_body_x = 0;    // [m] trunk box, along x
  double half_body_y = 0;    // [m] trunk box, along y
  double half_body_z = 0;    // [m] trunk box depth (mass and contact extent)
  double half_foot_x = 0;    // [m]
  double half_foot_y = 0;    // [m]
  double half_foot_z = 0;    // [m] (mass and contact extent)
  double femur_length = 0;   // [m] hip -> knee
  double tibia_length = 0;   // [m] knee -> ankle
  double knee_mass = 0;      // [kg] point mass at the femur's end
  double ankle_mass = 0;     // [kg] point mass at the tibia's end
  double hip_mass = 0;       // [kg] per hip, at the trunk's bottom centre
};

// A contact material of the authors' program (Simbody's ContactMaterial).
struct ContactMaterial {
  double stiffness = 1.0e8;       // [Pa]
  double dissipation = 1.0;       // [s/m] Hunt–Crossley
  double static_friction = 0.3;   // [-]
  double dynamic_friction = 0.3;  // [-]
  double viscous_friction = 0.3;  // [s/m] friction coefficient per slip speed
};

// The authors' contact surfaces (docs/model.md, "Contact"). The reasons for each value are
// in docs/model.md; tests/dynamics/contact_test.cc checks the laws.
struct ContactParameters {
  ContactMaterial surface;  // trunk, feet and ground
  // the knee spheres' material was built without viscous friction
  ContactMaterial knee{1.0e8, 1.0, 0.3, 0.3, 0.0};
  double mesh_thickness = 0.5;        // [m] of the trunk's and feet's elastic foundation
  int mesh_resolution = 6;            // Simbody's createBrickMesh resolution
  double knee_radius = 0.1;           // [m] contact sphere at each knee
  double transition_velocity = 1e-3;  // [m/s] of Simbody's friction curve
  double leg_z = 0.25;                // [m] each leg's plane: the left at +leg_z, the right at -leg_z
};

// Simbody's friction curve for a pair of materials: mu(s) rises smoothly from
// 0 to the static coefficient at the transition velocity, falls to the
// dynamic one by 3 transition velocities, plus viscous * s.
struct FrictionLaw {
  double static_friction = 0;   // [-]
  double dynamic_friction = 0;  // [-]
  double viscous = 0;           // [s/m]
  double transition = 1e-3;     // [m/s]
};

// Elastic foundation of a pair: per triangle, f = k A d (1 + c d').
struct FoundationLaw {
  double stiffness = 0;    // [N/m^3] k: the two surfaces' springs in series
  double dissipation = 0;  // [s/m] c
  double squish = 0.5;     // [-] share of the deformation the mesh takes: where the force acts
  FrictionLaw friction;
};

// Hertz contact of a sphere with the ground: f = k x^1.5 (1 + 1.5 c x').
struct HertzLaw {
  double stiffness = 0;    // [N/m^1.5]
  double dissipation = 0;  // [s/m]
  double squish = 0.5;     // [-] share of the deformation the sphere takes: where the force acts
  FrictionLaw friction;
};

// The laws of the four kinds of pair, combined from the materials by
// Simbody's rules (CombineMaterials, dynamics/model.cc).
struct ContactLaws {
  FoundationLaw mesh_ground;
  FoundationLaw mesh_mesh;
  FoundationLaw mesh_knee;
  HertzLaw knee_ground;
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
  bool self_contact = true;  // the pairs between the walker's own bodies
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

  // derived mass model (docs/model.md, "Mass model")
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

  // contact: the pairs' laws and the spring sites of every surface
  ContactLaws laws;
  ContactSites sites;


  double leg_length() const { return body.femur_length + body.tibia_length; }
};

// Simbody's rules for a pair of materials: elastic-foundation springs per
// unit area k/h in series, Hertz stiffnesses combined as k^(2/3) in series,
// dissipation weighted by each surface's share of the deformation, friction
// coefficients by harmonic means (zero if either is zero).
ContactLaws CombineMaterials(const ContactParameters& contact);

// Builds the constant model from the body's sizes.
Model BuildModel(const BodyParameters& body, const ModelOptions& options = {},
                 const ContactParameters& contact = {}, const WeldParameters& weld = {});

}  // namespace walkers
