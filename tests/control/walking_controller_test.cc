#include "control/walking_controller.h"

#include <cmath>

#include <gtest/gtest.h>

#include "dynamics/kinematics.h"
#include "files/errors.h"

namespace walkers {
namespace {

class WalkingControllerTest : public ::testing::Test {
 protected:
  Genome genome_ = DefaultGenome();
  Model model_ = BuildModel(BodyOf(genome_));

  // A walker at rest with a level trunk whose hips are at trunk_y - halfBodyY
  // above x = 0, each foot flat with its centre at the given point (two-link
  // inverse kinematics, knees forward).
  State WithAnkles(const Vec2& left, const Vec2& right, double trunk_y = 0.95) const {
    State s;
    s.q(kY) = trunk_y;
    const Vec2 hip(0.0, trunk_y - model_.body.half_body_y);
    const double lf = model_.body.femur_length, lt = model_.body.tibia_length;
    const std::array<Vec2, kNumLegs> ankles = {left, right};
    for (int leg = 0; leg < kNumLegs; ++leg) {
      const Vec2 d = ankles[leg] - hip;
      const double reach = d.norm();
      const double toward = std::atan2(d.x(), -d.y());
      const double femur = toward + std::acos((lf * lf + reach * reach - lt * lt) / (2.0 * lf * reach));
      const Vec2 knee = hip + lf * SegmentDirection(femur);
      const Vec2 shin = ankles[leg] - knee;
      const double tibia = std::atan2(shin.x(), -shin.y());
      s.q(JointIndex(leg, kHip)) = -femur;
      s.q(JointIndex(leg, kKnee)) = femur - tibia;
      s.q(JointIndex(leg, kAnkle)) = tibia;
    }
    Kinematics kin;
    ComputeKinematics(model_, s.q, s.v, &kin);
    for (int leg = 0; leg < kNumLegs; ++leg) {
      EXPECT_NEAR((kin.legs[leg].ankle.p - ankles[leg]).norm(), 0.0, 1e-9);
      EXPECT_NEAR(kin.legs[leg].foot.angle, 0.0, 1e-12);
    }
    return s;
  }

