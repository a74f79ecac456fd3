// The cloth body kind (assignment A2, the cloth contract docs/cloth-physics.md): its [body] keys,
// its [collision] table and [[sphere]] entries, their checks, and how a cloth scene becomes a
// World. Registered by body.cmake.
#include <array>

#include "cloth_probe.hpp"
#include "cloth_study.hpp"
#include "cloth_summary.hpp"
#include "jelly/body_kind.hpp"
#include "jelly/cloth_physics.hpp"
#include "jelly/cloth_scene.hpp"
#include "jelly/recorder.hpp"
#include "jelly/simulator.hpp"
#include "jelly/world.hpp"
#include "param_rows.hpp"

namespace jelly::bodies {

namespace {

using namespace params_detail;

constexpr Range kClothN{true, 2.0, 200.0, true, true};
/// The named pin sets a cloth scene may list (cloth contract §1, decision 8).
constexpr std::array<std::string_view, 2> kPinSets = {"corners", "edge"};
/// A cloth scene's spring table without ks or kd: cloth contract decision 10 (A1's are the
/// SpringSettings defaults).
constexpr double kClothDefaultKs = 25000.0;
constexpr double kClothDefaultKd = 750.0;

std::string pin_message(std::size_t i, long long a, long long b, int n) {
  return "pin " + std::to_string(i) + " at (" + std::to_string(a) + ", " + std::to_string(b) +
         ") is outside the " + std::to_string(n) + "×" + std::to_string(n) +
         " grid; expected 0 ≤ i, k ≤ " + std::to_string(n - 1);
}

std::optional<std::string> schedule_order(const std::vector<ScheduleEntry>& list) {
  for (std::size_t i = 1; i < list.size(); ++i)
    if (!(list[i].time > list[i - 1].time))
      return "times must increase strictly (cloth contract decision 5): entry " +
             std::to_string(i) + " has time " + format_double(list[i].time) + " s after " +
             format_double(list[i - 1].time) + " s";
  return std::nullopt;
}

// The row checks of body.pin_points (inside the grid) and sphere.<i>.schedule (strictly
// increasing times).
std::optional<std::string> check_pin_points(const Decl&, const SceneSpec& s, const Ctx&,
                                            const Value& v) {
  const auto& pins = std::get<std::vector<IndexPair>>(v);
  const int n = cloth_spec(s).n;
  for (std::size_t i = 0; i < pins.size(); ++i)
    if (pins[i][0] < 0 || pins[i][1] < 0 || pins[i][0] >= n || pins[i][1] >= n)
      return pin_message(i, pins[i][0], pins[i][1], n);
  return std::nullopt;
}

std::optional<std::string> check_schedule(const Decl&, const SceneSpec&, const Ctx&,
                                          const Value& v) {
  return schedule_order(std::get<std::vector<ScheduleEntry>>(v));
}

// ----- [[sphere]] -----

SphereSpec& sphere_spec(SceneSpec& s, const Ctx& c) { return sphere_specs(s)[c.index]; }
const SphereSpec& sphere_spec(const SceneSpec& s, const Ctx& c) { return sphere_specs(s)[c.index]; }

/// Rows of dynamic spheres only, and of kinematic ones only.
Decl dynamic_only(Decl d) {
  return applies_when(
      std::move(d), "dynamic spheres",
      [](const SceneSpec& s, const Ctx& c) {
        return c.index < sphere_specs(s).size() && !sphere_specs(s)[c.index].kinematic;
      },
      [](const Bound& b, const SceneSpec&) {
        return std::string(key_local(b.decl->pattern)) +
               " is a key of a dynamic sphere, and sphere " + std::to_string(b.ctx.index) +
               " is kinematic (kinematic = true: it moves by its schedule)";
      });
}
Decl kinematic_only(Decl d) {
  return applies_when(
      std::move(d), "kinematic spheres",
      [](const SceneSpec& s, const Ctx& c) {
        return c.index < sphere_specs(s).size() && sphere_specs(s)[c.index].kinematic;
      },
      [](const Bound& b, const SceneSpec&) {
        return std::string(key_local(b.decl->pattern)) +
               " is a key of a kinematic sphere (kinematic = true), and sphere " +
               std::to_string(b.ctx.index) + " is dynamic";
      });
}

std::vector<Decl> sphere_rows() {
  return with_defaults(
      {
          make(
              "sphere.*.center", Scope::Element, ValueKind::Vector3, "m", Default::Yes, kAny,
              "Initial centre c",
              [](const SceneSpec& s, const Ctx& c) -> Value { return sphere_spec(s, c).center; },
              [](SceneSpec& s, const Ctx& c, const Value& v) {
                sphere_spec(s, c).center = vec(v);
              }),
          make(
              "sphere.*.radius", Scope::Element, ValueKind::Real, "m", Default::Yes, kPositive,
              "Radius r",
              [](const SceneSpec& s, const Ctx& c) -> Value { return sphere_spec(s, c).radius; },
              [](SceneSpec& s, const Ctx& c, const Value& v) {
                sphere_spec(s, c).radius = real(v);
              }),
          make(
              "sphere.*.kinematic", Scope::Element, ValueKind::Bool, "", Default::Yes, kAny,
              "Moved by its schedule with inverse mass 0 (true), or by gravity and impulses "
              "(false)",
              [](const SceneSpec& s, const Ctx& c) -> Value { return sphere_spec(s, c).kinematic; },
              [](SceneSpec& s, const Ctx& c, const Value& v) {
                sphere_spec(s, c).kinematic = flag(v);
              }),
          dynamic_only(written_if(
              make(
                  "sphere.*.mass", Scope::When, ValueKind::Real, "kg", Default::None, kPositive,
                  "Mass M; when not given 1000 r^3 (the course's formula)",
                  [](const SceneSpec& s, const Ctx& c) -> Value {
                    const SphereSpec& sp = sphere_spec(s, c);
                    return sp.mass.value_or(default_sphere_mass(sp.radius));
                  },
                  [](SceneSpec& s, const Ctx& c, const Value& v) {
                    // 1000·r³ is the mass not given: it keeps following the radius (and `jelly
                    // params` text set back leaves the scene as it was).
                    SphereSpec& sp = sphere_spec(s, c);
                    if (real(v) == default_sphere_mass(sp.radius)) {
                      sp.mass.reset();
                    } else {
                      sp.mass = real(v);
                    }
                  }),
              [](const SceneSpec& s, const Ctx& c) { return sphere_spec(s, c).mass.has_value(); })),
          dynamic_only(make(
              "sphere.*.velocity", Scope::When, ValueKind::Vector3, "m/s", Default::Yes, kAny,
              "Initial velocity u",
              [](const SceneSpec& s, const Ctx& c) -> Value { return sphere_spec(s, c).velocity; },
              [](SceneSpec& s, const Ctx& c, const Value& v) {
                sphere_spec(s, c).velocity = vec(v);
              })),
          kinematic_only(citing(
              checked(
                  make(
                      "sphere.*.schedule", Scope::When, ValueKind::Schedule, "s: m/s", Default::Yes,
                      kAny,
                      "From each time on, the velocity it moves at (zero before the first entry); "
                      "TOML [{ time = t, velocity = [x, y, z] }, ...]",
                      [](const SceneSpec& s, const Ctx& c) -> Value {
                        return sphere_spec(s, c).schedule;
                      },
                      [](SceneSpec& s, const Ctx& c, const Value& v) {
                        sphere_spec(s, c).schedule = std::get<std::vector<ScheduleEntry>>(v);
                      }),
                  check_schedule),
              "cloth contract decision 5")),
      },
      [](SceneSpec& s, const Decl&) { sphere_specs(s).emplace_back(); });
}

std::vector<std::string> sphere_names(const SceneSpec& s) {
  std::vector<std::string> out;
  for (std::size_t i = 0; i < sphere_specs(s).size(); ++i) out.push_back(std::to_string(i));
  return out;
}

class ClothKind final : public BodyKindModule {
 public:
  std::string_view name() const override { return "cloth"; }
  std::string_view description() const override { return "a cloth (assignment A2)"; }
  std::string_view body_phrase() const override { return "a cloth"; }

