// What the trajectory files, the tests and the controller read off a state.
#pragma once

#include "dynamics/contact.h"
#include "dynamics/coords.h"
#include "dynamics/model.h"
#include "dynamics/weld.h"

namespace walkers {

struct Observation {
  double kinetic = 0;          // [J]
  double potential = 0;        // [J] gravity + elastic
  bool trunk_contact = false;  // a trunk corner is below the ground
  double max_penetration = 0;  // [m] deepest contact point
};

Observation Observe(const Model& model, const State& state);

}  // namespace walkers
