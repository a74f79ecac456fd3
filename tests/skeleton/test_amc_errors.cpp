// The AMC reader (kinematics contract §2, §11.8): postures as read, channel orders, absent
// bones, and every error it reports with the file, the line and what was expected.
#include <gtest/gtest.h>

#include <filesystem>

#include "skeleton_test_files.hpp"

namespace jelly::skeleton {
namespace {

using test::expect_amc_error;
using test::kAmc;
using test::kAmcEndOfFile;
using test::small_skeleton;
using test::text_of;

MotionResult parse(const std::string& text) { return parse_amc(text, "t.amc", small_skeleton()); }

TEST(AmcReader, ReadsPosturesAndLeavesAbsentBonesAtZero) {
  const MotionResult r = parse(text_of(kAmc));
  ASSERT_TRUE(r) << r.error->text();
  ASSERT_EQ(r.motion->frames.size(), 2u);
  const Posture& p = r.motion->frames[0];
  EXPECT_EQ(p.root_translation, Vec3(0.2 * 1, 0.2 * 2, 0.2 * 3));
  EXPECT_EQ(p.angles[0], Vec3(4, 5, 6));
  EXPECT_EQ(p.angles[1], Vec3(7, 8, 9));
  EXPECT_EQ(p.angles[2], Vec3::Zero());
  EXPECT_EQ(r.motion->frames[1].angles[1], Vec3::Zero());  // a is absent from frame 2
  EXPECT_EQ(r.motion->first_frame_number, 1);
  EXPECT_EQ(r.motion->fps, 120.0);
  EXPECT_TRUE(r.notes.empty());
}

TEST(AmcReader, AbsentRootHasZeroTranslationAndAngles) {
  const MotionResult r = parse(text_of(kAmc, 8, "a 1 2 3"));
  ASSERT_TRUE(r) << r.error->text();
  EXPECT_EQ(r.motion->frames[1].root_translation, Vec3::Zero());
  EXPECT_EQ(r.motion->frames[1].angles[0], Vec3::Zero());
  EXPECT_EQ(r.motion->frames[1].angles[1], Vec3(1, 2, 3));
}

TEST(AmcReader, ValuesFollowTheDofAndOrderLines) {
  std::vector<std::string> asf = test::kAsf;
  asf[9] = "order RZ TX RX TY RY TZ";
  asf[20] = "dof rz rx";
  asf[22] = "#";  // two limits for two channels
  const SkeletonResult s = parse_asf(text_of(asf), "t.asf", 0.5);
  ASSERT_TRUE(s) << s.error->text();
  const MotionResult r = parse_amc("1\nroot 1 2 3 4 5 6\na 10 20\n", "t.amc", *s.skeleton);
  ASSERT_TRUE(r) << r.error->text();
  const Posture& p = r.motion->frames[0];
  EXPECT_EQ(p.angles[0], Vec3(3, 5, 1));
  EXPECT_EQ(p.root_translation, Vec3(0.5 * 2, 0.5 * 4, 0.5 * 6));
  EXPECT_EQ(p.angles[1], Vec3(20, 0, 10));
}

TEST(AmcReader, FirstFrameNumberIsAnyInteger) {
  std::vector<std::string> lines = kAmc;
  lines[3] = "-5";
  lines[6] = "-4";
  const MotionResult r = parse(text_of(lines));
  ASSERT_TRUE(r) << r.error->text();
  EXPECT_EQ(r.motion->first_frame_number, -5);
  EXPECT_EQ(r.motion->frames.size(), 2u);
  EXPECT_TRUE(parse(text_of(kAmc, 4, "+1")));  // an optional sign
}

TEST(AmcReader, WithoutDegreesKeywordReadsDegreesAndNotesOtherKeywords) {
  std::vector<std::string> lines = kAmc;
  lines[2] = ":SAMPLES-PER-SECOND 120";
  const MotionResult r = parse(text_of(lines));
  ASSERT_TRUE(r) << r.error->text();
  EXPECT_EQ(r.motion->frames[0].angles[1], Vec3(7, 8, 9));
  ASSERT_EQ(r.notes.size(), 1u);
  EXPECT_EQ(r.notes[0].line, 3);
}

TEST(AmcErrors, Radians) {
  expect_amc_error(text_of(kAmc, 3, ":RADIANS"), 3, ":RADIANS is not supported");
}
TEST(AmcErrors, NoFrame) {
  expect_amc_error("# only a header\n:DEGREES\n\n", 4, "no frame; expected at least one");
}
TEST(AmcErrors, BoneLineBeforeFirstFrame) {
  expect_amc_error(text_of(kAmc, 4, "root 1 2 3 4 5 6"), 4, "expected a frame number");
}
TEST(AmcErrors, FrameNumberNotAnInteger) {
  expect_amc_error(text_of(kAmc, 4, "1.0"), 4, "expected a frame number");
}
TEST(AmcErrors, FrameNumbersSkip) {
  expect_amc_error(text_of(kAmc, 7, "3"), 7, "frame number 3: expected 2");
}
TEST(AmcErrors, FrameNumbersRepeat) {
  expect_amc_error(text_of(kAmc, 7, "1"), 7, "frame number 1: expected 2");
}
TEST(AmcErrors, UnknownBone) {
  expect_amc_error(text_of(kAmc, 6, "zz 7 8 9"), 6, "unknown bone 'zz'");
}
TEST(AmcErrors, BoneNamesAreCaseSensitive) {
  expect_amc_error(text_of(kAmc, 6, "A 7 8 9"), 6, "unknown bone 'A'");
}
TEST(AmcErrors, BoneTwiceInAFrame) {
  expect_amc_error(text_of(kAmc, 6, "root 1 2 3 4 5 6"), 6,
                   "'root' given twice in one frame (line 5)");
}
TEST(AmcErrors, TooFewNumbers) {
  expect_amc_error(text_of(kAmc, 6, "a 7 8"), 6, "expected 3 numbers (its channels), got 2");
}
TEST(AmcErrors, TooManyNumbers) {
  expect_amc_error(text_of(kAmc, 5, "root 1 2 3 4 5 6 7"), 5, "expected 6 numbers");
}
TEST(AmcErrors, NotANumber) {
  expect_amc_error(text_of(kAmc, 6, "a 7 8 x"), 6, "expected a finite number for rz, got 'x'");
}
TEST(AmcErrors, NanIsNotANumber) {
  expect_amc_error(text_of(kAmc, 6, "a nan 8 9"), 6, "for rx, got 'nan'");
}
TEST(AmcErrors, InfinityIsNotANumber) {
  expect_amc_error(text_of(kAmc, 6, "a 7 -inf 9"), 6, "for ry, got '-inf'");
}
TEST(AmcErrors, OverflowIsNotANumber) {
  expect_amc_error(text_of(kAmc, 5, "root 1e999 2 3 4 5 6"), 5, "for tx");
}
TEST(AmcErrors, BoneWithoutChannels) {
  expect_amc_error(text_of(kAmc, 6, "b"), 6, "'b' has no channels");
}
TEST(AmcErrors, CommentAfterFirstFrame) {
  expect_amc_error(text_of(kAmc, 6, "# late"), 6, "header lines come before");
}
TEST(AmcErrors, KeywordAfterFirstFrame) {
  expect_amc_error(text_of(kAmc, 6, ":DEGREES"), 6, "header lines come before");
}

TEST(AmcErrors, MissingFile) {
  const MotionResult r = read_amc("no/such/file.amc", small_skeleton());
  ASSERT_FALSE(r);
  EXPECT_EQ(r.error->file, std::filesystem::path("no/such/file.amc").string());
  EXPECT_NE(r.error->message.find("no such file"), std::string::npos);
}

}  // namespace
}  // namespace jelly::skeleton
