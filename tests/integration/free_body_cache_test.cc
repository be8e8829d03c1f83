#include "integration/free_body_cache.h"

#include <cmath>
#include <initializer_list>

#include <gtest/gtest.h>

#include "tests/dynamics/default_walker_test.h"

namespace walkers {
namespace {

class FreeBodyCacheTest : public testing::DefaultWalkerTest {
 protected:
  FreeBodyCacheTest() : DefaultWalkerTest(11) {}

  State RandomState() { return {RandomQ(), testing::RandomVector<kNumCoords>(rng_, -1.0, 1.0)}; }

  static void ExpectSame(const FreeBodyState& a, const FreeBodyState& b) {
    EXPECT_EQ(a.z, b.z);
    EXPECT_EQ(a.u, b.u);
  }
};

// An attempt's pattern: its end and embedded solution, its start, the end
// again, then a projected end; every answer is the conversion itself.
TEST_F(FreeBodyCacheTest, EveryAnswerIsTheConversionOfTheStateAskedFor) {
  FreeBodyCache cache;
  for (int step = 0; step < 5; ++step) {
    const State y0 = RandomState(), y1 = RandomState(), y_check = RandomState();
    State projected = y1;
    projected.q(kY) += 1e-3;
    for (const State* y : std::initializer_list<const State*>{&y1, &y_check, &y0, &y1, &y1, &projected, &y0, &y_check}) {
      ExpectSame(cache.Get(model_, *y), ToFreeBodies(model_, *y));
    }
  }
}

// A state that differs in one coordinate's last bit, or only in a zero's
// sign, is another state: it is converted, not taken from the cache.
TEST_F(FreeBodyCacheTest, AStateIsRecognisedByItsBits) {
  FreeBodyCache cache;
  State a = RandomState();
  a.v(kPitch) = 0.0;
  const FreeBodyState first = cache.Get(model_, a);
  State b = a;
  b.q(JointIndex(kLeft, kKnee)) = std::nextafter(a.q(JointIndex(kLeft, kKnee)), 10.0);
  ExpectSame(cache.Get(model_, b), ToFreeBodies(model_, b));
  EXPECT_NE(cache.Get(model_, b).z, first.z);
  State c = a;
  c.v(kPitch) = -0.0;
  EXPECT_TRUE(std::signbit(cache.Get(model_, c).u(kTrunkX + 2)));
  EXPECT_FALSE(std::signbit(cache.Get(model_, a).u(kTrunkX + 2)));
}

}  // namespace
}  // namespace walkers
