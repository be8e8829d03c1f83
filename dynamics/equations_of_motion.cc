#include "dynamics/equations_of_motion.h"

namespace walkers {
namespace {

void AddPointMass(double m, const PointKinematics& p, Mat9* M) {
  M->noalias() += m * p.J.transpose() * p.J;
}

void AddInertia(double inertia, const AngleKinematics& a, Mat9* M) {
  M->noalias() += inertia * a.j.transpose() * a.j;
}

// gravity and velocity-product forces of a point mass: J^T m (g - a_bias)
void AddPointMassForces(double m, double gravity, const PointKinematics& p, Vec9* Q) {
  const Vec2 f = m * (Vec2(0.0, -gravity) - p.a_bias);
  Q->noalias() += p.J.transpose() * f;
}

}  // namespace

void MassMatrix(const Model& model, const Kinematics& kin, Mat9* M) {
  M->setZero();
  AddPointMass(model.trunk_mass, kin.trunk, M);
  AddPointMass(model.hips_mass, kin.hip, M);
  AddInertia(model.trunk_inertia, kin.pitch, M);
  for (const LegKinematics& leg : kin.legs) {
    AddPointMass(model.knee_mass, leg.knee, M);
    AddPointMass(model.ankle_mass, leg.ankle, M);
    AddInertia(model.femur_inertia, leg.femur, M);
    AddInertia(model.tibia_inertia, leg.tibia, M);
    AddInertia(model.foot_inertia, leg.foot, M);
  }
}

Mat9 MassMatrix(const Model& model, const Vec9& q) {
  Kinematics kin;
  ComputeKinematics(model, q, Vec9::Zero(), &kin);
  Mat9 M;
  MassMatrix(model, kin, &M);
  return M;
}

void GeneralizedForces(const Model& model, const Inputs& inputs, const Kinematics& kin, const Vec9& q,
                       const Vec9& v, Vec9* Q) {
  // held joint torques act on the joint coordinates only
  *Q = inputs.joint_torque;
  Q->head<3>().setZero();

  // gravity and velocity products of every point mass (rotational inertias
  // have none: every absolute angle is linear in q)
  const double g = model.options.gravity;
  AddPointMassForces(model.trunk_mass, g, kin.trunk, Q);
  AddPointMassForces(model.hips_mass, g, kin.hip, Q);
  for (const LegKinematics& leg : kin.legs) {
    AddPointMassForces(model.knee_mass, g, leg.knee, Q);
    AddPointMassForces(model.ankle_mass, g, leg.ankle, Q);
  }

  if (model.options.contact) AddGroundContactForces(model, kin, Q);
  AddWeldForces(model, kin, inputs.welds, Q);
  if (model.options.joint_stops) AddJointStopTorques(model, q, v, Q);
}

bool ForwardDynamics(const Model& model, const Inputs& inputs, const Vec9& q, const Vec9& v, Workspace* ws,
                     Vec9* qdd) {
  ComputeKinematics(model, q, v, &ws->kin);
  MassMatrix(model, ws->kin, &ws->M);
  GeneralizedForces(model, inputs, ws->kin, q, v, &ws->Q);

  // a locked coordinate: its row becomes q''_i = 0
  for (int i = 0; i < kNumCoords; ++i) {
    if (!model.options.locked[i]) continue;
    ws->M.row(i).setZero();
    ws->M.col(i).setZero();
    ws->M(i, i) = 1.0;
    ws->Q(i) = 0.0;
  }

  ws->llt.compute(ws->M);
  *qdd = ws->llt.solve(ws->Q);
  return ws->llt.info() == Eigen::Success && qdd->allFinite();
}

}  // namespace walkers
