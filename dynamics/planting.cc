#include "dynamics/planting.h"

#include <Eigen/Cholesky>
#include <Eigen/LU>

#include "dynamics/equations_of_motion.h"
#include "dynamics/kinematics.h"

namespace walkers {
namespace {

using Jac3x9 = Eigen::Matrix<double, 3, kNumCoords>;

// the weld's constraint error (foot centre, foot angle) and its Jacobian
void WeldConstraint(const Model& model, const Weld& weld, int leg, const Vec9& q, Vec3* error, Jac3x9* J,
                    Mat9* M) {
  Kinematics kin;
  ComputeKinematics(model, q, Vec9::Zero(), &kin);
  const LegKinematics& l = kin.legs[leg];
  error->head<2>() = l.ankle.p - weld.anchor;
  (*error)(2) = l.foot.angle - weld.angle;
  J->topRows<2>() = l.ankle.J;
  J->row(2) = l.foot.j;
  MassMatrix(model, kin, M);
}

// the mass-weighted least-norm correction M^-1 J^T (J M^-1 J^T)^-1 r; locked
// coordinates do not move
Vec9 WeightedCorrection(const Model& model, const Mat9& M, Jac3x9 J, const Vec3& r) {
  Mat9 W = M;
  for (int i = 0; i < kNumCoords; ++i) {
    if (!model.options.locked[i]) continue;
    J.col(i).setZero();
    W.row(i).setZero();
    W.col(i).setZero();
    W(i, i) = 1.0;
  }
  const Eigen::LLT<Mat9> llt(W);
  const Eigen::Matrix<double, kNumCoords, 3> Minv_Jt = llt.solve(J.transpose());
  const Mat3 S = J * Minv_Jt;
  return Minv_Jt * S.partialPivLu().solve(r);
}

}  // namespace

bool ProjectOntoWeld(const Model& model, const Weld& weld, int leg, State* state) {
  Vec9 q = state->q;
  Vec3 error;
  Jac3x9 J;
  Mat9 M;
  // positions: Gauss-Newton on the three weld equations
  bool converged = false;
  for (int iteration = 0; iteration < 20; ++iteration) {
    WeldConstraint(model, weld, leg, q, &error, &J, &M);
    if (error.norm() < 1e-12) {
      converged = true;
      break;
    }
    q -= WeightedCorrection(model, M, J, error);
  }
  if (!converged || !q.allFinite()) return false;

  // velocities: the plastic impact that stops the foot
  const Vec9 v = state->v - WeightedCorrection(model, M, J, J * state->v);
  if (!v.allFinite()) return false;
  state->q = q;
  state->v = v;
  return true;
}

}  // namespace walkers
