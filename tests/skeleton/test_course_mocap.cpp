// The course's motion-capture files (data/mocap/) through the skeleton module's readers: their
// counts, the quirks of IK.amc read as given, the derived data against an independent
// computation, and the kinematics contract's §8 reference numbers from a forward kinematics
// written here (the students' task: the framework has none).
#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <cmath>
#include <string>
#include <vector>

#include "jelly/skeleton/skeleton_files.hpp"

namespace jelly::skeleton {
namespace {

const std::string kMocap = std::string(JELLY_SOURCE_DIR) + "/data/mocap/";

Skeleton course_skeleton() {
  const SkeletonResult r = read_asf(kMocap + "skeleton.asf", 0.2);
  EXPECT_TRUE(r) << (r.error ? r.error->text() : "");
  return r ? *r.skeleton : Skeleton{};
}

Motion course_motion(const Skeleton& skeleton, const std::string& name) {
  const MotionResult r = read_amc(kMocap + name, skeleton);
  EXPECT_TRUE(r) << (r.error ? r.error->text() : "");
  return r ? *r.motion : Motion{};
}

// E(rx, ry, rz) = R_z·R_y·R_x from Eigen's angle-axis and the C library, independent of the
// module's rotation code.
Mat3 independent_e(const Vec3& degrees) {
  const Vec3 r = degrees * (3.14159265358979323846 / 180.0);
  return (Eigen::AngleAxisd(r.z(), Vec3::UnitZ()) * Eigen::AngleAxisd(r.y(), Vec3::UnitY()) *
          Eigen::AngleAxisd(r.x(), Vec3::UnitX()))
      .toRotationMatrix();
}

struct Segment {
  Vec3 start, end;
};

// Contract §4: R_0 = E(θ_0), s_0 = e_0 = T; R_i = R_p·C_i·E(θ_i), s_i = e_p, e_i = s_i +
// L_i·R_i·d_i.
std::vector<Segment> forward_kinematics(const Skeleton& s, const Posture& p) {
  std::vector<Segment> out(s.bones.size());
  std::vector<Mat3> rotation(s.bones.size());
  std::vector<int> stack = {0};
  while (!stack.empty()) {
    const int i = stack.back();
    stack.pop_back();
    const Bone& b = s.bones[i];
    if (b.parent < 0) {
      rotation[i] = independent_e(p.angles[i]);
      out[i] = {p.root_translation, p.root_translation};
    } else {
      rotation[i] = rotation[b.parent] * b.C * independent_e(p.angles[i]);
      out[i].start = out[b.parent].end;
      out[i].end = out[i].start + b.L * rotation[i] * b.d;
    }
    for (int c : b.children) stack.push_back(c);
  }
  return out;
}

void expect_point(const Skeleton& s, const std::vector<Segment>& fk, const std::string& bone,
                  bool end, Vec3 expected) {
  const auto i = s.find(bone);
  ASSERT_TRUE(i) << bone;
  const Vec3 got = end ? fk[*i].end : fk[*i].start;
  // The contract prints 5 decimals: within half a unit of the last digit (and rounding).
  for (int k = 0; k < 3; ++k)
    EXPECT_NEAR(got[k], expected[k], 5.01e-6) << bone << " coordinate " << k;
}

TEST(CourseMocap, SkeletonCounts) {
  const Skeleton s = course_skeleton();
  ASSERT_EQ(s.bones.size(), 31u);
  EXPECT_EQ(s.bones[0].name, "root");
  EXPECT_EQ(s.bones[1].name, "lhipjoint");
  EXPECT_EQ(s.bones[30].name, "rthumb");
  EXPECT_EQ(s.channel_count(), 6 + 56);
  EXPECT_TRUE(s.bones[*s.find("lhipjoint")].channels.empty());
  EXPECT_TRUE(s.bones[*s.find("rhipjoint")].channels.empty());
  const Bone& lfoot = s.bones[*s.find("lfoot")];
  ASSERT_EQ(lfoot.channels, (std::vector<Channel>{Channel::rx, Channel::rz}));
  ASSERT_EQ(lfoot.limits.size(), 2u);
  EXPECT_EQ(lfoot.limits[1].lo, -70.0);
  EXPECT_EQ(lfoot.limits[1].hi, 20.0);
  const std::vector<Channel> root_order = {Channel::tx, Channel::ty, Channel::tz,
                                           Channel::rx, Channel::ry, Channel::rz};
  EXPECT_EQ(s.bones[0].channels, root_order);
}

TEST(CourseMocap, HierarchyKeepsListedOrder) {
  const Skeleton s = course_skeleton();
  ASSERT_EQ(s.bones.size(), 31u);
  std::vector<std::string> root_children;
  for (int c : s.bones[0].children) root_children.push_back(s.bones[c].name);
  EXPECT_EQ(root_children, (std::vector<std::string>{"lhipjoint", "rhipjoint", "lowerback"}));
  const Bone& thorax = s.bones[*s.find("thorax")];
  std::vector<std::string> thorax_children;
  for (int c : thorax.children) thorax_children.push_back(s.bones[c].name);
  EXPECT_EQ(thorax_children, (std::vector<std::string>{"lowerneck", "lclavicle", "rclavicle"}));
  EXPECT_EQ(s.bones[*s.find("rfingers")].parent, *s.find("rhand"));
}

TEST(CourseMocap, DerivedDataMatchesAnIndependentComputation) {
  const Skeleton s = course_skeleton();
  ASSERT_EQ(s.bones.size(), 31u);
  for (std::size_t i = 0; i < s.bones.size(); ++i) {
    const Bone& b = s.bones[i];
    const Mat3 a = independent_e(b.axis);
    const Mat3 c = b.parent < 0 ? Mat3::Identity()
                                : Mat3(independent_e(s.bones[b.parent].axis).transpose() * a);
    EXPECT_LT((b.C - c).cwiseAbs().maxCoeff(), 1e-15) << b.name;
    EXPECT_LT((b.d - a.transpose() * b.direction).cwiseAbs().maxCoeff(), 1e-15) << b.name;
    EXPECT_EQ(b.L, i == 0 ? 0.0 : b.length * 0.2) << b.name;
  }
  const Bone& lfemur = s.bones[*s.find("lfemur")];
  EXPECT_EQ(lfemur.length, 7.03469);
  EXPECT_EQ(lfemur.axis, Vec3(0.0, 0.0, 20.0));
  EXPECT_EQ(lfemur.direction, Vec3(0.34202, -0.939693, 0.0));  // as written, not normalised
  // lfemur's axis turns 20° about z: its direction in its own frame is (0, −0.99999…, 0).
  EXPECT_NEAR(lfemur.d.x(), 0.0, 1e-6);
  EXPECT_NEAR(lfemur.d.y(), -1.0, 1e-6);
}

TEST(CourseMocap, MotionFrameCounts) {
  const Skeleton s = course_skeleton();
  EXPECT_EQ(course_motion(s, "walk.amc").frames.size(), 148u);
  EXPECT_EQ(course_motion(s, "punch_kick.amc").frames.size(), 450u);
  EXPECT_EQ(course_motion(s, "running.amc").frames.size(), 148u);
  EXPECT_EQ(course_motion(s, "IK.amc").frames.size(), 1u);
  EXPECT_EQ(course_motion(s, "walk.amc").first_frame_number, 1);
}

TEST(CourseMocap, IkAmcQuirksAreReadAsGiven) {
  const Skeleton s = course_skeleton();
  const Motion m = course_motion(s, "IK.amc");
  ASSERT_EQ(m.frames.size(), 1u);
  const Posture& p = m.frames[0];
  EXPECT_EQ(p.angles[*s.find("thorax")].x(), -10.4283);  // outside its limit (−10, 35)
  EXPECT_EQ(p.angles[*s.find("lthumb")].z(), -286.656);  // lthumb's dof is rx rz
  EXPECT_EQ(p.angles[*s.find("lthumb")].y(), 0.0);
  EXPECT_EQ(p.angles[*s.find("lfoot")], Vec3(3.57704, 0.0, 3.62653));
  EXPECT_EQ(p.root_translation, Vec3(0.2 * 0.590969, 0.2 * 17.2875, 0.2 * -16.0743));
  EXPECT_EQ(p.angles[0], Vec3(-1.10083, -4.485, -4.98517));
}

TEST(CourseMocap, ReferenceNumbersOfIkAmcFrame0) {
  const Skeleton s = course_skeleton();
  const Motion m = course_motion(s, "IK.amc");
  ASSERT_EQ(m.frames.size(), 1u);
  const auto fk = forward_kinematics(s, m.frames[0]);
  expect_point(s, fk, "root", false, Vec3(0.11819, 3.45750, -3.21486));
  expect_point(s, fk, "lowerback", true, Vec3(0.13451, 3.87846, -3.14020));
  expect_point(s, fk, "head", true, Vec3(0.21388, 5.61436, -2.58160));
  expect_point(s, fk, "rfingers", true, Vec3(-1.09300, 2.81041, -2.59974));
}

TEST(CourseMocap, ReferenceNumbersOfWalkAmc) {
  const Skeleton s = course_skeleton();
  const Motion m = course_motion(s, "walk.amc");
  ASSERT_EQ(m.frames.size(), 148u);
  const auto first = forward_kinematics(s, m.frames[0]);
  expect_point(s, first, "root", false, Vec3(2.57906, 3.55306, -4.64220));
  expect_point(s, first, "head", true, Vec3(2.65770, 5.79724, -4.31246));
  expect_point(s, first, "rfingers", true, Vec3(2.06460, 2.78074, -3.81936));
  const auto last = forward_kinematics(s, m.frames[147]);
  expect_point(s, last, "root", false, Vec3(2.89442, 3.54780, -0.77105));
  expect_point(s, last, "rfingers", true, Vec3(2.13008, 2.81343, 0.08133));
}

}  // namespace
}  // namespace jelly::skeleton