  std::vector<Decl> rows() const override {
    return body_section(
        name(),
        {
            make(
                "body.n", Scope::Body, ValueKind::Integer, "", Default::Yes, kClothN,
                "Particles per cloth edge (n² particles)",
                [](const SceneSpec& s, const Ctx&) -> Value {
                  return static_cast<long long>(cloth_spec(s).n);
                },
                [](SceneSpec& s, const Ctx&, const Value& v) {
                  cloth_spec(s).n = static_cast<int>(std::get<long long>(v));
                }),
            make(
                "body.size", Scope::Body, ValueKind::Real, "m", Default::Yes, kPositive,
                "Side L of the square cloth; spacing L/(n-1)",
                [](const SceneSpec& s, const Ctx&) -> Value { return cloth_spec(s).size; },
                [](SceneSpec& s, const Ctx&, const Value& v) { cloth_spec(s).size = real(v); }),
            make(
                "body.mass", Scope::Body, ValueKind::Real, "kg", Default::Yes, kPositive,
                "Mass of every cloth particle",
                [](const SceneSpec& s, const Ctx&) -> Value { return cloth_spec(s).mass; },
                [](SceneSpec& s, const Ctx&, const Value& v) { cloth_spec(s).mass = real(v); }),
            make(
                "body.center", Scope::Body, ValueKind::Vector3, "m", Default::Yes, kAny,
                "Centre c0; the horizontal square grid is centred exactly on it",
                [](const SceneSpec& s, const Ctx&) -> Value { return cloth_spec(s).center; },
                [](SceneSpec& s, const Ctx&, const Value& v) { cloth_spec(s).center = vec(v); }),
            make(
                "body.velocity", Scope::Body, ValueKind::Vector3, "m/s", Default::Yes, kAny,
                "Initial velocity of every unpinned particle (not rotated)",
                [](const SceneSpec& s, const Ctx&) -> Value { return cloth_spec(s).velocity; },
                [](SceneSpec& s, const Ctx&, const Value& v) { cloth_spec(s).velocity = vec(v); }),
            make(
                "body.rotation_axis", Scope::Body, ValueKind::Vector3, "", Default::Yes, kAny,
                "Axis of the initial rotation about c0 (normalised when used)",
                [](const SceneSpec& s, const Ctx&) -> Value { return cloth_spec(s).rotation_axis; },
                [](SceneSpec& s, const Ctx&, const Value& v) {
                  cloth_spec(s).rotation_axis = vec(v);
                },
                {},
                /*nonzero=*/true),
            make(
                "body.rotation_degrees", Scope::Body, ValueKind::Real, "deg", Default::Yes, kAny,
                "Initial rotation angle about rotation_axis (90 about x: a curtain; 90 about z: a "
                "flag)",
                [](const SceneSpec& s, const Ctx&) -> Value {
                  return cloth_spec(s).rotation_degrees;
                },
                [](SceneSpec& s, const Ctx&, const Value& v) {
                  cloth_spec(s).rotation_degrees = real(v);
                }),
            make(
                "body.pins", Scope::Body, ValueKind::NameList, "", Default::Yes, kAny,
                "Named sets of pinned particles: corners (the four), edge (the row k = 0); [] for "
                "none",
                [](const SceneSpec& s, const Ctx&) -> Value { return cloth_spec(s).pin_sets; },
                [](SceneSpec& s, const Ctx&, const Value& v) {
                  cloth_spec(s).pin_sets = std::get<std::vector<std::string>>(v);
                },
                {kPinSets.begin(), kPinSets.end()}),
            written_if(
                checked(make(
                            "body.pin_points", Scope::Body, ValueKind::GridList, "", Default::Yes,
                            kAny, "Further pinned particles by grid coordinates [[i, k], ...]",
                            [](const SceneSpec& s, const Ctx&) -> Value {
                              std::vector<IndexPair> out;
                              for (const GridCoord& p : cloth_spec(s).pins)
                                out.push_back({p[0], p[1]});
                              return out;
                            },
                            [](SceneSpec& s, const Ctx&, const Value& v) {
                              cloth_spec(s).pins.clear();
                              for (const IndexPair& p : std::get<std::vector<IndexPair>>(v))
                                cloth_spec(s).pins.push_back(
                                    {static_cast<int>(p[0]), static_cast<int>(p[1])});
                            }),
                        check_pin_points),
                [](const SceneSpec& s, const Ctx&) { return !cloth_spec(s).pins.empty(); }),
            make(
                "body.air_drag", Scope::Body, ValueKind::Real, "N*s/m", Default::Yes, kNonNegative,
                "Air drag k_air: force -k_air v on every cloth particle (the course: 3.4e-4)",
                [](const SceneSpec& s, const Ctx&) -> Value { return cloth_spec(s).air_drag; },
                [](SceneSpec& s, const Ctx&, const Value& v) { cloth_spec(s).air_drag = real(v); }),
            // [collision] of a cloth scene (cloth contract §4)
            make(
                "collision.cloth_restitution", Scope::Body, ValueKind::Real, "", Default::Yes,
                kUnitInterval, "Restitution e_cloth of cloth-sphere impulses (the course: 0)",
                [](const SceneSpec& s, const Ctx&) -> Value {
                  return cloth_collisions(s).cloth_restitution;
                },
                [](SceneSpec& s, const Ctx&, const Value& v) {
                  cloth_collisions(s).cloth_restitution = real(v);
                }),
            make(
                "collision.sphere_restitution", Scope::Body, ValueKind::Real, "", Default::Yes,
                kUnitInterval, "Restitution e_sphere of sphere-sphere impulses",
                [](const SceneSpec& s, const Ctx&) -> Value {
                  return cloth_collisions(s).sphere_restitution;
                },
                [](SceneSpec& s, const Ctx&, const Value& v) {
                  cloth_collisions(s).sphere_restitution = real(v);
                }),
            make(
                "collision.tolerance", Scope::Body, ValueKind::Real, "m", Default::Yes,
                kNonNegative,
                "Tolerance ε: a pair collides when its gap φ < ε and it approaches (both kinds of "
                "pair)",
                [](const SceneSpec& s, const Ctx&) -> Value {
                  return cloth_collisions(s).tolerance;
                },
                [](SceneSpec& s, const Ctx&, const Value& v) {
                  cloth_collisions(s).tolerance = real(v);
                }),
            make(
                "collision.friction", Scope::Body, ValueKind::Real, "", Default::Yes, kNonNegative,
                "Coulomb friction μ of every pair's impulse (the course's bonus; 0: none)",
                [](const SceneSpec& s, const Ctx&) -> Value {
                  return cloth_collisions(s).friction;
                },
                [](SceneSpec& s, const Ctx&, const Value& v) {
                  cloth_collisions(s).friction = real(v);
                }),
            make(
                "collision.push_out", Scope::Body, ValueKind::Real, "", Default::Yes, kUnitInterval,
                "Push-out β: a particle inside a sphere moves the share β of its depth out (0: "
                "none)",
                [](const SceneSpec& s, const Ctx&) -> Value {
                  return cloth_collisions(s).push_out;
                },
                [](SceneSpec& s, const Ctx&, const Value& v) {
                  cloth_collisions(s).push_out = real(v);
                }),
        });
  }

