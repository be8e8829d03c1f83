#include "dynamics/contact.h"

#include <gtest/gtest.h>

namespace walkers {
namespace {

const ContactParameters kContact;

TEST(GroundForceTest, IsZeroOffTheGroundAndGrowsSmoothlyFromFirstTouch) {
  EXPECT_EQ(GroundForce(kContact, -1e-3, 1.0, 0.5), Vec2::Zero());
  EXPECT_EQ(GroundForce(kContact, 0.0, 1.0, 0.5), Vec2::Zero());
  // d^1.5: force and stiffness vanish at first touch
  const double f1 = GroundForce(kContact, 1e-6, 0.0, 0.0).y();
  const double f2 = GroundForce(kContact, 2e-6, 0.0, 0.0).y();
  EXPECT_GT(f1, 0.0);
  EXPECT_NEAR(f2 / f1, std::pow(2.0, 1.5), 1e-9);
  EXPECT_LT(f1, 1.0);
}

TEST(GroundForceTest, DampsApproachAndNeverPulls) {
  const double depth = 1e-3;
  const double at_rest = GroundForce(kContact, depth, 0.0, 0.0).y();
  EXPECT_GT(GroundForce(kContact, depth, 0.5, 0.0).y(), at_rest);   // pressing in
  EXPECT_LT(GroundForce(kContact, depth, -0.5, 0.0).y(), at_rest);  // leaving
  EXPECT_EQ(GroundForce(kContact, depth, -5.0, 0.0).y(), 0.0);      // leaving fast: no suction
}

TEST(GroundForceTest, FrictionOpposesSlipAndIsBoundedByCoulombPlusViscous) {
  const double depth = 1e-3;
  for (double slip : {-2.0, -0.1, -0.003, 0.003, 0.1, 2.0}) {
    const Vec2 f = GroundForce(kContact, depth, 0.0, slip);
    EXPECT_LT(f.x() * slip, 0.0) << slip;
    EXPECT_LE(std::abs(f.x()), (kContact.friction + kContact.viscous_friction * std::abs(slip)) * f.y() + 1e-9);
  }
  EXPECT_EQ(GroundForce(kContact, depth, 0.0, 0.0).x(), 0.0);
  // sliding well above the regularisation speed: full Coulomb friction
  const Vec2 sliding = GroundForce(kContact, depth, 0.0, 5 * kContact.slip_velocity);
  EXPECT_GT(-sliding.x(), 0.999 * kContact.friction * sliding.y());
}

TEST(GroundForceTest, PenetrationUnderTheWholeWalkerOnOneCornerIsUnderTwoMillimetres) {
  // the default walker weighs about 3800 N
  const double weight = 3805.0;
  const double depth = std::pow(weight / kContact.stiffness, 2.0 / 3.0);
  EXPECT_NEAR(GroundForce(kContact, depth, 0.0, 0.0).y(), weight, 1e-6 * weight);
  EXPECT_LT(depth, 0.002);
}

TEST(JointStopTest, PushesBackOnlyPastTheLimit) {
  const JointStop stop{M_PI / 4, 2.0, 5.0};
  EXPECT_EQ(JointStopTorque(stop, 0.5, 3.0), 0.0);
  EXPECT_EQ(JointStopTorque(stop, -0.5, -3.0), 0.0);
  EXPECT_NEAR(JointStopTorque(stop, M_PI / 4 + 0.1, 0.0), -0.2, 1e-12);
  EXPECT_NEAR(JointStopTorque(stop, -M_PI / 4 - 0.1, 0.0), 0.2, 1e-12);
  EXPECT_LT(JointStopTorque(stop, M_PI / 4 + 0.1, 1.0), -0.2);  // damped going further
  EXPECT_EQ(JointStopTorque(stop, M_PI / 4 + 0.1, -1.0), 0.0);  // no pull when coming back fast
}

}  // namespace
}  // namespace walkers
