// The shipped scenes load, build the worlds they describe, and survive writing and reading back.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include "jelly/a1/task_table.hpp"
#include "jelly/cube_scene.hpp"
#include "jelly/params.hpp"
#include "jelly/particles_scene.hpp"
#include "jelly/scene.hpp"
#include "jelly/task_table.hpp"
#include "scene_compare.hpp"

namespace jelly {
namespace {

const std::filesystem::path kScenes = std::filesystem::path(JELLY_SOURCE_DIR) / "scenes";

SceneSpec load_ok(const std::string& file) {
  const SceneResult r = load_scene(kScenes / file);
  EXPECT_TRUE(r) << (r.error ? r.error->text() : std::string());
  return r ? *r.scene : SceneSpec{};
}

std::vector<std::string> shipped_scenes() {
  std::vector<std::string> out;
  // Every scene under scenes/, including subfolders (scenes/hard/), as a path relative to it.
  for (const auto& e : std::filesystem::recursive_directory_iterator(kScenes))
    if (e.is_regular_file() && e.path().extension() == ".toml")
      out.push_back(std::filesystem::relative(e.path(), kScenes).generic_string());
  std::sort(out.begin(), out.end());
  return out;
}

std::size_t group_size(const World& w, SpringType t) {
  std::size_t n = 0;
  for (const SpringGroup& g : w.spring_groups())
    if (g.type == t) n += g.springs.size();
  return n;
}

TEST(SceneLoader, TheRequiredScenesAreShipped) {
  const std::vector<std::string> files = shipped_scenes();
  for (const char* name :
       {"course-2023.toml", "course-2023-structural-only.toml", "course-2021-plane.toml",
        "course-2021-sphere.toml", "course-2021-bowl.toml", "course-2021-tilted.toml",
        "free-fall.toml", "two-particle-spring.toml"})
    EXPECT_NE(std::find(files.begin(), files.end(), name), files.end()) << name;
}

TEST(SceneLoader, EveryShippedSceneLoadsAndOpensWithAComment) {
  for (const std::string& file : shipped_scenes()) {
    SCOPED_TRACE(file);
    const SceneResult r = load_scene(kScenes / file);
    ASSERT_TRUE(r) << r.error->text();
    EXPECT_FALSE(r.scene->name.empty());
    EXPECT_FALSE(r.scene->description.empty());
    EXPECT_EQ(r.scene->source, (kScenes / file).string());
    std::ifstream in(kScenes / file);
    std::string first;
    std::getline(in, first);
    EXPECT_EQ(first.rfind("# ", 0), 0u) << "a scene file opens with a comment saying what it shows";
  }
}

TEST(SceneLoader, Course2023IsTheCourseScene) {
  const SceneSpec s = load_ok("course-2023.toml");
  EXPECT_EQ(s.integrator, IntegratorKind::SymplecticEuler);
  EXPECT_EQ(s.dt, 0.001);
  EXPECT_EQ(s.duration, 10.0);
  ASSERT_TRUE(s.gravity);
  EXPECT_EQ(*s.gravity, Vec3(0.0, -9.8, 0.0));
  EXPECT_EQ(s.body_kind, kCubeKind);
  EXPECT_EQ(cube_spec(s).n, 10);
  EXPECT_EQ(cube_spec(s).edge, 4.0);
  EXPECT_EQ(cube_spec(s).mass, 1.0);
  EXPECT_EQ(cube_spec(s).center, Vec3(-4.8, 11.0, 0.0));
  EXPECT_EQ(cube_spec(s).rotation_degrees, 0.0);
  for (const SpringSettings* st : {&s.structural, &s.shear, &s.bending}) {
    EXPECT_TRUE(st->enabled);
    EXPECT_EQ(st->ks, 2000.0);
    EXPECT_EQ(st->kd, 60.0);
  }
  EXPECT_FALSE(s.shear_body.enabled);
  ASSERT_EQ(s.terrains.size(), 2u);
  EXPECT_EQ(s.terrains[0].name, "floor");
  EXPECT_EQ(s.terrains[1].name, "bowl");
  EXPECT_TRUE(testing::scene_difference(SceneSpec{}, SceneSpec{}).empty());
  // The terrains are exactly the presets, in order.
  SceneSpec presets = s;
  presets.terrains = {*terrain_preset("course-2023-floor"), *terrain_preset("course-2023-bowl")};
  EXPECT_EQ(testing::scene_difference(s, presets), "");
}

TEST(SceneLoader, Course2023PresetsGiveTheContractNumbers) {
  const double r = 9.0 / std::sqrt(2.0);
  const auto floor = terrain_preset("course-2023-floor");
  ASSERT_TRUE(floor);
  const Plane& p = std::get<Plane>(floor->shape);
  EXPECT_EQ(p.point, Vec3(0.0, 0.0, 0.0));
  EXPECT_EQ(p.normal, Vec3(0.0, 1.0, 0.0));
  EXPECT_TRUE(p.has_hole);
  EXPECT_EQ(p.hole_center, Vec3(2.0, 0.0, 1.0));
  EXPECT_EQ(p.hole_radius, r);
  const auto bowl = terrain_preset("course-2023-bowl");
  ASSERT_TRUE(bowl);
  const Bowl& b = std::get<Bowl>(bowl->shape);
  EXPECT_EQ(b.center, Vec3(2.0, r, 1.0));
  EXPECT_EQ(b.radius, 9.0);
  EXPECT_EQ(b.rim_height, 0.0);
  // The bowl's rim is the hole's edge.
  EXPECT_NEAR(b.rim_radius(), p.hole_radius, 1e-12);
  for (const Terrain* t : {&*floor, &*bowl}) {
    EXPECT_EQ(t->surface().epsilon, 0.01);
    EXPECT_EQ(t->surface().restitution, 0.8);
    EXPECT_EQ(t->surface().friction, 0.2);
    EXPECT_TRUE(t->collision);
    EXPECT_TRUE(t->contact);
    EXPECT_FALSE(t->project);
  }
}

TEST(SceneLoader, Course2021ScenesHaveOneTerrainEach) {
  struct Case {
    const char* file;
    const char* terrain;
    std::size_t shape_index;  // 0 plane, 1 bowl, 2 sphere
  };
  for (const Case& c :
       {Case{"course-2021-plane.toml", "plane", 0}, Case{"course-2021-sphere.toml", "sphere", 2},
        Case{"course-2021-bowl.toml", "bowl", 1}, Case{"course-2021-tilted.toml", "tilted", 0}}) {
    SCOPED_TRACE(c.file);
    const SceneSpec s = load_ok(c.file);
    EXPECT_EQ(cube_spec(s).center, Vec3(0.0, 9.0, 0.0));
    ASSERT_EQ(s.terrains.size(), 1u);
    EXPECT_EQ(s.terrains[0].name, c.terrain);
    EXPECT_EQ(s.terrains[0].shape.index(), c.shape_index);
    EXPECT_EQ(s.terrains[0].surface().friction, 0.3);
  }
  // The tilted plane's normal is unit length (the course's was not).
  const SceneSpec tilted = load_ok("course-2021-tilted.toml");
  const Plane& p = std::get<Plane>(tilted.terrains[0].shape);
  EXPECT_NEAR(p.normal.norm(), 1.0, 1e-15);
  EXPECT_NEAR(p.normal.x(), 1.0 / std::sqrt(2.0), 1e-15);
}

TEST(SceneLoader, FreeFallAndTwoParticleSpring) {
  const SceneSpec ff = load_ok("free-fall.toml");
  EXPECT_TRUE(ff.terrains.empty());
  ASSERT_TRUE(ff.gravity);
  EXPECT_EQ(ff.duration, 1.0);
  EXPECT_EQ(cube_spec(ff).center, Vec3(-4.8, 11.0, 0.0));

  const SceneSpec tp = load_ok("two-particle-spring.toml");
  EXPECT_EQ(tp.body_kind, BodyKind{"particles"});
  EXPECT_FALSE(tp.gravity);
  EXPECT_TRUE(tp.terrains.empty());
  ASSERT_EQ(particles_scene(tp).positions.cols(), 2);
  EXPECT_EQ(Vec3(particles_scene(tp).positions.col(0)), Vec3(-0.55, 0.0, 0.0));
  EXPECT_EQ(Vec3(particles_scene(tp).positions.col(1)), Vec3(0.55, 0.0, 0.0));
  EXPECT_EQ(particles_scene(tp).mass, 1.0);
  ASSERT_EQ(particles_scene(tp).springs.size(), 1u);
  EXPECT_EQ(particles_scene(tp).springs[0].a, 0);
  EXPECT_EQ(particles_scene(tp).springs[0].b, 1);
  EXPECT_EQ(particles_scene(tp).springs[0].rest_length, 1.0);
  EXPECT_TRUE(tp.structural.enabled);
  EXPECT_EQ(tp.structural.ks, 10.0);
  EXPECT_EQ(tp.structural.kd, 0.0);
  EXPECT_FALSE(tp.shear.enabled);
  EXPECT_FALSE(tp.shear_body.enabled);
  EXPECT_FALSE(tp.bending.enabled);
}

TEST(SceneLoader, BuildWorldBuildsWhatEachSceneNames) {
  struct Case {
    const char* file;
    std::size_t structural, shear, bending;
    std::vector<std::string> terrains;
    bool gravity;
  };
  const std::vector<Case> cases = {
      {"course-2023.toml", 2700, 7776, 2400, {"floor", "bowl"}, true},
      {"course-2023-structural-only.toml", 2700, 0, 0, {"floor", "bowl"}, true},
      {"course-2021-plane.toml", 2700, 7776, 2400, {"plane"}, true},
      {"course-2021-sphere.toml", 2700, 7776, 2400, {"sphere"}, true},
      {"course-2021-bowl.toml", 2700, 7776, 2400, {"bowl"}, true},
      {"course-2021-tilted.toml", 2700, 7776, 2400, {"tilted"}, true},
      {"free-fall.toml", 2700, 7776, 2400, {}, true},
      {"two-particle-spring.toml", 1, 0, 0, {}, false},
  };
  for (const Case& c : cases) {
    SCOPED_TRACE(c.file);
    const SceneSpec s = load_ok(c.file);
    const auto world = build_world(s, a1::task_table());
    ASSERT_TRUE(world);
    EXPECT_EQ(group_size(*world, SpringType::Structural), c.structural);
    EXPECT_EQ(group_size(*world, SpringType::Shear), c.shear);
    EXPECT_EQ(group_size(*world, SpringType::Bending), c.bending);
    EXPECT_EQ(group_size(*world, SpringType::ShearBody), 0u);
    EXPECT_EQ(world->spring_count(), c.structural + c.shear + c.bending);
    // Absent spring types are not built at all: no empty groups either.
    for (const SpringGroup& g : world->spring_groups()) EXPECT_FALSE(g.springs.empty());
    std::vector<std::string> names;
    for (const Terrain& t : world->terrains()) names.push_back(t.name);
    EXPECT_EQ(names, c.terrains);
    EXPECT_EQ(world->gravity().has_value(), c.gravity);
  }
  const auto course = build_world(load_ok("course-2023.toml"), a1::task_table());
  EXPECT_EQ(course->spring_count(), 12876u);
  EXPECT_EQ(course->particle_count(), 1000);
}

TEST(SceneLoader, ShearBodySetsBodyDiagonalsApart) {
  SceneSpec s = load_ok("course-2023.toml");
  ASSERT_EQ(set_parameter(s, "springs.shear_body.enabled", "true"), std::nullopt);
  ASSERT_EQ(set_parameter(s, "springs.shear_body.ks", "500"), std::nullopt);
  const auto world = build_world(s, a1::task_table());
  EXPECT_EQ(group_size(*world, SpringType::Shear), 4860u);
  EXPECT_EQ(group_size(*world, SpringType::ShearBody), 2916u);
  EXPECT_EQ(world->spring_count(), 12876u);
}

TEST(SceneLoader, EveryShippedSceneRoundTripsThroughToToml) {
  for (const std::string& file : shipped_scenes()) {
    SCOPED_TRACE(file);
    const SceneSpec s = load_ok(file);
    const std::string text = to_toml(s);
    const SceneResult again = parse_scene(text, "round-trip");
    ASSERT_TRUE(again) << again.error->text() << "\n" << text;
    EXPECT_EQ(testing::scene_difference(s, *again.scene), "") << text;
    EXPECT_EQ(to_toml(*again.scene), text) << "writing is deterministic";
  }
}

TEST(SceneLoader, EditedScenesRoundTripToo) {
  SceneSpec s = load_ok("course-2023.toml");
  for (auto [key, value] : std::vector<std::pair<const char*, const char*>>{
           {"scene.name", "quotes \" and \\ backslash\ttab \u00e9"},
           {"scene.description", "line one\nline two"},
           {"body.center", "0.1,0.2,0.30000000000000004"},
           {"body.rotation_degrees", "33.3"},
           {"body.rotation_axis", "1e-300,2,3"},
           {"simulation.dt", "1e-07"},
           {"terrain.floor.normal", "1,1,0.3"},
           {"terrain.floor.point", "0,-1,0"},
           {"terrain.floor.hole_radius", "3"},
           {"terrain.bowl.project", "true"},
           {"terrain.bowl.collision", "false"},
           {"gravity.acceleration", "0.5,-9.81,0"},
           {"springs.shear_body.enabled", "true"},
           {"springs.shear_body.kd", "7.5"},
           {"springs.bending.enabled", "false"}}) {
    ASSERT_EQ(set_parameter(s, key, value), std::nullopt) << key;
  }
  const SceneResult again = parse_scene(to_toml(s), "round-trip");
  ASSERT_TRUE(again) << again.error->text();
  EXPECT_EQ(testing::scene_difference(s, *again.scene), "") << to_toml(s);

  SceneSpec no_gravity = load_ok("two-particle-spring.toml");
  ASSERT_EQ(set_parameter(no_gravity, "body.velocities", "0,1,0; 0,-1,0"), std::nullopt);
  const SceneResult tp = parse_scene(to_toml(no_gravity), "round-trip");
  ASSERT_TRUE(tp) << tp.error->text();
  EXPECT_EQ(testing::scene_difference(no_gravity, *tp.scene), "");
  EXPECT_FALSE(tp.scene->gravity);
}

TEST(SceneLoader, DefaultsFillWhatAFileLeavesOut) {
  const SceneResult r = parse_scene(R"([body]
center = [0, 5, 0]
[springs.structural]
)",
                                    "minimal");
  ASSERT_TRUE(r) << r.error->text();
  const SceneSpec& s = *r.scene;
  EXPECT_EQ(cube_spec(s).n, 10);
  EXPECT_EQ(cube_spec(s).edge, 4.0);
  EXPECT_EQ(cube_spec(s).mass, 1.0);
  EXPECT_EQ(cube_spec(s).rotation_axis, Vec3(1.0, 0.0, 1.0));
  EXPECT_EQ(cube_spec(s).velocity, Vec3::Zero());
  EXPECT_EQ(s.dt, 0.001);
  EXPECT_FALSE(s.gravity) << "no [gravity] table: no gravity term";
  EXPECT_TRUE(s.structural.enabled);
  EXPECT_EQ(s.structural.ks, 2000.0);
  EXPECT_EQ(s.structural.kd, 60.0);
  EXPECT_FALSE(s.shear.enabled);
  EXPECT_TRUE(s.terrains.empty());

