#include "dynamics/observation.h"

#include "dynamics/energy.h"
#include "dynamics/kinematics.h"

namespace walkers {

Observation Observe(const Model& model, const State& state) {
  Kinematics kin;
  ComputeKinematics(model, state.q, state.v, &kin);
  Observation o;
  o.kinetic = KineticEnergy(model, kin);
  o.potential = PotentialEnergy(model, kin);
  o.trunk_contact = TrunkSupported(model, kin);
  o.max_penetration = MaxGroundPenetration(model, kin);
  return o;
}
}  // namespace walkers
