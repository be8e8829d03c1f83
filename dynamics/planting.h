// Switching a weld on: the foot lands on the ground and stops. As the
// authors' program projected its state onto a newly enabled weld constraint,
// this projects the walker onto the weld's pose and treats the landing as a
// perfectly plastic impact.
#pragma once

#include "dynamics/contact.h"
#include "dynamics/coords.h"
#include "dynamics/model.h"

namespace walkers {

// Moves `state` onto the weld of `leg`: the foot centre at weld.anchor and its
// angle at weld.angle, by the smallest change of q in the mass-matrix metric;
// then the plastic impact M (v+ - v-) = J^T lambda with J v+ = 0 (J: the
// foot's position and angle Jacobian), which conserves the generalized
// momentum in every direction the weld leaves free. Returns false (state
// unchanged) if the projection does not converge.
bool ProjectOntoWeld(const Model& model, const Weld& weld, int leg, State* state);

}  // namespace walkers
