#include "dynamics/equations_of_motion.h"

#include <array>

namespace walkers {
namespace {

// Columns of q a point or an angle depends on, at most the trunk's (x, y,
// pitch) and one leg's joints (ColumnsOf). Products over these alone keep M's
// assembly cheap.
template <size_t N>
using Support = std::array<int, N>;
constexpr Support<2> kTrunkSupport = {kX, kY};
constexpr Support<3> kHipSupport = {kX, kY, kPitch};
constexpr Support<4> LegAngleSupport(int leg) {
  return {kPitch, JointIndex(leg, kHip), JointIndex(leg, kKnee), JointIndex(leg, kAnkle)};
}

// upper triangle of m J^T J over the point's support
template <size_t N>
void AddPointMass(double m, const PointKinematics& p, const Support<N>& cols, Mat9* M) {
  #pragma GCC unroll 6
  for (size_t a = 0; a < N; ++a) {
    const int i = cols[a];
    const double mx = m * p.J(0, i), my = m * p.J(1, i);
    #pragma GCC unroll 6
    for (size_t b = a; b < N; ++b) {
      const int k = cols[b];
      (*M)(i, k) += mx * p.J(0, k) + my * p.J(1, k);
    }
  }
}

// upper triangle of I j^T j over the angle's support
template <size_t N>
void AddInertia(double inertia, const AngleKinematics& angle, const Support<N>& cols, Mat9* M) {
  #pragma GCC unroll 6
  for (size_t a = 0; a < N; ++a) {
    const double ij = inertia * angle.j(cols[a]);
    #pragma GCC unroll 6
    for (size_t b = a; b < N; ++b) (*M)(cols[a], cols[b]) += ij * angle.j(cols[b]);
  }
}

// gravity and velocity-product forces of a point mass: J^T m (g - a_bias)
void AddPointMassForces(double m, double gravity, const PointKinematics& p, Vec9* Q) {
  const Vec2 f = m * (Vec2(0.0, -gravity) - p.a_bias);
  AddTransposeProduct(p, f, Q);
}

}  // namespace

void MassMatrix(const Model& model, const Kinematics& kin, Mat9* M) {
  M->setZero();
  AddPointMass(model.trunk_mass, kin.trunk, kTrunkSupport, M);
  AddPointMass(model.hips_mass, kin.hip, kHipSupport, M);
  (*M)(kPitch, kPitch) += model.trunk_inertia;
  for (int leg = 0; leg < kNumLegs; ++leg) {
    const LegKinematics& l = kin.legs[leg];
    AddPointMass(model.knee_mass, l.knee, ColumnsOf(leg), M);
    AddPointMass(model.ankle_mass, l.ankle, ColumnsOf(leg), M);
    AddInertia(model.femur_inertia, l.femur, LegAngleSupport(leg), M);
    AddInertia(model.tibia_inertia, l.tibia, LegAngleSupport(leg), M);
    AddInertia(model.foot_inertia, l.foot, LegAngleSupport(leg), M);
  }
  // the lower triangle mirrors the upper
  *M = M->selfadjointView<Eigen::Upper>();
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

  if (!ws->mass_ldlt.Compute(ws->M)) return false;
  *qdd = ws->Q;
  ws->mass_ldlt.SolveInPlace(qdd);
  return qdd->allFinite();
}

}  // namespace walkers
