// The declaration table: every scene parameter, declared once (house style §14).
//
// Each row gives the key (with '*' for a spring type or a terrain name), when it applies, its
// value kind, unit, whether it has a default, valid range, a one-line description, and how it is
// read from and written to a SceneSpec. Defaults are not typed here: they are read from the
// default-constructed structs of jelly/scene_spec.hpp and jelly/terrain.hpp, so each is written
// once. The loader (scene_loader.cpp), set_parameter, get_parameter, scene_parameters, to_toml and
// docs/scenes.md all go through these rows. Also here: resolving a dotted key against a scene.
#include <algorithm>
#include <cmath>
#include <limits>
#include <string>

#include "param_table.hpp"

namespace jelly::params_detail {

namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();

/// A valid range: [min, max] with each side inclusive or not; `bounded` false means any finite
/// value.
struct Range {
  bool bounded = false;
  double min = -kInf;
  double max = kInf;
  bool min_inclusive = true;
  bool max_inclusive = true;
};
constexpr Range kAny{};
constexpr Range kPositive{true, 0.0, kInf, false, true};
constexpr Range kNonNegative{true, 0.0, kInf, true, true};
constexpr Range kUnitInterval{true, 0.0, 1.0, true, true};
constexpr Range kCubeN{true, 2.0, 64.0, true, true};

using Getter = Value (*)(const SceneSpec&, const Ctx&);
using Setter = void (*)(SceneSpec&, const Ctx&, const Value&);

/// Whether a row has a default. Its value is never typed in the table: it is read from
/// default-constructed scene structs (see with_defaults).
enum class Default { Yes, None };

Decl make(std::string_view pattern, Scope scope, ValueKind kind, std::string_view unit, Default def,
          Range range, std::string_view description, Getter get, Setter set,
          std::vector<std::string_view> choices = {}, bool nonzero = false) {
  Decl d;
  d.pattern = pattern;
  d.scope = scope;
  d.kind = kind;
  d.unit = unit;
  d.has_default = def == Default::Yes;
  d.bounded = range.bounded;
  d.min = range.min;
  d.max = range.max;
  d.min_inclusive = range.min_inclusive;
  d.max_inclusive = range.max_inclusive;
  d.nonzero = nonzero;
  d.choices = std::move(choices);
  d.description = description;
  d.get = get;
  d.set = set;
  return d;
}

// ----- accessors shared by several rows -----

Terrain& terrain(SceneSpec& s, const Ctx& c) { return s.terrains[c.terrain]; }
const Terrain& terrain(const SceneSpec& s, const Ctx& c) { return s.terrains[c.terrain]; }
SurfaceProperties& surface(SceneSpec& s, const Ctx& c) {
  return std::visit([](auto& shape) -> SurfaceProperties& { return shape.surface; },
                    terrain(s, c).shape);
}
Plane& plane(SceneSpec& s, const Ctx& c) { return std::get<Plane>(terrain(s, c).shape); }
const Plane& plane(const SceneSpec& s, const Ctx& c) {
  return std::get<Plane>(terrain(s, c).shape);
}
Bowl& bowl(SceneSpec& s, const Ctx& c) { return std::get<Bowl>(terrain(s, c).shape); }
const Bowl& bowl(const SceneSpec& s, const Ctx& c) { return std::get<Bowl>(terrain(s, c).shape); }
Sphere& sphere(SceneSpec& s, const Ctx& c) { return std::get<Sphere>(terrain(s, c).shape); }
const Sphere& sphere(const SceneSpec& s, const Ctx& c) {
  return std::get<Sphere>(terrain(s, c).shape);
}

double real(const Value& v) { return std::get<double>(v); }
const Vec3& vec(const Value& v) { return std::get<Vec3>(v); }
bool flag(const Value& v) { return std::get<bool>(v); }
const std::string& text(const Value& v) { return std::get<std::string>(v); }

/// Unit normal of what a scene gives. A vector already unit length to within a few ulps is kept
/// as it is, so that writing a scene and reading it back gives the same bits.
Vec3 normalised(const Vec3& n) {
  const double len = n.norm();
  if (std::abs(len - 1.0) <= 4.0 * std::numeric_limits<double>::epsilon()) return n;
  return n / len;
}

std::vector<Vec3> columns(const Vec3Array& a) {
  std::vector<Vec3> out;
  out.reserve(static_cast<std::size_t>(a.cols()));
  for (Eigen::Index i = 0; i < a.cols(); ++i) out.emplace_back(a.col(i));
  return out;
}
Vec3Array matrix(const std::vector<Vec3>& v) {
  Vec3Array out(3, static_cast<Eigen::Index>(v.size()));
  for (std::size_t i = 0; i < v.size(); ++i) out.col(static_cast<Eigen::Index>(i)) = v[i];
  return out;
}

// The scene whose values are the defaults: default-constructed structs (no gravity, as a scene
// without a [gravity] table), with gravity's default acceleration for the rows that need gravity
// and one terrain of the row's shape, so that every row reads its default from what the structs
// say.
SceneSpec defaults_scene(Scope scope) {
  SceneSpec s;
  if (scope == Scope::GravityOn) s.gravity = default_gravity();
  Terrain t;
  t.name = "default";
  if (scope == Scope::Bowl) t.shape = Bowl{};
  if (scope == Scope::Sphere) t.shape = Sphere{};
  s.terrains.push_back(std::move(t));
  return s;
}

// A table with each row's default text filled in from defaults_scene.
std::vector<Decl> with_defaults(std::vector<Decl> table) {
  for (Decl& d : table)
    if (d.has_default) d.default_text = format_text(d.kind, d.get(defaults_scene(d.scope), Ctx{}));
  return table;
}

std::vector<std::string_view> integrator_names() {
  std::vector<std::string_view> out;
  for (IntegratorKind k : kAllIntegrators) out.push_back(to_string(k));
  return out;
}

}  // namespace