  double FootY() const { return model_.body.half_foot_y; }
};

TEST_F(WalkingControllerTest, HoldsDoubleSupportDuringTheLock) {
  WalkingController c(genome_, model_, OriginalPreset());
  const State s = WithAnkles(Vec2(-0.1, FootY()), Vec2(0.1, FootY()));
  c.Start(s);
  for (double t : {0.0, 1.0, 1.99}) {
    c.Tick(t, s);
    EXPECT_EQ(c.state(), WalkingState::kDoubleSupport) << t;
    EXPECT_DOUBLE_EQ(c.x_target(), 0.0);
  }
  EXPECT_TRUE(c.inputs().welds[kLeft].active && c.inputs().welds[kRight].active);
}

TEST_F(WalkingControllerTest, AfterTheLockTheRearFootSwingsAndTheBunnyTargetRunsAhead) {
  for (int rear : {kLeft, kRight}) {
    WalkingController c(genome_, model_, OriginalPreset());
    const Vec2 back(-0.1, FootY()), front(0.15, FootY());
    const State s = rear == kLeft ? WithAnkles(back, front) : WithAnkles(front, back);
    c.Start(s);
    c.Tick(2.0, s);
    EXPECT_EQ(c.state(), rear == kLeft ? WalkingState::kRightSupport : WalkingState::kLeftSupport);
    EXPECT_FALSE(c.inputs().welds[rear].active);
    EXPECT_TRUE(c.inputs().welds[1 - rear].active);
    EXPECT_NEAR(c.x_target(), 0.5 * (-0.1 + 0.15) + kTargetLead, 1e-12);
  }
}

TEST_F(WalkingControllerTest, OnATieTheLeftFootSwings) {
  WalkingController c(genome_, model_, OriginalPreset());
  const State s = WithAnkles(Vec2(0.0, FootY()), Vec2(0.0, FootY()));
  c.Start(s);
  c.Tick(2.5, s);
  EXPECT_EQ(c.state(), WalkingState::kRightSupport);
}

TEST_F(WalkingControllerTest, LeavesDoubleSupportOnlyWhenStable) {
  WalkingController c(genome_, model_, OriginalPreset());
  State s = WithAnkles(Vec2(-0.1, FootY()), Vec2(0.1, FootY()));
  s.v(kKneeR) = 1.0;  // a knee still moving
  c.Start(s);
  c.Tick(2.5, s);
  EXPECT_EQ(c.state(), WalkingState::kDoubleSupport);
}

// the two presets' "stable" rules, on the same states
TEST_F(WalkingControllerTest, PaperStableRuleBoundsEveryJointRatesMagnitude) {
  const double tol = genome_[kStableTolerance];
  State s = WithAnkles(Vec2(-0.1, FootY()), Vec2(0.1, FootY()));
  EXPECT_TRUE(IsStable(genome_, PaperPreset(), s));
  s.v(kAnkleL) = -2.0 * tol;  // fast, but negative
  EXPECT_FALSE(IsStable(genome_, PaperPreset(), s));
  EXPECT_TRUE(IsStable(genome_, OriginalPreset(), s));  // signed: passes
  s.v(kAnkleL) = 0.0;
  s.v(kX) = 2.0 * tol;  // the trunk moving forward
  EXPECT_TRUE(IsStable(genome_, PaperPreset(), s));     // the paper looks at joints only
  EXPECT_FALSE(IsStable(genome_, OriginalPreset(), s));
  s.v(kY) = -2.0 * tol;  // ... but x' + y' is what the authors compared
  EXPECT_TRUE(IsStable(genome_, OriginalPreset(), s));
}

TEST_F(WalkingControllerTest, TouchdownOnlyPastTheStepDistanceAndOnlyWhenDown) {
  WalkingController c(genome_, model_, OriginalPreset());
  c.Start(WithAnkles(Vec2(-0.1, FootY()), Vec2(0.0, FootY())));
  c.Tick(2.0, WithAnkles(Vec2(-0.1, FootY()), Vec2(0.0, FootY())));  // left swings
  ASSERT_EQ(c.state(), WalkingState::kRightSupport);

  // first step: more than 0.01 m ahead of the stance ankle, and down
  c.Tick(2.1, WithAnkles(Vec2(0.005, FootY()), Vec2(0.0, FootY())));
  EXPECT_EQ(c.state(), WalkingState::kRightSupport) << "0.005 m ahead is not far enough";
  c.Tick(2.2, WithAnkles(Vec2(0.02, FootY() + 0.01), Vec2(0.0, FootY())));
  EXPECT_EQ(c.state(), WalkingState::kRightSupport) << "1 cm up is not down";
  const State landing = WithAnkles(Vec2(0.02, FootY() + 0.0005), Vec2(0.0, FootY()));
  c.Tick(2.3, landing);
  EXPECT_EQ(c.state(), WalkingState::kDoubleSupport);
  EXPECT_EQ(c.footsteps(), 1);
  // planted where it is, flat, its centre the weld's depth below halfFootY
  EXPECT_TRUE(c.inputs().welds[kLeft].active);
  EXPECT_NEAR(c.inputs().welds[kLeft].anchor.x(), 0.02, 1e-9);
  EXPECT_DOUBLE_EQ(c.inputs().welds[kLeft].anchor.y(), FootY() - model_.weld.depth);
  EXPECT_DOUBLE_EQ(c.inputs().welds[kLeft].angle, 0.0);

  // later steps need 0.04 m: the right (now rear) foot swings next
  c.Tick(2.4, WithAnkles(Vec2(0.02, FootY()), Vec2(0.0, FootY())));
  ASSERT_EQ(c.state(), WalkingState::kLeftSupport);
  c.Tick(2.5, WithAnkles(Vec2(0.02, FootY()), Vec2(0.05, FootY())));
  EXPECT_EQ(c.state(), WalkingState::kLeftSupport) << "0.03 m ahead is not a later step";
  c.Tick(2.6, WithAnkles(Vec2(0.02, FootY()), Vec2(0.07, FootY())));
  EXPECT_EQ(c.state(), WalkingState::kDoubleSupport);
  EXPECT_EQ(c.footsteps(), 2);
}

TEST_F(WalkingControllerTest, OnlyTheSwingHipAndStanceLegsOnTheFloorGetTorques) {
  WalkingController c(genome_, model_, OriginalPreset());
  const State start = WithAnkles(Vec2(-0.1, FootY()), Vec2(0.0, FootY()));
  c.Start(start);
  c.Tick(1.0, start);  // double support: both legs driven
  for (int i = kHipL; i < kNumCoords; ++i) EXPECT_NE(c.inputs().joint_torque(i), 0.0) << i;
  EXPECT_EQ(c.inputs().joint_torque.head<3>(), Vec3::Zero());

  c.Tick(2.0, start);  // left swings: only its hip is driven, by eq. (5)
  ASSERT_EQ(c.state(), WalkingState::kRightSupport);
  EXPECT_DOUBLE_EQ(c.inputs().joint_torque(kHipL), SwingHipTorque(genome_, start.q(kHipL)));
  EXPECT_EQ(c.inputs().joint_torque(kKneeL), 0.0);
  EXPECT_EQ(c.inputs().joint_torque(kAnkleL), 0.0);
  EXPECT_NE(c.inputs().joint_torque(kKneeR), 0.0);

  // a stance foot off the floor gets nothing
  const State lifted = WithAnkles(Vec2(0.1, FootY() + 0.1), Vec2(0.0, FootY() + 0.05));
  c.Tick(2.1, lifted);
  EXPECT_EQ(c.inputs().joint_torque(kKneeR), 0.0);
  EXPECT_EQ(c.inputs().joint_torque(kAnkleR), 0.0);
  EXPECT_EQ(c.inputs().joint_torque(kHipR), 0.0);
}

TEST_F(WalkingControllerTest, FallRuleOfEachPreset) {
  const double standing = genome_.leg_length() + genome_[kHalfFootY] + genome_[kHalfBodyY];
  State s;
  for (const Preset& preset : {PaperPreset(), OriginalPreset()}) {
    const double fraction = preset.name == "paper" ? 0.5 : 1.0 / 3.0;
    s.q(kY) = fraction * standing + 1e-6;
    EXPECT_FALSE(HasFallen(genome_, preset, s)) << preset.name;
    s.q(kY) = fraction * standing - 1e-6;
    EXPECT_TRUE(HasFallen(genome_, preset, s)) << preset.name;
  }
  // between the two heights: fallen for the paper, not for the authors
  s.q(kY) = 0.4 * standing;
  EXPECT_TRUE(HasFallen(genome_, PaperPreset(), s));
  EXPECT_FALSE(HasFallen(genome_, OriginalPreset(), s));
}

TEST(PresetTest, ByNameAndUnknownNamesAreRejected) {
  EXPECT_EQ(PresetByName("paper").stable_rule, StableRule::kJointRateMagnitudes);
  EXPECT_EQ(PresetByName("original").performance_ceiling, PerformanceCeiling::kAuthorsFormula);
  try {
    PresetByName("authors");
    FAIL() << "accepted an unknown preset";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("paper, original"), std::string::npos);
  }
}

}  // namespace
}  // namespace walkers
