// The right-hand side and the Jacobian allocate nothing: this program counts
// every operator new (it replaces the global one) around their calls.
#include <atomic>
#include <cstdlib>
#include <new>

#include <gtest/gtest.h>

#include "control/genome.h"
#include "control/start_pose.h"
#include "dynamics/equations_of_motion.h"
#include "dynamics/jacobian.h"
#include "dynamics/observation.h"

namespace {
std::atomic<long> g_allocations{0};
}

void* operator new(std::size_t size) {
  ++g_allocations;
  if (void* p = std::malloc(size ? size : 1)) return p;
  throw std::bad_alloc();
}
void operator delete(void* p) noexcept { std::free(p); }
void operator delete(void* p, std::size_t) noexcept { std::free(p); }

namespace walkers {
namespace {

TEST(NoAllocationTest, RightHandSideAndJacobianAllocateNothing) {
  const Model model = BuildModel(BodyOf(DefaultGenome()));
  State s = StartState(model);
  s.q(kY) -= 0.002;  // feet pressed into the ground: contact forces run too
  s.v.setConstant(0.1);
  Inputs inputs;
  inputs.welds[kLeft] = PlantFoot(model, s, kLeft);
  inputs.joint_torque.tail<6>().setConstant(50.0);
  Workspace ws;
  Vec9 qdd;
  Mat9 da_dq, da_dv;

  const long before = g_allocations.load();
  for (int i = 0; i < 100; ++i) {
    ASSERT_TRUE(ForwardDynamics(model, inputs, s.q, s.v, &ws, &qdd));
    ASSERT_TRUE(AccelerationJacobian(model, inputs, s.q, s.v, &ws, &da_dq, &da_dv));
  }
  EXPECT_EQ(g_allocations.load() - before, 0);

  // the counter counts: an allocation is seen
  const long probe = g_allocations.load();
  auto* p = new std::vector<double>(1000);
  delete p;
  EXPECT_GT(g_allocations.load(), probe);
}

}  // namespace
}  // namespace walkers