// ----- the table -----

const std::vector<Decl>& global_decls() {
  static const std::vector<Decl> table = with_defaults({
      // [scene]
      make(
          "scene.name", Scope::Always, ValueKind::Text, "", Default::None, kAny,
          "Name shown by the viewer and written into results",
          [](const SceneSpec& s, const Ctx&) -> Value { return s.name; },
          [](SceneSpec& s, const Ctx&, const Value& v) { s.name = text(v); }),
      make(
          "scene.description", Scope::Always, ValueKind::Text, "", Default::None, kAny,
          "What the scene shows, one or two sentences",
          [](const SceneSpec& s, const Ctx&) -> Value { return s.description; },
          [](SceneSpec& s, const Ctx&, const Value& v) { s.description = text(v); }),
      // [simulation]
      make(
          "simulation.integrator", Scope::Always, ValueKind::Choice, "", Default::Yes, kAny,
          "Time integrator (explicit_euler, implicit_euler, midpoint, rk4 are student tasks)",
          [](const SceneSpec& s, const Ctx&) -> Value {
            return std::string(to_string(s.integrator));
          },
          [](SceneSpec& s, const Ctx&, const Value& v) {
            s.integrator = *integrator_from_string(text(v));
          },
          integrator_names()),
      make(
          "simulation.dt", Scope::Always, ValueKind::Real, "s", Default::Yes, kPositive,
          "Fixed time step h", [](const SceneSpec& s, const Ctx&) -> Value { return s.dt; },
          [](SceneSpec& s, const Ctx&, const Value& v) { s.dt = real(v); }),
      make(
          "simulation.duration", Scope::Always, ValueKind::Real, "s", Default::Yes, kPositive,
          "Simulated time a run covers",
          [](const SceneSpec& s, const Ctx&) -> Value { return s.duration; },
          [](SceneSpec& s, const Ctx&, const Value& v) { s.duration = real(v); }),
      make(
          "simulation.auto_dt", Scope::Always, ValueKind::Bool, "", Default::Yes, kAny,
          "Choose the step automatically: the largest h <= dt that the stability estimate allows "
          "for the integrator (half its limit), with whole substeps per 1/60 s frame",
          [](const SceneSpec& s, const Ctx&) -> Value { return s.auto_dt; },
          [](SceneSpec& s, const Ctx&, const Value& v) { s.auto_dt = flag(v); }),
      // [gravity]
      make(
          "gravity.enabled", Scope::Always, ValueKind::Bool, "", Default::Yes, kAny,
          "Whether the scene has gravity (a [gravity] table); true adds it with the default "
          "acceleration",
          [](const SceneSpec& s, const Ctx&) -> Value { return s.gravity.has_value(); },
          [](SceneSpec& s, const Ctx&, const Value& v) {
            if (!flag(v)) {
              s.gravity.reset();
            } else if (!s.gravity) {
              s.gravity = default_gravity();
            }
          }),
      make(
          "gravity.acceleration", Scope::GravityOn, ValueKind::Vector3, "m/s^2", Default::Yes, kAny,
          "Constant gravitational acceleration g (y is up)",
          [](const SceneSpec& s, const Ctx&) -> Value { return *s.gravity; },
          [](SceneSpec& s, const Ctx&, const Value& v) { s.gravity = vec(v); }),
      // [body]
      make(
          "body.type", Scope::Always, ValueKind::Choice, "", Default::Yes, kAny,
          "The body: a jelly cube, or particles given one by one",
          [](const SceneSpec& s, const Ctx&) -> Value {
            return std::string(s.body_kind == BodyKind::Cube ? "cube" : "particles");
          },
          [](SceneSpec& s, const Ctx&, const Value& v) {
            s.body_kind = text(v) == "cube" ? BodyKind::Cube : BodyKind::Particles;
          },
          {"cube", "particles"}),
      make(
          "body.n", Scope::Cube, ValueKind::Integer, "", Default::Yes, kCubeN,
          "Particles per cube edge (n³ particles)",
          [](const SceneSpec& s, const Ctx&) -> Value { return static_cast<long long>(s.cube.n); },
          [](SceneSpec& s, const Ctx&, const Value& v) {
            s.cube.n = static_cast<int>(std::get<long long>(v));
          }),
      make(
          "body.edge", Scope::Cube, ValueKind::Real, "m", Default::Yes, kPositive,
          "Cube edge length L", [](const SceneSpec& s, const Ctx&) -> Value { return s.cube.edge; },
          [](SceneSpec& s, const Ctx&, const Value& v) { s.cube.edge = real(v); }),
      make(
          "body.mass", Scope::Cube, ValueKind::Real, "kg", Default::Yes, kPositive,
          "Mass of every particle",
          [](const SceneSpec& s, const Ctx&) -> Value { return s.cube.mass; },
          [](SceneSpec& s, const Ctx&, const Value& v) { s.cube.mass = real(v); }),
      make(
          "body.center", Scope::Cube, ValueKind::Vector3, "m", Default::Yes, kAny,
          "Initial centre c0; the grid is centred exactly on it",
          [](const SceneSpec& s, const Ctx&) -> Value { return s.cube.center; },
          [](SceneSpec& s, const Ctx&, const Value& v) { s.cube.center = vec(v); }),
      make(
          "body.velocity", Scope::Cube, ValueKind::Vector3, "m/s", Default::Yes, kAny,
          "Initial velocity of every particle (not rotated)",
          [](const SceneSpec& s, const Ctx&) -> Value { return s.cube.velocity; },
          [](SceneSpec& s, const Ctx&, const Value& v) { s.cube.velocity = vec(v); }),
      make(
          "body.rotation_axis", Scope::Cube, ValueKind::Vector3, "", Default::Yes, kAny,
          "Axis of the initial rotation about c0 (normalised when used)",
          [](const SceneSpec& s, const Ctx&) -> Value { return s.cube.rotation_axis; },
          [](SceneSpec& s, const Ctx&, const Value& v) { s.cube.rotation_axis = vec(v); }, {},
          /*nonzero=*/true),
      make(
          "body.rotation_degrees", Scope::Cube, ValueKind::Real, "deg", Default::Yes, kAny,
          "Initial rotation angle about rotation_axis, right-hand rule",
          [](const SceneSpec& s, const Ctx&) -> Value { return s.cube.rotation_degrees; },
          [](SceneSpec& s, const Ctx&, const Value& v) { s.cube.rotation_degrees = real(v); }),
      make(
          "body.mass", Scope::Particles, ValueKind::Real, "kg", Default::Yes, kPositive,
          "Mass of every particle",
          [](const SceneSpec& s, const Ctx&) -> Value { return s.particles.mass; },
          [](SceneSpec& s, const Ctx&, const Value& v) { s.particles.mass = real(v); }),
      make(
          "body.positions", Scope::Particles, ValueKind::Vec3List, "m", Default::None, kAny,
          "Initial positions, at least one; text form \"x,y,z; x,y,z\"",
          [](const SceneSpec& s, const Ctx&) -> Value { return columns(s.particles.positions); },
          [](SceneSpec& s, const Ctx&, const Value& v) {
            s.particles.positions = matrix(std::get<std::vector<Vec3>>(v));
            // A different count makes the old velocities meaningless: start at rest.
            if (s.particles.velocities.cols() != s.particles.positions.cols())
              s.particles.velocities = Vec3Array::Zero(3, s.particles.positions.cols());
          }),
      make(
          "body.velocities", Scope::Particles, ValueKind::Vec3List, "m/s", Default::None, kAny,
          "Initial velocities, one per position (optional: zero)",
          [](const SceneSpec& s, const Ctx&) -> Value { return columns(s.particles.velocities); },
          [](SceneSpec& s, const Ctx&, const Value& v) {
            s.particles.velocities = matrix(std::get<std::vector<Vec3>>(v));
          }),
      make(
          "body.springs", Scope::Particles, ValueKind::IndexPairList, "", Default::None, kAny,
          "Springs as pairs of particle indices (0-based, a ≠ b); text form \"a,b; a,b\"",
          [](const SceneSpec& s, const Ctx&) -> Value {
            std::vector<IndexPair> out;
            for (const Spring& sp : s.particles.springs) out.push_back({sp.a, sp.b});
            return out;
          },
          [](SceneSpec& s, const Ctx&, const Value& v) {
            // A spring that is unchanged (same pair at the same place in the list) keeps its
            // rest length; a new one rests at the distance between the current positions.
            const Vec3Array& x = s.particles.positions;
            const std::vector<Spring>& old = s.particles.springs;
            std::vector<Spring> springs;
            for (const IndexPair& p : std::get<std::vector<IndexPair>>(v)) {
              Spring sp{static_cast<int>(p[0]), static_cast<int>(p[1]),
                        std::numeric_limits<double>::quiet_NaN()};
              const std::size_t k = springs.size();
              if (k < old.size() && old[k].a == sp.a && old[k].b == sp.b)
                sp.rest_length = old[k].rest_length;
              else if (p[0] >= 0 && p[1] >= 0 && p[0] < x.cols() && p[1] < x.cols())
                sp.rest_length = (x.col(sp.a) - x.col(sp.b)).norm();
              springs.push_back(sp);
            }
            s.particles.springs = std::move(springs);
          }),
      make(
          "body.rest_lengths", Scope::Particles, ValueKind::RealList, "m", Default::None, kPositive,
          "Rest length of each spring, one per spring (optional: the initial distance)",
          [](const SceneSpec& s, const Ctx&) -> Value {
            std::vector<double> out;
            for (const Spring& sp : s.particles.springs) out.push_back(sp.rest_length);
            return out;
          },
          [](SceneSpec& s, const Ctx&, const Value& v) {
            const auto& r = std::get<std::vector<double>>(v);
            for (std::size_t i = 0; i < r.size() && i < s.particles.springs.size(); ++i)
              s.particles.springs[i].rest_length = r[i];
          }),
      make(
          "body.spring_type", Scope::Particles, ValueKind::Choice, "", Default::Yes, kAny,
          "Whose coefficients the springs use; that [springs.<type>] table must be present",
          [](const SceneSpec& s, const Ctx&) -> Value {
            return std::string(to_string(s.particles.spring_type));
          },
          [](SceneSpec& s, const Ctx&, const Value& v) {
            s.particles.spring_type = *spring_type_from_string(text(v));
          },
          {"structural", "shear", "shear_body", "bending"}),
  });
  return table;
}

