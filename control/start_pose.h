// How every simulation of the walker starts (docs/model.md, "Coordinates and
// conventions": the start pose).
#pragma once

#include <cmath>

#include "dynamics/contact.h"
#include "dynamics/coords.h"
#include "dynamics/model.h"

namespace walkers {

constexpr double kControlRate = 30.0;               // [Hz] controller ticks, zero-order hold
constexpr double kStartKneeFlexion = M_PI / 10.0;   // [rad]

// Both feet welded flat at x = 0.
Welds StartWelds(const Model& model);

// The authors' start: their default state (trunk level at height L +
// halfFootY + halfBodyY above the origin, feet flat at (0, halfFootY), knees
// pi/10, hips and ankles 0, at rest) projected onto both foot welds at x = 0
// and the hip welds as Simbody's project() does. The trunk is then not level
// (docs/model.md). `trunk_raise` [m] raises the default state's trunk before
// the projection: the accuracy criterion's ensembles perturb the start by it
// (control/accuracy.h). Throws std::runtime_error if the projection fails.
State StartState(const Model& model, double trunk_raise = 0.0);

}  // namespace walkers
