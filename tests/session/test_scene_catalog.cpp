// The one scene resolver every command uses (`jelly run/check/params/study/render`, jelly-lab):
// a scene by path or by name, and an error that names what was tried and the known names.
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include "jelly/linked_assignments.hpp"
#include "jelly/session/assignments.hpp"
#include "jelly/session/scene_catalog.hpp"

namespace jelly::session {
namespace {

namespace fs = std::filesystem;

const fs::path kScenes = fs::path(JELLY_SOURCE_DIR) / "scenes";

/// A scenes folder of its own: a.toml and sub/b.toml (two particles each, told apart by name).
class SceneCatalog : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = fs::path(JELLY_BINARY_DIR) / "artifacts" / "session" /
           ::testing::UnitTest::GetInstance()->current_test_info()->name();
    fs::remove_all(dir_);
    fs::create_directories(dir_ / "sub");
    write(dir_ / "a.toml", "alpha");
    write(dir_ / "sub" / "b.toml", "beta");
  }
  static void write(const fs::path& p, const std::string& name) {
    std::ofstream(p) << "[scene]\nname = \"" << name
                     << "\"\n[body]\ntype = \"particles\"\nmass = 1.0\n"
                     << "positions = [[0.0, 1.0, 0.0], [1.0, 1.0, 0.0]]\n";
  }
  static std::string name_of(const SceneResult& r) {
    EXPECT_TRUE(r) << (r.error ? r.error->text() : "");
    return r ? r.scene->name : "";
  }
  fs::path dir_;
};

TEST_F(SceneCatalog, FindsAFileByItsPath) {
  EXPECT_EQ(name_of(resolve_scene((dir_ / "sub" / "b.toml").string(), kScenes)), "beta");
}

TEST_F(SceneCatalog, FindsANameInTheScenesFolderWithOrWithoutToml) {
  EXPECT_EQ(name_of(resolve_scene("a", dir_)), "alpha");
  EXPECT_EQ(name_of(resolve_scene("sub/b", dir_)), "beta");
  EXPECT_EQ(name_of(resolve_scene("sub/b.toml", dir_)), "beta");
}

/// "builtin:<scene>" for each linked assignment's default scene, in the assignments' order.
std::vector<std::string> builtin_names() {
  std::vector<std::string> out;
  for (const LinkedAssignment& a : linked_assignments()) {
    const std::string& scene = manifest_of(a).default_scene;
    if (scene.empty() || a.default_scene_text.empty()) continue;
    const std::string name = "builtin:" + scene;
    if (std::find(out.begin(), out.end(), name) == out.end()) out.push_back(name);
  }
  return out;
}

TEST_F(SceneCatalog, TheDefaultSceneIsBuiltInWhereTheFolderLacksIt) {
  // The default scene is the linked assignment's manifest's default_scene (a1: course-2023).
  const std::string name = default_scene_name();
  ASSERT_FALSE(name.empty());
  EXPECT_EQ(name, manifest_of(linked_assignments().front()).default_scene);
  const SceneResult by_name = resolve_scene(name, dir_);
  ASSERT_TRUE(by_name) << by_name.error->text();
  EXPECT_NE(by_name.scene->description.find("(built in)"), std::string::npos);
  EXPECT_TRUE(resolve_scene("builtin:" + name, dir_));
  EXPECT_FALSE(resolve_scene("builtin:no-such-scene", dir_));
  // The catalogue lists the built-in copy of every linked assignment's default scene first (in
  // the order of the assignments: a1's course-2023, then a2's cloth-2024 when A2 is linked), then
  // the folder's scenes by name.
  const std::vector<std::string> builtins = builtin_names();
  ASSERT_FALSE(builtins.empty());
  EXPECT_EQ(builtins.front(), "builtin:" + name);
  const auto entries = list_scenes(dir_);
  ASSERT_EQ(entries.size(), builtins.size() + 2);
  for (std::size_t i = 0; i < builtins.size(); ++i) EXPECT_EQ(entries[i].name, builtins[i]);
  EXPECT_EQ(entries[builtins.size()].name, "a");
  EXPECT_EQ(entries[builtins.size() + 1].name, "sub/b");
}

