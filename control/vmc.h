// Virtual model control of a stance leg and the swing leg (paper §2.2,
// eqs. 1–5, in the chain convention of docs/model.md, "Coordinates and
// conventions"; the authors' choices in "Controller").
#pragma once

#include "control/genome.h"
#include "dynamics/coords.h"

namespace walkers {

// A leg's joint angles in the paper's order (ankle, knee, hip).
using LegAngles = Vec3;

LegAngles StanceLegAngles(const Vec9& q_or_v, int leg);

// paper eq. (1): the hip's position relative to the ankle and the trunk pitch,
// (p_x, p_y, phi), for a flat planted foot.
Vec3 StanceLegPose(double tibia_length, double femur_length, const LegAngles& theta);

// paper eq. (2): J = d(p_x, p_y, phi) / d(theta_a, theta_k, theta_h).
Mat3 StanceLegJacobian(double tibia_length, double femur_length, const LegAngles& theta);

// paper eq. (3): tau = J^T F, the (ankle, knee, hip) torques that act on the
// trunk like the force (F_x, F_y) at the hip and the moment F_theta.
Vec3 StanceLegTorques(const Mat3& J, const Vec3& F);

enum class SupportPhase { kDouble, kSingle };

// The trunk's motion the virtual components see.
struct TrunkMotion {
  double x = 0, y = 0;        // trunk centre [m]
  double x_dot = 0, y_dot = 0;  // [m/s]
};

// Height of the trunk centre the vertical spring pulls to: the authors'
// target L - halfBodyY - halfFootY - offset, reproduced as is (docs/model.md,
// "Controller").
double TargetHeight(const Genome& g, SupportPhase phase);

// paper eq. (4) with the authors' targets: the virtual force (F_x, F_y, F_theta)
// of one stance leg. Single support doubles F_x, F_theta and the vertical spring
// and uses stepOffset instead of standOffset.
Vec3 VirtualForce(const Genome& g, SupportPhase phase, double x_target, const TrunkMotion& trunk, double hip,
                  double hip_rate);

// paper eq. (5): the swing hip's torque, driving the femur 36 degrees forward
// of the trunk: -kStep (theta_h + pi/5).
double SwingHipTorque(const Genome& g, double hip);

constexpr double kSwingHipTarget = -M_PI / 5.0;  // [rad]

}  // namespace walkers
