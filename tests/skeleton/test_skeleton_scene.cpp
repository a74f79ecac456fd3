// The skeleton body kind's scene section (body.type = "skeleton", docs/skeleton-scenes.md): the
// kind is registered and plays frames, every key's bad value is refused naming the file, the
// line, the key and what was expected, and a scene writes back to itself.
#include <gtest/gtest.h>

#include <string>

#include "jelly/body_kind.hpp"
#include "jelly/params.hpp"
#include "jelly/scene.hpp"
#include "jelly/skeleton_scene.hpp"

namespace jelly {
namespace {

// A valid warp scene; its line numbers are the tests' (line 8 is `mode`).
const std::string kWarp = R"([scene]
name = "t"

[body]
type = "skeleton"
asf = "skeleton.asf"
amc = "punch_kick.amc"
mode = "warp"
frames = 450
keyframe_in = 160
keyframe_out = 150
)";

std::string with(const std::string& from, const std::string& to) {
  std::string s = kWarp;
  const auto at = s.find(from);
  EXPECT_NE(at, std::string::npos) << from;
  if (at != std::string::npos) s.replace(at, from.size(), to);
  return s;
}

// The scene is refused naming bad.toml, `key` (and `line` when > 0) and `expected`.
void expect_refused(const std::string& text, const std::string& key, int line,
                    const std::string& expected) {
  const SceneResult r = parse_scene(text, "bad.toml");
  ASSERT_FALSE(r) << "expected an error on " << key << " for:\n" << text;
  EXPECT_FALSE(r.scene.has_value());
  EXPECT_EQ(r.error->file, "bad.toml");
  EXPECT_EQ(r.error->key, key) << r.error->text();
  if (line > 0) {
    EXPECT_EQ(r.error->line, line) << r.error->text();
  }
  EXPECT_NE(r.error->message.find(expected), std::string::npos)
      << r.error->text() << "\n  expected: " << expected;
}

TEST(SkeletonScene, TheKindIsRegisteredAndPlaysFrames) {
  const BodyKindModule* kind = find_body_kind("skeleton");
  ASSERT_NE(kind, nullptr) << body_kind_names();
  EXPECT_TRUE(kind->plays_frames());
  EXPECT_TRUE(kind->spring_types().empty());
  for (const char* other : {"cube", "particles", "cloth"})
    if (const BodyKindModule* k = find_body_kind(other)) {
      EXPECT_FALSE(k->plays_frames()) << other;
    }
}

TEST(SkeletonScene, AWarpSceneReadsItsKeys) {
  const SceneResult r = parse_scene(kWarp, "t.toml");
  ASSERT_TRUE(r) << r.error->text();
  const SkeletonSceneSpec& k = skeleton_scene(*r.scene);
  EXPECT_EQ(k.asf, "skeleton.asf");
  EXPECT_EQ(k.amc, "punch_kick.amc");
  EXPECT_EQ(k.scale, 0.2);
  EXPECT_EQ(k.fps, 120.0);
  EXPECT_EQ(k.mode, SkeletonMode::Warp);
  EXPECT_EQ(k.frames, 450);
  EXPECT_EQ(k.keyframe_in, 160);
  EXPECT_EQ(k.keyframe_out, 150);
}

TEST(SkeletonScene, EveryKeysBadValueNamesTheFileLineKeyAndWhatWasExpected) {
  expect_refused(with("asf = \"skeleton.asf\"\n", ""), "body.asf", 0, "names its ASF file");
  expect_refused(with("amc = \"punch_kick.amc\"\n", ""), "body.amc", 0, "names its AMC file");
  expect_refused(with("mode = \"warp\"", "mode = \"warp\"\nscale = 0"), "body.scale", 9, "> 0");
  expect_refused(with("mode = \"warp\"", "mode = \"warp\"\nfps = -120"), "body.fps", 9, "> 0");
  expect_refused(with("mode = \"warp\"", "mode = \"dance\""), "body.mode", 8, "playback");
  expect_refused(with("frames = 450", "frames = 1"), "body.frames", 9, "must be ≥ 2");
  expect_refused(with("frames = 450", "frames = -3"), "body.frames", 9, "≥ 0");
  expect_refused(with("frames = 450", "frames = 4.5"), "body.frames", 9, "integer");
  expect_refused(with("keyframe_in = 160", "keyframe_in = 0"), "body.keyframe_in", 10,
                 "0 < K < frames − 1");
  expect_refused(with("keyframe_out = 150", "keyframe_out = -2"), "body.keyframe_out", 11, "≥ -1");
  expect_refused(with("keyframe_out = 150\n", ""), "body.keyframe_out", 0, "a keyframe is a pair");
  expect_refused(with("keyframe_in = 160\n", ""), "body.keyframe_in", 0, "a keyframe is a pair");
}

TEST(SkeletonScene, ABlendReadsItsKeysAndRefusesTheirBadValues) {
  const std::string blend = with(
      "mode = \"warp\"\nframes = 450\nkeyframe_in = 160\n"
      "keyframe_out = 150\n",
      "mode = \"blend\"\namc_b = \"running.amc\"\na = 127\nb = 1\n"
      "window = 20\n");
  const auto variant = [&](const std::string& from, const std::string& to) {
    std::string s = blend;
    s.replace(s.find(from), from.size(), to);
    return s;
  };
  const SceneResult ok = parse_scene(blend, "t.toml");
  ASSERT_TRUE(ok) << ok.error->text();
  EXPECT_EQ(skeleton_scene(*ok.scene).mode, SkeletonMode::Blend);
  EXPECT_EQ(skeleton_scene(*ok.scene).amc_b, "running.amc");
  EXPECT_EQ(skeleton_scene(*ok.scene).a, 127);
  EXPECT_EQ(skeleton_scene(*ok.scene).b, 1);
  EXPECT_EQ(skeleton_scene(*ok.scene).window, 20);
  expect_refused(variant("window = 20", "window = 1"), "body.window", 12, "≥ 2");
  expect_refused(variant("a = 127", "a = -1"), "body.a", 10, "≥ 0");
  expect_refused(variant("b = 1\n", "b = \"one\"\n"), "body.b", 11, "integer");
  expect_refused(variant("amc_b = \"running.amc\"\n", ""), "body.amc_b", 0,
                 "a blend names its motion B");
}

TEST(SkeletonScene, AKeyOfAnotherModeIsRefused) {
  // A playback scene with a warp's keys, a warp with a blend's.
  expect_refused(with("mode = \"warp\"", "mode = \"playback\""), "body.frames", 0,
                 "is a key of a warp (body.mode = \"warp\"); this scene's mode is \"playback\"");
  expect_refused(with("frames = 450", "frames = 450\nwindow = 10"), "body.window", 0,
                 "is a key of a blend");
}

TEST(SkeletonScene, MisspeltKeysAndTablesItHasNoneOfAreRefused) {
  expect_refused(with("frames = 450", "framez = 450"), "body.framez", 9, "frames");
  // body.frame is inverse kinematics' start frame: in a warp, a slip for frames.
  expect_refused(with("frames = 450", "frame = 450"), "body.frame", 0,
                 "(did you mean \"frames\", a warp's output frames?)");
  expect_refused(kWarp + "\n[gravity]\nacceleration = [0, -9.8, 0]\n", "gravity", 0,
                 "a skeleton scene has no [gravity]");
  expect_refused(kWarp + "\n[[terrain]]\nname = \"floor\"\ntype = \"plane\"\n", "terrain", 0,
                 "a skeleton scene has no [terrain]");
  expect_refused(kWarp + "\n[springs.structural]\nks = 1\n", "springs.structural", 0, "");
}

TEST(SkeletonScene, ACubeKeyInASkeletonSceneAndASkeletonKeyInACubeSceneAreRefused) {
  expect_refused(with("frames = 450", "frames = 450\nn = 4"), "body.n", 10, "");
  const std::string cube = "[scene]\nname = \"c\"\n\n[body]\ntype = \"cube\"\nasf = \"x.asf\"\n";
  expect_refused(cube, "body.asf", 6, "");
}

TEST(SkeletonScene, WritesBackToItself) {
  for (const std::string& text :
       {kWarp, with("keyframe_in = 160\nkeyframe_out = 150\n", ""),
        with("mode = \"warp\"\nframes = 450\nkeyframe_in = 160\nkeyframe_out = 150\n", "")}) {
    const SceneResult r = parse_scene(text, "t.toml");
    ASSERT_TRUE(r) << r.error->text();
    const std::string written = to_toml(*r.scene);
    const SceneResult again = parse_scene(written, "again.toml");
    ASSERT_TRUE(again) << again.error->text() << "\n" << written;
    EXPECT_EQ(to_toml(*again.scene), written);
    const SkeletonSceneSpec& a = skeleton_scene(*r.scene);
    const SkeletonSceneSpec& b = skeleton_scene(*again.scene);
    EXPECT_EQ(a.mode, b.mode);
    EXPECT_EQ(a.frames, b.frames);
    EXPECT_EQ(a.keyframe_in, b.keyframe_in);
    EXPECT_EQ(a.amc, b.amc);
  }
}

TEST(SkeletonScene, ParamsListTheKeysAndSetChangesThem) {
  SceneSpec s = *parse_scene(kWarp, "t.toml").scene;
  std::string keys;
  for (const ParamInfo& p : scene_parameters(s)) keys += p.key + " ";
  for (const char* key : {"body.asf", "body.amc", "body.scale", "body.fps", "body.mode",
                          "body.frames", "body.keyframe_in", "body.keyframe_out", "body.window"})
    EXPECT_NE(keys.find(std::string(key) + " "), std::string::npos) << key << " in " << keys;
  EXPECT_FALSE(set_parameter(s, "body.frames", "300").has_value());
  EXPECT_EQ(skeleton_scene(s).frames, 300);
  const auto err = set_parameter(s, "body.frames", "1");
  ASSERT_TRUE(err.has_value());
  EXPECT_NE(err->text().find("must be ≥ 2"), std::string::npos) << err->text();
}

// ----- inverse kinematics (body.mode = "ik", [[chain]]) -----

// A valid ik scene with one chain; line 13 is `start`, line 15 `target`.
const std::string kIk = R"([scene]
name = "ik"

[body]
type = "skeleton"
asf = "skeleton.asf"
amc = "IK.amc"
mode = "ik"
step = 0.2
limits = true

[[chain]]
start = "lowerback"
end = "rfingers"
target = [-0.0692501, 3.85358, -1.63441]
)";