  std::vector<Collection> collections() const override {
    // [[sphere]]: a cloth scene's spheres, named by their position: sphere.0.radius. Kinematic
    // is read first, since it decides which keys apply (velocity and mass for a dynamic sphere,
    // schedule for a kinematic one).
    Collection c =
        collection("sphere", "<i>", "sphere", Layout::Indexed, sphere_names, sphere_rows());
    c.append = [](SceneSpec& s) { sphere_specs(s).emplace_back(); };
    c.first_key = "kinematic";
    return {std::move(c)};
  }

  std::string foreign_key(const std::string& key, const std::string&,
                          std::string_view scene_body) const override {
    return key + " is a key of cloth scenes (body.type = \"cloth\"), and this scene's body is " +
           std::string(scene_body);
  }
  bool explains_foreign_keys() const override { return true; }
  std::string foreign_section(std::string_view section,
                              std::string_view scene_body) const override {
    const std::string body = "this scene's body is " + std::string(scene_body);
    if (section == "sphere")
      return "[[sphere]] belongs to cloth scenes (body.type = \"cloth\"), and " + body +
             " (a cube meets spheres as terrains: [[terrain]] type = \"sphere\")";
    return BodyKindModule::foreign_section(section, scene_body);
  }
  std::optional<std::string> refuses_section(std::string_view section) const override {
    if (section == "terrain")
      return std::string(
          "a cloth scene has no terrains (cloth contract §6): the cloth meets spheres, "
          "[[sphere]]");
    return std::nullopt;
  }

