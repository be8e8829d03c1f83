// Generalized coordinates of the planar walker and the fixed-size types used
// throughout the project (docs/model.md, "Coordinates and conventions").
#pragma once

#include <Eigen/Core>

namespace walkers {

// q = (x, y, pitch, hip_l, knee_l, ankle_l, hip_r, knee_r, ankle_r): the trunk
// centre and pitch (floating base), then each leg's relative joint angles from
// the trunk down. Joint angle = parent's absolute angle - child's absolute
// angle, so a planted foot's angle plus its leg's ankle, knee and hip angles is
// the trunk pitch. Positive knee angle = knee flexed forward.
enum Coord : int {
  kX,
  kY,
  kPitch,
  kHipL,
  kKneeL,
  kAnkleL,
  kHipR,
  kKneeR,
  kAnkleR,
  kNumCoords
};

enum Leg : int { kLeft = 0, kRight = 1, kNumLegs = 2 };

// Joint of a leg, in the order its coordinates appear in q.
enum Joint : int { kHip = 0, kKnee = 1, kAnkle = 2, kNumJoints = 3 };

// Index in q of joint `joint` of leg `leg`.
constexpr int JointIndex(int leg, int joint) { return kHipL + 3 * leg + joint; }

using Vec2 = Eigen::Vector2d;
using Vec3 = Eigen::Vector3d;
using Vec9 = Eigen::Matrix<double, kNumCoords, 1>;
using Mat9 = Eigen::Matrix<double, kNumCoords, kNumCoords>;
using Mat3 = Eigen::Matrix3d;
using Jac2x9 = Eigen::Matrix<double, 2, kNumCoords>;  // d(point)/dq
using Row9 = Eigen::Matrix<double, 1, kNumCoords>;    // d(angle)/dq

// Mechanical state: positions and velocities.
struct State {
  Vec9 q = Vec9::Zero();
  Vec9 v = Vec9::Zero();
};

// Names of the coordinates as they appear in trajectory files.
constexpr const char* kCoordNames[kNumCoords] = {
    "x", "y", "pitch", "hip_l", "knee_l", "ankle_l", "hip_r", "knee_r", "ankle_r"};

}  // namespace walkers
