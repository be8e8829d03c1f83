#include "dynamics/model.h"

#include <algorithm>
#include <vector>

#include <gtest/gtest.h>

#include "control/genome.h"

namespace walkers {
namespace {

// The mass model of the default genome, computed by hand from its half
// sizes (docs/model.md, "Mass model"). The authors' program, built against
// Simbody 3.7, reports the same masses and pitch inertias to 1e-7 (its genes
// are 32-bit floats): trunk 371.51137 kg and 98.649221 kg m^2, each hip body
// 105.45029 kg m^2 about its origin, foot and tibia 0.12287443, knee 0.0007.
TEST(ModelTest, TheDefaultGenomesMassModelIsTheAuthors) {
  const Model m = BuildModel(BodyOf(DefaultGenome()));
  const double hx = 0.8822120184545844, hy = 0.1353015130243578, hz = 0.329704208858325;
  const double fx = 0.22018185203456214, fy = 0.05, fz = 0.06957592968690621;
  // boxes of density 1180
  const double trunk = 8 * hx * hy * hz * 1180;  // 371.511369 kg
  const double foot = 8 * fx * fy * fz * 1180;   // 7.2307365 kg
  EXPECT_NEAR(trunk, 371.511369, 1e-6);
  EXPECT_DOUBLE_EQ(m.trunk_mass, trunk);
  EXPECT_DOUBLE_EQ(m.foot_mass, foot);
  // the trunk's pitch inertia: its box's, plus each hip's box shifted by halfBodyY
  const double box = trunk * (hx * hx + hy * hy) / 3;
  const double hip = trunk * ((hx * hx + hy * hy) / 3 + hy * hy);
  EXPECT_NEAR(box, 98.649215, 1e-6);
  EXPECT_NEAR(hip, 105.450288, 1e-6);
  EXPECT_DOUBLE_EQ(m.trunk_inertia, box + 2 * hip);  // 309.5498 kg m^2, three boxes' worth
  // the legs: the knee's 0.7 kg sphere of radius 0.05 on the femur, the foot's
  // inertia on the tibia as well as on the foot, the ankle and foot masses at the ankle
  EXPECT_DOUBLE_EQ(m.femur_inertia, 0.7 * 0.4 * 0.05 * 0.05);
  EXPECT_DOUBLE_EQ(m.foot_inertia, foot * (fx * fx + fy * fy) / 3);
  EXPECT_DOUBLE_EQ(m.tibia_inertia, m.foot_inertia);
  EXPECT_DOUBLE_EQ(m.knee_mass, 0.7);
  EXPECT_DOUBLE_EQ(m.ankle_mass, 0.1 + foot);
  EXPECT_DOUBLE_EQ(m.hips_mass, 0.2);
  EXPECT_NEAR(m.total_mass, 387.772842, 1e-6);
}

// A scaffolded trunk 0.1 m long is one quad along x: its bottom springs sit a
// third of its half length either side of its centre.
TEST(ModelTest, AShortTrunksBottomIsTwoRowsOfSprings) {
  BodyParameters b = BodyOf(DefaultGenome());
  b.half_body_x = 0.05;
  const Model m = BuildModel(b);
  std::vector<double> xs;
  for (const GroundSite& s : m.sites.trunk_ground.sites()) {
    if (s.p.y() == -b.half_body_y) xs.push_back(s.p.x());
  }
  std::sort(xs.begin(), xs.end());
  ASSERT_EQ(xs.size(), 2u);
  EXPECT_NEAR(xs[0], -0.05 / 3, 1e-15);
  EXPECT_NEAR(xs[1], 0.05 / 3, 1e-15);
}

}  // namespace
}  // namespace walkers
