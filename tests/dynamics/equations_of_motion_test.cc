#include "dynamics/equations_of_motion.h"

#include <random>

#include <Eigen/Eigenvalues>

#include <gtest/gtest.h>

#include "control/genome.h"
#include "dynamics/energy.h"
#include "tests/dynamics/default_walker_test.h"
#include "tests/finite_difference.h"

namespace walkers {
namespace {

using testing::MatricesNear;
using testing::NumericalJacobian;

class EquationsOfMotionTest : public testing::DefaultWalkerTest {
 protected:
  EquationsOfMotionTest() : DefaultWalkerTest(2024) {}

  Kinematics At(const Model& m, const Vec9& q, const Vec9& v = Vec9::Zero()) const {
    Kinematics kin;
    ComputeKinematics(m, q, v, &kin);
    return kin;
  }
  Vec9 RandomV() { return testing::RandomVector<kNumCoords>(rng_, -3.0, 3.0); }
};

TEST_F(EquationsOfMotionTest, MassMatrixIsSymmetricPositiveDefinite) {
  for (int trial = 0; trial < 20; ++trial) {
    const Mat9 M = MassMatrix(model_, RandomQ());
    EXPECT_TRUE(MatricesNear(M, M.transpose(), 1e-12));
    const Eigen::SelfAdjointEigenSolver<Mat9> eig(M);
    EXPECT_GT(eig.eigenvalues().minCoeff(), 1e-6) << "trial " << trial;
    // the trunk block carries the whole mass
    EXPECT_NEAR(M(kX, kX), model_.total_mass, 1e-9);
    EXPECT_NEAR(M(kY, kY), model_.total_mass, 1e-9);
  }
}

TEST_F(EquationsOfMotionTest, QuadraticFormIsKineticEnergySummedBodyByBody) {
  for (int trial = 0; trial < 20; ++trial) {
    const Vec9 q = RandomQ(), v = RandomV();
    const Kinematics kin = At(model_, q, v);
    Mat9 M;
    MassMatrix(model_, kin, &M);
    const double by_bodies = KineticEnergy(model_, kin);
    EXPECT_GT(by_bodies, 1.0);
    EXPECT_NEAR(0.5 * v.dot(M * v), by_bodies, 1e-10 * by_bodies);
  }
}

TEST_F(EquationsOfMotionTest, GravityIsMinusTheGradientOfItsPotential) {
  Model m = model_;
  m.options.contact = false;
  m.options.joint_stops = false;
  const Vec9 q = RandomQ();
  Vec9 Q;
  GeneralizedForces(m, Inputs{}, At(m, q), q, Vec9::Zero(), &Q);
  auto energy = [&](const Vec9& x) { return Eigen::Matrix<double, 1, 1>(GravitationalEnergy(m, At(m, x))); };
  const Row9 gradient = NumericalJacobian<1, kNumCoords>(energy, q);
  EXPECT_TRUE(MatricesNear(-gradient.transpose(), Q, 1e-4));
  EXPECT_NEAR(Q(kY), -m.total_mass * m.options.gravity, 1e-9);
}

TEST_F(EquationsOfMotionTest, VelocityProductForcesMatchLagrangesEquations) {
  // with no forces, M q'' = -(dM/dt q' - d(1/2 q'^T M q')/dq): check the
  // generalized velocity-product force against finite differences of M
  Model m = model_;
  m.options.contact = false;
  m.options.joint_stops = false;
  m.options.gravity = 0.0;
  const Vec9 q = RandomQ(), v = RandomV();
  Vec9 Q;
  GeneralizedForces(m, Inputs{}, At(m, q, v), q, v, &Q);

  // dM/dt q' = d/de [M(q + e v)] q'
  auto M_along = [&](const Eigen::Matrix<double, 1, 1>& e) -> Vec9 { return MassMatrix(m, q + v * e(0)) * v; };
  const Vec9 Mdot_v = NumericalJacobian<kNumCoords, 1>(M_along, Eigen::Matrix<double, 1, 1>::Zero());
  auto kinetic = [&](const Vec9& x) { return Eigen::Matrix<double, 1, 1>(0.5 * v.dot(MassMatrix(m, x) * v)); };
  const Row9 dT_dq = NumericalJacobian<1, kNumCoords>(kinetic, q);
  const Vec9 expected = -(Mdot_v - dT_dq.transpose());
  EXPECT_GT(expected.norm(), 1.0);
  EXPECT_TRUE(MatricesNear(expected, Q, 1e-5 * (1.0 + expected.norm())));
}

TEST_F(EquationsOfMotionTest, ElasticForcesAtRestAreMinusTheGradientOfTheirEnergy) {
  // contact springs and joint stops at zero velocity are conservative: their
  // generalized force is -dE/dq, which checks every contact Jacobian
  Model m = model_;
  m.options.gravity = 0.0;
  State s = StandingState(m, 2.4);         // knees folded past their stops
  s.q(kY) -= 0.004;                        // feet 4 mm into the ground
  s.q(kAnkleL) -= 0.004;                   // both feet tilted a little, so that
  s.q(kAnkleR) -= 0.002;                   // their brick meshes sink unevenly
  const Inputs inputs;
  Vec9 Q;
  GeneralizedForces(m, inputs, At(m, s.q), s.q, Vec9::Zero(), &Q);
  auto energy = [&](const Vec9& x) { return Eigen::Matrix<double, 1, 1>(ElasticEnergy(m, At(m, x))); };
  const Row9 gradient = NumericalJacobian<1, kNumCoords>(energy, s.q);
  EXPECT_GT(Q.norm(), 100.0);
  EXPECT_TRUE(MatricesNear(-gradient.transpose(), Q, 1e-6 * Q.norm()));
}

TEST_F(EquationsOfMotionTest, LockedCoordinatesDoNotAccelerate) {
  Model m = model_;
  m.options.locked[kX] = m.options.locked[kY] = m.options.locked[kPitch] = true;
  Workspace ws;
  Vec9 qdd;
  const Vec9 q = RandomQ();
  ASSERT_TRUE(ForwardDynamics(m, Inputs{}, q, Vec9::Zero(), &ws, &qdd));
  EXPECT_EQ(qdd.head<3>(), Vec3::Zero());
  EXPECT_GT(qdd.tail<6>().norm(), 1.0);
}

}  // namespace
}  // namespace walkers

namespace walkers {
namespace {

TEST(CenterOfMassTest, MovesWithTheGeneralizedMomentum) {
  // total momentum = M v_com = the first two rows of the mass matrix times q'
  const Model m = BuildModel(BodyOf(DefaultGenome()));
  std::mt19937 rng(3);
  const Vec9 q = testing::RandomVector<kNumCoords>(rng, -1.0, 1.0);
  const Vec9 v = testing::RandomVector<kNumCoords>(rng, -1.0, 1.0);
  Kinematics kin;
  ComputeKinematics(m, q, v, &kin);
  const CenterOfMass c = ComputeCenterOfMass(m, kin);
  const Vec9 momentum = MassMatrix(m, q) * v;
  EXPECT_TRUE(testing::MatricesNear(Vec2(momentum.head<2>()), Vec2(m.total_mass * c.v), 1e-9));
  // the heavy trunk dominates: the centre of mass is near it, below it
  EXPECT_LT((c.p - kin.trunk.p).norm(), 0.3);
  EXPECT_GT(c.v.norm(), 0.0);
}

}  // namespace
}  // namespace walkers
