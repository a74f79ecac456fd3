// The skeleton's TaskTable slots (jelly/skeleton_tasks.hpp): a part of TaskTable::kinds, null until
// an assignment's bindings fill them.
#include <gtest/gtest.h>

#include "jelly/skeleton_tasks.hpp"

namespace jelly {
namespace {

skeleton::Mat3 identity_rotation(const Vec3&) { return skeleton::Mat3::Identity(); }

TEST(SkeletonTasks, EverySlotIsNullInATableThatFillsNone) {
  const TaskTable table;
  const SkeletonTasks& t = skeleton_tasks(table);
  EXPECT_EQ(t.local_rotation, nullptr);
  EXPECT_EQ(t.forward_kinematics, nullptr);
  EXPECT_EQ(t.time_map, nullptr);
  EXPECT_EQ(t.warped_posture, nullptr);
  EXPECT_EQ(t.blend_motions, nullptr);
  EXPECT_EQ(t.ik_chain, nullptr);
  EXPECT_EQ(t.ik_jacobian, nullptr);
  EXPECT_EQ(t.least_squares, nullptr);
  EXPECT_EQ(t.ik_iterate, nullptr);
  EXPECT_EQ(t.clamp_to_limits, nullptr);
  EXPECT_EQ(t.ik_solve, nullptr);
  EXPECT_EQ(table.kinds.find<SkeletonTasks>(), nullptr) << "reading makes no part";
}

TEST(SkeletonTasks, AFilledSlotIsKeptInTheTableAndCopiedWithIt) {
  TaskTable table;
  skeleton_tasks(table).local_rotation = identity_rotation;
  const TaskTable copy = table;
  EXPECT_EQ(skeleton_tasks(copy).local_rotation, &identity_rotation);
  EXPECT_EQ(skeleton_tasks(copy).forward_kinematics, nullptr);
}

}  // namespace
}  // namespace jelly
