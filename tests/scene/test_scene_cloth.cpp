// Cloth scenes (assignment A2, cloth contract §6): body.type = "cloth", [collision] and
// [[sphere]] are read, validated with file:line:key messages, set with --set keys
// (body.air_drag, collision.friction, sphere.<i>.radius) and written back to the same scene;
// cube scenes are untouched by any of it.
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <string>
#include <vector>

#include "jelly/cloth_scene.hpp"
#include "jelly/params.hpp"
#include "jelly/scene.hpp"
#include "scene_compare.hpp"

namespace jelly {
namespace {

const std::filesystem::path kScenes = std::filesystem::path(JELLY_SOURCE_DIR) / "scenes";

SceneSpec load_ok(const std::string& file) {
  const SceneResult r = load_scene(kScenes / file);
  EXPECT_TRUE(r) << (r.error ? r.error->text() : std::string());
  return r ? *r.scene : SceneSpec{};
}

/// A small valid cloth scene; tests replace lines to break it. Line numbers matter below.
const std::string kCloth = R"([scene]
name = "c"

[simulation]
integrator = "rk4"
dt = 1e-4
duration = 1.0

[gravity]
acceleration = [0, -9.8, 0]

[body]
type = "cloth"
n = 5
size = 2.0
pins = ["corners"]
air_drag = 3.4e-4

[springs.structural]
ks = 20000

[collision]
tolerance = 0.02

[[sphere]]
center = [0, -1, 0]
radius = 0.5

[[sphere]]
kinematic = true
center = [1, -1, 0]
radius = 0.25
schedule = [
  { time = 0.0, velocity = [0, 0, 0] },
  { time = 0.5, velocity = [1, 0, 0] },
]
)";

std::string with(const std::string& base, const std::string& from, const std::string& to) {
  std::string s = base;
  const auto at = s.find(from);
  EXPECT_NE(at, std::string::npos) << from;
  if (at != std::string::npos) s.replace(at, from.size(), to);
  return s;
}

SceneError error_of(const std::string& text) {
  const SceneResult r = parse_scene(text, "cloth.toml");
  EXPECT_FALSE(r) << "expected an error for:\n" << text;
  return r.error ? *r.error : SceneError{};
}

bool contains(const std::string& s, const std::string& part) {
  return s.find(part) != std::string::npos;
}

TEST(SceneCloth, TheBaseClothSceneReadsAsWritten) {
  const SceneResult r = parse_scene(kCloth, "cloth.toml");
  ASSERT_TRUE(r) << r.error->text();
  const SceneSpec& s = *r.scene;
  EXPECT_EQ(s.body_kind, kClothKind);
  EXPECT_EQ(cloth_spec(s).n, 5);
  EXPECT_EQ(cloth_spec(s).size, 2.0);
  EXPECT_EQ(cloth_spec(s).pin_sets, std::vector<std::string>{"corners"});
  EXPECT_TRUE(cloth_spec(s).pins.empty());
  EXPECT_EQ(cloth_spec(s).air_drag, 3.4e-4);
  // A cloth's spring table without kd takes decision 10's default (750), not A1's 60.
  EXPECT_TRUE(s.structural.enabled);
  EXPECT_EQ(s.structural.ks, 20000.0);
  EXPECT_EQ(s.structural.kd, 750.0);
  EXPECT_FALSE(s.shear.enabled);
  EXPECT_EQ(cloth_collisions(s).tolerance, 0.02);
  EXPECT_EQ(cloth_collisions(s).sphere_restitution, 0.8);  // decision 10 defaults
  EXPECT_EQ(cloth_collisions(s).cloth_restitution, 0.0);
  ASSERT_EQ(sphere_specs(s).size(), 2u);
  EXPECT_FALSE(sphere_specs(s)[0].kinematic);
  EXPECT_FALSE(sphere_specs(s)[0].mass.has_value());
  EXPECT_EQ(*get_parameter(s, "sphere.0.mass"), "125");  // 1000·r³ when not given
  EXPECT_TRUE(sphere_specs(s)[1].kinematic);
  ASSERT_EQ(sphere_specs(s)[1].schedule.size(), 2u);
  EXPECT_EQ(sphere_specs(s)[1].schedule[1].time, 0.5);
  EXPECT_EQ(sphere_specs(s)[1].schedule[1].velocity, Vec3(1, 0, 0));
  EXPECT_TRUE(s.terrains.empty());
}

TEST(SceneCloth, TheCourseScenesHaveTheContractNumbers) {
  const SceneSpec a = load_ok("cloth-2022.toml");
  EXPECT_EQ(cloth_spec(a).n, 25);
  EXPECT_EQ(cloth_spec(a).size, 4.0);
  EXPECT_EQ(cloth_spec(a).center, Vec3(0, 0, 0));
  EXPECT_EQ(cloth_spec(a).air_drag, 3.4e-4);
  EXPECT_EQ(a.structural.ks, 25000.0);
  EXPECT_EQ(a.bending.kd, 750.0);
  ASSERT_EQ(sphere_specs(a).size(), 4u);
  // x-major, then z (cloth contract §6).
  const std::vector<Vec3> centres = {
      {-0.75, 1, -0.75}, {-0.75, 1, 0.75}, {0.75, 1, -0.75}, {0.75, 1, 0.75}};
  for (std::size_t i = 0; i < 4; ++i) {
    EXPECT_EQ(sphere_specs(a)[i].center, centres[i]);
    EXPECT_EQ(sphere_specs(a)[i].radius, 0.5);
    EXPECT_FALSE(sphere_specs(a)[i].kinematic);
  }
  EXPECT_EQ(cloth_collisions(a).sphere_restitution, 0.8);

  const SceneSpec b = load_ok("cloth-2024.toml");
  EXPECT_EQ(cloth_spec(b).center, Vec3(0, 1, 0));
  EXPECT_EQ(b.shear.ks, 20000.0);
  ASSERT_EQ(sphere_specs(b).size(), 1u);
  EXPECT_TRUE(sphere_specs(b)[0].kinematic);
  EXPECT_EQ(sphere_specs(b)[0].radius, 1.0);
  ASSERT_EQ(sphere_specs(b)[0].schedule.size(), 4u);
  EXPECT_EQ(sphere_specs(b)[0].schedule[2].time, 1.0);
  EXPECT_EQ(sphere_specs(b)[0].schedule[2].velocity, Vec3(-2, 0, 0));

  EXPECT_EQ(cloth_spec(load_ok("cloth-curtain.toml")).pin_sets, std::vector<std::string>{"edge"});
  EXPECT_EQ(cloth_spec(load_ok("cloth-flag.toml")).rotation_axis, Vec3(0, 0, 1));
}

TEST(SceneCloth, ParamsListTheClothKeysAndNoCubeKeys) {
  const SceneSpec s = load_ok("cloth-2024.toml");
  std::vector<std::string> keys;
  for (const ParamInfo& p : scene_parameters(s)) keys.push_back(p.key);
  const auto has = [&](const std::string& k) {
    return std::find(keys.begin(), keys.end(), k) != keys.end();
  };
  for (const char* k :
       {"body.n", "body.size", "body.pins", "body.pin_points", "body.air_drag",
        "collision.cloth_restitution", "collision.sphere_restitution", "collision.tolerance",
        "collision.friction", "collision.push_out", "sphere.0.center", "sphere.0.radius",
        "sphere.0.kinematic", "sphere.0.schedule", "springs.bending.ks"})
    EXPECT_TRUE(has(k)) << k;
  // A cube's keys, a dynamic sphere's keys on a kinematic sphere, body diagonals: not here.
  for (const char* k : {"body.edge", "sphere.0.velocity", "sphere.0.mass", "sphere.1.center",
                        "springs.shear_body.enabled", "terrain.floor.epsilon"})
    EXPECT_FALSE(has(k)) << k;
}

TEST(SceneCloth, ACubeSceneHasNoClothKeys) {
  const SceneSpec s = load_ok("course-2023.toml");
  for (const ParamInfo& p : scene_parameters(s)) {
    EXPECT_NE(p.key.rfind("collision.", 0), 0u) << p.key;
    EXPECT_NE(p.key.rfind("sphere.", 0), 0u) << p.key;
    EXPECT_NE(p.key, "body.air_drag");
  }
  const std::string text = to_toml(s);
  EXPECT_FALSE(contains(text, "[collision]"));
  EXPECT_FALSE(contains(text, "[[sphere]]"));
  const auto err = set_parameter(*const_cast<SceneSpec*>(&s), "collision.friction", "0.5");
  ASSERT_TRUE(err);
  EXPECT_TRUE(contains(err->message, "collision.friction is a key of cloth scenes")) << err->text();
}

TEST(SceneCloth, SetKeysOfAClothScene) {
  SceneSpec s = load_ok("cloth-2022.toml");
  EXPECT_EQ(set_parameter(s, "body.air_drag", "0.01"), std::nullopt);
  EXPECT_EQ(cloth_spec(s).air_drag, 0.01);
  EXPECT_EQ(set_parameter(s, "collision.friction", "0.4"), std::nullopt);
  EXPECT_EQ(cloth_collisions(s).friction, 0.4);
  EXPECT_EQ(set_parameter(s, "collision.push_out", "1"), std::nullopt);
  EXPECT_EQ(cloth_collisions(s).push_out, 1.0);
  EXPECT_EQ(set_parameter(s, "sphere.2.radius", "0.25"), std::nullopt);
  EXPECT_EQ(sphere_specs(s)[2].radius, 0.25);
  EXPECT_EQ(*get_parameter(s, "sphere.2.mass"), "15.625");  // follows the radius when not given
  EXPECT_EQ(set_parameter(s, "sphere.2.mass", "10"), std::nullopt);
  EXPECT_EQ(*sphere_specs(s)[2].mass, 10.0);
  EXPECT_EQ(set_parameter(s, "sphere.0.velocity", "0,-1,0"), std::nullopt);
  EXPECT_EQ(sphere_specs(s)[0].velocity, Vec3(0, -1, 0));
  EXPECT_EQ(set_parameter(s, "body.pins", "corners,edge"), std::nullopt);
  EXPECT_EQ(cloth_spec(s).pin_sets, (std::vector<std::string>{"corners", "edge"}));
  EXPECT_EQ(set_parameter(s, "body.pins", ""), std::nullopt);
  EXPECT_TRUE(cloth_spec(s).pin_sets.empty());
  EXPECT_EQ(set_parameter(s, "body.pin_points", "0,12; 24,12"), std::nullopt);
  EXPECT_EQ(cloth_spec(s).pins, (std::vector<GridCoord>{{0, 12}, {24, 12}}));
  EXPECT_EQ(set_parameter(s, "sphere.1.kinematic", "true"), std::nullopt);
  EXPECT_EQ(set_parameter(s, "sphere.1.schedule", "0: 0,0,0; 1.5: 1,0,0"), std::nullopt);
  ASSERT_EQ(sphere_specs(s)[1].schedule.size(), 2u);
  EXPECT_EQ(sphere_specs(s)[1].schedule[1].time, 1.5);
  EXPECT_EQ(*get_parameter(s, "sphere.1.schedule"), "0: 0,0,0; 1.5: 1,0,0");

  // What --set refuses, with what was expected.
  const auto message = [&](const char* key, const char* value) {
    const auto e = set_parameter(s, key, value);
    EXPECT_TRUE(e) << key << "=" << value;
    return e ? e->key + ": " + e->message : std::string();
  };
  EXPECT_TRUE(contains(message("collision.push_out", "1.5"), "≤ 1"));
  EXPECT_TRUE(contains(message("body.pins", "corner"), "did you mean \"corners\""));
  EXPECT_TRUE(contains(message("body.pin_points", "25,0"), "outside the 25×25 grid"));
  EXPECT_TRUE(contains(message("sphere.1.schedule", "1: 0,0,0; 0.5: 1,0,0"), "increase strictly"));
  EXPECT_TRUE(contains(message("sphere.1.velocity", "1,0,0"), "sphere 1 is kinematic"));
  EXPECT_TRUE(contains(message("sphere.0.schedule", "0: 1,0,0"), "sphere 0 is dynamic"));
  EXPECT_TRUE(contains(message("sphere.4.radius", "1"), "not a parameter"));
  EXPECT_TRUE(contains(message("body.edge", "1"), "this scene's body is a cloth"));
  EXPECT_TRUE(contains(message("body.air_dreg", "1"), "did you mean \"body.air_drag\""));
  // Shrinking the grid under a listed pin is caught by the whole-scene check.
  EXPECT_TRUE(contains(message("body.n", "10"), "pin 0 at (0, 12) is outside the 10×10 grid"));
}

TEST(SceneCloth, EveryClothSceneAndAnEditedOneRoundTrip) {
  SceneSpec s = load_ok("cloth-2022.toml");
  for (auto [key, value] : std::vector<std::pair<const char*, const char*>>{
           {"body.pins", "edge"},
           {"body.pin_points", "3,4; 0,0"},
           {"body.rotation_degrees", "30"},
           {"body.velocity", "0.1,0,0"},
           {"collision.friction", "0.3"},
           {"collision.push_out", "0.5"},
           {"sphere.0.mass", "0.1"},
           {"sphere.3.kinematic", "true"},
           {"sphere.3.schedule", "0: 0,0,0; 0.25: 0,1e-7,2"},
           {"springs.shear.enabled", "false"}}) {
    ASSERT_EQ(set_parameter(s, key, value), std::nullopt) << key;
  }
  const std::string text = to_toml(s);
  const SceneResult again = parse_scene(text, "round-trip");
  ASSERT_TRUE(again) << again.error->text() << "\n" << text;
  EXPECT_EQ(testing::scene_difference(s, *again.scene), "") << text;
  EXPECT_EQ(to_toml(*again.scene), text);
  EXPECT_TRUE(contains(text, "pin_points = [[3, 4], [0, 0]]")) << text;
  EXPECT_TRUE(contains(text, "{ time = 0.25, velocity = [0.0, 1e-07, 2.0] }")) << text;
  EXPECT_FALSE(contains(text, "shear_body"));
  // A sphere's mass is written only when the scene gives it (else it follows 1000·r³).
  const SceneSpec plain = load_ok("cloth-2022.toml");
  EXPECT_FALSE(contains(to_toml(plain), "mass = 125"));
  EXPECT_FALSE(contains(to_toml(plain), "pin_points"));
}

TEST(SceneCloth, ErrorsNameTheFileLineKeyAndWhatWasExpected) {
  struct Case {
    std::string text;
    std::string key;
    int line;
    std::string says;
  };
  const std::vector<Case> cases = {
      {with(kCloth, "air_drag = 3.4e-4", "air_drug = 3.4e-4"), "body.air_drug", 17,
       "did you mean \"air_drag\""},
      {with(kCloth, "pins = [\"corners\"]", "pins = [\"corner\"]"), "body.pins", 16,
       "did you mean \"corners\""},
      {with(kCloth, "pins = [\"corners\"]", "pins = \"corners\""), "body.pins", 16,
       "must be an array of strings"},
      {with(kCloth, "pins = [\"corners\"]", "pin_points = [[5, 0]]"), "body.pin_points", 16,
       "pin 0 at (5, 0) is outside the 5×5 grid; expected 0 ≤ i, k ≤ 4"},
      {with(kCloth, "{ time = 0.5,", "{ time = 0.0,"), "sphere.1.schedule", 35,
       "times must increase strictly"},
      {with(kCloth, "{ time = 0.5, velocity = [1, 0, 0] }", "{ time = 0.5 }"), "sphere.1.schedule",
       35, "velocity is missing"},
      {with(kCloth, "{ time = 0.5, velocity", "{ tme = 0.5, velocity"), "sphere.1.schedule", 35,
       "did you mean \"time\""},
      {with(kCloth, "radius = 0.25", "radius = 0.25\nvelocity = [1, 0, 0]"), "sphere.1.velocity",
       33, "is a key of a dynamic sphere, and sphere 1 is kinematic"},
      {with(kCloth, "radius = 0.5\n", "radius = 0.5\nschedule = []\n"), "sphere.0.schedule", 28,
       "is a key of a kinematic sphere"},
      {with(kCloth, "radius = 0.5\n", "radius = -0.5\n"), "sphere.0.radius", 27, "> 0 m"},
      {with(kCloth, "radius = 0.5\n", "radis = 0.5\n"), "sphere.0.radis", 27,
       "did you mean \"radius\""},
      {with(kCloth, "tolerance = 0.02", "push_out = 2"), "collision.push_out", 23, "≤ 1"},
      {with(kCloth, "tolerance = 0.02", "frction = 0.2"), "collision.frction", 23,
       "did you mean \"friction\""},
      {with(kCloth, "n = 5", "n = 1"), "body.n", 14, "≥ 2"},
      {with(kCloth, "n = 5", "edge = 1.0"), "body.edge", 14,
       "edge is a key of a cube body, and this scene's body is a cloth"},
      {with(kCloth, "[springs.structural]", "[springs.shear_body]"), "springs.shear_body", 19,
       "expected one of: structural, shear, bending"},
      {kCloth + "\n[[terrain]]\npreset = \"course-2021-plane\"\n", "terrain", 38,
       "a cloth scene has no terrains"},
  };
  for (const Case& c : cases) {
    SCOPED_TRACE(c.says);
    const SceneError e = error_of(c.text);
    EXPECT_EQ(e.file, "cloth.toml");
    EXPECT_EQ(e.key, c.key) << e.text();
    EXPECT_EQ(e.line, c.line) << e.text();
    EXPECT_TRUE(contains(e.message, c.says)) << e.text();
  }
}

TEST(SceneCloth, ClothTablesInACubeSceneAreErrorsThatSaySo) {
  const std::string cube = R"([scene]
name = "t"

[body]
type = "cube"
n = 4

[collision]
friction = 0.2

[[sphere]]
radius = 1.0
)";
  const SceneError a = error_of(cube);
  EXPECT_EQ(a.key, "collision");
  EXPECT_EQ(a.line, 8);  // its header
  EXPECT_TRUE(contains(a.message, "[collision] is a table of cloth scenes")) << a.text();
  EXPECT_TRUE(contains(a.message, "this scene's body is cube")) << a.text();
  const SceneError b = error_of(with(cube, "[collision]\nfriction = 0.2\n", ""));
  EXPECT_EQ(b.key, "sphere");
  EXPECT_EQ(b.line, 9);
  EXPECT_TRUE(contains(b.message, "[[sphere]] belongs to cloth scenes")) << b.text();
}

}  // namespace
}  // namespace jelly