const std::vector<Decl>& spring_decls() {
  static const std::vector<Decl> table = with_defaults({
      make(
          "springs.*.enabled", Scope::SpringAny, ValueKind::Bool, "", Default::Yes, kAny,
          "Whether springs of this type are built (the table is present); true adds them with "
          "the default coefficients",
          [](const SceneSpec& s, const Ctx& c) -> Value {
            return spring_settings(s, c.spring).enabled;
          },
          [](SceneSpec& s, const Ctx& c, const Value& v) {
            SpringSettings& st = spring_settings(s, c.spring);
            if (flag(v) == st.enabled) return;
            st = SpringSettings{};  // on: defaults; off: back to the normal form of an absent table
            st.enabled = flag(v);
          }),
      make(
          "springs.*.ks", Scope::SpringOn, ValueKind::Real, "N/m", Default::Yes, kNonNegative,
          "Stiffness of every spring of this type",
          [](const SceneSpec& s, const Ctx& c) -> Value { return spring_settings(s, c.spring).ks; },
          [](SceneSpec& s, const Ctx& c, const Value& v) {
            spring_settings(s, c.spring).ks = real(v);
          }),
      make(
          "springs.*.kd", Scope::SpringOn, ValueKind::Real, "N*s/m", Default::Yes, kNonNegative,
          "Damping along every spring of this type",
          [](const SceneSpec& s, const Ctx& c) -> Value { return spring_settings(s, c.spring).kd; },
          [](SceneSpec& s, const Ctx& c, const Value& v) {
            spring_settings(s, c.spring).kd = real(v);
          }),
  });
  return table;
}

