#include "dynamics/planting.h"

#include <random>

#include <Eigen/LU>
#include <gtest/gtest.h>

#include "control/genome.h"
#include "dynamics/energy.h"
#include "dynamics/equations_of_motion.h"
#include "dynamics/kinematics.h"
#include "tests/dynamics/default_walker_test.h"
#include "tests/finite_difference.h"

namespace walkers {
namespace {

class PlantingTest : public testing::DefaultWalkerTest {
 protected:
  PlantingTest() : DefaultWalkerTest(5) {}

  // a swinging walker: standing pose, the left foot a little off its pose, moving
  State Swinging() {
    State s = StandingState(model_, 0.6);
    s.q(kAnkleL) += 0.15;   // foot tilted
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

TEST_F(PlantingTest, PutsTheFootOnItsWeldAtRest) {
  const State before = Swinging();
  const Weld weld{true, Vec2(At(before).legs[kLeft].ankle.p.x(), model_.body.half_foot_y), 0.0};
  State after = before;
  ASSERT_TRUE(ProjectOntoWeld(model_, weld, kLeft, &after));
  const Kinematics kin = At(after);
  EXPECT_NEAR((kin.legs[kLeft].ankle.p - weld.anchor).norm(), 0.0, 1e-10);
  EXPECT_NEAR(kin.legs[kLeft].foot.angle, 0.0, 1e-10);
  EXPECT_NEAR(kin.legs[kLeft].ankle.v.norm(), 0.0, 1e-10);
  EXPECT_NEAR(kin.legs[kLeft].foot.rate, 0.0, 1e-10);
  // the foot had to move: the test is not vacuous
  EXPECT_GT((after.q - before.q).norm(), 0.01);
  EXPECT_GT(At(before).legs[kLeft].ankle.v.norm(), 0.1);
}

TEST_F(PlantingTest, LandingIsAPlasticImpact) {
  const State before = Swinging();
  const Weld weld{true, Vec2(At(before).legs[kLeft].ankle.p.x(), model_.body.half_foot_y), 0.0};
  State after = before;
  ASSERT_TRUE(ProjectOntoWeld(model_, weld, kLeft, &after));

  // momentum M (v+ - v-) is conserved along every motion the weld leaves free
  const Kinematics kin = At(after);
  Eigen::Matrix<double, 3, kNumCoords> C;
  C.topRows<2>() = kin.legs[kLeft].ankle.J;
  C.row(2) = kin.legs[kLeft].foot.j;
  const Eigen::MatrixXd free_motions = Eigen::FullPivLU<Eigen::Matrix<double, 3, kNumCoords>>(C).kernel();
  const Mat9 M = MassMatrix(model_, after.q);
  State at_new_pose = after;
  at_new_pose.v = before.v;
  const Eigen::VectorXd impulse = free_motions.transpose() * M * (after.v - before.v);
  EXPECT_LT(impulse.norm(), 1e-8 * (M * before.v).norm());
  // and it can only lose kinetic energy
  EXPECT_LT(KineticEnergy(model_, At(after)), KineticEnergy(model_, At(at_new_pose)));
}

TEST_F(PlantingTest, LeavesAStateAlreadyOnItsWeldAlone) {
  State s = StandingState(model_, 0.6);
  const Weld weld{true, At(s).legs[kRight].ankle.p, 0.0};
  const State before = s;
  ASSERT_TRUE(ProjectOntoWeld(model_, weld, kRight, &s));
  EXPECT_TRUE(testing::MatricesNear(before.q, s.q, 1e-14));
  EXPECT_TRUE(testing::MatricesNear(before.v, s.v, 1e-14));
}

TEST_F(PlantingTest, ReportsAnUnreachableWeld) {
  State s = StandingState(model_, 0.6);
  s.q(kX) = 0.0;
  Model pinned = model_;
  for (int i = 0; i < kNumCoords; ++i) pinned.options.locked[i] = true;  // nothing may move
  const Weld weld{true, Vec2(1.0, 0.05), 0.0};
  const State before = s;
  EXPECT_FALSE(ProjectOntoWeld(pinned, weld, kLeft, &s));
  EXPECT_EQ(before.q, s.q);
}

}  // namespace
}  // namespace walkers
