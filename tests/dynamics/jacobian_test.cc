#include "dynamics/jacobian.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

#include <random>

#include <gtest/gtest.h>

#include "control/genome.h"
#include "dynamics/contact.h"
#include "tests/dynamics/contact_poses.h"
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
    s.q(kY) += LowestPointDepth(model_, kin) - depth;
    s.v = testing::RandomVector<kNumCoords>(rng_, -0.05, 0.05);
    return s;
  }
  ContactReports Reports(const State& s) const {
    Kinematics kin;
    ComputeKinematics(model_, s.q, s.v, &kin);
    return ReportContacts(model_, kin);
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
    // The differences' own rounding: a position is computed to about
    // eps (1 + |q|) absolute, which a stiff contact turns into an error of the
    // accelerations of that times their largest derivative; divided by the
    // step of column j. It matters only for columns that are nearly zero.
    const double eps = std::numeric_limits<double>::epsilon();
    const double rounding_q = eps * (1.0 + s.q.cwiseAbs().maxCoeff()) * fd_q.cwiseAbs().maxCoeff();
    const double rounding_v = eps * (1.0 + s.v.cwiseAbs().maxCoeff()) * fd_v.cwiseAbs().maxCoeff();
    for (int j = 0; j < kNumCoords; ++j) {
      const double step_q = std::cbrt(eps) * std::max(1.0, std::abs(s.q(j)));
      const double step_v = std::cbrt(eps) * std::max(1.0, std::abs(s.v(j)));
      const double tol_q = 1e-5 * (1.0 + fd_q.col(j).cwiseAbs().maxCoeff()) + rounding_q / step_q;
      const double tol_v = 1e-5 * (1.0 + fd_v.col(j).cwiseAbs().maxCoeff()) + rounding_v / step_v;
      EXPECT_TRUE(MatricesNear(fd_q.col(j), da_dq.col(j), tol_q)) << "d/dq column " << j;
      EXPECT_TRUE(MatricesNear(fd_v.col(j), da_dv.col(j), tol_v)) << "d/dv column " << j;
    }
    EXPECT_GT(da_dq.norm(), 1.0);
    EXPECT_GT(da_dv.norm(), 1.0);
  }
};

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
  ASSERT_GE(Reports(s)[kGroundFootL].elements + Reports(s)[kGroundFootR].elements, 4);
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
  ASSERT_TRUE(Reports(s)[kGroundTrunk].touching);
  ExpectMatchesFiniteDifferences(model_, Inputs{}, s);
}

TEST_F(JacobianTest, KneeCirclesOnTheGroundMatchFiniteDifferences) {
  // femurs hanging straight down, tibias folded back up: the knees are lowest
  State s;
  s.q(kKneeL) = 2.9;
  s.q(kKneeR) = 2.8;
  s = Pressed(s, 0.002);
  ASSERT_TRUE(Reports(s)[kGroundKneeL].touching);
  ExpectMatchesFiniteDifferences(model_, Inputs{}, s);
}

// The trunk level in the air, both feet folded up under it, their tops
// 1.5 mm into its bottom, 0.25 m and 0.4 m ahead of the hips.
TEST_F(JacobianTest, TrunkOnItsFeetMatchesFiniteDifferences) {
  State s = testing::TrunkAt(2.0, 0.0);
  const double drop = model_.body.half_foot_y - 1.5e-3;
  testing::PlaceAnkle(model_, kLeft, Vec2(0.25, -drop), &s);
  testing::PlaceAnkle(model_, kRight, Vec2(0.4, -drop), &s);
  s.v = testing::RandomVector<kNumCoords>(rng_, -0.05, 0.05);
  const ContactReports r = Reports(s);
  ASSERT_TRUE(r[kTrunkFootL].touching);
  ASSERT_TRUE(r[kTrunkFootR].touching);
  ExpectMatchesFiniteDifferences(model_, Inputs{}, s);
}

TEST_F(JacobianTest, KneeInTheTrunkMatchesFiniteDifferences) {
  testing::Posed p = testing::KneeInTheTrunk(model_.body, kLeft, 4e-3);
  p.state.v = testing::RandomVector<kNumCoords>(rng_, -0.05, 0.05);
  Kinematics kin;
  ComputeKinematics(p.model, p.state.q, p.state.v, &kin);
  ASSERT_TRUE(ReportContacts(p.model, kin)[kTrunkKneeL].touching);
  ExpectMatchesFiniteDifferences(p.model, Inputs{}, p.state);
}

TEST_F(JacobianTest, KneeOnItsFootMatchesFiniteDifferences) {
  testing::Posed p = testing::KneeOnItsFoot(model_.body, kRight, 4e-3);
  p.state.v = testing::RandomVector<kNumCoords>(rng_, -0.05, 0.05);
  Kinematics kin;
  ComputeKinematics(p.model, p.state.q, p.state.v, &kin);
  ASSERT_TRUE(ReportContacts(p.model, kin)[kFootKneeR].touching);
  ExpectMatchesFiniteDifferences(p.model, Inputs{}, p.state);
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