std::string ik_with(const std::string& from, const std::string& to) {
  std::string s = kIk;
  const auto at = s.find(from);
  EXPECT_NE(at, std::string::npos) << from;
  if (at != std::string::npos) s.replace(at, from.size(), to);
  return s;
}

TEST(SkeletonScene, AnIkSceneReadsItsKeysAndChainsWithTheCoursesDefaults) {
  const SceneResult r = parse_scene(kIk, "t.toml");
  ASSERT_TRUE(r) << r.error->text();
  const SkeletonSceneSpec& k = skeleton_scene(*r.scene);
  EXPECT_EQ(k.mode, SkeletonMode::Ik);
  EXPECT_EQ(k.frame, 0);
  EXPECT_EQ(k.step, 0.2);
  EXPECT_EQ(k.epsilon, 1e-3);
  EXPECT_EQ(k.max_iterations, 1000);
  EXPECT_TRUE(k.limits);
  EXPECT_TRUE(k.restore);
  ASSERT_EQ(ik_chain_specs(*r.scene).size(), 1u);
  const IkChainSpec& c = ik_chain_specs(*r.scene)[0];
  EXPECT_EQ(c.start, "lowerback");
  EXPECT_EQ(c.end, "rfingers");
  ASSERT_TRUE(c.target.has_value());
  EXPECT_EQ(*c.target, Vec3(-0.0692501, 3.85358, -1.63441));
  EXPECT_EQ(find_body_kind("skeleton")->scene_variant(*r.scene), "ik");
}

