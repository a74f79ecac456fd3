// The cube body kind (assignment A1's jelly): its [body] keys, and how a cube scene becomes a
// World (contract §1-§3). Registered by body.cmake.
#include "cube_probe.hpp"
#include "cube_study.hpp"
#include "jelly/body_kind.hpp"
#include "jelly/cube_physics.hpp"
#include "jelly/cube_scene.hpp"
#include "jelly/world.hpp"
#include "param_rows.hpp"

namespace jelly::bodies {

namespace {

using namespace params_detail;

constexpr Range kCubeN{true, 2.0, 64.0, true, true};

class CubeKind final : public BodyKindModule {
 public:
  std::string_view name() const override { return "cube"; }
  std::string_view description() const override { return "a jelly cube"; }
  std::string_view body_phrase() const override { return "a cube"; }

  std::vector<Decl> rows() const override {
    return body_section(
        name(),
        {
            make(
                "body.n", Scope::Body, ValueKind::Integer, "", Default::Yes, kCubeN,
                "Particles per cube edge (n³ particles)",
                [](const SceneSpec& s, const Ctx&) -> Value {
                  return static_cast<long long>(cube_spec(s).n);
                },
                [](SceneSpec& s, const Ctx&, const Value& v) {
                  cube_spec(s).n = static_cast<int>(std::get<long long>(v));
                }),
            make(
                "body.edge", Scope::Body, ValueKind::Real, "m", Default::Yes, kPositive,
                "Cube edge length L",
                [](const SceneSpec& s, const Ctx&) -> Value { return cube_spec(s).edge; },
                [](SceneSpec& s, const Ctx&, const Value& v) { cube_spec(s).edge = real(v); }),
            make(
                "body.mass", Scope::Body, ValueKind::Real, "kg", Default::Yes, kPositive,
                "Mass of every particle",
                [](const SceneSpec& s, const Ctx&) -> Value { return cube_spec(s).mass; },
                [](SceneSpec& s, const Ctx&, const Value& v) { cube_spec(s).mass = real(v); }),
            make(
                "body.center", Scope::Body, ValueKind::Vector3, "m", Default::Yes, kAny,
                "Initial centre c0; the grid is centred exactly on it",
                [](const SceneSpec& s, const Ctx&) -> Value { return cube_spec(s).center; },
                [](SceneSpec& s, const Ctx&, const Value& v) { cube_spec(s).center = vec(v); }),
            make(
                "body.velocity", Scope::Body, ValueKind::Vector3, "m/s", Default::Yes, kAny,
                "Initial velocity of every particle (not rotated)",
                [](const SceneSpec& s, const Ctx&) -> Value { return cube_spec(s).velocity; },
                [](SceneSpec& s, const Ctx&, const Value& v) { cube_spec(s).velocity = vec(v); }),
            make(
                "body.rotation_axis", Scope::Body, ValueKind::Vector3, "", Default::Yes, kAny,
                "Axis of the initial rotation about c0 (normalised when used)",
                [](const SceneSpec& s, const Ctx&) -> Value { return cube_spec(s).rotation_axis; },
                [](SceneSpec& s, const Ctx&, const Value& v) {
                  cube_spec(s).rotation_axis = vec(v);
                },
                {},
                /*nonzero=*/true),
            make(
                "body.rotation_degrees", Scope::Body, ValueKind::Real, "deg", Default::Yes, kAny,
                "Initial rotation angle about rotation_axis, right-hand rule",
                [](const SceneSpec& s, const Ctx&) -> Value {
                  return cube_spec(s).rotation_degrees;
                },
                [](SceneSpec& s, const Ctx&, const Value& v) {
                  cube_spec(s).rotation_degrees = real(v);
                }),
        });
  }

  std::string_view stability_reason() const override { return "since contact stiffens the cube"; }
  std::string_view run_help(std::string_view option) const override {
    return option == "--threads" ? "pays off for large cubes,\n                      n ≥ 20, " : "";
  }

  // ----- the smoke tests of the slots that build its springs -----
  std::vector<std::string_view> probe_slots() const override { return cube_probe_slots(); }
  TaskStatus probe_slot(std::string_view slot, std::string id, std::string name,
                        const TaskTable& tasks) const override {
    return probe_cube_slot(slot, std::move(id), std::move(name), tasks);
  }

  // ----- what the studies measure on it -----
  std::unique_ptr<BodyStudy> study(const World& world, const State& start, const StudyLook&,
                                   const std::vector<std::string>& measures) const override {
    return make_cube_study(world, start, measures);
  }
  const std::vector<BodyMeasure>& measures() const override { return cube_measures(); }

  void build(const SceneSpec& scene, World& world) const override {
    CubePhysics& physics = cube_physics(world);  // the cube's lattices, the default physics' rest
    const int cube = physics.add_cube(cube_spec(scene));
    if (scene.structural.enabled)
      physics.build_cube_springs(cube, SpringType::Structural, scene.structural.ks,
                                 scene.structural.kd);
    if (scene.shear.enabled)
      physics.build_cube_springs(cube, SpringType::Shear, scene.shear.ks, scene.shear.kd);
    if (scene.shear_body.enabled)
      physics.build_cube_springs(cube, SpringType::ShearBody, scene.shear_body.ks,
                                 scene.shear_body.kd);
    if (scene.bending.enabled)
      physics.build_cube_springs(cube, SpringType::Bending, scene.bending.ks, scene.bending.kd);
    world.set_gravity(scene.gravity);
    for (const Terrain& t : scene.terrains) world.add_terrain(t);
  }
};

}  // namespace

const BodyKindModule& cube_kind() {
  static const CubeKind kind;
  return kind;
}

}  // namespace jelly::bodies
