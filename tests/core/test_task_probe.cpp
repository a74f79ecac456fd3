// The task probe against the reference solution: every task is reported implemented.
#include <gtest/gtest.h>

#include "a1_manifest.hpp"
#include "jelly/a1/task_table.hpp"
#include "jelly/task_probe.hpp"

namespace jelly {
namespace {

TEST(TaskProbe, ReferenceSolutionHasAllThirteenTasks) {
  const auto statuses = probe_tasks(testing::a1_manifest(), a1::task_table());
  ASSERT_EQ(statuses.size(), 13u);
  for (std::size_t i = 0; i < statuses.size(); ++i) {
    EXPECT_EQ(statuses[i].id, "A1.T" + std::to_string(i + 1));
    EXPECT_TRUE(statuses[i].implemented)
        << statuses[i].id << " " << statuses[i].name << ": " << statuses[i].evidence;
  }
  EXPECT_TRUE(missing_task_ids(statuses).empty());
}

TEST(TaskProbe, NullFunctionCountsAsMissing) {
  TaskTable t = a1::task_table();
  t.spring_force = nullptr;
  t.rk4_step = nullptr;
  const auto missing = missing_task_ids(probe_tasks(testing::a1_manifest(), t));
  EXPECT_EQ(missing, (std::vector<std::string>{"A1.T4", "A1.T13"}));
}

TEST(TaskProbe, OneTaskSwappedForAStubIsTheOnlyOneReported) {
  TaskTable t = a1::task_table();
  // An integrator that does nothing, as the student stub does.
  t.midpoint_step = [](System&, State&, double, Workspace&) {};
  t.collide_bowl = [](const Bowl&, const Vec3&, Vec3&) { return false; };
  const auto missing = missing_task_ids(probe_tasks(testing::a1_manifest(), t));
  EXPECT_EQ(missing, (std::vector<std::string>{"A1.T7", "A1.T12"}));
}

}  // namespace
}  // namespace jelly
