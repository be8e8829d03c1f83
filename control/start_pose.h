// How every simulation of the walker starts (MODEL.md §4).
#pragma once

#include <cmath>

#include "dynamics/kinematics.h"
#include "dynamics/model.h"

namespace walkers {

constexpr double kControlRate = 30.0;               // [Hz] controller ticks, zero-order hold
constexpr double kStartKneeFlexion = M_PI / 10.0;   // [rad]

// Both feet flat at x = 0, knees flexed pi/10, trunk level, at rest.
inline State StartState(const Model& model) { return StandingState(model, kStartKneeFlexion, 0.0); }

}  // namespace walkers
