#include "dynamics/jacobian.h"

#include <random>

#include <gtest/gtest.h>

#include "control/genome.h"
#include "tests/dynamics/default_walker_test.h"
#include "tests/finite_difference.h"

namespace walkers {
namespace {

using testing::MatricesNear;
using testing::NumericalJacobian;

class JacobianTest : public testing::DefaultWalkerTest {
 protected:
  JacobianTest() : DefaultWalkerTest(31) {}

  // lowers (or raises) the walker so that its lowest contact point is `depth`
  // into the ground, and gives it a small random velocity
  State Pressed(State s, double depth) {
    Kinematics kin;
    ComputeKinematics(model_, s.q, s.v, &kin);
    double deepest = -1e9;
    for (const ContactSample& c : SampleContacts(model_, kin)) deepest = std::max(deepest, c.depth);
    s.q(kY) += deepest - depth;
    s.v = testing::RandomVector<kNumCoords>(rng_, -0.05, 0.05);
    return s;
  }
  int Touching(const State& s) const {
    Kinematics kin;
    ComputeKinematics(model_, s.q, s.v, &kin);
    int n = 0;
    for (const ContactSample& c : SampleContacts(model_, kin)) n += c.depth > 0 ? 1 : 0;
    return n;
  }

  Vec9 Accelerations(const Inputs& inputs, const Vec9& q, const Vec9& v) const {
    Workspace ws;
    Vec9 a;
    EXPECT_TRUE(ForwardDynamics(model_, inputs, q, v, &ws, &a));
    return a;
  }

