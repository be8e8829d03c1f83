// The right-hand side's written-out foundation sums (dynamics/contact_sums.cc)
// against the reference templates of dynamics/contact_laws.h, which the
// Jacobian's automatic differentiation runs: for every pair, at random
// overlapping poses and motions, the same wrenches and reports.
#include <random>

#include <Eigen/Core>
#include <gtest/gtest.h>
#include <unsupported/Eigen/AutoDiff>

#include "control/genome.h"
#include "dynamics/contact_laws.h"

namespace walkers {
namespace {

using contact_laws::BodyMotion;
using AD = Eigen::AutoDiffScalar<Eigen::Matrix<double, 1, 1>>;

// a motion with its cosine and sine, for doubles and (without partials) for the template
struct Drawn {
  BodyMotion<double> plain;
  BodyMotion<AD> reference;
};
Drawn Draw(const Vec2& p, double angle, const Vec2& v, double rate) {
  Drawn d;
  d.plain.p = p;
  d.plain.v = v;
  d.plain.angle = angle;
  d.plain.rate = rate;
  d.plain.cos = std::cos(angle);
  d.plain.sin = std::sin(angle);
  const auto ad = [](double x) { return AD(x, Eigen::Matrix<double, 1, 1>::Zero()); };
  d.reference.p = contact_laws::V2<AD>(ad(p.x()), ad(p.y()));
  d.reference.v = contact_laws::V2<AD>(ad(v.x()), ad(v.y()));
  d.reference.angle = ad(angle);
  d.reference.rate = ad(rate);
  d.reference.cos = ad(d.plain.cos);
  d.reference.sin = ad(d.plain.sin);
  return d;
}

void ExpectSameWrench(const contact_laws::Wrench<double>& sums, const contact_laws::Wrench<AD>& reference,
                      double scale, const std::string& where) {
  EXPECT_NEAR(sums.force.x(), reference.force.x().value(), 1e-11 * scale) << where;
  EXPECT_NEAR(sums.force.y(), reference.force.y().value(), 1e-11 * scale) << where;
  EXPECT_NEAR(sums.torque, reference.torque.value(), 1e-11 * scale) << where;
}

class ContactSumsTest : public ::testing::TestWithParam<int> {};

TEST_P(ContactSumsTest, AgreeWithTheReferenceLawsAtRandomOverlaps) {
  const int pair = GetParam();
  const ContactPairSpec& spec = ContactPairs()[pair];
  std::mt19937 rng(100 + pair);
  std::uniform_real_distribution<double> unit(-1.0, 1.0);
  // a walker with a square-ish trunk as well as the default genome's long one
  BodyParameters square = BodyOf(DefaultGenome());
  square.half_body_x = 0.3;
  for (const BodyParameters& body : {BodyOf(DefaultGenome()), square}) {
    const Model model = BuildModel(body);
    const Vec2 half_trunk(body.half_body_x, body.half_body_y), half_foot(body.half_foot_x, body.half_foot_y);
    const double reach = spec.a == ContactBody::kGround ? 0.0
                         : spec.a == ContactBody::kTrunk ? half_trunk.norm()
                                                          : half_foot.norm();
    int touching = 0;
    for (int draw = 0; draw < 400; ++draw) {
      const Drawn a = Draw(Vec2(0.0, 0.3 * unit(rng)), 0.4 * unit(rng), Vec2(unit(rng), unit(rng)), 3 * unit(rng));
      // b within reach of a (of the ground: around its surface), at slip
      // speeds around the friction law's transition velocity and well past it
      const double speed = draw % 2 ? 1e-3 : 1.0;
      const Vec2 offset = spec.a == ContactBody::kGround ? Vec2(0.0, 0.15 * unit(rng) + 0.05)
                                                         : Vec2(reach * unit(rng), 0.5 * reach * unit(rng));
      const Drawn b = Draw(a.plain.p + offset, 3.2 * unit(rng), speed * Vec2(unit(rng), unit(rng)),
                           speed * 5 * unit(rng));
      const auto sums = contact_laws::PairContact<double>(model, pair, a.plain, b.plain);
      const auto reference = contact_laws::PairContact<AD>(model, pair, a.reference, b.reference);
      const std::string where = std::string(spec.name) + " draw " + std::to_string(draw);
      ASSERT_EQ(sums.report.touching, reference.report.touching) << where;
      ASSERT_EQ(sums.report.elements, reference.report.elements) << where;
      touching += sums.report.touching ? 1 : 0;
      const double scale = 1.0 + std::abs(reference.on_b.force.x().value()) +
                           std::abs(reference.on_b.force.y().value()) + std::abs(reference.on_b.torque.value()) +
                           std::abs(reference.on_a.torque.value());
      ExpectSameWrench(sums.on_a, reference.on_a, scale, where + " on a");
      ExpectSameWrench(sums.on_b, reference.on_b, scale, where + " on b");
      EXPECT_NEAR(sums.report.force.x(), reference.report.force.x(), 1e-11 * scale) << where;
      EXPECT_NEAR(sums.report.force.y(), reference.report.force.y(), 1e-11 * scale) << where;
      EXPECT_NEAR(sums.report.energy, reference.report.energy, 1e-11 * (1.0 + reference.report.energy)) << where;
    }
    // the draws must exercise the law, not only its early exits
    EXPECT_GT(touching, 20) << spec.name;
  }
}

INSTANTIATE_TEST_SUITE_P(EveryPair, ContactSumsTest, ::testing::Range(0, static_cast<int>(kNumContactPairs)),
                         [](const ::testing::TestParamInfo<int>& param) {
                           std::string name = ContactPairs()[param.param].name;
                           for (char& c : name) c = std::isalnum(static_cast<unsigned char>(c)) ? c : '_';
                           return name;
                         });

}  // namespace
}  // namespace walkers
