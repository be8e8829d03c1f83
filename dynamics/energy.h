// Mechanical energy of the walker.
#pragma once

#include "dynamics/contact.h"
#include "dynamics/coords.h"
#include "dynamics/kinematics.h"
#include "dynamics/model.h"

namespace walkers {

// Kinetic energy summed body by body: 1/2 m |v|^2 of every point mass and
// 1/2 I w^2 of every rotational inertia [J].
double KineticEnergy(const Model& model, const Kinematics& kin);

// Gravitational potential energy, zero at ground level [J].
double GravitationalEnergy(const Model& model, const Kinematics& kin);

// Potential energy: gravity plus the elastic energy of contact springs and
// joint stops [J]. With no torques, kinetic + potential can only decrease:
// every other force element dissipates, and the welds do no work.
double PotentialEnergy(const Model& model, const Kinematics& kin);

// Centre of mass and its velocity (every point mass of the tree).
struct CenterOfMass {
  Vec2 p = Vec2::Zero();  // [m]
  Vec2 v = Vec2::Zero();  // [m/s]
};
CenterOfMass ComputeCenterOfMass(const Model& model, const Kinematics& kin);

}  // namespace walkers
