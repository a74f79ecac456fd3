// The parameter declarations: listing, get/set through text, validation like the file, and that
// each declared default is the default the code actually uses.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <set>
#include <sstream>
#include <string>
#include <vector>

#include "jelly/cube_scene.hpp"
#include "jelly/params.hpp"
#include "jelly/particles_scene.hpp"
#include "jelly/scene.hpp"
#include "scene_compare.hpp"

namespace jelly {
namespace {

const std::filesystem::path kScenes = std::filesystem::path(JELLY_SOURCE_DIR) / "scenes";

SceneSpec scene(const std::string& file) {
  const SceneResult r = load_scene(kScenes / file);
  EXPECT_TRUE(r) << (r.error ? r.error->text() : std::string());
  return r ? *r.scene : SceneSpec{};
}

std::vector<std::string> keys_of(const SceneSpec& s) {
  std::vector<std::string> out;
  for (const ParamInfo& p : scene_parameters(s)) out.push_back(p.key);
  return out;
}

bool has(const std::vector<std::string>& v, const std::string& k) {
  return std::find(v.begin(), v.end(), k) != v.end();
}

TEST(SceneParams, CourseSceneListsItsKeysInAStableOrder) {
  const SceneSpec s = scene("course-2023.toml");
  const std::vector<std::string> keys = keys_of(s);
  ASSERT_GE(keys.size(), 10u);
  const std::vector<std::string> head(keys.begin(), keys.begin() + 8);
  EXPECT_EQ(head,
            (std::vector<std::string>{"scene.name", "scene.description", "simulation.integrator",
                                      "simulation.dt", "simulation.duration", "simulation.auto_dt",
                                      "gravity.enabled", "gravity.acceleration"}));
  for (const char* k : {"body.type",
                        "body.n",
                        "body.edge",
                        "body.mass",
                        "body.center",
                        "body.velocity",
                        "body.rotation_axis",
                        "body.rotation_degrees",
                        "springs.structural.enabled",
                        "springs.structural.ks",
                        "springs.shear.kd",
                        "springs.bending.ks",
                        "springs.shear_body.enabled",
                        "terrain.floor.type",
                        "terrain.floor.point",
                        "terrain.floor.normal",
                        "terrain.floor.hole_center",
                        "terrain.floor.hole_radius",
                        "terrain.floor.epsilon",
                        "terrain.floor.restitution",
                        "terrain.floor.friction",
                        "terrain.floor.collision",
                        "terrain.floor.contact",
                        "terrain.floor.project",
                        "terrain.bowl.center",
                        "terrain.bowl.radius",
                        "terrain.bowl.rim_height"})
    EXPECT_TRUE(has(keys, k)) << k;
  // Keys of absent effects and of other shapes/kinds are not parameters of this scene.
  for (const char* k : {"springs.shear_body.ks", "terrain.floor.radius", "terrain.bowl.normal",
                        "body.positions", "terrain.sphere.radius"})
    EXPECT_FALSE(has(keys, k)) << k;
  // Unique, and the same every time.
  EXPECT_EQ(std::set<std::string>(keys.begin(), keys.end()).size(), keys.size());
  EXPECT_EQ(keys_of(s), keys);
  // Terrain keys follow scene order: floor's before bowl's.
  const auto pos = [&](const std::string& k) {
    return std::find(keys.begin(), keys.end(), k) - keys.begin();
  };
  EXPECT_LT(pos("terrain.floor.project"), pos("terrain.bowl.type"));
  EXPECT_LT(pos("springs.structural.kd"), pos("springs.shear.enabled"));
}

TEST(SceneParams, ParticleSceneHasParticleKeys) {
  const std::vector<std::string> keys = keys_of(scene("two-particle-spring.toml"));
  for (const char* k : {"body.positions", "body.velocities", "body.springs", "body.rest_lengths",
                        "body.spring_type", "body.mass", "gravity.enabled"})
    EXPECT_TRUE(has(keys, k)) << k;
  for (const char* k : {"body.n", "body.center", "gravity.acceleration", "springs.shear.ks"})
    EXPECT_FALSE(has(keys, k)) << k;
}

TEST(SceneParams, MetadataComesFromTheDeclaration) {
  const SceneSpec s = scene("course-2023.toml");
  const auto dt = find_parameter(s, "simulation.dt");
  ASSERT_TRUE(dt);
  EXPECT_EQ(dt->type, ParamType::Real);
  EXPECT_EQ(dt->unit, "s");
  EXPECT_EQ(dt->default_text, "0.001");
  EXPECT_TRUE(dt->bounded);
  EXPECT_EQ(dt->min, 0.0);
  EXPECT_FALSE(dt->min_inclusive);
  EXPECT_FALSE(dt->description.empty());

  const auto n = find_parameter(s, "body.n");
  ASSERT_TRUE(n);
  EXPECT_EQ(n->type, ParamType::Integer);
  EXPECT_EQ(n->min, 2.0);
  EXPECT_EQ(n->max, 64.0);

  const auto integ = find_parameter(s, "simulation.integrator");
  ASSERT_TRUE(integ);
  EXPECT_EQ(integ->type, ParamType::Choice);
  EXPECT_EQ(integ->choices.size(), kAllIntegrators.size());

  const auto kr = find_parameter(s, "terrain.bowl.restitution");
  ASSERT_TRUE(kr);
  EXPECT_EQ(kr->min, 0.0);
  EXPECT_EQ(kr->max, 1.0);
  EXPECT_EQ(find_parameter(s, "terrain.floor.normal")->type, ParamType::Vector3);
  EXPECT_EQ(find_parameter(s, "terrain.floor.contact")->type, ParamType::Bool);
  EXPECT_FALSE(find_parameter(s, "terrain.nowhere.epsilon"));
  EXPECT_FALSE(find_parameter(s, "body.rotation_degree"));

  for (const ParamInfo& p : scene_parameters(s)) {
    EXPECT_FALSE(p.description.empty()) << p.key;
    if (p.type == ParamType::Choice) {
      EXPECT_FALSE(p.choices.empty()) << p.key;
    }
  }
}

TEST(SceneParams, GetAndGetNumber) {
  const SceneSpec s = scene("course-2023.toml");
  EXPECT_EQ(get_parameter(s, "simulation.dt"), "0.001");
  EXPECT_EQ(get_parameter(s, "simulation.integrator"), "symplectic_euler");
  EXPECT_EQ(get_parameter(s, "body.center"), "-4.8,11,0");
  EXPECT_EQ(get_parameter(s, "body.n"), "10");
  EXPECT_EQ(get_parameter(s, "gravity.enabled"), "true");
  EXPECT_EQ(get_parameter(s, "terrain.floor.contact"), "true");
  EXPECT_EQ(get_parameter(s, "terrain.bowl.type"), "bowl");
  EXPECT_EQ(get_parameter(s, "springs.shear_body.enabled"), "false");
  EXPECT_EQ(get_parameter(s, "springs.shear_body.ks"), std::nullopt);
  EXPECT_EQ(get_number(s, "body.n"), 10.0);
  EXPECT_EQ(get_number(s, "terrain.bowl.radius"), 9.0);
  EXPECT_EQ(get_number(s, "body.center"), std::nullopt);
  EXPECT_EQ(get_number(s, "no.such"), std::nullopt);
  const SceneSpec tp = scene("two-particle-spring.toml");
  EXPECT_EQ(get_parameter(tp, "body.positions"), "-0.55,0,0; 0.55,0,0");
  EXPECT_EQ(get_parameter(tp, "body.springs"), "0,1");
  EXPECT_EQ(get_parameter(tp, "body.rest_lengths"), "1");
}

// "key=value" as --set, the viewer's per-run parameters and `jelly render --set` take it.
TEST(SceneParams, SetAssignmentSplitsAtTheFirstEqualsSign) {
  SceneSpec s = scene("course-2023.toml");
  EXPECT_EQ(set_assignment(s, " springs.shear.ks = 5000 "), std::nullopt);
  EXPECT_EQ(s.shear.ks, 5000.0);
  EXPECT_EQ(set_assignment(s, "body.center=-5,11,0"), std::nullopt);
  EXPECT_EQ(cube_spec(s).center, Vec3(-5.0, 11.0, 0.0));
  const SceneSpec before = s;
  for (const char* bad : {"springs.shear.ks", "=5000", " = 5000", ""}) {
    const auto e = set_assignment(s, bad);
    ASSERT_TRUE(e) << "'" << bad << "'";
    EXPECT_EQ(e->file, "--set");
    EXPECT_NE(e->message.find("expected key=value"), std::string::npos) << e->message;
  }
  const auto unknown = set_assignment(s, "springs.shear.kss=1");
  ASSERT_TRUE(unknown);
  EXPECT_EQ(unknown->key, "springs.shear.kss");  // set_parameter's error, key named
  EXPECT_EQ(to_toml(s), to_toml(before));        // nothing changed by the failures
}

TEST(SceneParams, SetParsesByTypeAndValidatesLikeTheFile) {
  SceneSpec s = scene("course-2023.toml");
  EXPECT_EQ(set_parameter(s, "springs.shear.ks", "5000"), std::nullopt);
  EXPECT_EQ(s.shear.ks, 5000.0);
  EXPECT_EQ(set_parameter(s, "body.center", "-5,11,0"), std::nullopt);
  EXPECT_EQ(cube_spec(s).center, Vec3(-5.0, 11.0, 0.0));
  EXPECT_EQ(set_parameter(s, "body.center", " [1, 2.5, -3] "), std::nullopt);
  EXPECT_EQ(cube_spec(s).center, Vec3(1.0, 2.5, -3.0));
  EXPECT_EQ(set_parameter(s, "simulation.integrator", "rk4"), std::nullopt);
  EXPECT_EQ(s.integrator, IntegratorKind::RK4);
  EXPECT_EQ(set_parameter(s, "terrain.floor.project", "true"), std::nullopt);
  EXPECT_TRUE(s.terrains[0].project);
  EXPECT_EQ(set_parameter(s, "body.n", "+12"), std::nullopt);
  EXPECT_EQ(cube_spec(s).n, 12);
  EXPECT_EQ(set_parameter(s, "terrain.floor.normal", "0,2,0"), std::nullopt);
  EXPECT_EQ(std::get<Plane>(s.terrains[0].shape).normal, Vec3(0.0, 1.0, 0.0));

  const SceneSpec before = s;
  const auto expect_error = [&](const char* key, const char* value, const std::string& err_key,
                                const std::string& message_part) {
    const auto e = set_parameter(s, key, value);
    ASSERT_TRUE(e) << key << "=" << value;
    EXPECT_EQ(e->file, "--set");
    EXPECT_EQ(e->key, err_key);
    EXPECT_NE(e->message.find(message_part), std::string::npos) << e->message;
    EXPECT_EQ(testing::scene_difference(s, before), "") << "a rejected --set changes nothing";
  };
  expect_error("body.n", "1", "body.n", "must be an integer ≥ 2, got 1");
  expect_error("body.n", "2.5", "body.n", "must be an integer, got \"2.5\"");
  expect_error("body.mass", "-1", "body.mass", "must be a number > 0 kg, got -1");
  expect_error("simulation.dt", "0", "simulation.dt", "> 0 s, got 0");
  expect_error("simulation.dt", "fast", "simulation.dt", "must be a number");
  expect_error("simulation.dt", "1e-3x", "simulation.dt", "must be a number");
  expect_error("simulation.integrator", "rk5", "simulation.integrator", "did you mean \"rk4\"");
  expect_error("body.center", "1,2", "body.center", "three numbers");
  expect_error("terrain.floor.normal", "0,0,0", "terrain.floor.normal", "non-zero length");
  expect_error("terrain.floor.restitution", "1.5", "terrain.floor.restitution", "≤ 1");
  expect_error("terrain.floor.contact", "yes", "terrain.floor.contact", "true or false");
  expect_error("terrain.bowl.rim_height", "7", "terrain.bowl.rim_height", "rim_height ≤ center.y");
  expect_error("terrain.bowl.radius", "1", "terrain.bowl.rim_height",
               "after setting terrain.bowl.radius=1");
  expect_error("body.rotation_degree", "30", "body.rotation_degree",
               "did you mean \"body.rotation_degrees\"");
  expect_error("springs.shear_body.ks", "5", "springs.shear_body.ks",
               "springs.shear_body.enabled=true");
  expect_error("body.positions", "0,0,0", "body.positions", "particles body");
  expect_error("terrain.floor.radius", "3", "terrain.floor.radius", "plane");
  expect_error("body.type", "particles", "body.positions", "at least one position");
}

TEST(SceneParams, EnableAndDisableEffects) {
  SceneSpec s = scene("course-2023-structural-only.toml");
  EXPECT_EQ(set_parameter(s, "springs.bending.enabled", "true"), std::nullopt);
  EXPECT_TRUE(s.bending.enabled);
  EXPECT_EQ(s.bending.ks, 2000.0);
  EXPECT_EQ(s.bending.kd, 60.0);
  EXPECT_EQ(set_parameter(s, "springs.bending.ks", "100"), std::nullopt);
  EXPECT_EQ(set_parameter(s, "springs.bending.enabled", "true"), std::nullopt);
  EXPECT_EQ(s.bending.ks, 100.0) << "enabling an enabled type keeps its values";
  EXPECT_EQ(set_parameter(s, "springs.bending.enabled", "false"), std::nullopt);
  EXPECT_FALSE(s.bending.enabled);

  EXPECT_EQ(set_parameter(s, "gravity.enabled", "false"), std::nullopt);
  EXPECT_FALSE(s.gravity);
  EXPECT_TRUE(set_parameter(s, "gravity.acceleration", "0,-1,0"));
  EXPECT_EQ(set_parameter(s, "gravity.enabled", "true"), std::nullopt);
  ASSERT_TRUE(s.gravity);
  EXPECT_EQ(*s.gravity, Vec3(0.0, -9.8, 0.0));
  EXPECT_EQ(set_parameter(s, "gravity.acceleration", "0,-1.62,0"), std::nullopt);
  EXPECT_EQ(*s.gravity, Vec3(0.0, -1.62, 0.0));

  // The particle scene's spring type needs its table.
  SceneSpec tp = scene("two-particle-spring.toml");
  const auto e = set_parameter(tp, "springs.structural.enabled", "false");
  ASSERT_TRUE(e);
  EXPECT_EQ(e->key, "body.spring_type");
  EXPECT_TRUE(tp.structural.enabled);
}

TEST(SceneParams, ChangingATerrainTypeKeepsTheSurface) {
  SceneSpec s = scene("course-2021-plane.toml");
  ASSERT_EQ(set_parameter(s, "terrain.plane.friction", "0.7"), std::nullopt);
  ASSERT_EQ(set_parameter(s, "terrain.plane.type", "sphere"), std::nullopt);
  ASSERT_TRUE(std::holds_alternative<Sphere>(s.terrains[0].shape));
  EXPECT_EQ(s.terrains[0].surface().friction, 0.7);
  EXPECT_EQ(get_parameter(s, "terrain.plane.radius"), "1");
  EXPECT_TRUE(find_parameter(s, "terrain.plane.center"));
  EXPECT_FALSE(find_parameter(s, "terrain.plane.normal"));
}

TEST(SceneParams, ParticleListsThroughText) {
  SceneSpec tp = scene("two-particle-spring.toml");
  EXPECT_EQ(set_parameter(tp, "body.positions", "0,0,0; 2,0,0"), std::nullopt);
  EXPECT_EQ(particles_scene(tp).springs[0].rest_length, 1.0) << "rest lengths are kept";
  EXPECT_EQ(set_parameter(tp, "body.springs", "1,0"), std::nullopt);
  EXPECT_EQ(particles_scene(tp).springs[0].a, 1);
  EXPECT_EQ(particles_scene(tp).springs[0].rest_length, 2.0)
      << "new springs rest at the current distance";
  EXPECT_EQ(set_parameter(tp, "body.rest_lengths", "1.5"), std::nullopt);
  EXPECT_EQ(particles_scene(tp).springs[0].rest_length, 1.5);
  EXPECT_TRUE(set_parameter(tp, "body.rest_lengths", "1,2"));
  EXPECT_TRUE(set_parameter(tp, "body.springs", "0,5"));
  EXPECT_TRUE(set_parameter(tp, "body.springs", "0,4294967297"));
  EXPECT_TRUE(set_parameter(tp, "body.velocities", "0,0,0"));
  EXPECT_EQ(set_parameter(tp, "body.velocities", "0,1,0; 0,-1,0"), std::nullopt);
  EXPECT_EQ(particles_scene(tp).velocities(1, 1), -1.0);
  // Fewer particles: the springs would point past the end.
  const auto e = set_parameter(tp, "body.positions", "0,0,0");
  ASSERT_TRUE(e);
  EXPECT_EQ(e->key, "body.springs");
}

TEST(SceneParams, GetReturnsTextThatSetAccepts) {
  for (const auto& entry : std::filesystem::recursive_directory_iterator(kScenes)) {
    if (entry.path().extension() != ".toml") continue;
    const std::string file = std::filesystem::relative(entry.path(), kScenes).generic_string();
    SCOPED_TRACE(file);
    const SceneSpec original = scene(file);
    SceneSpec s = original;
    for (const ParamInfo& p : scene_parameters(original)) {
      const auto text = get_parameter(s, p.key);
      ASSERT_TRUE(text) << p.key;
      const auto e = set_parameter(s, p.key, *text);
      EXPECT_FALSE(e) << p.key << "=" << *text << ": " << (e ? e->text() : "");
    }
    EXPECT_EQ(testing::scene_difference(s, original), "");
  }
}

TEST(SceneParams, DeclaredDefaultsAreTheDefaultsTheCodeUses) {
  // A scene with every effect on, built from the structs' own defaults.
  SceneSpec s;
  s.gravity = Vec3(0.0, -9.8, 0.0);
  for (SpringSettings* st : {&s.structural, &s.shear, &s.shear_body, &s.bending})
    st->enabled = true;
  s.terrains = {Terrain{"p", Plane{}}, Terrain{"b", Bowl{}}, Terrain{"s", Sphere{}}};
  int checked = 0;
  for (const ParamInfo& p : scene_parameters(s)) {
    if (p.default_text.empty() || p.key.find(".enabled") != std::string::npos) continue;
    SceneSpec copy = s;
    const auto e = set_parameter(copy, p.key, p.default_text);
    ASSERT_FALSE(e) << p.key << ": " << e->text();
    EXPECT_EQ(testing::scene_difference(copy, s), "")
        << p.key << " declared default " << p.default_text << " differs from the code's default";
    ++checked;
  }
  EXPECT_GT(checked, 25);
  // Effects are off by default (an absent table), as declared.
  const SceneSpec plain;
  EXPECT_EQ(get_parameter(plain, "gravity.enabled"),
            find_parameter(plain, "gravity.enabled")->default_text);
  EXPECT_EQ(get_parameter(plain, "springs.shear.enabled"),
            find_parameter(plain, "springs.shear.enabled")->default_text);
  // The default gravity that gravity.enabled=true adds is the declared one.
  SceneSpec g;
  ASSERT_EQ(set_parameter(g, "gravity.enabled", "true"), std::nullopt);
  EXPECT_EQ(get_parameter(g, "gravity.acceleration"),
            find_parameter(g, "gravity.acceleration")->default_text);
}

}  // namespace
}  // namespace jelly

