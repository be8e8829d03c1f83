#include "control/vmc.h"

#include <random>

#include <Eigen/LU>
#include <gtest/gtest.h>

#include "dynamics/kinematics.h"
#include "tests/finite_difference.h"

namespace walkers {
namespace {

using testing::kFiniteDifferenceTolerance;
using testing::MatricesNear;
using testing::NumericalJacobian;

class VmcTest : public ::testing::Test {
 protected:
  Genome genome_ = DefaultGenome();
  Model model_ = BuildModel(BodyOf(genome_));
  std::mt19937 rng_{99};

  // a random configuration whose `leg` has its foot flat on the ground
  Vec9 RandomFlatFootConfiguration(int leg) {
    Vec9 q = testing::RandomVector<kNumCoords>(rng_, -1.2, 1.2);
    q(kPitch) = q(JointIndex(leg, kHip)) + q(JointIndex(leg, kKnee)) + q(JointIndex(leg, kAnkle));
    return q;
  }
};

TEST_F(VmcTest, StanceLegJacobianMatchesFiniteDifferencesOfEquationOne) {
  for (int leg = 0; leg < kNumLegs; ++leg) {
    for (int trial = 0; trial < 20; ++trial) {
      const LegAngles theta = StanceLegAngles(RandomFlatFootConfiguration(leg), leg);
      auto pose = [&](const Vec3& x) { return StanceLegPose(genome_[kTibiaLength], genome_[kFemurLength], x); };
      const Mat3 J = StanceLegJacobian(genome_[kTibiaLength], genome_[kFemurLength], theta);
      EXPECT_TRUE(MatricesNear(NumericalJacobian<3, 3>(pose, theta), J, kFiniteDifferenceTolerance));
      // the position rows depend on ankle and knee; the hip moves only phi
      for (int row = 0; row < 2; ++row) {
        EXPECT_GT(std::abs(J(row, 0)), 1e-3);
        EXPECT_NE(J(row, 1), 0.0);
        EXPECT_EQ(J(row, 2), 0.0);
      }
      EXPECT_EQ(J.row(2), Eigen::RowVector3d(1, 1, 1));
    }
  }
}

TEST_F(VmcTest, EquationOneIsTheDynamicsHipSeenFromAFlatFoot) {
  for (int leg = 0; leg < kNumLegs; ++leg) {
    const Vec9 q = RandomFlatFootConfiguration(leg);
    Kinematics kin;
    ComputeKinematics(model_, q, Vec9::Zero(), &kin);
    ASSERT_NEAR(kin.legs[leg].foot.angle, 0.0, 1e-12);
    const Vec3 pose = StanceLegPose(genome_[kTibiaLength], genome_[kFemurLength], StanceLegAngles(q, leg));
    EXPECT_TRUE(MatricesNear(Vec2(kin.hip.p - kin.legs[leg].ankle.p), pose.head<2>(), 1e-12));
    EXPECT_NEAR(pose(2), q(kPitch), 1e-12);
  }
}

TEST_F(VmcTest, JointTorquesDoTheVirtualWorkOfTheHipForceAndTrunkMoment) {
  // for every motion that keeps the planted foot still, the torques J^T F do
  // the same work as the force (F_x, F_y) applied at the hip and the moment
  // F_theta applied to the trunk (paper eq. 3), measured with the dynamics'
  // own Jacobians
  for (int leg = 0; leg < kNumLegs; ++leg) {
    for (int trial = 0; trial < 20; ++trial) {
      const Vec9 q = RandomFlatFootConfiguration(leg);
      const Vec3 F = testing::RandomVector<3>(rng_, -500.0, 500.0);
      Kinematics kin;
      ComputeKinematics(model_, q, Vec9::Zero(), &kin);

      // generalized force of the joint torques, and of the external wrench
      const Vec3 tau = StanceLegTorques(
          StanceLegJacobian(genome_[kTibiaLength], genome_[kFemurLength], StanceLegAngles(q, leg)), F);
      Vec9 Q_torques = Vec9::Zero();
      Q_torques(JointIndex(leg, kAnkle)) = tau(0);
      Q_torques(JointIndex(leg, kKnee)) = tau(1);
      Q_torques(JointIndex(leg, kHip)) = tau(2);
      Vec9 Q_wrench = kin.hip.J.transpose() * F.head<2>();
      Q_wrench(kPitch) += F(2);

      // motions that keep the foot still: the null space of its Jacobian
      Eigen::Matrix<double, 3, kNumCoords> C;
      C.topRows<2>() = kin.legs[leg].ankle.J;
      C.row(2) = kin.legs[leg].foot.j;
      const Eigen::FullPivLU<Eigen::Matrix<double, 3, kNumCoords>> lu(C);
      const Eigen::MatrixXd N = lu.kernel();
      ASSERT_EQ(N.cols(), 6);
      const Eigen::VectorXd work_torques = N.transpose() * Q_torques;
      const Eigen::VectorXd work_wrench = N.transpose() * Q_wrench;
      EXPECT_GT(work_torques.norm(), 1.0);
      EXPECT_TRUE(MatricesNear(work_wrench, work_torques, 1e-9 * (1.0 + work_wrench.norm())));
    }
  }
}

TEST_F(VmcTest, VirtualForceFollowsEquationFourWithTheAuthorsTargets) {
  const TrunkMotion trunk{0.3, 1.1, 0.2, -0.1};
  const double x_target = 0.8, hip = 0.05, hip_rate = -0.4;
  const Genome& g = genome_;
  const double y_stand = g.leg_length() - g[kHalfBodyY] - g[kHalfFootY] - g[kStandOffset];
  const double y_step = g.leg_length() - g[kHalfBodyY] - g[kHalfFootY] - g[kStepOffset];
  EXPECT_DOUBLE_EQ(TargetHeight(g, SupportPhase::kDouble), y_stand);
  EXPECT_DOUBLE_EQ(TargetHeight(g, SupportPhase::kSingle), y_step);

  const Vec3 ds = VirtualForce(g, SupportPhase::kDouble, x_target, trunk, hip, hip_rate);
  EXPECT_DOUBLE_EQ(ds(0), -g[kKx] * (0.3 - 0.8) - g[kLambdaX] * 0.2);
  EXPECT_DOUBLE_EQ(ds(1), -g[kKy] * (1.1 - y_stand) - g[kLambdaY] * -0.1);
  EXPECT_DOUBLE_EQ(ds(2), -g[kKTheta] * 0.05 - g[kLambdaTheta] * -0.4);

  // single support: x and theta doubled, the vertical spring doubled but not its damper
  const Vec3 ss = VirtualForce(g, SupportPhase::kSingle, x_target, trunk, hip, hip_rate);
  EXPECT_DOUBLE_EQ(ss(0), 2 * ds(0));
  EXPECT_DOUBLE_EQ(ss(1), -2 * g[kKy] * (1.1 - y_step) - g[kLambdaY] * -0.1);
  EXPECT_DOUBLE_EQ(ss(2), 2 * ds(2));
}

TEST_F(VmcTest, SwingHipSpringDrivesTheFemurThirtySixDegreesForward) {
  EXPECT_DOUBLE_EQ(SwingHipTorque(genome_, -M_PI / 5), 0.0);
  // femur behind its target (hip angle above -pi/5): torque pushes the hip angle down
  EXPECT_LT(SwingHipTorque(genome_, 0.0), 0.0);
  EXPECT_DOUBLE_EQ(SwingHipTorque(genome_, 0.0), -genome_[kKStep] * M_PI / 5);
  EXPECT_GT(SwingHipTorque(genome_, -1.0), 0.0);
}

}  // namespace
}  // namespace walkers