TEST_F(SceneCatalog, TheBuiltInCopyIsTheDefaultSceneFile) {
  const std::string name = default_scene_name();
  const SceneResult file = resolve_scene(name, kScenes);
  ASSERT_TRUE(file) << file.error->text();
  EXPECT_EQ(file.scene->description.find("(built in)"), std::string::npos);
  const std::optional<SceneResult> builtin = builtin_scene(name);
  ASSERT_TRUE(builtin && *builtin);
  SceneSpec copy = *builtin->scene;
  copy.description = file.scene->description;
  copy.source = file.scene->source;
  EXPECT_EQ(to_toml(copy), to_toml(*file.scene));
  // Where the folder has the file, the catalogue lists the file and no built-in copy.
  for (const SceneEntry& e : list_scenes(kScenes)) EXPECT_NE(e.name, "builtin:" + name);
}

TEST_F(SceneCatalog, TheRepositorysScenesResolveByName) {
  const SceneResult r = resolve_scene("hard/stiff-springs", kScenes);
  ASSERT_TRUE(r) << r.error->text();
  EXPECT_EQ(r.scene->description.find("(built in)"), std::string::npos);
  EXPECT_TRUE(resolve_scene(default_scene_name(), kScenes));
}

TEST_F(SceneCatalog, AnUnknownSceneNamesWhatWasTriedAndTheKnownNames) {
  for (const std::string arg : {"nope", "nope.toml"}) {
    const SceneResult r = resolve_scene(arg, dir_);
    ASSERT_FALSE(r) << arg;
    const std::string text = r.error->text();
    EXPECT_EQ(text.rfind(arg + ": no such scene", 0), 0u) << text;
    EXPECT_NE(text.find((dir_ / "nope.toml").string()), std::string::npos) << text;
    std::string known;
    for (const std::string& b : builtin_names()) known += b + ", ";
    EXPECT_NE(text.find("known scenes: " + known + "a, sub/b"), std::string::npos) << text;
  }
}

TEST_F(SceneCatalog, AFileWithErrorsGivesTheLoadersMessageNotNoSuchScene) {
  std::ofstream(dir_ / "bad.toml") << "[body]\nn = = 3\n";
  for (const std::string& arg : {std::string("bad"), (dir_ / "bad.toml").string()}) {
    const SceneResult r = resolve_scene(arg, dir_);
    ASSERT_FALSE(r);
    EXPECT_NE(r.error->text().find((dir_ / "bad.toml").string() + ":2"), std::string::npos)
        << r.error->text();
  }
  // A folder given as the scene says so.
  const SceneResult folder = resolve_scene((dir_ / "sub").string(), dir_);
  ASSERT_FALSE(folder);
  EXPECT_NE(folder.error->text().find("is a directory"), std::string::npos) << folder.error->text();
}

// The help texts name only the scenes the build finds (a release ships only its assignments'
// scenes): the list is the folder's files, sub-folders counted, never a linked default scene that
// the folder lacks; the example is a scene of the folder.
/// scenes_line() as one line (it wraps long lists for a terminal, indenting the next lines).
std::string unwrapped(std::string s) {
  for (std::size_t at; (at = s.find("\n  ")) != std::string::npos;) s.replace(at, 3, " ");
  return s;
}

TEST_F(SceneCatalog, TheHelpLineNamesTheFolderScenesOnly) {
  write(dir_ / "sub" / "c.toml", "gamma");
  EXPECT_EQ(unwrapped(scenes_line(dir_)), "scenes in " + dir_.string() + ": a, sub/ (2 scenes)");
  EXPECT_EQ(example_scene(dir_), "a");
  const fs::path empty = dir_ / "empty";
  fs::create_directories(empty);
  EXPECT_EQ(scenes_line(empty), "no scenes in " + empty.string());
  EXPECT_EQ(example_scene(empty), default_scene_name());  // the built-in copy still runs
}

TEST_F(SceneCatalog, TheHelpExampleIsALinkedDefaultSceneWhenTheFolderHasIt) {
  const std::string name = default_scene_name();
  if (name.empty()) GTEST_SKIP() << "no linked assignment names a default scene";
  fs::copy_file(kScenes / (name + ".toml"), dir_ / (name + ".toml"));
  EXPECT_EQ(example_scene(dir_), name);  // not "a", which sorts first
  EXPECT_NE(unwrapped(scenes_line(dir_)).find(name), std::string::npos);
}

}  // namespace
}  // namespace jelly::session