  const SceneResult g = parse_scene("[gravity]\n", "g");
  ASSERT_TRUE(g);
  ASSERT_TRUE(g.scene->gravity);
  EXPECT_EQ(*g.scene->gravity, Vec3(0.0, -9.8, 0.0));
  const SceneResult off =
      parse_scene("[gravity]\nenabled = false\n[springs.shear]\nenabled = false\n", "g");
  ASSERT_TRUE(off) << off.error->text();
  EXPECT_FALSE(off.scene->gravity);
  EXPECT_FALSE(off.scene->shear.enabled);
}

TEST(SceneLoader, TerrainsByTypeAndPresetOverrides) {
  const SceneResult r = parse_scene(R"(
[[terrain]]
preset = "course-2023-floor"
name = "ground"
restitution = 0.5
hole_radius = 2.0

[[terrain]]
name = "ramp"
type = "plane"
point = [0, -2, 0]
normal = [0, 0, 3]
hole_center = [1, -2, 0]
hole_radius = 0.5
friction = 0.0
contact = false
project = true

[[terrain]]
name = "ball"
type = "sphere"
center = [1, 2, 3]
radius = 0.25
epsilon = 0.001

[[terrain]]
name = "cup"
type = "bowl"
center = [0, 3, 0]
radius = 2
rim_height = 3
)",
                                    "terrains");
  ASSERT_TRUE(r) << r.error->text();
  const auto& t = r.scene->terrains;
  ASSERT_EQ(t.size(), 4u);
  EXPECT_EQ(t[0].name, "ground");
  const Plane& g = std::get<Plane>(t[0].shape);
  EXPECT_EQ(g.hole_radius, 2.0);
  EXPECT_EQ(g.hole_center, Vec3(2.0, 0.0, 1.0)) << "kept from the preset";
  EXPECT_EQ(t[0].surface().restitution, 0.5);
  EXPECT_EQ(t[0].surface().friction, 0.2) << "kept from the preset";
  const Plane& ramp = std::get<Plane>(t[1].shape);
  EXPECT_EQ(ramp.normal, Vec3(0.0, 0.0, 1.0)) << "normalised";
  EXPECT_TRUE(ramp.has_hole);
  EXPECT_FALSE(t[1].contact);
  EXPECT_TRUE(t[1].collision);
  EXPECT_TRUE(t[1].project);
  EXPECT_EQ(t[1].surface().friction, 0.0);
  const Sphere& ball = std::get<Sphere>(t[2].shape);
  EXPECT_EQ(ball.center, Vec3(1.0, 2.0, 3.0));
  EXPECT_EQ(ball.radius, 0.25);
  EXPECT_EQ(t[2].surface().epsilon, 0.001);
  EXPECT_EQ(t[2].surface().restitution, 0.8) << "default";
  const Bowl& cup = std::get<Bowl>(t[3].shape);
  EXPECT_EQ(cup.rim_height, 3.0);
  EXPECT_EQ(cup.radius, 2.0);
}

