// Switching a weld on, as the authors' program does: it enables a weld
// constraint and calls Simbody's project(), which moves the state onto every
// enabled constraint by the smallest change of its coordinates.
//
// The authors' model is not a tree rooted at the trunk like ours: the trunk
// and both feet are free bodies, each leg a chain of pins from its foot up
// to a hip welded to the trunk. Simbody's projection measures changes in
// those coordinates with unit weights (metres and radians alike), first of
// positions, then of velocities. So we project in those coordinates too.
#pragma once

#include <limits>

#include <Eigen/Core>

#include "dynamics/contact.h"
#include "dynamics/coords.h"
#include "dynamics/model.h"

namespace walkers {

// The authors' coordinates in the plane, and their rates: trunk (x, y,
// angle), left foot (x, y, angle), right foot (x, y, angle), then per leg
// (left, right) the ankle, knee and hip pins (the same angles as ours).
constexpr int kNumFreeBodyCoords = 15;
using FreeBodyVector = Eigen::Matrix<double, kNumFreeBodyCoords, 1>;
struct FreeBodyState {
  FreeBodyVector z = FreeBodyVector::Zero();
  FreeBodyVector u = FreeBodyVector::Zero();
};
enum FreeBodyCoord : int { kTrunkX = 0, kFootX = 3, kPins = 9 };
constexpr int FootCoord(int leg) { return kFootX + 3 * leg; }
constexpr int PinCoord(int leg, int joint) {  // joint: kHip, kKnee, kAnkle
  return kPins + 3 * leg + (joint == kAnkle ? 0 : joint == kKnee ? 1 : 2);
}

// Our state in the authors' coordinates (the hip welds hold exactly).
FreeBodyState ToFreeBodies(const Model& model, const State& state);
// The authors' coordinates as our state: the trunk and the pins (the feet
// follow when the hip welds hold).
State FromFreeBodies(const FreeBodyState& s);

// Simbody's project(): Gauss-Newton steps of least norm onto the hip welds
// and the active foot welds (each holds the foot at its anchor and angle),
// then the change of the rates of least norm relative to the rates (each
// measured against max(1, |u_i|)) that satisfies them. False (s unchanged)
// if the positions do not converge.
bool ProjectFreeBodies(const Model& model, const Welds& welds, FreeBodyState* s);

// The same for our state.
bool ProjectOntoWelds(const Model& model, const Welds& welds, State* state);

// ---- Simbody's projection with its tolerances (SimbodyMatterSubsystemRep's
// projectQ and projectU), as its RK-Merson integrator projects after every
// step and System::project projects at a touchdown ----

// Simbody counts six constraint equations per weld, three of them out of
// the plane (always satisfied): the two hip welds' and each active foot weld's.
int SimbodyConstraintEquations(const Welds& welds);

struct SimbodyProjection {
  double tolerance = 1e-4;  // [-] RMS of the weld errors over SimbodyConstraintEquations; System::project's default
  double limit = std::numeric_limits<double>::infinity();  // fail when the RMS on entry exceeds it
  bool local_only = false;  // stop (and fail) when an iteration makes the errors grow, as while integrating
};

enum class ProjectionOutcome {
  kUnchanged,  // within the tolerance already: nothing moves
  kProjected,
  kFailed,  // beyond the limit, diverged, or not within the tolerance after Simbody's iterations
};

// The positions: when the welds' RMS error exceeds the tolerance,
// Gauss-Newton steps of least norm (a free body's turn weighing a quarter)
// to a tenth of it, at most 20. `error`, if given, is a position error
// estimate in the same coordinates (turns as angles): the part of it that
// the linearised welds do not allow is taken out, by the same least norm.
ProjectionOutcome ProjectFreeBodyPositions(const Model& model, const Welds& welds, const SimbodyProjection& how,
                                           FreeBodyVector* z, FreeBodyVector* error = nullptr);

// The rates at positions z: when the welds' RMS rate error exceeds the
// tolerance, least-squares steps of the change of least norm relative to
// max(1, |u_i|), at most 7; `error` is a rate error estimate, projected the same way.
ProjectionOutcome ProjectFreeBodyRates(const Model& model, const Welds& welds, const SimbodyProjection& how,
                                       const FreeBodyVector& z, FreeBodyVector* u, FreeBodyVector* error = nullptr);

// System::project(state) of the authors' program: positions, then rates, at
// the tolerance. False when either fails (state unchanged).
bool ProjectOntoWeldsAsSimbody(const Model& model, const Welds& welds, double tolerance, State* state);

}  // namespace walkers
