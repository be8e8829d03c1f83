// The analytic Jacobian of the equations of motion, for CVODE's Newton
// iteration: with a = q'' = M(q)^-1 Q(q, v),
//   M da/dq = d(Q - M a)/dq at fixed a,   M da/dv = dQ/dv.
// Every generalized force is a force F at a point p of the tree, J^T F, whose
// derivative in the planar tree is sum_k j_k^T j_k (-r_k . F) + J^T dF/dq over
// the point's links r_k (tests/dynamics/jacobian_test.cc checks it against
// finite differences).
#pragma once

#include "dynamics/equations_of_motion.h"

namespace walkers {

// da/dq and da/dv at (q, v). Runs ForwardDynamics on the workspace first.
// Returns false if the accelerations are not finite.
bool AccelerationJacobian(const Model& model, const Inputs& inputs, const Vec9& q, const Vec9& v, Workspace* ws,
                          Mat9* da_dq, Mat9* da_dv);

}  // namespace walkers
