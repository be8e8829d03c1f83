#include "control/start_pose.h"

#include <stdexcept>

#include "dynamics/planting.h"

namespace walkers {

Welds StartWelds(const Model& model) {
  Welds welds;
  for (Weld& w : welds) w = FlatWeldAt(model, 0.0);
  return welds;
}

State StartState(const Model& model, double trunk_raise) {
  const BodyParameters& b = model.body;
  FreeBodyState s;
  s.z(kTrunkX + 1) = model.leg_length() + b.half_foot_y + b.half_body_y + trunk_raise;
  for (int leg = 0; leg < kNumLegs; ++leg) {
    s.z(FootCoord(leg) + 1) = b.half_foot_y;
    s.z(PinCoord(leg, kKnee)) = kStartKneeFlexion;
  }
  if (!ProjectFreeBodies(model, StartWelds(model), &s)) {
    throw std::runtime_error("the start pose cannot be projected onto the welds");
  }
  return FromFreeBodies(s);
}

}  // namespace walkers
