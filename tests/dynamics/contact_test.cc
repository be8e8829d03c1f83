#include "dynamics/contact.h"

#include <algorithm>
#include <cmath>

#include <gtest/gtest.h>

#include "dynamics/contact_geometry.h"
#include "tests/dynamics/contact_poses.h"
#include "tests/dynamics/default_walker_test.h"

namespace walkers {
namespace {

class ContactTest : public testing::DefaultWalkerTest {
 protected:
  ContactTest() : DefaultWalkerTest(47) {}

  ContactReports Reports(const Model& m, const State& s) const {
    Kinematics kin;
    ComputeKinematics(m, s.q, s.v, &kin);
    return ReportContacts(m, kin);
  }
  ContactReports Reports(const State& s) const { return Reports(model_, s); }

};

// ---- the surfaces ----

TEST(BrickMeshTest, HasSimbodysFaceDivisionsAndCoversTheBox) {
  // the default trunk: 1.76 x 0.27 x 0.66 m cut into 7 x 1 x 3 pieces
  const Vec3 half(0.8822120184545844, 0.1353015130243578, 0.329704208858325);
  const std::vector<MeshTriangle> triangles = BrickMeshTriangles(half, 6);
  int bottom = 0;
  double area = 0.0;
  for (const MeshTriangle& t : triangles) {
    bottom += t.centroid.y() == -half.y() ? 1 : 0;
    area += t.area;
    EXPECT_LE(t.centroid.cwiseAbs().maxCoeff(), half.maxCoeff() + 1e-15);
  }
  EXPECT_EQ(bottom, 42);  // 7 x 3 quads, two triangles each
  EXPECT_EQ(triangles.size(), 2u * (7 * 1 + 7 * 3 + 1 * 3) * 2);
  const double box_area = 8.0 * (half.x() * half.y() + half.x() * half.z() + half.y() * half.z());
  EXPECT_NEAR(area, box_area, 1e-12);
}

TEST(BrickMeshTest, TheNearestSpringsSitAThirdOfAQuadInFromTheEdges) {
  const Vec3 half(0.8822120184545844, 0.1353015130243578, 0.329704208858325);
  const ContactSites sites = BuildContactSites(half, Vec3(0.22, 0.05, 0.07), 0.25, 0.1, 6);
  const double quad = 2.0 * half.x() / 7.0;
  double outermost_bottom = 0.0, bottom_area = 0.0;
  for (const GroundSite& s : sites.trunk_ground.sites()) {
    if (s.p.y() != -half.y()) continue;
    outermost_bottom = std::max(outermost_bottom, std::abs(s.p.x()));
    bottom_area += s.area;
  }
  EXPECT_NEAR(outermost_bottom, half.x() - quad / 3.0, 1e-12);
  EXPECT_NEAR(bottom_area, 4.0 * half.x() * half.z(), 1e-12);
  // every bottom site carries the triangles of all three quads along z
  EXPECT_EQ(sites.trunk_ground.sites().size(), 14u + 14u + 2u * 2u + 7u * 4u);
}

// The sums visit only the sites low enough in their box to be below the
// ground: none that is below may be left out, the order stays, and a flat foot
// just touching the ground visits its bottom row alone.
TEST(GroundMeshTest, LeavesOutOnlySitesAboveTheGroundAndKeepsTheirOrder) {
  const Vec3 half_foot(0.1215, 0.0501, 0.0719);
  const GroundMesh& mesh = BuildContactSites(Vec3(0.6, 0.13, 0.3), half_foot, 0.25, 0.1, 6).foot_ground;
  const auto below = [](const std::vector<GroundSite>& sites, double c, double s, double y) {
    std::vector<const GroundSite*> out;
    for (const GroundSite& site : sites) {
      if (y + s * site.p.x() + c * site.p.y() < 0.0) out.push_back(&site);
    }
    return out;
  };
  const auto same = [](const std::vector<const GroundSite*>& a, const std::vector<const GroundSite*>& b) {
    if (a.size() != b.size()) return false;
    for (size_t i = 0; i < a.size(); ++i) {
      if (a[i]->p != b[i]->p || a[i]->area != b[i]->area) return false;
    }
    return true;
  };
  int poses = 0, touching = 0;
  for (double angle = -3.0; angle <= 3.0; angle += 0.0137) {
    for (double y = -0.06; y <= 0.14; y += 0.0031) {
      const double c = std::cos(angle), s = std::sin(angle);
      const std::vector<const GroundSite*> all = below(mesh.sites(), c, s, y);
      EXPECT_TRUE(same(below(mesh.CanTouch(c, s, y), c, s, y), all)) << "angle " << angle << " y " << y;
      ++poses;
      touching += !all.empty();
    }
  }
  EXPECT_GT(touching, poses / 4);

  size_t bottom_row = 0;
  for (const GroundSite& site : mesh.sites()) bottom_row += site.p.y() == -half_foot.y();
  EXPECT_EQ(mesh.CanTouch(1.0, 0.0, half_foot.y() - 1e-4).size(), bottom_row);
  EXPECT_LT(bottom_row, mesh.sites().size() / 3);
  EXPECT_TRUE(mesh.CanTouch(1.0, 0.0, half_foot.y() + 1e-4).empty());
}

// ---- the laws, combined from the materials as Simbody combines them ----

TEST(ContactLawsTest, CombineTheAuthorsMaterialsBySimbodysRules) {
  const ContactLaws laws = CombineMaterials(ContactParameters{});
  // two surfaces of 1e8 Pa over 0.5 m in series: 1e8 N/m^3 per unit area
  EXPECT_DOUBLE_EQ(laws.mesh_ground.stiffness, 1e8);
  EXPECT_DOUBLE_EQ(laws.mesh_ground.dissipation, 1.0);
  EXPECT_DOUBLE_EQ(laws.mesh_ground.squish, 0.5);
  EXPECT_DOUBLE_EQ(laws.mesh_ground.friction.viscous, 0.3);
  // Hertz: 4/3 sqrt(0.1) ((1e8)^(2/3) / 2)^1.5 = 1.4907e7
  EXPECT_NEAR(laws.knee_ground.stiffness, 4.0 / 3.0 * std::sqrt(0.1) * 1e8 / std::pow(2.0, 1.5), 1e-3);
  EXPECT_NEAR(laws.knee_ground.stiffness, 1.4907e7, 1e3);
  // the knees' material has no viscous friction, so no pair with a knee has any
  EXPECT_EQ(laws.knee_ground.friction.viscous, 0.0);
  EXPECT_EQ(laws.mesh_knee.friction.viscous, 0.0);
  EXPECT_DOUBLE_EQ(laws.mesh_knee.friction.static_friction, 0.3);
}

TEST(FrictionLawTest, RisesToStaticAtTheTransitionVelocityThenAddsViscous) {
  const FrictionLaw law{0.3, 0.3, 0.3, 1e-3};
  const auto mu = [&](double s) { return s * FrictionPerSlip(law, s * s); };
  EXPECT_NEAR(mu(1e-3), 0.3 + 0.3e-3, 1e-12);
  EXPECT_NEAR(mu(0.5e-3), 0.3 * 0.5 + 0.3 * 0.5e-3, 1e-12);  // the quintic step is 1/2 half way
  EXPECT_NEAR(mu(2.0), 0.3 + 0.6, 1e-12);
  EXPECT_LT(mu(1e-5), 1e-4);  // no stiction: the curve starts flat
  double previous = 0.0;
  for (double s = 1e-5; s < 5e-3; s += 1e-5) {
    EXPECT_GT(mu(s), previous) << s;
    previous = mu(s);
  }
  // a Stribeck drop when dynamic < static
  const FrictionLaw stribeck{0.5, 0.3, 0.0, 1e-3};
  EXPECT_NEAR(2e-3 * FrictionPerSlip(stribeck, 4e-6), 0.4, 1e-12);
  EXPECT_NEAR(5e-3 * FrictionPerSlip(stribeck, 25e-6), 0.3, 1e-12);
}

// A tilted trunk pressed into the ground at rest: the force is the direct sum
// over its triangles of 1e8 A d, at their centroids lifted by d / 2.
TEST_F(ContactTest, ATiltedBrickOnTheGroundPushesAsTheSumOverItsTriangles) {
  const double pitch = 0.3;
  State s = testing::TrunkAt(0.0, pitch);
  const BodyParameters& b = model_.body;
  const std::vector<MeshTriangle> triangles =
      BrickMeshTriangles(Vec3(b.half_body_x, b.half_body_y, b.half_body_z), 6);
  // lowest corner 60 mm deep: the two nearest rows of springs, a third and two
  // thirds of a quad in from it, sink too
  s.q(kY) = std::sin(pitch) * b.half_body_x + std::cos(pitch) * b.half_body_y - 60e-3;
  double force = 0.0, moment = 0.0, energy = 0.0;
  int springs = 0;
  for (const MeshTriangle& t : triangles) {
    const Vec2 r(std::cos(pitch) * t.centroid.x() - std::sin(pitch) * t.centroid.y(),
                 std::sin(pitch) * t.centroid.x() + std::cos(pitch) * t.centroid.y());
    const double depth = -(s.q(kY) + r.y());
    if (depth <= 0.0) continue;
    force += 1e8 * t.area * depth;
    moment += r.x() * 1e8 * t.area * depth;
    energy += 0.5 * 1e8 * t.area * depth * depth;
    ++springs;
  }
  ASSERT_GE(springs, 6);
  const ContactReport r = Reports(s)[kGroundTrunk];
  EXPECT_NEAR(r.force.y(), force, 1e-9 * force);
  EXPECT_EQ(r.force.x(), 0.0);
  EXPECT_NEAR(r.energy, energy, 1e-9 * energy);
  // and the moment about the trunk centre, through the generalized force on the pitch
  Kinematics kin;
  ComputeKinematics(model_, s.q, s.v, &kin);
  Vec9 Q = Vec9::Zero();
  AddContactForces(model_, kin, Welds{}, &Q);
  EXPECT_NEAR(Q(kPitch), moment, 1e-9 * std::abs(moment));
  EXPECT_NEAR(Q(kY), force, 1e-9 * force);
}

TEST_F(ContactTest, ABrickSlidingOnTheGroundIsBrakedByFrictionAndDampedIntoIt) {
  State s = testing::TrunkAt(model_.body.half_body_y - 1e-3, 0.0);
  const double at_rest = Reports(s)[kGroundTrunk].force.y();
  s.v(kY) = -0.1;  // sinking in: damped
  EXPECT_NEAR(Reports(s)[kGroundTrunk].force.y(), 1.1 * at_rest, 1e-9 * at_rest);
  s.v(kY) = -2.0;  // pulling out fast: no force at all
  s.v(kY) = 2.0;
  EXPECT_EQ(Reports(s)[kGroundTrunk].force, Vec2::Zero());
  s.v(kY) = 0.0;
  s.v(kX) = 0.5;  // sliding forward: mu = 0.3 + 0.3 s
  const Vec2 f = Reports(s)[kGroundTrunk].force;
  EXPECT_NEAR(f.x(), -(0.3 + 0.3 * 0.5) * f.y(), 1e-9 * f.y());
}

TEST_F(ContactTest, AKneeSphereOnTheGroundIsAHertzContact) {
  State s;
  s.q(kKneeL) = s.q(kKneeR) = 3.0;  // femurs down, tibias folded up: the knees lowest
  Kinematics kin;
  ComputeKinematics(model_, s.q, s.v, &kin);
  const double depth = 1.5e-3;
  s.q(kY) += model_.contact.knee_radius - depth - kin.legs[kLeft].knee.p.y();
  const ContactReport r = Reports(s)[kGroundKneeL];
  ASSERT_TRUE(r.touching);
  EXPECT_NEAR(r.force.y(), 1.4907e7 * std::pow(depth, 1.5), 1e-4 * r.force.y());
  EXPECT_NEAR(r.energy, 0.4 * r.force.y() * depth, 1e-9 * r.energy);
  s.v(kY) = -0.2;  // 1.5 c x' of Hunt and Crossley
  EXPECT_NEAR(Reports(s)[kGroundKneeL].force.y(), 1.3 * r.force.y(), 1e-9 * r.force.y());
}

// ---- the walker's own surfaces against each other ----

TEST_F(ContactTest, TheTrunkRestingOnAFootPushesItDownAndNothingElse) {
  State s = testing::TrunkAt(2.0, 0.0);
  // the left foot folded up under the trunk's bottom, its top 1 mm in
  testing::PlaceAnkle(model_, kLeft, Vec2(0.3, -(model_.body.half_foot_y - 1e-3)), &s);
  const ContactReports r = Reports(s);
  ASSERT_TRUE(r[kTrunkFootL].touching);
  EXPECT_LT(r[kTrunkFootL].force.y(), 0.0);
  EXPECT_NEAR(r[kTrunkFootL].force.x(), 0.0, 1e-9);
  EXPECT_GT(r[kTrunkFootL].energy, 0.0);
  EXPECT_FALSE(r[kTrunkFootR].touching);
  EXPECT_FALSE(r[kGroundTrunk].touching);
  // without self-contact the pair is gone
  Model apart = model_;
  apart.options.self_contact = false;
  EXPECT_FALSE(Reports(apart, s)[kTrunkFootL].touching);
}

TEST_F(ContactTest, AKneeSwungUpIntoTheTrunkIsPushedDown) {
  const testing::Posed p = testing::KneeInTheTrunk(model_.body, kRight, 3e-3);
  const ContactReports r = Reports(p.model, p.state);
  ASSERT_TRUE(r[kTrunkKneeR].touching);
  EXPECT_LT(r[kTrunkKneeR].force.y(), 0.0);
  EXPECT_FALSE(r[kTrunkKneeL].touching);
}

TEST_F(ContactTest, AKneeLeaningOnItsFootIsHeldUp) {
  const testing::Posed p = testing::KneeOnItsFoot(model_.body, kLeft, 3e-3);
  const ContactReports r = Reports(p.model, p.state);
  ASSERT_TRUE(r[kFootKneeL].touching);
  EXPECT_GT(r[kFootKneeL].force.y(), 0.0);
  EXPECT_FALSE(r[kFootKneeR].touching);
}

// ---- where the contact forces switch (an integrator's events) ----

// Each pair's switch function is the depth of its deepest site: positive
// exactly where the pair touches (at rest, where no spring pulls), zero where
// it starts or stops touching; a welded foot's ground pair is off.
TEST_F(ContactTest, SwitchDepthsAreTheDeepestSitesAndChangeSignWhereAPairStartsToTouch) {
  const auto depths = [](const Model& m, const State& s, const Welds& welds) {
    Kinematics kin;
    ComputeKinematics(m, s.q, s.v, &kin);
    return ContactSwitchDepths(m, kin, welds);
  };
  State on_foot = testing::TrunkAt(2.0, 0.0);
  testing::PlaceAnkle(model_, kLeft, Vec2(0.3, -(model_.body.half_foot_y - 1e-3)), &on_foot);
  const testing::Posed knee_in_trunk = testing::KneeInTheTrunk(model_.body, kRight, 3e-3);
  const testing::Posed knee_on_foot = testing::KneeOnItsFoot(model_.body, kLeft, 3e-3);
  struct Case {
    const char* what;
    const Model& model;
    State state;
    int pair;
    double depth;  // [m]
  };
  for (const Case& c : {Case{"the trunk on a foot, 1 mm in", model_, on_foot, kTrunkFootL, 1e-3},
                        Case{"a knee 3 mm in the trunk", knee_in_trunk.model, knee_in_trunk.state, kTrunkKneeR, 3e-3},
                        Case{"a knee 3 mm in its foot", knee_on_foot.model, knee_on_foot.state, kFootKneeL, 3e-3}}) {
    SCOPED_TRACE(c.what);
    const ContactSwitches d = depths(c.model, c.state, Welds{});
    const ContactReports r = Reports(c.model, c.state);
    EXPECT_NEAR(d[c.pair], c.depth, 1e-9);
    for (int pair = 0; pair < kNumContactPairs; ++pair) {
      EXPECT_EQ(d[pair] > 0.0, r[pair].touching) << ContactPairs()[pair].name << ": " << d[pair];
    }
  }

  // a tilted trunk 60 mm into the ground, raised by its deepest site's depth
  // all but a micrometre, then a micrometre more
  const double pitch = 0.3;
  State s = testing::TrunkAt(0.0, pitch);
  s.q(kY) = std::sin(pitch) * model_.body.half_body_x + std::cos(pitch) * model_.body.half_body_y - 60e-3;
  const double deepest = depths(model_, s, Welds{})[kGroundTrunk];
  EXPECT_GT(deepest, 0.0);
  EXPECT_LT(deepest, 60e-3);  // the springs sit in from the corner
  s.q(kY) += deepest - 1e-6;
  EXPECT_NEAR(depths(model_, s, Welds{})[kGroundTrunk], 1e-6, 1e-12);
  EXPECT_TRUE(Reports(s)[kGroundTrunk].touching);
  s.q(kY) += 2e-6;
  EXPECT_NEAR(depths(model_, s, Welds{})[kGroundTrunk], -1e-6, 1e-12);
  EXPECT_FALSE(Reports(s)[kGroundTrunk].touching);

  // a welded foot's ground pair is off, whatever its depth
  Welds welds;
  welds[kRight].active = true;
  const ContactSwitches welded = depths(model_, State{}, welds);
  EXPECT_EQ(welded[kGroundFootR], -1.0);
  EXPECT_NE(welded[kGroundFootL], -1.0);
}

TEST_F(ContactTest, JointStopMarginsAreTheOverrunPastEachLimit) {
  Vec9 q = Vec9::Zero();
  q(JointIndex(kRight, kKnee)) = -(model_.stops[kKnee].limit + 0.1);
  q(JointIndex(kLeft, kHip)) = model_.stops[kHip].limit - 0.2;
  const JointStopSwitches margin = JointStopMargins(model_, q);
  const auto at = [&](int leg, int joint) { return margin[JointIndex(leg, joint) - JointIndex(kLeft, kHip)]; };
  EXPECT_NEAR(at(kRight, kKnee), 0.1, 1e-12);
  EXPECT_NEAR(at(kLeft, kHip), -0.2, 1e-12);
  EXPECT_EQ(at(kLeft, kAnkle), -model_.stops[kAnkle].limit);
  Model without = model_;
  without.options.joint_stops = false;
  for (double m : JointStopMargins(without, q)) EXPECT_EQ(m, -1.0);
}

// ---- the power contact dissipates (Simbody's power loss) ----

// The same walker without its contact's damping and friction.
Model WithoutDissipation(Model m) {
  for (FoundationLaw* law : {&m.laws.mesh_ground, &m.laws.mesh_mesh, &m.laws.mesh_knee}) {
    law->dissipation = 0.0;
    law->friction.static_friction = law->friction.dynamic_friction = law->friction.viscous = 0.0;
  }
  m.laws.knee_ground.dissipation = 0.0;
  m.laws.knee_ground.friction.static_friction = m.laws.knee_ground.friction.dynamic_friction = 0.0;
  return m;
}

// The dissipated power two ways: summed spring by spring, and as the power
// of the contact forces less that of their elastic parts alone.
void ExpectDissipationIsTheNonElasticForcesPower(const Model& m, const State& s, double at_least, const char* what) {
  SCOPED_TRACE(what);
  Kinematics kin;
  ComputeKinematics(m, s.q, s.v, &kin);
  Vec9 Q = Vec9::Zero(), Q_elastic = Vec9::Zero();
  double power = -1.0;
  AddContactForces(m, kin, Welds{}, &Q, &power);
  AddContactForces(WithoutDissipation(m), kin, Welds{}, &Q_elastic);
  EXPECT_GE(power, at_least);
  EXPECT_NEAR(power, -(Q - Q_elastic).dot(s.v), 1e-9 * std::max(1.0, power));
}

TEST_F(ContactTest, DissipationIsThePowerOfDampingAndFrictionOnEveryPair) {
  // a trunk sinking and sliding on the ground
  State s = testing::TrunkAt(model_.body.half_body_y - 1e-3, 0.05);
  s.v(kX) = 0.4;
  s.v(kY) = -0.1;
  s.v(kPitch) = 0.3;
  ExpectDissipationIsTheNonElasticForcesPower(model_, s, 1.0, "the trunk sinking and sliding on the ground");
  // pulling out fast: the springs let go, and their elastic energy with them
  s.v(kY) = 2.0;
  ExpectDissipationIsTheNonElasticForcesPower(model_, s, 1.0, "the trunk pulled out of the ground");
  // the self-contacts, moving
  testing::Posed trunk_knee = testing::KneeInTheTrunk(model_.body, kRight, 3e-3);
  trunk_knee.state.v.setConstant(0.2);
  ExpectDissipationIsTheNonElasticForcesPower(trunk_knee.model, trunk_knee.state, 1e-6, "a knee in the trunk");
  testing::Posed foot_knee = testing::KneeOnItsFoot(model_.body, kLeft, 3e-3);
  foot_knee.state.v.setConstant(-0.3);
  ExpectDissipationIsTheNonElasticForcesPower(foot_knee.model, foot_knee.state, 1e-6, "a knee on its foot");
  State on_foot = testing::TrunkAt(2.0, 0.0);
  testing::PlaceAnkle(model_, kLeft, Vec2(0.3, -(model_.body.half_foot_y - 1e-3)), &on_foot);
  on_foot.v(JointIndex(kLeft, kHip)) = 0.5;  // the foot slides under the trunk
  on_foot.v(JointIndex(kLeft, kAnkle)) = -0.2;
  ExpectDissipationIsTheNonElasticForcesPower(model_, on_foot, 1e-6, "the trunk on a foot");
  // at rest nothing dissipates
  on_foot.v.setZero();
  ExpectDissipationIsTheNonElasticForcesPower(model_, on_foot, 0.0, "the trunk on a foot at rest");
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