TEST(SkeletonScene, FourChainsAndASchedule) {
  const std::string four = kIk +
                           "\n[[chain]]\nstart = \"lclavicle\"\nend = \"lfingers\"\n"
                           "target = [0.65, 3.55, -1.95]\n"
                           "\n[[chain]]\nstart = \"rhipjoint\"\nend = \"rtoes\"\n"
                           "schedule = [{ time = 0, target = [1, 2, 3] }, "
                           "{ time = 1.5, target = [4, 5, 6] }]\n";
  const SceneResult r = parse_scene(four, "t.toml");
  ASSERT_TRUE(r) << r.error->text();
  const std::vector<IkChainSpec>& c = ik_chain_specs(*r.scene);
  ASSERT_EQ(c.size(), 3u);
  EXPECT_EQ(c[1].end, "lfingers");
  EXPECT_FALSE(c[2].target.has_value());
  ASSERT_EQ(c[2].schedule.size(), 2u);
  EXPECT_EQ(c[2].schedule[1].time, 1.5);
  EXPECT_EQ(c[2].schedule[1].velocity, Vec3(4, 5, 6));
  // Written back and read again: the same scene.
  const std::string written = to_toml(*r.scene);
  const SceneResult again = parse_scene(written, "again.toml");
  ASSERT_TRUE(again) << again.error->text() << "\n" << written;
  EXPECT_EQ(to_toml(*again.scene), written);
  EXPECT_NE(written.find("{ time = 1.5, target = [4.0, 5.0, 6.0] },"), std::string::npos)
      << written;
}

