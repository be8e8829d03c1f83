// Equations of motion of the walker: M(q) q'' = Q(q, q', inputs), with Q the
// generalized forces of gravity, velocity products, ground contact, welds,
// joint stops and the held joint torques.
#pragma once

#include "dynamics/contact.h"
#include "dynamics/coords.h"
#include "dynamics/kinematics.h"
#include "dynamics/model.h"
#include "dynamics/tree_ldlt9.h"

namespace walkers {

// What the controller holds between ticks.
struct Inputs {
  Vec9 joint_torque = Vec9::Zero();  // [N m] on the joint coordinates; trunk entries are ignored
  Welds welds;                       // planted feet
};

// Per-integration scratch: nothing in it outlives one right-hand side.
struct Workspace {
  Kinematics kin;
  Mat9 M = Mat9::Identity();
  Vec9 Q = Vec9::Zero();
  TreeLdlt9 mass_ldlt;  // of M (locked rows and columns replaced by the identity)
};

// Mass matrix from computed kinematics: sum of m J^T J over point masses and
// I j^T j over rotational inertias.
void MassMatrix(const Model& model, const Kinematics& kin, Mat9* M);
Mat9 MassMatrix(const Model& model, const Vec9& q);

// Every generalized force except M q'' (right-hand side of the equations).
void GeneralizedForces(const Model& model, const Inputs& inputs, const Kinematics& kin, const Vec9& q,
                       const Vec9& v, Vec9* Q);

// Solves M q'' = Q for q''. Locked coordinates get q'' = 0. Returns false if
// the result is not finite.
bool ForwardDynamics(const Model& model, const Inputs& inputs, const Vec9& q, const Vec9& v, Workspace* ws,
                     Vec9* qdd);

}  // namespace walkers