  /// A cloth has no body diagonals (cloth contract §2): its spring types.
  std::vector<SpringType> spring_types() const override {
    return {SpringType::Structural, SpringType::Shear, SpringType::Bending};
  }
  void spring_defaults(SpringSettings& st) const override {
    st.ks = kClothDefaultKs;  // cloth contract decision 10
    st.kd = kClothDefaultKd;
  }

  std::optional<CrossError> check(const SceneSpec& s) const override {
    const ClothSpec& c = cloth_spec(s);
    for (std::size_t i = 0; i < c.pins.size(); ++i)
      if (c.pins[i][0] < 0 || c.pins[i][1] < 0 || c.pins[i][0] >= c.n || c.pins[i][1] >= c.n)
        return CrossError{"body.pin_points", pin_message(i, c.pins[i][0], c.pins[i][1], c.n)};
    if (!s.terrains.empty())
      return CrossError{"terrain",
                        "a cloth scene has no terrains (cloth contract §6); got terrain " +
                            in_quotes(s.terrains.front().name) +
                            " (the cloth meets spheres: [[sphere]])"};
    if (s.shear_body.enabled)
      return CrossError{"springs.shear_body",
                        "a cloth has no body diagonals; its spring types are structural, shear "
                        "and bending"};
    for (std::size_t i = 0; i < sphere_specs(s).size(); ++i)
      if (auto msg = schedule_order(sphere_specs(s)[i].schedule))
        return CrossError{"sphere." + std::to_string(i) + ".schedule", *msg};
    return std::nullopt;
  }
  std::optional<CrossError> check_absent(const SceneSpec& s) const override {
    if (sphere_specs(s).empty()) return std::nullopt;
    return CrossError{"sphere",
                      "spheres ([[sphere]]) belong to cloth scenes (body.type = "
                      "\"cloth\"), and this scene's body is " +
                          std::string(s.body_kind.name)};
  }

