#include "dynamics/kinematics.h"

#include <algorithm>
#include <functional>
#include <random>

#include <gtest/gtest.h>

#include "control/genome.h"
#include "dynamics/contact.h"
#include "tests/dynamics/default_walker_test.h"
#include "tests/finite_difference.h"

namespace walkers {
namespace {

using testing::kFiniteDifferenceTolerance;
using testing::MatricesNear;
using testing::NumericalJacobian;

// every point the dynamics uses, by name, as a function of the kinematics
using PointOf = std::function<const PointKinematics&(const Kinematics&)>;

std::vector<std::pair<std::string, PointOf>> AllPoints() {
  std::vector<std::pair<std::string, PointOf>> points = {
      {"trunk", [](const Kinematics& k) -> const PointKinematics& { return k.trunk; }},
      {"hip", [](const Kinematics& k) -> const PointKinematics& { return k.hip; }},
  };
  for (int leg = 0; leg < kNumLegs; ++leg) {
    const std::string side = leg == kLeft ? "_l" : "_r";
    points.push_back({"knee" + side, [leg](const Kinematics& k) -> const PointKinematics& { return k.legs[leg].knee; }});
    points.push_back(
        {"ankle" + side, [leg](const Kinematics& k) -> const PointKinematics& { return k.legs[leg].ankle; }});
  }
  return points;
}

class KinematicsTest : public testing::DefaultWalkerTest {
 protected:
  KinematicsTest() : DefaultWalkerTest(12345) {}

