#include "control/vmc.h"

#include <cmath>

namespace walkers {

LegAngles StanceLegAngles(const Vec9& q_or_v, int leg) {
  return LegAngles(q_or_v(JointIndex(leg, kAnkle)), q_or_v(JointIndex(leg, kKnee)), q_or_v(JointIndex(leg, kHip)));
}

Vec3 StanceLegPose(double tibia_length, double femur_length, const LegAngles& theta) {
  // paper eq. (1): the foot is flat, so the tibia's absolute angle is the
  // ankle angle and the femur's is ankle + knee
  const double a = theta(0), ak = theta(0) + theta(1);
  return Vec3(-tibia_length * std::sin(a) - femur_length * std::sin(ak),
              tibia_length * std::cos(a) + femur_length * std::cos(ak), theta(0) + theta(1) + theta(2));
}

Mat3 StanceLegJacobian(double tibia_length, double femur_length, const LegAngles& theta) {
  // paper eq. (2)
  const double s_a = std::sin(theta(0)), c_a = std::cos(theta(0));
  const double s_ak = std::sin(theta(0) + theta(1)), c_ak = std::cos(theta(0) + theta(1));
  const double lt = tibia_length, lf = femur_length;
  Mat3 J;
  // clang-format off
  J << -lt * c_a - lf * c_ak, -lf * c_ak, 0.0,
       -lt * s_a - lf * s_ak, -lf * s_ak, 0.0,
        1.0,                   1.0,       1.0;
  // clang-format on
  return J;
}

Vec3 StanceLegTorques(const Mat3& J, const Vec3& F) {
  // paper eq. (3): tau = J^T F
  return J.transpose() * F;
}

double TargetHeight(const Genome& g, SupportPhase phase) {
  const double offset = phase == SupportPhase::kDouble ? g[kStandOffset] : g[kStepOffset];
  return g.leg_length() - g[kHalfBodyY] - g[kHalfFootY] - offset;
}

Vec3 VirtualForce(const Genome& g, SupportPhase phase, double x_target, const TrunkMotion& trunk, double hip,
                  double hip_rate) {
  // paper eq. (4): springs toward the targets, dampers on the rates
  const double y_target = TargetHeight(g, phase);
  const double fx = -g[kKx] * (trunk.x - x_target) - g[kLambdaX] * trunk.x_dot;
  const double fy_spring = -g[kKy] * (trunk.y - y_target);
  const double fy_damper = -g[kLambdaY] * trunk.y_dot;
  const double ftheta = -g[kKTheta] * hip - g[kLambdaTheta] * hip_rate;
  // one leg carries the walker in single support: springs doubled, the
  // vertical damper not (the authors' program)
  const double gain = phase == SupportPhase::kSingle ? 2.0 : 1.0;
  return Vec3(gain * fx, gain * fy_spring + fy_damper, gain * ftheta);
}

double SwingHipTorque(const Genome& g, double hip) {
  // paper eq. (5)
  return -g[kKStep] * (hip - kSwingHipTarget);
}

}  // namespace walkers