const std::vector<Decl>& terrain_decls() {
  static const std::vector<Decl> table = with_defaults({
      make(
          "terrain.*.type", Scope::TerrainAny, ValueKind::Choice, "", Default::None, kAny,
          "Shape: plane, bowl (inside of a sphere below a rim) or sphere (obstacle); changing it "
          "keeps the surface and takes the new shape's default geometry",
          [](const SceneSpec& s, const Ctx& c) -> Value {
            return std::string(terrain_type_name(terrain(s, c)));
          },
          [](SceneSpec& s, const Ctx& c, const Value& v) {
            Terrain& t = terrain(s, c);
            if (terrain_type_name(t) == text(v)) return;
            Terrain fresh = default_terrain(t.name, text(v));
            const SurfaceProperties keep = t.surface();
            fresh.collision = t.collision;
            fresh.contact = t.contact;
            fresh.project = t.project;
            t = std::move(fresh);
            surface(s, c) = keep;
          },
          {"plane", "bowl", "sphere"}),
      // Plane geometry
      make(
          "terrain.*.point", Scope::Plane, ValueKind::Vector3, "m", Default::Yes, kAny,
          "A point p on the plane",
          [](const SceneSpec& s, const Ctx& c) -> Value { return plane(s, c).point; },
          [](SceneSpec& s, const Ctx& c, const Value& v) { plane(s, c).point = vec(v); }),
      make(
          "terrain.*.normal", Scope::Plane, ValueKind::Vector3, "", Default::Yes, kAny,
          "Plane normal N (normalised by the loader)",
          [](const SceneSpec& s, const Ctx& c) -> Value { return plane(s, c).normal; },
          [](SceneSpec& s, const Ctx& c, const Value& v) {
            plane(s, c).normal = normalised(vec(v));
          },
          {}, /*nonzero=*/true),
      make(
          "terrain.*.hole_center", Scope::PlaneHole, ValueKind::Vector3, "m", Default::None, kAny,
          "Centre h of a circular hole, on the plane (give with hole_radius, or neither)",
          [](const SceneSpec& s, const Ctx& c) -> Value { return plane(s, c).hole_center; },
          [](SceneSpec& s, const Ctx& c, const Value& v) { plane(s, c).hole_center = vec(v); }),
      make(
          "terrain.*.hole_radius", Scope::PlaneHole, ValueKind::Real, "m", Default::None, kPositive,
          "Radius r_h of the hole, measured in the plane (give with hole_center, or neither)",
          [](const SceneSpec& s, const Ctx& c) -> Value { return plane(s, c).hole_radius; },
          [](SceneSpec& s, const Ctx& c, const Value& v) { plane(s, c).hole_radius = real(v); }),
      // Bowl geometry
      make(
          "terrain.*.center", Scope::Bowl, ValueKind::Vector3, "m", Default::Yes, kAny,
          "Centre c of the bowl's sphere",
          [](const SceneSpec& s, const Ctx& c) -> Value { return bowl(s, c).center; },
          [](SceneSpec& s, const Ctx& c, const Value& v) { bowl(s, c).center = vec(v); }),
      make(
          "terrain.*.radius", Scope::Bowl, ValueKind::Real, "m", Default::Yes, kPositive,
          "Radius R of the bowl's sphere",
          [](const SceneSpec& s, const Ctx& c) -> Value { return bowl(s, c).radius; },
          [](SceneSpec& s, const Ctx& c, const Value& v) { bowl(s, c).radius = real(v); }),
      make(
          "terrain.*.rim_height", Scope::Bowl, ValueKind::Real, "m", Default::Yes, kAny,
          "Height y of the rim plane; needs center.y - radius < rim_height <= center.y",
          [](const SceneSpec& s, const Ctx& c) -> Value { return bowl(s, c).rim_height; },
          [](SceneSpec& s, const Ctx& c, const Value& v) { bowl(s, c).rim_height = real(v); }),
      // Sphere geometry
      make(
          "terrain.*.center", Scope::Sphere, ValueKind::Vector3, "m", Default::Yes, kAny,
          "Centre of the sphere obstacle",
          [](const SceneSpec& s, const Ctx& c) -> Value { return sphere(s, c).center; },
          [](SceneSpec& s, const Ctx& c, const Value& v) { sphere(s, c).center = vec(v); }),
      make(
          "terrain.*.radius", Scope::Sphere, ValueKind::Real, "m", Default::Yes, kPositive,
          "Radius of the sphere obstacle",
          [](const SceneSpec& s, const Ctx& c) -> Value { return sphere(s, c).radius; },
          [](SceneSpec& s, const Ctx& c, const Value& v) { sphere(s, c).radius = real(v); }),
      // Surface, every terrain
      make(
          "terrain.*.epsilon", Scope::TerrainAny, ValueKind::Real, "m", Default::Yes, kPositive,
          "Collision tolerance ε",
          [](const SceneSpec& s, const Ctx& c) -> Value { return terrain(s, c).surface().epsilon; },
          [](SceneSpec& s, const Ctx& c, const Value& v) { surface(s, c).epsilon = real(v); }),
      make(
          "terrain.*.restitution", Scope::TerrainAny, ValueKind::Real, "", Default::Yes,
          kUnitInterval,
          "Coefficient of restitution k_r: the share of normal velocity kept, reversed",
          [](const SceneSpec& s, const Ctx& c) -> Value {
            return terrain(s, c).surface().restitution;
          },
          [](SceneSpec& s, const Ctx& c, const Value& v) { surface(s, c).restitution = real(v); }),
      make(
          "terrain.*.friction", Scope::TerrainAny, ValueKind::Real, "s/m", Default::Yes,
          kNonNegative, "Friction coefficient k_f: friction = -k_f (-N·f) v_T",
          [](const SceneSpec& s, const Ctx& c) -> Value {
            return terrain(s, c).surface().friction;
          },
          [](SceneSpec& s, const Ctx& c, const Value& v) { surface(s, c).friction = real(v); }),
      make(
          "terrain.*.collision", Scope::TerrainAny, ValueKind::Bool, "", Default::Yes, kAny,
          "Apply the collision velocity response at the start of each step",
          [](const SceneSpec& s, const Ctx& c) -> Value { return terrain(s, c).collision; },
          [](SceneSpec& s, const Ctx& c, const Value& v) { terrain(s, c).collision = flag(v); }),
      make(
          "terrain.*.contact", Scope::TerrainAny, ValueKind::Bool, "", Default::Yes, kAny,
          "Add the contact and friction forces in every evaluation",
          [](const SceneSpec& s, const Ctx& c) -> Value { return terrain(s, c).contact; },
          [](SceneSpec& s, const Ctx& c, const Value& v) { terrain(s, c).contact = flag(v); }),
      make(
          "terrain.*.project", Scope::TerrainAny, ValueKind::Bool, "", Default::Yes, kAny,
          "After the response, move particles behind the surface onto it (not in the course)",
          [](const SceneSpec& s, const Ctx& c) -> Value { return terrain(s, c).project; },
          [](SceneSpec& s, const Ctx& c, const Value& v) { terrain(s, c).project = flag(v); }),
  });
  return table;
}

