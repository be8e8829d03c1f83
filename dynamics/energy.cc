#include "dynamics/energy.h"

namespace walkers {

double KineticEnergy(const Model& model, const Kinematics& kin) {
  auto point = [](double m, const PointKinematics& p) { return 0.5 * m * p.v.squaredNorm(); };
  auto spin = [](double inertia, const AngleKinematics& a) { return 0.5 * inertia * a.rate * a.rate; };
  double e = point(model.trunk_mass, kin.trunk) + point(model.hips_mass, kin.hip) +
             spin(model.trunk_inertia, kin.pitch);
  for (const LegKinematics& leg : kin.legs) {
    e += point(model.knee_mass, leg.knee) + point(model.ankle_mass, leg.ankle);
    e += spin(model.femur_inertia, leg.femur) + spin(model.tibia_inertia, leg.tibia) +
         spin(model.foot_inertia, leg.foot);
  }
  return e;
}

double GravitationalEnergy(const Model& model, const Kinematics& kin) {
  double mass_height = model.trunk_mass * kin.trunk.p.y() + model.hips_mass * kin.hip.p.y();
  for (const LegKinematics& leg : kin.legs) {
    mass_height += model.knee_mass * leg.knee.p.y() + model.ankle_mass * leg.ankle.p.y();
  }
  return model.options.gravity * mass_height;
}

CenterOfMass ComputeCenterOfMass(const Model& model, const Kinematics& kin) {
  CenterOfMass c;
  auto add = [&c](double m, const PointKinematics& p) {
    c.p += m * p.p;
    c.v += m * p.v;
  };
  add(model.trunk_mass, kin.trunk);
  add(model.hips_mass, kin.hip);
  for (const LegKinematics& leg : kin.legs) {
    add(model.knee_mass, leg.knee);
    add(model.ankle_mass, leg.ankle);
  }
  c.p /= model.total_mass;
  c.v /= model.total_mass;
  return c;
}

double PotentialEnergy(const Model& model, const Kinematics& kin) {
  return GravitationalEnergy(model, kin) + ElasticEnergy(model, kin);
}

}  // namespace walkers
