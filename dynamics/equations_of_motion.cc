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

// A leg's supports as compile-time constants. The helpers below take their
// support as a template argument so that, their loops unrolled, every entry of
// M and J sits at a constant offset: with the support read from a run-time
// array (ColumnsOf(leg) in a loop over the legs) every address was computed at
// run time, which cost more than the products themselves.
template <int kLeg>
struct LegSupports {
  static constexpr TreeColumns kPoint = ColumnsOf(kLeg);
  static constexpr Support<4> kAngle = LegAngleSupport(kLeg);
};

// The helpers fill M column by column from scaled Jacobian rows held in local
// arrays (m J(0, :), m J(1, :), I j): down one column of M the entries are
// adjacent in memory (M is column-major) and each is the same expression of
// the next local value, so the compiler pairs them into SSE2 operations. Each
// entry still gets the same products and the same sum; each helper is still
// one whole pass over its entries, in the order MassMatrix calls them.

// upper triangle of m J^T J over the point's support
template <const auto& kCols>
void AddPointMass(double m, const PointKinematics& p, Mat9* M) {
  constexpr size_t N = kCols.size();
  double mx[N], my[N];
  #pragma GCC unroll 6
  for (size_t a = 0; a < N; ++a) {
    mx[a] = m * p.J(0, kCols[a]);
    my[a] = m * p.J(1, kCols[a]);
  }
  #pragma GCC unroll 6
  for (size_t b = 0; b < N; ++b) {
    const int k = kCols[b];
    const double jx = p.J(0, k), jy = p.J(1, k);
    #pragma GCC unroll 6
    for (size_t a = 0; a <= b; ++a) (*M)(kCols[a], k) += mx[a] * jx + my[a] * jy;
  }
}

// upper triangle of I j^T j over the angle's support
template <const auto& kCols>
void AddInertia(double inertia, const AngleKinematics& angle, Mat9* M) {
  constexpr size_t N = kCols.size();
  double ij[N];
  #pragma GCC unroll 6
  for (size_t a = 0; a < N; ++a) ij[a] = inertia * angle.j(kCols[a]);
  #pragma GCC unroll 6
  for (size_t b = 0; b < N; ++b) {
    const int k = kCols[b];
    const double jk = angle.j(k);
    #pragma GCC unroll 6
    for (size_t a = 0; a <= b; ++a) (*M)(kCols[a], k) += ij[a] * jk;
  }
}

// one leg's two point masses and three segment inertias, in this order: the
// order of the passes is the order of the sums in each entry of M, part of its
// result
template <int kLeg>
void AddLeg(const Model& model, const LegKinematics& l, Mat9* M) {
  using S = LegSupports<kLeg>;
  AddPointMass<S::kPoint>(model.knee_mass, l.knee, M);
  AddPointMass<S::kPoint>(model.ankle_mass, l.ankle, M);
  AddInertia<S::kAngle>(model.femur_inertia, l.femur, M);
  AddInertia<S::kAngle>(model.tibia_inertia, l.tibia, M);
  AddInertia<S::kAngle>(model.foot_inertia, l.foot, M);
}

// gravity and velocity-product forces of a point mass: J^T m (g - a_bias)
void AddPointMassForces(double m, double gravity, const PointKinematics& p, Vec9* Q) {
  const Vec2 f = m * (Vec2(0.0, -gravity) - p.a_bias);
  AddTransposeProduct(p, f, Q);
}

// The welds' part of the forward dynamics for their R rows: G, M^-1 G^T, the
// factors of G M^-1 G^T and lambda into the workspace, qdd corrected.
template <int R>
void SolveWelds(const Model& model, const Welds& welds, Workspace* ws, Vec9* qdd) {
  WeldVector b;
  WeldConstraints(model, ws->kin, welds, &ws->G, &b);
  Eigen::Matrix<double, kNumCoords, R> Minv_Gt = ws->G.topRows<R>().transpose();
  ws->mass_ldlt.SolveInPlace(&Minv_Gt);
  ws->Minv_Gt.leftCols<R>() = Minv_Gt;
  const Eigen::Matrix<double, R, R> S = ws->G.topRows<R>().lazyProduct(Minv_Gt);
  if constexpr (R == kWeldRowsPerFoot) {
    ws->one_weld_ldlt.Compute(S);
  } else {
    ws->two_welds_ldlt.Compute(S);
  }
  ws->lambda.head<R>() = ws->ApplyWelds<R, 1>(b.head<R>(), qdd);
}

}  // namespace

void MassMatrix(const Model& model, const Kinematics& kin, Mat9* M) {
  M->setZero();
  AddPointMass<kTrunkSupport>(model.trunk_mass, kin.trunk, M);
  AddPointMass<kHipSupport>(model.hips_mass, kin.hip, M);
  (*M)(kPitch, kPitch) += model.trunk_inertia;
  AddLeg<kLeft>(model, kin.legs[kLeft], M);
  AddLeg<kRight>(model, kin.legs[kRight], M);
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
                       const Vec9& v, Vec9* Q, double* contact_dissipation) {
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

  AddContactForces(model, kin, inputs.welds, Q, contact_dissipation);
  if (model.options.joint_stops) AddJointStopTorques(model, q, v, Q);
}

bool ForwardDynamics(const Model& model, const Inputs& inputs, const Vec9& q, const Vec9& v, Workspace* ws,
                     Vec9* qdd) {
  ComputeKinematics(model, q, v, &ws->kin);
  MassMatrix(model, ws->kin, &ws->M);
  GeneralizedForces(model, inputs, ws->kin, q, v, &ws->Q, ws->count_dissipation ? &ws->contact_dissipation : nullptr);

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

  // the welds: q'' = M^-1 (Q + G^T lambda) with lambda from
  // (G M^-1 G^T) lambda = b - G M^-1 Q
  ws->weld_rows = ActiveWeldRows(inputs.welds);
  if (ws->weld_rows == kWeldRowsPerFoot) {
    SolveWelds<kWeldRowsPerFoot>(model, inputs.welds, ws, qdd);
  } else if (ws->weld_rows == kMaxWeldRows) {
    SolveWelds<kMaxWeldRows>(model, inputs.welds, ws, qdd);
  }
  return qdd->allFinite();
}

}  // namespace walkers