TEST(SceneLoader, ParticlesDefaultRestLengthsAndVelocities) {
  const SceneResult r = parse_scene(R"(
[body]
type = "particles"
mass = 2.0
positions = [[0, 0, 0], [3, 4, 0], [0, 0, 1]]
springs = [[0, 1], [2, 0]]
spring_type = "bending"
[springs.bending]
ks = 5
)",
                                    "particles");
  ASSERT_TRUE(r) << r.error->text();
  const ParticleBodySpec& p = particles_scene(*r.scene);
  EXPECT_EQ(p.mass, 2.0);
  EXPECT_EQ(p.velocities, Vec3Array::Zero(3, 3));
  ASSERT_EQ(p.springs.size(), 2u);
  EXPECT_EQ(p.springs[0].rest_length, 5.0);
  EXPECT_EQ(p.springs[1].rest_length, 1.0);
  EXPECT_EQ(p.spring_type, SpringType::Bending);
  const auto world = build_world(*r.scene, a1::task_table());
  ASSERT_EQ(world->spring_groups().size(), 1u);
  EXPECT_EQ(world->spring_groups()[0].type, SpringType::Bending);
  EXPECT_EQ(world->spring_groups()[0].ks, 5.0);
  EXPECT_EQ(world->particle_count(), 3);
}

}  // namespace
}  // namespace jelly
