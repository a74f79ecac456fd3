// The ASF reader (kinematics contract §1, §11.1–§11.7): what it accepts, what it derives, and
// every error it reports, each with the file, the line and what was expected. Each error test
// changes one line of a valid file (skeleton_test_files.hpp).
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

#include "jelly/skeleton/rotation.hpp"
#include "skeleton_test_files.hpp"

namespace jelly::skeleton {
namespace {

using test::expect_asf_error;
using test::kAsf;
using test::kAsfEndOfFile;
using test::text_of;

SkeletonResult parse(const std::string& text) { return parse_asf(text, "t.asf", 0.2); }

TEST(AsfReader, ReadsTheSmallSkeleton) {
  const SkeletonResult r = parse(text_of(kAsf));
  ASSERT_TRUE(r) << r.error->text();
  const Skeleton& s = *r.skeleton;
  ASSERT_EQ(s.bones.size(), 3u);
  EXPECT_EQ(s.bones[0].name, "root");
  EXPECT_EQ(s.bones[0].parent, -1);
  EXPECT_EQ(s.bones[0].children, std::vector<int>{1});
  EXPECT_EQ(s.bones[1].parent, 0);
  EXPECT_EQ(s.bones[1].children, std::vector<int>{2});
  EXPECT_EQ(s.bones[2].parent, 1);
  EXPECT_EQ(s.bones[1].channels, (std::vector<Channel>{Channel::rx, Channel::ry, Channel::rz}));
  ASSERT_EQ(s.bones[1].limits.size(), 3u);
  EXPECT_EQ(s.bones[1].limits[2].lo, -30.0);
  EXPECT_TRUE(s.bones[2].channels.empty());
  EXPECT_TRUE(r.notes.empty());
  EXPECT_EQ(s.scale, 0.2);
}

TEST(AsfReader, DerivesCdAndL) {
  const Skeleton s = *parse(text_of(kAsf)).skeleton;
  // a: axis 10° about z, parent root (A = I): C_a = R_z(10), d_a = R_z(10)ᵀ·(0, 1, 0).
  EXPECT_LT((s.bones[1].C - rotation_z(10.0)).cwiseAbs().maxCoeff(), 1e-16);
  EXPECT_LT((s.bones[1].d - rotation_z(10.0).transpose() * Vec3(0, 1, 0)).cwiseAbs().maxCoeff(),
            1e-16);
  EXPECT_EQ(s.bones[1].L, 2.0 * 0.2);
  // b: axis 0, parent a: C_b = R_z(10)ᵀ, d_b = (1, 0, 0).
  EXPECT_LT((s.bones[2].C - rotation_z(10.0).transpose()).cwiseAbs().maxCoeff(), 1e-16);
  EXPECT_EQ(s.bones[2].d, Vec3(1, 0, 0));
  EXPECT_EQ(s.bones[0].C, Mat3::Identity());
  EXPECT_EQ(s.bones[0].L, 0.0);
  const Skeleton twice = *parse_asf(text_of(kAsf), "t.asf", 0.4).skeleton;
  EXPECT_EQ(twice.bones[1].L, 2.0 * 0.4);
}

TEST(AsfReader, DirectionIsUsedAsWritten) {
  const Skeleton s = *parse(text_of(kAsf, 29, "direction 2 0 0")).skeleton;
  EXPECT_EQ(s.bones[2].direction, Vec3(2, 0, 0));
  EXPECT_EQ(s.bones[2].d, Vec3(2, 0, 0));
}

TEST(AsfReader, CaseCommentsCrlfAndOptionalRootKeys) {
  std::vector<std::string> lines = kAsf;
  lines[8] = ":ROOT";
  lines[9] = "ORDER rx ry rz tx ty tz";
  lines[10] = "# axis is optional";
  lines[11] = "POSITION 0.0 -0 0e5";  // zeros compared as numbers
  lines[12] = "#";
  lines[14] = "BEGIN";
  lines[20] = "DOF Rz rX";
  lines[21] = "LIMITS (-30 30) (-10 10)";  // two whole pairs on one line
  lines[22] = "  # a comment inside a block";
  lines[23] = "";
  lines[24] = "END";
  lines[30] = "axis 0 0 0 xyz";
  std::string text;
  for (const std::string& l : lines) text += l + "\r\n";
  const SkeletonResult r = parse(text);
  ASSERT_TRUE(r) << r.error->text();
  const Skeleton& s = *r.skeleton;
  EXPECT_EQ(s.bones[0].channels, (std::vector<Channel>{Channel::rx, Channel::ry, Channel::rz,
                                                       Channel::tx, Channel::ty, Channel::tz}));
  EXPECT_EQ(s.bones[1].channels, (std::vector<Channel>{Channel::rz, Channel::rx}));
  ASSERT_EQ(s.bones[1].limits.size(), 2u);
  EXPECT_EQ(s.bones[1].limits[1].hi, 10.0);
}

TEST(AsfReader, LimitsMayComeBeforeDof) {
  std::vector<std::string> lines = kAsf;
  lines[20] = "limits (-10 10)";
  lines[21] = "(-20 20)";
  lines[22] = "(-30 30)";
  lines[23] = "dof rx ry rz";
  const SkeletonResult r = parse(text_of(lines));
  ASSERT_TRUE(r) << r.error->text();
  EXPECT_EQ(r.skeleton->bones[1].limits.size(), 3u);
}

TEST(AsfReader, NotesUnknownSectionsAndKeys) {
  std::vector<std::string> lines = kAsf;
  lines[4] = "  furlongs 3";    // in :units
  lines[6] = ":weird section";  // skipped with its next line
  lines[7] = "cofmass 1";
  lines[12] = "colour red";  // in :root
  const SkeletonResult r = parse(text_of(lines));
  ASSERT_TRUE(r) << r.error->text();
  ASSERT_EQ(r.notes.size(), 3u);
  EXPECT_EQ(r.notes[0].line, 5);
  EXPECT_NE(r.notes[0].message.find("furlongs"), std::string::npos);
  EXPECT_EQ(r.notes[1].line, 7);
  EXPECT_NE(r.notes[1].message.find("unknown section"), std::string::npos);
  EXPECT_EQ(r.notes[2].line, 13);
  EXPECT_NE(r.notes[2].message.find("colour"), std::string::npos);
}

TEST(AsfReader, NotesAnUnknownKeyOfABoneBlock) {
  std::vector<std::string> lines = kAsf;
  lines.insert(lines.begin() + 31, "bodymass 3.5");  // line 32, before b's `end`
  const SkeletonResult r = parse(text_of(lines));
  ASSERT_TRUE(r) << r.error->text();
  ASSERT_EQ(r.notes.size(), 1u);
  EXPECT_EQ(r.notes[0].line, 32);
  EXPECT_NE(r.notes[0].message.find("bone 'b': unknown key 'bodymass'"), std::string::npos);
}

TEST(AsfReader, AParentOnTwoLinesAppendsItsChildren) {
  const SkeletonResult r = parse(text_of(kAsf, 36, "root b"));
  ASSERT_TRUE(r) << r.error->text();
  EXPECT_EQ(r.skeleton->bones[0].children, (std::vector<int>{1, 2}));
  EXPECT_EQ(r.skeleton->bones[2].parent, 0);
}

TEST(AsfReader, AFileOnDiskIsNamedByItsPathInErrors) {
  const std::filesystem::path path =
      std::filesystem::temp_directory_path() / "jelly_skeleton_test_bad.asf";
  {
    std::ofstream out(path, std::ios::binary);
    out << text_of(kAsf, 19, "length -2");
  }
  const SkeletonResult r = read_asf(path, 0.2);
  std::filesystem::remove(path);
  test::expect_error(r, path.string(), 19, "length: expected one number ≥ 0");
}

// ---- Sections
// ------------------------------------------------------------------------------------

TEST(AsfErrors, TextBeforeASection) {
  expect_asf_error(text_of(kAsf, 1, "hello"), 1, "expected a section line");
}
TEST(AsfErrors, SectionGivenTwice) {
  expect_asf_error(text_of(kAsf, 8, ":name again"), 8, ":name given twice");
}
TEST(AsfErrors, AngleInRadians) {
  expect_asf_error(text_of(kAsf, 6, "angle rad"), 6, "'rad' is not supported");
}
TEST(AsfErrors, AngleUnitUnknown) {
  expect_asf_error(text_of(kAsf, 6, "angle grad"), 6, "expected 'angle deg'");
}

TEST(AsfErrors, NoRoot) {
  std::vector<std::string> lines = kAsf;
  for (int i = 8; i < 13; ++i) lines[i] = "#";
  expect_asf_error(text_of(lines), kAsfEndOfFile, "no :root section");
}

// ---- :root
// ----------------------------------------------------------------------------------------

TEST(AsfErrors, RootWithoutOrder) {
  expect_asf_error(text_of(kAsf, 10, "#"), 9, ":root has no 'order'");
}
TEST(AsfErrors, RootOrderMissingAChannel) {
  expect_asf_error(text_of(kAsf, 10, "order TX TY TZ RX RY"), 10, "six channels TX TY TZ RX RY RZ");
}
TEST(AsfErrors, RootOrderRepeatsAChannel) {
  expect_asf_error(text_of(kAsf, 10, "order TX TX TY TZ RX RY"), 10, "each once");
}
TEST(AsfErrors, RootAxisNotXyz) {
  expect_asf_error(text_of(kAsf, 11, "axis ZYX"), 11, "axis must be XYZ");
}
TEST(AsfErrors, RootPositionNotZero) {
  expect_asf_error(text_of(kAsf, 12, "position 0 0 1"), 12, "position must be 0 0 0");
}
TEST(AsfErrors, RootOrientationNotThreeNumbers) {
  expect_asf_error(text_of(kAsf, 13, "orientation 0 0"), 13, "orientation must be 0 0 0");
}
TEST(AsfErrors, RootKeyTwice) {
  expect_asf_error(text_of(kAsf, 11, "order TX TY TZ RX RY RZ"), 11, "order given twice");
}

// ---- :bonedata
// ------------------------------------------------------------------------------------

TEST(AsfErrors, BoneDataWithoutBegin) {
  expect_asf_error(text_of(kAsf, 15, "start"), 15, "expected 'begin'");
}
TEST(AsfErrors, IdNotItsPosition) {
  expect_asf_error(text_of(kAsf, 16, "id 2"), 16, "id: expected 1");
}
TEST(AsfErrors, IdNotANumber) {
  expect_asf_error(text_of(kAsf, 27, "id two"), 27, "id: expected 2");
}
TEST(AsfErrors, NameRoot) {
  expect_asf_error(text_of(kAsf, 17, "name root"), 17, "'root' is the root's name");
}
TEST(AsfErrors, NameTwice) {
  expect_asf_error(text_of(kAsf, 28, "name a"), 28, "'a' is already a bone's name");
}
TEST(AsfErrors, NameWithTwoWords) {
  expect_asf_error(text_of(kAsf, 28, "name b c"), 28, "expected one name");
}
TEST(AsfErrors, DirectionZero) {
  expect_asf_error(text_of(kAsf, 18, "direction 0 0 0"), 18, "non-zero");
}
TEST(AsfErrors, DirectionTwoNumbers) {
  expect_asf_error(text_of(kAsf, 18, "direction 0 1"), 18, "direction: expected three numbers");
}
TEST(AsfErrors, LengthNegative) {
  expect_asf_error(text_of(kAsf, 19, "length -1"), 19, "length: expected one number ≥ 0");
}
TEST(AsfErrors, LengthInfinite) {
  expect_asf_error(text_of(kAsf, 19, "length 1e999"), 19, "length: expected one number");
}
TEST(AsfErrors, LengthNan) {
  expect_asf_error(text_of(kAsf, 19, "length nan"), 19, "length: expected one number");
}
TEST(AsfErrors, LengthHexadecimal) {
  expect_asf_error(text_of(kAsf, 19, "length 0x10"), 19, "length: expected one number");
}
TEST(AsfErrors, AxisOrderNotXyz) {
  expect_asf_error(text_of(kAsf, 20, "axis 0 0 10 ZYX"), 20, "'ZYX' is not supported");
}
TEST(AsfErrors, AxisWithoutOrder) {
  expect_asf_error(text_of(kAsf, 20, "axis 0 0 10"), 20, "expected 'axis ax ay az XYZ'");
}
TEST(AsfErrors, DofTranslation) {
  expect_asf_error(text_of(kAsf, 21, "dof rx tx"), 21, "'tx' is not supported");
}
TEST(AsfErrors, DofLength) {
  expect_asf_error(text_of(kAsf, 21, "dof l"), 21, "'l' is not supported");
}
TEST(AsfErrors, DofUnknown) {
  expect_asf_error(text_of(kAsf, 21, "dof rx qq"), 21, "expected rx, ry or rz, got 'qq'");
}
TEST(AsfErrors, DofTwice) {
  expect_asf_error(text_of(kAsf, 21, "dof rx ry rx"), 21, "'rx' given twice");
}
TEST(AsfErrors, DofEmpty) {
  expect_asf_error(text_of(kAsf, 21, "dof"), 21, "expected one to three of rx ry rz");
}
TEST(AsfErrors, LimitsWithoutDof) {
  expect_asf_error(text_of(kAsf, 21, "#"), 22, "limits without dof");
}
TEST(AsfErrors, LimitsCountDiffers) {
  expect_asf_error(text_of(kAsf, 24, "#"), 22, "2 limits for 3 dof channels");
}
TEST(AsfErrors, LimitLoAboveHi) { expect_asf_error(text_of(kAsf, 23, "(20 -20)"), 23, "lo ≤ hi"); }
TEST(AsfErrors, LimitPairSplit) {
  expect_asf_error(text_of(kAsf, 22, "limits (-10"), 22, "'(lo hi)' pairs");
}
TEST(AsfErrors, LimitNotANumber) {
  expect_asf_error(text_of(kAsf, 23, "(-inf 20)"), 23, "'(lo hi)' pairs");
}
TEST(AsfErrors, StrayLimitLine) {
  expect_asf_error(text_of(kAsf, 27, "(1 2)"), 27, "must follow 'limits'");
}
TEST(AsfErrors, BoneKeyTwice) {
  expect_asf_error(text_of(kAsf, 19, "direction 0 1 0"), 19, "direction given twice");
}
TEST(AsfErrors, BoneWithoutLength) {
  expect_asf_error(text_of(kAsf, 19, "#"), 25, "bone 'a' has no 'length'");
}
TEST(AsfErrors, BoneWithoutId) { expect_asf_error(text_of(kAsf, 16, "#"), 25, "has no 'id'"); }
TEST(AsfErrors, BoneWithoutName) {
  expect_asf_error(text_of(kAsf, 28, "#"), 32, "bone block has no 'name'");
}
TEST(AsfErrors, BoneWithoutDirection) {
  expect_asf_error(text_of(kAsf, 29, "#"), 32, "has no 'direction'");
}
TEST(AsfErrors, BoneWithoutAxis) { expect_asf_error(text_of(kAsf, 31, "#"), 32, "has no 'axis'"); }
TEST(AsfErrors, BoneWithoutEnd) {
  expect_asf_error(text_of(kAsf, 32, "#"), 33, "bone block of line 26 has no 'end'");
}

// ---- :hierarchy
// -----------------------------------------------------------------------------------

TEST(AsfErrors, HierarchyUnknownBone) {
  expect_asf_error(text_of(kAsf, 36, "a zz"), 36, "unknown bone 'zz'");
}
TEST(AsfErrors, HierarchyNamesAreCaseSensitive) {
  expect_asf_error(text_of(kAsf, 36, "A b"), 36, "unknown bone 'A'");
}
TEST(AsfErrors, HierarchyParentWithoutChildren) {
  expect_asf_error(text_of(kAsf, 36, "a"), 36, "has no children");
}
TEST(AsfErrors, HierarchyRootAsChild) {
  expect_asf_error(text_of(kAsf, 36, "a b root"), 36, "root cannot be a child");
}
TEST(AsfErrors, HierarchyTwoParents) {
  expect_asf_error(text_of(kAsf, 35, "root a b"), 36,
                   "'b' is already the child of 'root' (line 35)");
}
TEST(AsfErrors, HierarchyMissingBone) {
  expect_asf_error(text_of(kAsf, 36, "#"), 37, "bone 'b' is missing from it");
}
TEST(AsfErrors, HierarchyCycle) {
  std::vector<std::string> lines = kAsf;
  lines[34] = "a b";
  lines[35] = "b a";
  expect_asf_error(text_of(lines), 36, "bone 'a' does not lead up to root");
}
TEST(AsfErrors, NoHierarchy) {
  std::vector<std::string> lines = kAsf;
  for (int i = 32; i < 37; ++i) lines[i] = "#";
  expect_asf_error(text_of(lines), kAsfEndOfFile, "bone 'a' is missing from it");
}
TEST(AsfErrors, HierarchyWithoutBegin) {
  expect_asf_error(text_of(kAsf, 34, "#"), 35, "expected 'begin'");
}
TEST(AsfErrors, HierarchyWithoutEnd) {
  expect_asf_error(text_of(kAsf, 37, "#"), kAsfEndOfFile, "has no 'end'");
}
TEST(AsfErrors, TextAfterHierarchyEnd) {
  expect_asf_error(text_of(kAsf) + "root a\n", kAsfEndOfFile, "expected a section after 'end'");
}

// ---- Files and arguments
// --------------------------------------------------------------------------

TEST(AsfErrors, MissingFile) {
  const SkeletonResult r = read_asf("no/such/file.asf", 0.2);
  ASSERT_FALSE(r);
  EXPECT_EQ(r.error->file, std::filesystem::path("no/such/file.asf").string());
  EXPECT_NE(r.error->message.find("no such file"), std::string::npos);
}

TEST(AsfErrors, ScaleNotPositive) {
  const SkeletonResult r = parse_asf(text_of(kAsf), "t.asf", 0.0);
  ASSERT_FALSE(r);
  EXPECT_NE(r.error->message.find("scale"), std::string::npos);
}

}  // namespace
}  // namespace jelly::skeleton
