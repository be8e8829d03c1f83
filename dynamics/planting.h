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

}  // namespace walkers