  Kinematics At(const Vec9& q, const Vec9& v = Vec9::Zero()) const {
    Kinematics kin;
    ComputeKinematics(model_, q, v, &kin);
    return kin;
  }
};

TEST_F(KinematicsTest, PointJacobiansMatchFiniteDifferences) {
  for (int trial = 0; trial < 20; ++trial) {
    const Vec9 q = RandomQ();
    const Kinematics kin = At(q);
    for (const auto& [name, point] : AllPoints()) {
      auto position = [&](const Vec9& x) -> Vec2 { return point(At(x)).p; };
      const Jac2x9 numeric = NumericalJacobian<2, kNumCoords>(position, q);
      EXPECT_TRUE(MatricesNear(numeric, point(kin).J, kFiniteDifferenceTolerance)) << name << " trial " << trial;
      EXPECT_GT(point(kin).J.norm(), 0.5) << name;
    }
  }
}

TEST_F(KinematicsTest, AngleJacobiansMatchFiniteDifferences) {
  const Vec9 q = RandomQ();
  const Kinematics kin = At(q);
  for (int leg = 0; leg < kNumLegs; ++leg) {
    const std::array<const AngleKinematics*, 3> angles = {&kin.legs[leg].femur, &kin.legs[leg].tibia,
                                                          &kin.legs[leg].foot};
    for (int i = 0; i < 3; ++i) {
      auto angle = [&](const Vec9& x) {
        const Kinematics k = At(x);
        const std::array<double, 3> a = {k.legs[leg].femur.angle, k.legs[leg].tibia.angle, k.legs[leg].foot.angle};
        return Eigen::Matrix<double, 1, 1>(a[i]);
      };
      EXPECT_TRUE(MatricesNear(NumericalJacobian<1, kNumCoords>(angle, q), angles[i]->j, kFiniteDifferenceTolerance));
    }
  }
  // chain convention: foot angle + ankle + knee + hip = pitch
  for (int leg = 0; leg < kNumLegs; ++leg) {
    const double sum = kin.legs[leg].foot.angle + q(JointIndex(leg, kAnkle)) + q(JointIndex(leg, kKnee)) +
                       q(JointIndex(leg, kHip));
    EXPECT_NEAR(sum, q(kPitch), 1e-12);
  }
}

TEST_F(KinematicsTest, VelocityAndBiasAccelerationMatchTimeDerivatives) {
  // along q(t) = q + v t: dp/dt = J v, and d(J v)/dt = a_bias
  for (int trial = 0; trial < 10; ++trial) {
    const Vec9 q = RandomQ();
    const Vec9 v = testing::RandomVector<kNumCoords>(rng_, -2.0, 2.0);
    const Kinematics kin = At(q, v);
    for (const auto& [name, point] : AllPoints()) {
      auto along = [&](const Eigen::Matrix<double, 1, 1>& t) -> Vec2 { return point(At(q + v * t(0))).p; };
      auto velocity_along = [&](const Eigen::Matrix<double, 1, 1>& t) -> Vec2 {
        return point(At(q + v * t(0), v)).v;
      };
      const Eigen::Matrix<double, 1, 1> t0 = Eigen::Matrix<double, 1, 1>::Zero();
      EXPECT_TRUE(MatricesNear(NumericalJacobian<2, 1>(along, t0), point(kin).v, 1e-6)) << name;
      EXPECT_TRUE(MatricesNear(NumericalJacobian<2, 1>(velocity_along, t0), point(kin).a_bias, 1e-5)) << name;
      if (name != "trunk") {
        EXPECT_GT(point(kin).a_bias.norm(), 1e-3) << name;
      }
    }
  }
}

// The Jacobian-transpose products and the kinematics' own Jacobian updates
// visit only ColumnsOf(leg): every point and angle must be
// exactly zero outside it, and the products must equal the dense ones.
TEST_F(KinematicsTest, JacobiansVanishOutsideTheirColumnsAndSparseProductsMatchDenseOnes) {
  auto outside = [](int leg) {
    std::vector<int> cols;
    const TreeColumns inside = ColumnsOf(leg);
    for (int c = 0; c < kNumCoords; ++c) {
      if (std::find(inside.begin(), inside.end(), c) == inside.end()) cols.push_back(c);
    }
    return cols;
  };
  for (int trial = 0; trial < 10; ++trial) {
    const Vec9 q = RandomQ();
    const Kinematics kin = At(q, testing::RandomVector<kNumCoords>(rng_, -2.0, 2.0));
    const Vec2 f = testing::RandomVector<2>(rng_, -100.0, 100.0);
    const double torque = std::uniform_real_distribution<double>(-50.0, 50.0)(rng_);

    std::vector<std::pair<std::string, PointKinematics>> points;
    for (const auto& [name, point] : AllPoints()) points.push_back({name, point(kin)});
    for (const auto& [name, p] : points) {
      for (int c : outside(p.leg)) EXPECT_EQ(p.J.col(c), Vec2::Zero()) << name << " column " << c;
      const Vec9 start = testing::RandomVector<kNumCoords>(rng_, -10.0, 10.0);
      Vec9 sparse = start, dense = start;
      AddTransposeProduct(p, f, &sparse);
      dense += p.J.transpose() * f;
      EXPECT_EQ(sparse, dense) << name;
    }

    std::vector<std::pair<std::string, const AngleKinematics*>> angles = {{"pitch", &kin.pitch}};
    for (int leg = 0; leg < kNumLegs; ++leg) {
      for (const AngleKinematics* a : {&kin.legs[leg].femur, &kin.legs[leg].tibia, &kin.legs[leg].foot}) {
        angles.push_back({"leg " + std::to_string(leg) + " angle", a});
        EXPECT_EQ(a->leg, leg);
      }
    }
    for (const auto& [name, a] : angles) {
      for (int c : outside(a->leg)) EXPECT_EQ(a->j(c), 0.0) << name << " column " << c;
      const Vec9 start = testing::RandomVector<kNumCoords>(rng_, -10.0, 10.0);
      Vec9 sparse = start, dense = start;
      AddTransposeProduct(*a, torque, &sparse);
      dense += a->j.transpose() * torque;
      EXPECT_EQ(sparse, dense) << name;
    }
  }
}

TEST_F(KinematicsTest, StandingStatePutsBothFeetFlatAtTheOrigin) {
  const double flexion = M_PI / 10;
  const State s = StandingState(model_, flexion);
  const Kinematics kin = At(s.q);
  EXPECT_DOUBLE_EQ(s.q(kPitch), 0.0);
  for (int leg = 0; leg < kNumLegs; ++leg) {
    EXPECT_NEAR(kin.legs[leg].ankle.p.x(), 0.0, 1e-12);
    EXPECT_NEAR(kin.legs[leg].ankle.p.y(), model_.body.half_foot_y, 1e-12);
    EXPECT_NEAR(kin.legs[leg].foot.angle, 0.0, 1e-12);
    EXPECT_NEAR(s.q(JointIndex(leg, kKnee)), flexion, 1e-15);
    // knee flexed forward: the knee is ahead of both hip and ankle
    EXPECT_GT(kin.legs[leg].knee.p.x(), kin.hip.p.x());
    EXPECT_GT(kin.legs[leg].knee.p.x(), kin.legs[leg].ankle.p.x());
  }
  // the trunk's bottom is a leg length (times cos(flexion/2)) above the ankles
  EXPECT_NEAR(kin.hip.p.y() - model_.body.half_foot_y, model_.leg_length() * std::cos(flexion / 2), 1e-12);
  EXPECT_TRUE(s.v.isZero());
}

}  // namespace
}  // namespace walkers
