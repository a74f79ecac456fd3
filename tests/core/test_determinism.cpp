// Same scene, same binary: bit-identical trajectories (hashes of the full state).
#include <gtest/gtest.h>

#include "jelly/a1/task_table.hpp"
#include "jelly/recorder.hpp"
#include "jelly/simulator.hpp"
#include "scenes_in_code.hpp"

namespace jelly {
namespace {

std::uint64_t run_hash(IntegratorKind kind, double seconds) {
  Simulator sim(build_world(testing::course_2023(kind), a1::task_table()), {kind, 0.001});
  sim.run_until(seconds);
  return state_hash(sim.state());
}

class Determinism : public ::testing::TestWithParam<IntegratorKind> {};

TEST_P(Determinism, RepeatedRunsGiveIdenticalBitsThroughContact) {
  // 2 s: through first contact at ≈ 1.4 s, where a last-bit difference would grow fast.
  const std::uint64_t a = run_hash(GetParam(), 2.0);
  const std::uint64_t b = run_hash(GetParam(), 2.0);
  EXPECT_EQ(a, b);
}

INSTANTIATE_TEST_SUITE_P(AllIntegrators, Determinism, ::testing::ValuesIn(kAllIntegrators),
                         testing::integrator_param_name);

TEST(Determinism, HashSeesALastBitChange) {
  Simulator sim(build_world(testing::course_2023(), a1::task_table()),
                {IntegratorKind::ExplicitEuler, 0.001});
  State s = sim.state();
  const std::uint64_t h0 = state_hash(s);
  s.x(1, 17) = std::nextafter(s.x(1, 17), 1e9);
  EXPECT_NE(h0, state_hash(s));
}

}  // namespace
}  // namespace jelly