namespace jelly {
namespace {

TEST(SceneParams, AutoDtIsDeclaredSetAndWrittenBack) {
  SceneSpec s = scene("course-2023.toml");
  EXPECT_FALSE(s.auto_dt);  // the course scenes keep their fixed step
  EXPECT_EQ(get_parameter(s, "simulation.auto_dt"), "false");
  EXPECT_EQ(find_parameter(s, "simulation.auto_dt")->type, ParamType::Bool);
  EXPECT_EQ(find_parameter(s, "simulation.auto_dt")->default_text, "false");
  ASSERT_EQ(set_parameter(s, "simulation.auto_dt", "true"), std::nullopt);
  EXPECT_TRUE(s.auto_dt);
  const auto err = set_parameter(s, "simulation.auto_dt", "yes please");
  ASSERT_TRUE(err);
  EXPECT_EQ(err->key, "simulation.auto_dt");
  EXPECT_TRUE(s.auto_dt) << "a rejected value leaves the scene as it was";
  const SceneResult again = parse_scene(to_toml(s), "round-trip");
  ASSERT_TRUE(again) << again.error->text();
  EXPECT_TRUE(again.scene->auto_dt);
  const SceneResult from_text =
      parse_scene("[simulation]\nauto_dt = true\ndt = 0.005\n[body]\ntype = \"cube\"\n", "inline");
  ASSERT_TRUE(from_text) << from_text.error->text();
  EXPECT_TRUE(from_text.scene->auto_dt);
  EXPECT_EQ(from_text.scene->dt, 0.005);
}

TEST(SceneParams, DocsTableIsTheDeclarationTable) {
  // docs/scenes.md embeds the generated table between two markers; regenerate it from the
  // expected text below when a declaration changes.
  std::ifstream in(std::filesystem::path(JELLY_SOURCE_DIR) / "docs" / "scenes.md");
  ASSERT_TRUE(in) << "docs/scenes.md is missing";
  std::stringstream buffer;
  buffer << in.rdbuf();
  const std::string doc = buffer.str();
  const std::string begin = "<!-- params:begin (generated by parameter_reference_markdown) -->\n";
  const std::string end = "<!-- params:end -->";
  const auto b = doc.find(begin);
  const auto e = doc.find(end);
  ASSERT_NE(b, std::string::npos);
  ASSERT_NE(e, std::string::npos);
  const std::string table = doc.substr(b + begin.size(), e - b - begin.size());
  EXPECT_EQ(table, parameter_reference_markdown());
  // Every key of the course scene appears in it (with its wildcard).
  for (const ParamInfo& p : scene_parameters(scene("course-2023.toml"))) {
    std::string key = p.key;
    for (const char* t : {"floor", "bowl"})
      if (key.rfind(std::string("terrain.") + t + ".", 0) == 0)
        key.replace(8, std::string(t).size(), "<name>");
    for (const char* t : {"structural", "shear_body", "shear", "bending"})
      if (key.rfind(std::string("springs.") + t + ".", 0) == 0) {
        key.replace(8, std::string(t).size(), "<type>");
        break;
      }
    EXPECT_NE(table.find("| `" + key + "` |"), std::string::npos) << key;
  }
}

}  // namespace
}  // namespace jelly