  // compares the analytic Jacobian with central differences, column by column
  // relative to each column's size
  void ExpectMatchesFiniteDifferences(const Model& model, const Inputs& inputs, const State& s) {
    Workspace ws;
    Mat9 da_dq, da_dv;
    ASSERT_TRUE(AccelerationJacobian(model, inputs, s.q, s.v, &ws, &da_dq, &da_dv));
    auto of_q = [&](const Vec9& q) {
      Workspace w;
      Vec9 a;
      ForwardDynamics(model, inputs, q, s.v, &w, &a);
      return a;
    };
    auto of_v = [&](const Vec9& v) {
      Workspace w;
      Vec9 a;
      ForwardDynamics(model, inputs, s.q, v, &w, &a);
      return a;
    };
    const Mat9 fd_q = NumericalJacobian<kNumCoords, kNumCoords>(of_q, s.q);
    const Mat9 fd_v = NumericalJacobian<kNumCoords, kNumCoords>(of_v, s.v);
    for (int j = 0; j < kNumCoords; ++j) {
      const double scale_q = 1.0 + fd_q.col(j).cwiseAbs().maxCoeff();
      const double scale_v = 1.0 + fd_v.col(j).cwiseAbs().maxCoeff();
      EXPECT_TRUE(MatricesNear(fd_q.col(j), da_dq.col(j), 1e-5 * scale_q)) << "d/dq column " << j;
      EXPECT_TRUE(MatricesNear(fd_v.col(j), da_dv.col(j), 1e-5 * scale_v)) << "d/dv column " << j;
    }
    EXPECT_GT(da_dq.norm(), 1.0);
    EXPECT_GT(da_dv.norm(), 1.0);
  }
};

TEST_F(JacobianTest, GroundForceDerivativesMatchFiniteDifferences) {
  const ContactParameters c;
  // depth in millimetres, so that the differences resolve the d^1.5 law
  for (const Vec3& x : {Vec3(1.0, 0.02, 0.005), Vec3(0.4, -0.3, -0.2), Vec3(2.0, 0.5, 1.5)}) {
    auto force = [&](const Vec3& y) { return GroundForce(c, 1e-3 * y(0), y(1), y(2)); };
    Eigen::Matrix<double, 2, 3> fd = NumericalJacobian<2, 3>(force, x);
    fd.col(0) *= 1e3;
    const Eigen::Matrix<double, 2, 3> D = GroundForceDerivatives(c, 1e-3 * x(0), x(1), x(2));
    EXPECT_TRUE(MatricesNear(fd, D, 1e-6 * (1.0 + fd.cwiseAbs().maxCoeff())));
    EXPECT_GT(D(1, 0), 0.0);                 // contact stiffness
    EXPECT_LT(D(0, 2), 0.0);                 // friction resists more slip
    EXPECT_NE(D(1, 1), 0.0);                 // damping
  }
}

TEST_F(JacobianTest, PointVelocityJacobianMatchesFiniteDifferences) {
  const Vec9 q = testing::RandomVector<kNumCoords>(rng_, -1.0, 1.0);
  const Vec9 v = testing::RandomVector<kNumCoords>(rng_, -2.0, 2.0);
  Kinematics kin;
  ComputeKinematics(model_, q, v, &kin);
  auto ankle_velocity = [&](const Vec9& x) {
    Kinematics k;
    ComputeKinematics(model_, x, v, &k);
    return Vec2(k.legs[kRight].ankle.v);
  };
  const Jac2x9 analytic = PointVelocityJacobian(kin.legs[kRight].ankle);
  EXPECT_TRUE(MatricesNear(NumericalJacobian<2, kNumCoords>(ankle_velocity, q), analytic, 1e-7));
  EXPECT_GT(analytic.norm(), 0.1);
}

TEST_F(JacobianTest, FreeFlightMatchesFiniteDifferences) {
  State s;
  s.q = testing::RandomVector<kNumCoords>(rng_, -1.0, 1.0);
  s.q(kY) = 3.0;
  s.v = testing::RandomVector<kNumCoords>(rng_, -2.0, 2.0);
  ExpectMatchesFiniteDifferences(model_, Inputs{}, s);
}

TEST_F(JacobianTest, FeetOnTheGroundWithAWeldAndStopsMatchFiniteDifferences) {
  // both feet flat but for a slight tilt (heels deeper), knees past their stops
  State s = StandingState(model_, 2.4);
  s.q(kAnkleL) -= 0.004;
  s.q(kAnkleR) -= 0.002;
  s = Pressed(s, 0.002);
  ASSERT_GE(Touching(s), 4);
  Kinematics kin;
  ComputeKinematics(model_, s.q, s.v, &kin);
  Inputs inputs;
  inputs.welds[kRight] = {true, kin.legs[kRight].ankle.p + Vec2(0.003, -0.002), 0.01};
  inputs.joint_torque.tail<6>() = testing::RandomVector<6>(rng_, -100.0, 100.0);
  ExpectMatchesFiniteDifferences(model_, inputs, s);
}

TEST_F(JacobianTest, TrunkCornerOnTheGroundMatchesFiniteDifferences) {
  // trunk pitched nose-up, legs folded up: its rear bottom corner is lowest
  State s;
  s.q(kPitch) = 1.0;
  s.q(kKneeL) = s.q(kKneeR) = 2.8;
  s = Pressed(s, 0.002);
  Kinematics kin;
  ComputeKinematics(model_, s.q, s.v, &kin);
  ASSERT_GT(SampleContacts(model_, kin)[kTrunkCorner0].depth, 0.0);
  ExpectMatchesFiniteDifferences(model_, Inputs{}, s);
}

TEST_F(JacobianTest, KneeCirclesOnTheGroundMatchFiniteDifferences) {
  // femurs hanging straight down, tibias folded back up: the knees are lowest
  State s;
  s.q(kKneeL) = 2.9;
  s.q(kKneeR) = 2.8;
  s = Pressed(s, 0.002);
  Kinematics kin;
  ComputeKinematics(model_, s.q, s.v, &kin);
  ASSERT_GT(SampleContacts(model_, kin)[kKneeCircleL].depth, 0.0);
  ExpectMatchesFiniteDifferences(model_, Inputs{}, s);
}

TEST_F(JacobianTest, LockedCoordinatesHaveZeroRows) {
  Model m = model_;
  m.options.locked[kX] = m.options.locked[kY] = m.options.locked[kPitch] = true;
  State s;
  s.q = testing::RandomVector<kNumCoords>(rng_, -1.0, 1.0);
  s.q(kY) = 3.0;
  s.v.tail<6>() = testing::RandomVector<6>(rng_, -2.0, 2.0);
  Workspace ws;
  Mat9 da_dq, da_dv;
  ASSERT_TRUE(AccelerationJacobian(m, Inputs{}, s.q, s.v, &ws, &da_dq, &da_dv));
  EXPECT_TRUE(da_dq.topRows<3>().isZero());
  EXPECT_TRUE(da_dv.topRows<3>().isZero());
  ExpectMatchesFiniteDifferences(m, Inputs{}, s);
}

}  // namespace
}  // namespace walkers
