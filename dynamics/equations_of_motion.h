// Equations of motion of the walker: M(q) q'' = Q(q, q', inputs), with Q the
// generalized forces of gravity, velocity products, ground contact, welds,
// joint stops and the held joint torques.
#pragma once

#include "dynamics/contact.h"
#include "dynamics/coords.h"
#include "dynamics/kinematics.h"
#include "dynamics/model.h"
#include "dynamics/tree_ldlt9.h"

#include <cmath>

#include <Eigen/Cholesky>

namespace walkers {

// What the controller holds between ticks.
struct Inputs {
  Vec9 joint_torque = Vec9::Zero();  // [N m] on the joint coordinates; trunk entries are ignored
  Welds welds;                       // planted feet
};

// The welds' constraint rows: for each active weld the foot centre's two and
// its angle's one, stacked (at most two welds).
constexpr int kMaxWeldRows = 6;
using WeldJacobian = Eigen::Matrix<double, Eigen::Dynamic, kNumCoords, 0, kMaxWeldRows, kNumCoords>;
using WeldVector = Eigen::Matrix<double, Eigen::Dynamic, 1, 0, kMaxWeldRows, 1>;
using WeldSquare = Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, 0, kMaxWeldRows, kMaxWeldRows>;

// LDL^T of the welds' G M^-1 G^T that solves it in the least-squares sense
// when G loses rank (locked joints, or both welded legs straight): pivots
// below kRankTolerance of the largest count as zero, as a pseudo-inverse
// would have it, so redundant constraints share their load instead of
// producing huge multipliers.
class WeldLdlt {
 public:
  static constexpr double kRankTolerance = 1e-10;
  void Compute(const WeldSquare& S) { ldlt_.compute(S); }
  template <typename Rhs>
  Rhs Solve(const Rhs& rhs) const {
    Rhs x = ldlt_.transpositionsP() * rhs;
    ldlt_.matrixL().solveInPlace(x);
    const auto d = ldlt_.vectorD();
    const double floor = kRankTolerance * d.cwiseAbs().maxCoeff();
    for (int i = 0; i < d.size(); ++i) {
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
  Eigen::LDLT<WeldSquare> ldlt_;
};

// Per-integration scratch: nothing in it outlives one right-hand side.
struct Workspace {
  Kinematics kin;
  Mat9 M = Mat9::Identity();
  Vec9 Q = Vec9::Zero();
  TreeLdlt9 mass_ldlt;  // of M (locked rows and columns replaced by the identity)
  // the welds: G (rows of the constraints' Jacobian), M^-1 G^T, the LDL^T
  // of G M^-1 G^T, and the constraint forces' multipliers lambda (G^T lambda
  // is the welds' generalized force)
  WeldJacobian G;
  Eigen::Matrix<double, kNumCoords, Eigen::Dynamic, 0, kNumCoords, kMaxWeldRows> Minv_Gt;
  WeldLdlt weld_ldlt;
  WeldVector lambda;
};

// Mass matrix from computed kinematics: sum of m J^T J over point masses and
// I j^T j over rotational inertias.
void MassMatrix(const Model& model, const Kinematics& kin, Mat9* M);
Mat9 MassMatrix(const Model& model, const Vec9& q);

// Every generalized force except M q'' (right-hand side of the equations).
void GeneralizedForces(const Model& model, const Inputs& inputs, const Kinematics& kin, const Vec9& q,
                       const Vec9& v, Vec9* Q);

// The constraint rows of the active welds at the kinematics' state: G and
// the right-hand side b of G q'' = b (see ForwardDynamics).
void WeldConstraints(const Model& model, const Kinematics& kin, const Welds& welds, WeldJacobian* G, WeldVector* b);

// Solves M q'' = Q + G^T lambda for q'' with the active welds' constraints
// G q'' = -G' q' - 2 a G q' - a^2 e (Baumgarte's stabilisation of their
// errors e, WeldParameters). Locked coordinates get q'' = 0. Returns false if
// the result is not finite.
bool ForwardDynamics(const Model& model, const Inputs& inputs, const Vec9& q, const Vec9& v, Workspace* ws,
                     Vec9* qdd);

}  // namespace walkers