// ----- small helpers -----

const Decl* find_decl(std::string_view pattern) {
  for (const auto* table : {&global_decls(), &spring_decls(), &terrain_decls()})
    for (const Decl& d : *table)
      if (d.pattern == pattern) return &d;
  return nullptr;
}

SpringSettings& spring_settings(SceneSpec& s, SpringType t) {
  switch (t) {
    case SpringType::Structural: return s.structural;
    case SpringType::Shear: return s.shear;
    case SpringType::ShearBody: return s.shear_body;
    case SpringType::Bending: return s.bending;
  }
  return s.structural;
}
const SpringSettings& spring_settings(const SceneSpec& s, SpringType t) {
  return spring_settings(const_cast<SceneSpec&>(s), t);
}

std::optional<SpringType> spring_type_from_string(std::string_view name) {
  for (SpringType t : kSpringTypes)
    if (to_string(t) == name) return t;
  return std::nullopt;
}

std::string_view terrain_type_name(const Terrain& t) {
  if (std::holds_alternative<Plane>(t.shape)) return "plane";
  if (std::holds_alternative<Bowl>(t.shape)) return "bowl";
  return "sphere";
}

Terrain default_terrain(std::string_view name, std::string_view type) {
  Terrain t;
  t.name = std::string(name);
  if (type == "bowl") {
    t.shape = Bowl{};
  } else if (type == "sphere") {
    t.shape = Sphere{};
  } else {
    t.shape = Plane{};
  }
  return t;  // the structs' defaults, which the table's defaults are read from
}

