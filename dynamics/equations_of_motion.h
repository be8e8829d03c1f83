// Equations of motion of the walker: M(q) q'' = Q(q, q', inputs), with Q the
// generalized forces of gravity, velocity products, ground contact, welds,
// joint stops and the held joint torques.
#pragma once

#include "dynamics/contact.h"
#include "dynamics/coords.h"
#include "dynamics/kinematics.h"
#include "dynamics/model.h"
#include "dynamics/tree_ldlt9.h"
#include "dynamics/weld.h"

#include <cmath>

#include <Eigen/Cholesky>

namespace walkers {

// What the controller holds between ticks.
struct Inputs {
  Vec9 joint_torque = Vec9::Zero();  // [N m] on the joint coordinates; trunk entries are ignored
  Welds welds;                       // planted feet
};

// LDL^T of the welds' R x R matrix G M^-1 G^T (R = 3 per active weld) that
// solves it in the least-squares sense when G loses rank (locked joints, or
// both welded legs straight): pivots below kRankTolerance of the largest
// count as zero, as a pseudo-inverse would have it, so redundant constraints
// share their load instead of producing huge multipliers.
template <int R>
class WeldLdlt {
 public:
  using Square = Eigen::Matrix<double, R, R>;
  static constexpr double kRankTolerance = 1e-10;
  void Compute(const Square& S) { ldlt_.compute(S); }
  template <typename Rhs>
  Rhs Solve(const Rhs& rhs) const {
    Rhs x = ldlt_.transpositionsP() * rhs;
    ldlt_.matrixL().solveInPlace(x);
    const auto d = ldlt_.vectorD();
    const double floor = kRankTolerance * d.cwiseAbs().maxCoeff();
    for (int i = 0; i < R; ++i) {
      if (std::abs(d(i)) > floor) {
        x.row(i) /= d(i);
      } else {
        x.row(i).setZero();
      }
    }
    ldlt_.matrixU().solveInPlace(x);
    return ldlt_.transpositionsP().transpose() * x;
  }

 private:
  Eigen::LDLT<Square> ldlt_;
};

// Per-integration scratch: nothing in it outlives one right-hand side.
struct Workspace {
  Kinematics kin;
  Mat9 M = Mat9::Identity();
  Vec9 Q = Vec9::Zero();
  TreeLdlt9 mass_ldlt;  // of M (locked rows and columns replaced by the identity)
  // the welds: their rows (ActiveWeldRows: 0, 3 or 6), G (the constraints'
  // Jacobian), M^-1 G^T, the LDL^T of G M^-1 G^T for one weld or two, and
  // the constraint forces' multipliers lambda (G^T lambda is the welds'
  // generalized force). Only the first weld_rows rows (columns of Minv_Gt) hold.
  int weld_rows = 0;
  WeldJacobian G = WeldJacobian::Zero();
  Eigen::Matrix<double, kNumCoords, kMaxWeldRows> Minv_Gt = Eigen::Matrix<double, kNumCoords, kMaxWeldRows>::Zero();
  WeldLdlt<kWeldRowsPerFoot> one_weld_ldlt;
  WeldLdlt<kMaxWeldRows> two_welds_ldlt;
  WeldVector lambda = WeldVector::Zero();
  // [W] the power the contact dissipated at the last ForwardDynamics, when
  // asked to count it
  bool count_dissipation = false;
  double contact_dissipation = 0;

  // For the active welds' R rows: the change of x (M^-1 times a generalized
  // force, or nine of them) that the welds' constraint forces make so that
  // G x = r, x += M^-1 G^T S^+ (r - G x) with S = G M^-1 G^T; returns the
  // multipliers S^+ (r - G x).
  template <int R, int Cols>
  Eigen::Matrix<double, R, Cols> ApplyWelds(const Eigen::Matrix<double, R, Cols>& r,
                                            Eigen::Matrix<double, kNumCoords, Cols>* x) const {
    // products this small are cheapest coefficient by coefficient
    const Eigen::Matrix<double, R, Cols> residual = r - G.topRows<R>().lazyProduct(*x);
    Eigen::Matrix<double, R, Cols> multipliers;
    if constexpr (R == kWeldRowsPerFoot) {
      multipliers = one_weld_ldlt.Solve(residual);
    } else {
      multipliers = two_welds_ldlt.Solve(residual);
    }
    x->noalias() += Minv_Gt.leftCols<R>().lazyProduct(multipliers);
    return multipliers;
  }
};

// Mass matrix from computed kinematics: sum of m J^T J over point masses and
// I j^T j over rotational inertias.
void MassMatrix(const Model& model, const Kinematics& kin, Mat9* M);
Mat9 MassMatrix(const Model& model, const Vec9& q);

// Every generalized force except M q'' (right-hand side of the equations);
// and, if asked, the power the contact dissipates (AddContactForces).
void GeneralizedForces(const Model& model, const Inputs& inputs, const Kinematics& kin, const Vec9& q,
                       const Vec9& v, Vec9* Q, double* contact_dissipation = nullptr);

// Solves M q'' = Q + G^T lambda for q'' with the active welds' constraints
// G q'' = -G' q' - 2 a G q' - a^2 e (Baumgarte's stabilisation of their
// errors e, WeldParameters). Locked coordinates get q'' = 0. Returns false if
// the result is not finite.
bool ForwardDynamics(const Model& model, const Inputs& inputs, const Vec9& q, const Vec9& v, Workspace* ws,
                     Vec9* qdd);

}  // namespace walkers
