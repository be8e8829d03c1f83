// The weld that holds a planted foot (docs/model.md, "Planted-foot weld"):
// an exact constraint on the foot's centre and angle, as the authors'
// Simbody weld. Everything the rest of the code knows of a weld is here: its
// parameters, where it holds the foot, its constraint rows and their
// derivatives. The forward dynamics solve them with the equations of motion
// (ForwardDynamics), and planting projects onto them (dynamics/planting.h).
#pragma once

#include <array>

#include <Eigen/Core>

#include "dynamics/coords.h"

namespace walkers {

struct Model;
struct Kinematics;

struct WeldParameters {
  // the authors' weld holds the foot point (0, -halfFootY + depth) at ground
  // level: a planted foot sits this deep, its contact springs preloaded
  double depth = 0.002;  // [m]
  // Baumgarte's stabilisation: the constraint's error e obeys
  // e'' + 2 a e' + a^2 e = 0, so integration drift decays in ~1/a
  double stabilization = 100.0;  // [1/s] a
};

// A foot held at a planting pose by its weld.
struct Weld {
  bool active = false;
  Vec2 anchor = Vec2::Zero();  // where the foot's centre is held [m]
  double angle = 0;            // foot angle held [rad]
};
using Welds = std::array<Weld, kNumLegs>;

bool SameWeld(const Weld& a, const Weld& b);

// The point of the foot that the weld holds at ground level, in the foot's frame.
Vec2 WeldedFootPoint(const Model& model);

// A weld holding the foot flat with its centre above x (its welded point at
// ground level).
Weld FlatWeldAt(const Model& model, double x);

// A weld that plants a leg's foot flat where it is.
Weld PlantFoot(const Model& model, const State& state, int leg);

// The constraint rows: per active weld, the foot centre's two and its
// angle's one, stacked in leg order (at most two welds). Storage is fixed at
// the most rows; the first ActiveWeldRows are used.
constexpr int kWeldRowsPerFoot = 3;
constexpr int kMaxWeldRows = kNumLegs * kWeldRowsPerFoot;
using WeldJacobian = Eigen::Matrix<double, kMaxWeldRows, kNumCoords>;
using WeldVector = Eigen::Matrix<double, kMaxWeldRows, 1>;
int ActiveWeldRows(const Welds& welds);

// G and b of the welds' constraints G q'' = b at the kinematics' state, with
// Baumgarte's stabilisation of their errors e:
//   G q'' = -G' q' - 2 a G q' - a^2 e.
// Locked coordinates' columns are zero. Fills the first ActiveWeldRows rows.
void WeldConstraints(const Model& model, const Kinematics& kin, const Welds& welds, WeldJacobian* G, WeldVector* b);

// The derivatives of the constraints G q'' + G' q' + 2 a G q' + a^2 e = 0
// with respect to q and v at fixed q''. Fills the first ActiveWeldRows rows.
void WeldConstraintDerivatives(const Model& model, const Kinematics& kin, const Welds& welds, const Vec9& qdd,
                               WeldJacobian* C_q, WeldJacobian* C_v);

// The derivative with respect to q of the welds' constraint forces G^T lambda
// at fixed lambda, added to dR_dq.
void AddWeldForceDerivatives(const Kinematics& kin, const Welds& welds, const WeldVector& lambda, Mat9* dR_dq);

}  // namespace walkers