bool applies(const Decl& d, const SceneSpec& s, const Ctx& c) {
  const bool has_terrain = c.terrain < s.terrains.size();
  switch (d.scope) {
    case Scope::Always: return true;
    case Scope::GravityOn: return s.gravity.has_value();
    case Scope::Cube: return s.body_kind == BodyKind::Cube;
    case Scope::Particles: return s.body_kind == BodyKind::Particles;
    case Scope::SpringAny: return true;
    case Scope::SpringOn: return spring_settings(s, c.spring).enabled;
    case Scope::TerrainAny: return has_terrain;
    case Scope::Plane:
      return has_terrain && std::holds_alternative<Plane>(s.terrains[c.terrain].shape);
    case Scope::PlaneHole:
      return has_terrain && std::holds_alternative<Plane>(s.terrains[c.terrain].shape) &&
             std::get<Plane>(s.terrains[c.terrain].shape).has_hole;
    case Scope::Bowl:
      return has_terrain && std::holds_alternative<Bowl>(s.terrains[c.terrain].shape);
    case Scope::Sphere:
      return has_terrain && std::holds_alternative<Sphere>(s.terrains[c.terrain].shape);
  }
  return false;
}

namespace {

std::vector<std::string_view> split_key(std::string_view key) {
  std::vector<std::string_view> parts;
  std::size_t start = 0;
  while (true) {
    const std::size_t dot = key.find('.', start);
    parts.push_back(key.substr(start, dot == std::string_view::npos ? dot : dot - start));
    if (dot == std::string_view::npos) break;
    start = dot + 1;
  }
  return parts;
}

std::string_view local_part(std::string_view pattern) {
  return pattern.substr(pattern.rfind('.') + 1);
}

std::optional<Bound> resolve_impl(const SceneSpec& s, std::string_view key, bool check_scope) {
  const auto parts = split_key(key);
  if (parts.size() == 2) {
    for (const Decl& d : global_decls())
      if (d.pattern == key && (!check_scope || applies(d, s, Ctx{})))
        return Bound{&d, Ctx{}, std::string(key)};
    return std::nullopt;
  }
  if (parts.size() != 3) return std::nullopt;
  if (parts[0] == "springs") {
    const auto type = spring_type_from_string(parts[1]);
    if (!type) return std::nullopt;
    const Ctx ctx{*type, 0};
    for (const Decl& d : spring_decls())
      if (local_part(d.pattern) == parts[2] && (!check_scope || applies(d, s, ctx)))
        return Bound{&d, ctx, std::string(key)};
    return std::nullopt;
  }
  if (parts[0] == "terrain") {
    for (std::size_t i = 0; i < s.terrains.size(); ++i) {
      if (s.terrains[i].name != parts[1]) continue;
      const Ctx ctx{SpringType::Structural, i};
      for (const Decl& d : terrain_decls())
        if (local_part(d.pattern) == parts[2] && (!check_scope || applies(d, s, ctx)))
          return Bound{&d, ctx, std::string(key)};
      return std::nullopt;
    }
  }
  return std::nullopt;
}

}  // namespace