TEST(SkeletonScene, AnIkScenesBadKeysAndChainsAreRefused) {
  expect_refused(ik_with("step = 0.2", "step = 0"), "body.step", 9, "> 0");
  expect_refused(ik_with("step = 0.2", "max_iterations = -1"), "body.max_iterations", 9, "≥ 0");
  expect_refused(ik_with("step = 0.2", "frame = -2"), "body.frame", 9, "≥ 0");
  expect_refused(ik_with("limits = true", "limits = 1"), "body.limits", 10, "true or false");
  expect_refused(ik_with("[[chain]]\nstart = \"lowerback\"\nend = \"rfingers\"\n"
                         "target = [-0.0692501, 3.85358, -1.63441]\n",
                         ""),
                 "chain", 0, "solves at least one chain");
  expect_refused(ik_with("start = \"lowerback\"\n", ""), "chain.0.start", 0,
                 "names its start bone");
  expect_refused(ik_with("target = [-0.0692501, 3.85358, -1.63441]\n", ""), "chain.0.target", 0,
                 "needs a target");
  expect_refused(ik_with("target = [-0.0692501, 3.85358, -1.63441]",
                         "target = [1, 2, 3]\nschedule = [{ time = 0, target = [1, 2, 3] }]"),
                 "chain.0.target", 15,
                 "unknown key \"target\" for a chain; expected one of: start, end, schedule");
  expect_refused(ik_with("target = [-0.0692501, 3.85358, -1.63441]",
                         "schedule = [{ time = 0, velocity = [1, 2, 3] }]"),
                 "chain.0.schedule", 15, "unknown key \"velocity\"");
  expect_refused(ik_with("target = [-0.0692501, 3.85358, -1.63441]",
                         "schedule = [{ time = 1, target = [1, 2, 3] }, "
                         "{ time = 1, target = [1, 2, 3] }]"),
                 "chain.0.schedule", 15, "times must increase strictly");
  expect_refused(ik_with("target = [-0.0692501, 3.85358, -1.63441]", "schedule = [{ time = 1 }]"),
                 "chain.0.schedule", 15,
                 "needs both time (s) and target [x, y, z]; target is missing");
}

TEST(SkeletonScene, IkKeysAndChainsInAnotherModeAreRefused) {
  expect_refused(with("frames = 450", "frames = 450\nstep = 0.5"), "body.step", 0,
                 "is a key of inverse kinematics (body.mode = \"ik\"); this scene's mode is "
                 "\"warp\"");
  expect_refused(kWarp + "\n[[chain]]\nstart = \"a\"\nend = \"b\"\ntarget = [0, 0, 0]\n", "chain",
                 0, "[[chain]] is a chain of inverse kinematics");
  const std::string cube =
      "[scene]\nname = \"c\"\n\n[body]\ntype = \"cube\"\n\n[[chain]]\nstart = \"a\"\n";
  expect_refused(cube, "chain", 0, "[[chain]] belongs to skeleton scenes of inverse kinematics");
}

}  // namespace
}  // namespace jelly
