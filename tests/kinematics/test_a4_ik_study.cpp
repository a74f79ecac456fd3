// The IK study (framework/bodies/skeleton/skeleton_ik_study.cpp, docs/ik-studies.md) on A4's
// reference task table: its course variant is A4's ik_solve, update for update; the exact Euler
// Jacobian is the derivative of the end effector by the angles; the whole study runs and its CSVs
// have one row per solve and one per solve and update count.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>
#include <string>
#include <vector>

#include "jelly/a4/task_table.hpp"
#include "jelly/skeleton_tasks.hpp"
#include "skeleton_ik_study.hpp"
#include "test_folder.hpp"

namespace jelly {
namespace {

using bodies::IkStudyInputs;
using bodies::IkStudyRun;
using bodies::IkStudySolver;
using bodies::IkStudyVariant;

constexpr double kPi = 3.14159265358979323846;
const std::string kMocap = std::string(JELLY_SOURCE_DIR) + "/data/mocap/";

const TaskTable& reference_table() {
  static const TaskTable t = a4::task_table();
  return t;
}

const SkeletonTasks& tasks() { return skeleton_tasks(reference_table()); }

IkStudyInputs hw3_ik() {
  return bodies::read_ik_study_inputs(kMocap + "skeleton.asf", kMocap + "IK.amc", 0, 0.2,
                                      "lowerback", "rfingers", Vec3(-0.0692501, 3.85358, -1.63441),
                                      tasks());
}

TEST(A4IkStudy, TheCourseVariantIsTheTasksSolveUpdateForUpdate) {
  const IkStudyInputs in = hw3_ik();
  for (const bool limits : {false, true}) {
    skeleton::IkSettings s;
    s.limits = limits;
    const IkStudyRun r = bodies::run_ik_variant(in.skeleton, in.problem, {}, s, tasks(), 1);
    EXPECT_EQ(r.updates, limits ? 105 : 73);
    EXPECT_NEAR(r.initial_error, 1.75161, 5e-6);
    EXPECT_TRUE(r.stable);
    ASSERT_EQ(r.error.size(), static_cast<std::size_t>(r.updates) + 1);
    ASSERT_EQ(r.cpu_us.size(), r.error.size());
    for (std::size_t k = 1; k < r.cpu_us.size(); ++k) EXPECT_GE(r.cpu_us[k], r.cpu_us[k - 1]);
  }
}

TEST(A4IkStudy, TheExactJacobianIsTheDerivativeByTheEulerAngles) {
  const IkStudyInputs in = hw3_ik();
  const std::vector<int>& chain = in.problem.chain;
  skeleton::BoneFrames f;
  tasks().forward_kinematics(in.skeleton, in.problem.posture, f);
  skeleton::Matrix3X J;
  bodies::exact_euler_jacobian(in.skeleton, f, in.problem.posture, chain, J);
  ASSERT_EQ(J.cols(), 3 * static_cast<Eigen::Index>(chain.size()));
  const double h = 1e-6;  // degrees
  for (std::size_t b = 0; b < chain.size(); ++b) {
    for (int k = 0; k < 3; ++k) {
      skeleton::Posture plus = in.problem.posture, minus = in.problem.posture;
      plus.angles[chain[b]][k] += h;
      minus.angles[chain[b]][k] -= h;
      skeleton::BoneFrames fp, fm;
      tasks().forward_kinematics(in.skeleton, plus, fp);
      tasks().forward_kinematics(in.skeleton, minus, fm);
      const Vec3 slope = (fp.end[chain[0]] - fm.end[chain[0]]) / (2.0 * h * kPi / 180.0);
      const bool channel =
          in.skeleton.bones[chain[b]].parent < 0 || in.skeleton.bones[chain[b]].has_rotation(k);
      const Vec3 column = J.col(3 * static_cast<Eigen::Index>(b) + k);
      if (channel) {
        EXPECT_LT((column - slope).norm(), 1e-6) << "bone " << chain[b] << " axis " << k;
      } else {
        EXPECT_EQ(column, Vec3::Zero());
      }
    }
  }
}

TEST(A4IkStudy, DampedAndTransposeSolvesConvergeOnHw3Ik) {
  const IkStudyInputs in = hw3_ik();
  for (const IkStudyVariant& v : {IkStudyVariant{IkStudySolver::Damped, 0.1, false},
                                  IkStudyVariant{IkStudySolver::MinimumNorm, 0.0, true}}) {
    const IkStudyRun r = bodies::run_ik_variant(in.skeleton, in.problem, v, {}, tasks(), 1);
    EXPECT_TRUE(r.stable) << v.name();
    EXPECT_TRUE(r.finite) << v.name();
  }
  EXPECT_EQ((IkStudyVariant{IkStudySolver::Damped, 0.1, false}.name()), "dls-0.1");
  EXPECT_EQ((IkStudyVariant{IkStudySolver::Transpose, 0.0, true}.name()), "transpose+exact");
}

// The CSV's rows, split into cells.
std::vector<std::vector<std::string>> read_csv(const std::filesystem::path& path) {
  std::ifstream in(path);
  std::vector<std::vector<std::string>> rows;
  for (std::string line; std::getline(in, line);) {
    std::vector<std::string> cells;
    std::stringstream s(line);
    for (std::string cell; std::getline(s, cell, ',');) cells.push_back(cell);
    rows.push_back(cells);
  }
  return rows;
}

TEST(A4IkStudy, TheStudyWritesOneRowPerSolveAndOnePerUpdate) {
  const IkStudyInputs in = hw3_ik();
  const std::vector<IkStudyRun> runs = bodies::study_ik(in, tasks(), 1);
  // 5 steps, 5 epsilons, 2 steps × 6 variants, 4 hard cases × 6 variants.
  ASSERT_EQ(runs.size(), 5u + 5u + 12u + 24u);
  const std::filesystem::path dir = testing::fresh_test_folder("ik-study");
  const std::string report = bodies::write_ik_study(runs, (dir / "s").string());
  EXPECT_NE(report.find("step=0.1"), std::string::npos);
  const auto table = read_csv(dir / "s-runs.csv");
  const auto trace = read_csv(dir / "s-trace.csv");
  ASSERT_EQ(table.size(), runs.size() + 1);
  EXPECT_EQ(table[0].size(), 16u);
  EXPECT_EQ(table[0][0], "group");
  std::map<std::string, std::size_t> updates, rows;
  std::size_t expected_trace = 1;
  for (const IkStudyRun& r : runs) {
    updates[r.name] = static_cast<std::size_t>(r.updates);
    expected_trace += r.error.size();
    EXPECT_TRUE(r.finite) << r.name;
    if (r.checked) {
      EXPECT_TRUE(r.tasks_agree) << r.name;
    }
  }
  ASSERT_EQ(trace.size(), expected_trace);
  EXPECT_EQ(trace[0], (std::vector<std::string>{"name", "update", "error", "cpu_us"}));
  for (std::size_t i = 1; i < trace.size(); ++i) ++rows[trace[i].at(0)];
  for (const auto& [name, n] : updates) EXPECT_EQ(rows[name], n + 1) << name;
  EXPECT_EQ(updates["step=0.1"], 73u);
  EXPECT_EQ(updates["limits/minimum-norm"], 105u);
  for (const IkStudyRun& r : runs) {
    if (r.group != "unreachable") continue;
    EXPECT_FALSE(r.stable) << r.name;
    EXPECT_EQ(r.updates, 1000) << r.name;
    if (r.checked) {
      EXPECT_TRUE(r.restored) << r.name;
    }
  }
}

}  // namespace
}  // namespace jelly