std::optional<Bound> resolve(const SceneSpec& s, std::string_view key) {
  return resolve_impl(s, key, true);
}
std::optional<Bound> resolve_any(const SceneSpec& s, std::string_view key) {
  return resolve_impl(s, key, false);
}

std::string inapplicable_reason(const Bound& b, const SceneSpec& s) {
  const std::string local(local_part(b.decl->pattern));
  const auto terrain_label = [&] {
    const Terrain& t = s.terrains[b.ctx.terrain];
    return "terrain \"" + t.name + "\" is a " + std::string(terrain_type_name(t));
  };
  switch (b.decl->scope) {
    case Scope::GravityOn:
      return "the scene has no gravity (no [gravity] table); turn it on with gravity.enabled=true";
    case Scope::Cube: return local + " is a key of a cube body, and this scene's body is particles";
    case Scope::Particles:
      return local + " is a key of a particles body, and this scene's body is a cube";
    case Scope::SpringOn: {
      const std::string type(to_string(b.ctx.spring));
      return "the scene has no [springs." + type + "] table; add it with springs." + type +
             ".enabled=true";
    }
    case Scope::Plane: return local + " is a key of a plane terrain, and " + terrain_label();
    case Scope::PlaneHole:
      if (std::holds_alternative<Plane>(s.terrains[b.ctx.terrain].shape))
        return "terrain \"" + s.terrains[b.ctx.terrain].name +
               "\" has no hole; a hole needs both hole_center and hole_radius in the scene file";
      return local + " is a key of a plane terrain, and " + terrain_label();
    case Scope::Bowl: return local + " is a key of a bowl terrain, and " + terrain_label();
    case Scope::Sphere: return local + " is a key of a sphere terrain, and " + terrain_label();
    default: return "not a parameter of this scene";
  }
}

}  // namespace jelly::params_detail
