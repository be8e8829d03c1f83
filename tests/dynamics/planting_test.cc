#include "dynamics/planting.h"

#include <random>

#include <Eigen/LU>
#include <gtest/gtest.h>

#include "control/genome.h"
#include "control/start_pose.h"
#include "dynamics/kinematics.h"
#include "dynamics/observation.h"
#include "tests/dynamics/default_walker_test.h"
#include "tests/finite_difference.h"

namespace walkers {
namespace {

class PlantingTest : public testing::DefaultWalkerTest {
 protected:
  PlantingTest() : DefaultWalkerTest(5) {}

  // a swinging walker: the right foot planted, the left foot a little off
  // the ground and tilted, everything moving
  State Swinging(Welds* welds) {
    State s = StartState(model_);
    *welds = StartWelds(model_);
    welds->at(kLeft).active = false;
    s.q(kAnkleL) += 0.15;
    s.q(kHipL) -= 0.1;
    s.v = testing::RandomVector<kNumCoords>(rng_, -1.0, 1.0);
    return s;
  }
  Kinematics At(const State& s) const {
    Kinematics kin;
    ComputeKinematics(model_, s.q, s.v, &kin);
    return kin;
  }
};

// The authors' program, built against Debian's Simbody 3.7, projects its
// default state for the default genome to these (walker.cpp's first state;
// scripts/compare_authors.py builds it). Simbody turns its free bodies by
// quaternion steps, we by angle steps of the same weight: the two paths end
// within 1e-4 of each other.
TEST_F(PlantingTest, TheStartPoseIsTheOneSimbodysProjectionMakes) {
  const State s = StartState(model_);
  EXPECT_NEAR(s.q(kX), -0.07473986129, 2e-4);
  EXPECT_NEAR(s.q(kY), 1.384443671, 2e-4);
  EXPECT_NEAR(s.q(kPitch), 0.1649502532, 2e-4);
  for (int leg = 0; leg < kNumLegs; ++leg) {
    EXPECT_NEAR(s.q(JointIndex(leg, kHip)), -0.02887932029, 2e-4);
    EXPECT_NEAR(s.q(JointIndex(leg, kKnee)), 0.2663278308, 2e-4);
    EXPECT_NEAR(s.q(JointIndex(leg, kAnkle)), -0.07249825728, 2e-4);
  }
  EXPECT_EQ(s.v, Vec9::Zero());
  // both feet flat on their welds, 2 mm into the ground
  const Kinematics kin = At(s);
  for (int leg = 0; leg < kNumLegs; ++leg) {
    EXPECT_NEAR(kin.legs[leg].ankle.p.x(), 0.0, 1e-12);
    EXPECT_NEAR(kin.legs[leg].ankle.p.y(), model_.body.half_foot_y - 0.002, 1e-12);
    EXPECT_NEAR(kin.legs[leg].foot.angle, 0.0, 1e-12);
  }
}

TEST_F(PlantingTest, PutsTheFootOnItsWeldAndStopsIt) {
  Welds welds;
  const State before = Swinging(&welds);
  welds[kLeft] = PlantFoot(model_, before, kLeft);
  State after = before;
  ASSERT_TRUE(ProjectOntoWelds(model_, welds, &after));
  const Kinematics kin = At(after);
  for (int leg = 0; leg < kNumLegs; ++leg) {
    EXPECT_NEAR((kin.legs[leg].ankle.p - welds[leg].anchor).norm(), 0.0, 1e-10) << leg;
    EXPECT_NEAR(kin.legs[leg].foot.angle, 0.0, 1e-10) << leg;
    EXPECT_NEAR(kin.legs[leg].ankle.v.norm(), 0.0, 1e-10) << leg;
    EXPECT_NEAR(kin.legs[leg].foot.rate, 0.0, 1e-10) << leg;
  }
  EXPECT_GT((after.q - before.q).norm(), 0.01);
  EXPECT_GT(At(before).legs[kLeft].ankle.v.norm(), 0.1);
}

// Simbody's velocity projection is the least-norm change of the rates in its
// free-body coordinates, each rate's change measured against max(1, |u_i|):
// scaled so, the change lies in the span of the constraint rows, orthogonal
// to every motion the welds allow.
TEST_F(PlantingTest, TheVelocityChangeIsTheLeastNormOneInTheFreeBodyCoordinates) {
  Welds welds;
  State s = Swinging(&welds);
  welds[kLeft] = PlantFoot(model_, s, kLeft);
  ASSERT_TRUE(ProjectOntoWelds(model_, welds, &s));  // positions on the welds
  // new rates, then project them alone (positions already on the welds)
  s.v = testing::RandomVector<kNumCoords>(rng_, -1.0, 1.0);
  const FreeBodyState before = ToFreeBodies(model_, s);
  FreeBodyState after = before;
  ASSERT_TRUE(ProjectFreeBodies(model_, welds, &after));
  EXPECT_TRUE(testing::MatricesNear(before.z, after.z, 1e-12));
  const FreeBodyVector change = after.u - before.u;
  // the motions the welds allow: rates of our tree with both feet held (the
  // null space of the weld rows) mapped into the free-body coordinates, by
  // finite differences of the map
  Eigen::Matrix<double, kNumFreeBodyCoords, kNumCoords> map;
  for (int i = 0; i < kNumCoords; ++i) {
    State unit = s;
    unit.v = Vec9::Unit(i);
    map.col(i) = ToFreeBodies(model_, unit).u;
  }
  // every free-body rate vector of the form map * v satisfies the hip welds;
  // those that also hold both feet still are the allowed motions: the
  // projected rates are one of them, and the change is orthogonal to all
  Eigen::Matrix<double, 6, kNumCoords> feet;
  feet << map.middleRows<3>(FootCoord(kLeft)), map.middleRows<3>(FootCoord(kRight));
  const Eigen::FullPivLU<Eigen::Matrix<double, 6, kNumCoords>> lu(feet);
  const Eigen::MatrixXd allowed = map * lu.kernel();
  ASSERT_EQ(allowed.cols(), 3);
  const FreeBodyVector scale = before.u.cwiseAbs().cwiseMax(1.0);
  const FreeBodyVector scaled_change = change.cwiseQuotient(scale.cwiseProduct(scale));
  EXPECT_LT((allowed.transpose() * scaled_change).norm(), 1e-10 * scaled_change.norm());
  EXPECT_GT(change.norm(), 0.1);
  EXPECT_LT(after.u.segment<3>(FootCoord(kLeft)).norm(), 1e-10);
}

TEST_F(PlantingTest, LeavesAStateAlreadyOnItsWeldsAlone) {
  State s = StartState(model_);
  const State before = s;
  ASSERT_TRUE(ProjectOntoWelds(model_, StartWelds(model_), &s));
  EXPECT_TRUE(testing::MatricesNear(before.q, s.q, 1e-14));
  EXPECT_TRUE(testing::MatricesNear(before.v, s.v, 1e-14));
}

TEST_F(PlantingTest, ReportsUnreachableWelds) {
  // both feet welded 5 m apart: the legs cannot reach
  State s = StartState(model_);
  Welds welds = StartWelds(model_);
  welds[kRight].anchor.x() = 5.0;
  const State before = s;
  EXPECT_FALSE(ProjectOntoWelds(model_, welds, &s));
  EXPECT_EQ(before.q, s.q);
}

}  // namespace
}  // namespace walkers
