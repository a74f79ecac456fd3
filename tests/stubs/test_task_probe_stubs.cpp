// The task probe against the student stubs: all 13 tasks are reported missing, so the viewer and
// the CLI can tell a student what to implement first.
#include <gtest/gtest.h>

#include "a1_manifest.hpp"
#include "jelly/a1/task_table.hpp"
#include "jelly/task_probe.hpp"

namespace jelly {
namespace {

TEST(TaskProbeStubs, EveryStubIsReportedMissing) {
  const auto statuses = probe_tasks(testing::a1_manifest(), a1::task_table());
  ASSERT_EQ(statuses.size(), 13u);
  for (const TaskStatus& s : statuses) {
    EXPECT_FALSE(s.implemented) << s.id << " " << s.name << ": " << s.evidence;
    EXPECT_FALSE(s.name.empty());
    EXPECT_FALSE(s.evidence.empty());
  }
  EXPECT_EQ(missing_task_ids(statuses).size(), 13u);
  EXPECT_EQ(a1::task_table().origin, "assignments");
}

}  // namespace
}  // namespace jelly
