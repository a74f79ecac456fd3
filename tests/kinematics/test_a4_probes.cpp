// The probes of A4's inverse-kinematics slots (jelly probe, the viewer's task list;
// framework/bodies/skeleton/skeleton_probe.cpp): A4's reference counts as implemented, stubs that
// fill nothing (as assignments/a4/ does) and a table without the slots do not.
#include <gtest/gtest.h>

#include <algorithm>
#include <string_view>
#include <vector>

#include "jelly/a4/task_table.hpp"
#include "jelly/skeleton_tasks.hpp"
#include "jelly/task_probe.hpp"

namespace jelly {
namespace {

using skeleton::IkOps;
using skeleton::IkResult;
using skeleton::IkSettings;
using skeleton::Matrix3X;
using skeleton::Posture;
using skeleton::Skeleton;
using skeleton::VectorX;

std::vector<int> stub_chain(const Skeleton&, int, int) { return {}; }
void stub_jacobian(const Skeleton&, const skeleton::BoneFrames&, const std::vector<int>& chain,
                   Matrix3X& J) {
  J = Matrix3X::Zero(3, 3 * static_cast<Eigen::Index>(chain.size()));
}
void stub_least_squares(const Matrix3X& J, const Vec3&, VectorX& x) { x = VectorX::Zero(J.cols()); }
IkResult stub_iterate(const Skeleton&, const std::vector<int>&, const Vec3&, const IkSettings&,
                      const IkOps&, Posture&) {
  return {};
}
IkResult stub_solve(const IkSettings&, const IkOps&, Posture&) { return {}; }

TEST(A4Probe, TellsTheInverseKinematicsTasksFromStubsAndMissingOnes) {
  const std::vector<std::string_view> all = probe_slots();
  TaskTable stubs;
  SkeletonTasks& k = skeleton_tasks(stubs);
  k.ik_chain = stub_chain;
  k.ik_jacobian = stub_jacobian;
  k.least_squares = stub_least_squares;
  k.ik_iterate = stub_iterate;
  k.ik_solve = stub_solve;
  const TaskTable reference = a4::task_table();
  for (const char* slot : {"ik_chain", "ik_jacobian", "least_squares", "ik_iterate", "ik_solve"}) {
    EXPECT_NE(std::find(all.begin(), all.end(), slot), all.end()) << slot;
    const TaskStatus done = probe_slot(slot, "A4.T", "task", reference);
    EXPECT_TRUE(done.implemented) << slot << ": " << done.evidence;
    const TaskStatus stub = probe_slot(slot, "A4.T", "task", stubs);
    EXPECT_FALSE(stub.implemented) << slot << ": " << stub.evidence;
    const TaskStatus none = probe_slot(slot, "A4.T", "task", TaskTable{});
    EXPECT_FALSE(none.implemented) << slot;
    EXPECT_EQ(none.evidence, "function missing from the task table") << slot;
  }
  EXPECT_EQ(probe_slot("ik_chain", "A4.T1", "chain", reference).evidence,
            "the chain from the root to bone a has 2 bones");
}

}  // namespace
}  // namespace jelly