  void build(const SceneSpec& scene, World& world) const override {
    // Cloth contract §1–§4: the cloth, its springs type by type (structural, shear, bending:
    // decision 9's order), the spheres in scene order (it is part of the result), the collision
    // coefficients and gravity. A cloth scene has no terrains (the reader refuses them).
    ClothPhysics& physics = cloth_physics(world);  // installed in the empty world
    const int cloth = physics.add_cloth(cloth_spec(scene));
    if (scene.structural.enabled)
      physics.build_cloth_springs(cloth, SpringType::Structural, scene.structural.ks,
                                  scene.structural.kd);
    if (scene.shear.enabled)
      physics.build_cloth_springs(cloth, SpringType::Shear, scene.shear.ks, scene.shear.kd);
    if (scene.bending.enabled)
      physics.build_cloth_springs(cloth, SpringType::Bending, scene.bending.ks, scene.bending.kd);
    for (const SphereSpec& sphere : sphere_specs(scene)) physics.add_sphere(sphere);
    physics.set_cloth_collisions(cloth_collisions(scene));
    world.set_gravity(scene.gravity);
  }

  // ----- what a run reports -----
  std::string summary_header(const World& world) const override {
    return cloth_summary_header(cloth_physics(world).sphere_count());
  }
  std::string_view run_help(std::string_view option) const override {
    return option == "--summary"
               ? "\n                      (a cloth scene: the cloth's, then lowest_y and each "
                 "sphere's\n                      sphere<i>_x,_y,_z,_vx,_vy,_vz)"
               : "";
  }
  void write_summary(CsvWriter& out, const World& world, const State& s, double t) const override {
    out.write_row(cloth_summary_row(summarize_cloth(world, s, t)));
  }
  /// The end of a cloth scene's run (cloth contract decision 12): the cloth's centre of mass
  /// (pinned particles included), kinetic energy, largest speed and lowest y, and each sphere.
  std::string end_report(const SceneSpec& scene, const Simulator& sim, double wall) const override {
    const World& w = sim.world();
    const ClothPhysics& cloth = cloth_physics(w);
    const ClothFrameSummary end = summarize_cloth(w, sim.state(), sim.time());
    const FrameSummary& c = end.cloth;
    std::string out = text_printf(
        "%s: %ld steps of %s, h = %g s, %g s simulated in %.3f s (%.0f steps/s)\n"
        "  cloth of %lld particles, %zu springs, %d %s; %ld acceleration evaluations\n"
        "  cloth: final centre of mass (%.6f, %.6f, %.6f), lowest y %.6f, largest speed %.4g m/s\n"
        "  energy: cloth kinetic %.6g J, cloth gravitational %.6g J, spring %.6g J\n",
        scene.name.c_str(), sim.steps(), std::string(to_string(scene.integrator)).c_str(),
        sim.options().dt, sim.time(), wall,
        wall > 0 ? static_cast<double>(sim.steps()) / wall : 0.0,
        static_cast<long long>(cloth.cloth_particle_count()), w.spring_count(),
        cloth.sphere_count(), cloth.sphere_count() == 1 ? "sphere" : "spheres", sim.evaluations(),
        c.com.x(), c.com.y(), c.com.z(), end.lowest_y, c.max_speed, c.kinetic, c.potential,
        c.spring);
    for (int k = 0; k < cloth.sphere_count(); ++k) {
      const Vec3& p = end.sphere_centers[static_cast<std::size_t>(k)];
      const Vec3& u = end.sphere_velocities[static_cast<std::size_t>(k)];
      out +=
          text_printf("  sphere %d (%s): centre (%.6f, %.6f, %.6f), velocity (%.6f, %.6f, %.6f)\n",
                      k, cloth.sphere_is_kinematic(k) ? "kinematic" : "dynamic", p.x(), p.y(),
                      p.z(), u.x(), u.y(), u.z());
    }
    return out;
  }
  // ----- the smoke tests of the slots that build its springs -----
  std::vector<std::string_view> probe_slots() const override { return cloth_probe_slots(); }
  TaskStatus probe_slot(std::string_view slot, std::string id, std::string name,
                        const TaskTable& tasks) const override {
    return probe_cloth_slot(slot, std::move(id), std::move(name), tasks);
  }

  // ----- what the studies measure on it (cloth contract decision 12: the cloth, not the
  // dynamic spheres that follow it in the state) -----
  Eigen::Index measured_particles(const World& world) const override {
    return cloth_physics(world).cloth_particle_count();
  }
  std::unique_ptr<BodyStudy> study(const World& world, const State& start, const StudyLook& look,
                                   const std::vector<std::string>& measures) const override {
    return make_cloth_study(world, start, look, measures);
  }
  const std::vector<BodyMeasure>& measures() const override { return cloth_measures(); }
  std::string_view contact_help() const override { return cloth_contact_help(); }

  /// Cloth contract §1, §3: the pinned particles and the spheres, in scene order.
  std::string check_report(const SceneSpec& scene, const World& world) const override {
    const ClothPhysics& cloth = cloth_physics(world);
    long long pinned = 0;
    for (Eigen::Index i = 0; i < cloth.cloth_particle_count(); ++i)
      pinned += cloth.is_pinned(static_cast<int>(i)) ? 1 : 0;
    const int spheres = cloth.sphere_count();
    std::string out =
        text_printf(" (%lld pinned); gravity %s; %d %s", pinned, scene.gravity ? "on" : "off",
                    spheres, spheres == 1 ? "sphere" : "spheres");
    for (int k = 0; k < cloth.sphere_count(); ++k) {
      const SphereBody b = cloth.sphere(k);
      if (cloth.sphere_is_kinematic(k)) {
        out += text_printf(" [%d kinematic r %g]", k, b.radius);
      } else {
        out += text_printf(" [%d dynamic r %g, %g kg]", k, b.radius, 1.0 / b.inverse_mass);
      }
    }
    return out;
  }
  std::string_view stability_reason() const override {
    return "since the cloth stretches as it sags and hits spheres";
  }
};

}  // namespace

const BodyKindModule& cloth_kind() {
  static const ClothKind kind;
  return kind;
}

}  // namespace jelly::bodies
