// The declaration table: every scene parameter, declared once (house style §14).
//
// Each row gives the key (with '*' for a spring type or a terrain name), when it applies, its
// value kind, unit, default, valid range, a one-line description, and how it is read from and
// written to a SceneSpec. The loader (scene_loader.cpp), set_parameter, get_parameter,
// scene_parameters, to_toml and docs/scenes.md all go through these rows.
#include <algorithm>
#include <charconv>
#include <cmath>
#include <limits>
#include <string>
#if defined(_LIBCPP_VERSION) && !defined(__cpp_lib_to_chars)
#include <locale>
#include <sstream>
#endif

#include "param_table.hpp"

namespace jelly {
namespace params_detail {

namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();

/// A valid range: [min, max] with each side inclusive or not; `bounded` false means any finite value.
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

Decl make(std::string_view pattern, Scope scope, ValueKind kind, std::string_view unit,
          std::string_view default_text, Range range, std::string_view description, Getter get,
          Setter set, std::vector<std::string_view> choices = {}, bool nonzero = false) {
  Decl d;
  d.pattern = pattern;
  d.scope = scope;
  d.kind = kind;
  d.unit = unit;
  d.default_text = default_text;
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
const Plane& plane(const SceneSpec& s, const Ctx& c) { return std::get<Plane>(terrain(s, c).shape); }
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

std::vector<std::string_view> integrator_names() {
  std::vector<std::string_view> out;
  for (IntegratorKind k : kAllIntegrators) out.push_back(to_string(k));
  return out;
}

}  // namespace

// ----- the table -----

const std::vector<Decl>& global_decls() {
  static const std::vector<Decl> table = {
      // [scene]
      make("scene.name", Scope::Always, ValueKind::Text, "", "", kAny,
           "Name shown by the viewer and written into results",
           [](const SceneSpec& s, const Ctx&) -> Value { return s.name; },
           [](SceneSpec& s, const Ctx&, const Value& v) { s.name = text(v); }),
      make("scene.description", Scope::Always, ValueKind::Text, "", "", kAny,
           "What the scene shows, one or two sentences",
           [](const SceneSpec& s, const Ctx&) -> Value { return s.description; },
           [](SceneSpec& s, const Ctx&, const Value& v) { s.description = text(v); }),
      // [simulation]
      make("simulation.integrator", Scope::Always, ValueKind::Choice, "", "explicit_euler", kAny,
           "Time integrator (explicit_euler, implicit_euler, midpoint, rk4 are student tasks)",
           [](const SceneSpec& s, const Ctx&) -> Value { return std::string(to_string(s.integrator)); },
           [](SceneSpec& s, const Ctx&, const Value& v) {
             s.integrator = *integrator_from_string(text(v));
           },
           integrator_names()),
      make("simulation.dt", Scope::Always, ValueKind::Real, "s", "0.001", kPositive,
           "Fixed time step h",
           [](const SceneSpec& s, const Ctx&) -> Value { return s.dt; },
           [](SceneSpec& s, const Ctx&, const Value& v) { s.dt = real(v); }),
      make("simulation.duration", Scope::Always, ValueKind::Real, "s", "10", kPositive,
           "Simulated time a run covers",
           [](const SceneSpec& s, const Ctx&) -> Value { return s.duration; },
           [](SceneSpec& s, const Ctx&, const Value& v) { s.duration = real(v); }),
      make("simulation.auto_dt", Scope::Always, ValueKind::Bool, "", "false", kAny,
           "Choose the step automatically: the largest h <= dt that the stability estimate allows "
           "for the integrator (half its limit), with whole substeps per 1/60 s frame",
           [](const SceneSpec& s, const Ctx&) -> Value { return s.auto_dt; },
           [](SceneSpec& s, const Ctx&, const Value& v) { s.auto_dt = flag(v); }),
      // [gravity]
      make("gravity.enabled", Scope::Always, ValueKind::Bool, "", "false", kAny,
           "Whether the scene has gravity (a [gravity] table); true adds it with the default "
           "acceleration",
           [](const SceneSpec& s, const Ctx&) -> Value { return s.gravity.has_value(); },
           [](SceneSpec& s, const Ctx&, const Value& v) {
             if (!flag(v)) {
               s.gravity.reset();
             } else if (!s.gravity) {
               // The default acceleration is the one declared for gravity.acceleration.
               const Decl& acc = *find_decl("gravity.acceleration");
               s.gravity = std::get<Vec3>(std::get<Value>(parse_text(acc, acc.default_text)));
             }
           }),
      make("gravity.acceleration", Scope::GravityOn, ValueKind::Vector3, "m/s^2", "0,-9.8,0", kAny,
           "Constant gravitational acceleration g (y is up)",
           [](const SceneSpec& s, const Ctx&) -> Value { return *s.gravity; },
           [](SceneSpec& s, const Ctx&, const Value& v) { s.gravity = vec(v); }),
      // [body]
      make("body.type", Scope::Always, ValueKind::Choice, "", "cube", kAny,
           "The body: a jelly cube, or particles given one by one",
           [](const SceneSpec& s, const Ctx&) -> Value {
             return std::string(s.body_kind == BodyKind::Cube ? "cube" : "particles");
           },
           [](SceneSpec& s, const Ctx&, const Value& v) {
             s.body_kind = text(v) == "cube" ? BodyKind::Cube : BodyKind::Particles;
           },
           {"cube", "particles"}),
      make("body.n", Scope::Cube, ValueKind::Integer, "", "10", kCubeN,
           "Particles per cube edge (n³ particles)",
           [](const SceneSpec& s, const Ctx&) -> Value { return static_cast<long long>(s.cube.n); },
           [](SceneSpec& s, const Ctx&, const Value& v) {
             s.cube.n = static_cast<int>(std::get<long long>(v));
           }),
      make("body.edge", Scope::Cube, ValueKind::Real, "m", "4", kPositive, "Cube edge length L",
           [](const SceneSpec& s, const Ctx&) -> Value { return s.cube.edge; },
           [](SceneSpec& s, const Ctx&, const Value& v) { s.cube.edge = real(v); }),
      make("body.mass", Scope::Cube, ValueKind::Real, "kg", "1", kPositive,
           "Mass of every particle",
           [](const SceneSpec& s, const Ctx&) -> Value { return s.cube.mass; },
           [](SceneSpec& s, const Ctx&, const Value& v) { s.cube.mass = real(v); }),
      make("body.center", Scope::Cube, ValueKind::Vector3, "m", "0,9,0", kAny,
           "Initial centre c0; the grid is centred exactly on it",
           [](const SceneSpec& s, const Ctx&) -> Value { return s.cube.center; },
           [](SceneSpec& s, const Ctx&, const Value& v) { s.cube.center = vec(v); }),
      make("body.velocity", Scope::Cube, ValueKind::Vector3, "m/s", "0,0,0", kAny,
           "Initial velocity of every particle (not rotated)",
           [](const SceneSpec& s, const Ctx&) -> Value { return s.cube.velocity; },
           [](SceneSpec& s, const Ctx&, const Value& v) { s.cube.velocity = vec(v); }),
      make("body.rotation_axis", Scope::Cube, ValueKind::Vector3, "", "1,0,1", kAny,
           "Axis of the initial rotation about c0 (normalised when used)",
           [](const SceneSpec& s, const Ctx&) -> Value { return s.cube.rotation_axis; },
           [](SceneSpec& s, const Ctx&, const Value& v) { s.cube.rotation_axis = vec(v); }, {},
           /*nonzero=*/true),
      make("body.rotation_degrees", Scope::Cube, ValueKind::Real, "deg", "0", kAny,
           "Initial rotation angle about rotation_axis, right-hand rule",
           [](const SceneSpec& s, const Ctx&) -> Value { return s.cube.rotation_degrees; },
           [](SceneSpec& s, const Ctx&, const Value& v) { s.cube.rotation_degrees = real(v); }),
      make("body.mass", Scope::Particles, ValueKind::Real, "kg", "1", kPositive,
           "Mass of every particle",
           [](const SceneSpec& s, const Ctx&) -> Value { return s.particles.mass; },
           [](SceneSpec& s, const Ctx&, const Value& v) { s.particles.mass = real(v); }),
      make("body.positions", Scope::Particles, ValueKind::Vec3List, "m", "", kAny,
           "Initial positions, at least one; text form \"x,y,z; x,y,z\"",
           [](const SceneSpec& s, const Ctx&) -> Value { return columns(s.particles.positions); },
           [](SceneSpec& s, const Ctx&, const Value& v) {
             s.particles.positions = matrix(std::get<std::vector<Vec3>>(v));
             // A different count makes the old velocities meaningless: start at rest.
             if (s.particles.velocities.cols() != s.particles.positions.cols())
               s.particles.velocities = Vec3Array::Zero(3, s.particles.positions.cols());
           }),
      make("body.velocities", Scope::Particles, ValueKind::Vec3List, "m/s", "", kAny,
           "Initial velocities, one per position (optional: zero)",
           [](const SceneSpec& s, const Ctx&) -> Value { return columns(s.particles.velocities); },
           [](SceneSpec& s, const Ctx&, const Value& v) {
             s.particles.velocities = matrix(std::get<std::vector<Vec3>>(v));
           }),
      make("body.springs", Scope::Particles, ValueKind::IndexPairList, "", "", kAny,
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
      make("body.rest_lengths", Scope::Particles, ValueKind::RealList, "m", "", kPositive,
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
      make("body.spring_type", Scope::Particles, ValueKind::Choice, "", "structural", kAny,
           "Whose coefficients the springs use; that [springs.<type>] table must be present",
           [](const SceneSpec& s, const Ctx&) -> Value {
             return std::string(to_string(s.particles.spring_type));
           },
           [](SceneSpec& s, const Ctx&, const Value& v) {
             s.particles.spring_type = *spring_type_from_string(text(v));
           },
           {"structural", "shear", "shear_body", "bending"}),
  };
  return table;
}

const std::vector<Decl>& spring_decls() {
  static const std::vector<Decl> table = {
      make("springs.*.enabled", Scope::SpringAny, ValueKind::Bool, "", "false", kAny,
           "Whether springs of this type are built (the table is present); true adds them with "
           "the default coefficients",
           [](const SceneSpec& s, const Ctx& c) -> Value { return spring_settings(s, c.spring).enabled; },
           [](SceneSpec& s, const Ctx& c, const Value& v) {
             SpringSettings& st = spring_settings(s, c.spring);
             if (flag(v) == st.enabled) return;
             st = SpringSettings{};  // on: defaults; off: back to the normal form of an absent table
             st.enabled = flag(v);
           }),
      make("springs.*.ks", Scope::SpringOn, ValueKind::Real, "N/m", "2000", kNonNegative,
           "Stiffness of every spring of this type",
           [](const SceneSpec& s, const Ctx& c) -> Value { return spring_settings(s, c.spring).ks; },
           [](SceneSpec& s, const Ctx& c, const Value& v) { spring_settings(s, c.spring).ks = real(v); }),
      make("springs.*.kd", Scope::SpringOn, ValueKind::Real, "N*s/m", "60", kNonNegative,
           "Damping along every spring of this type",
           [](const SceneSpec& s, const Ctx& c) -> Value { return spring_settings(s, c.spring).kd; },
           [](SceneSpec& s, const Ctx& c, const Value& v) { spring_settings(s, c.spring).kd = real(v); }),
  };
  return table;
}

const std::vector<Decl>& terrain_decls() {
  static const std::vector<Decl> table = {
      make("terrain.*.type", Scope::TerrainAny, ValueKind::Choice, "", "", kAny,
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
      make("terrain.*.point", Scope::Plane, ValueKind::Vector3, "m", "0,0,0", kAny,
           "A point p on the plane",
           [](const SceneSpec& s, const Ctx& c) -> Value { return plane(s, c).point; },
           [](SceneSpec& s, const Ctx& c, const Value& v) { plane(s, c).point = vec(v); }),
      make("terrain.*.normal", Scope::Plane, ValueKind::Vector3, "", "0,1,0", kAny,
           "Plane normal N (normalised by the loader)",
           [](const SceneSpec& s, const Ctx& c) -> Value { return plane(s, c).normal; },
           [](SceneSpec& s, const Ctx& c, const Value& v) { plane(s, c).normal = normalised(vec(v)); },
           {}, /*nonzero=*/true),
      make("terrain.*.hole_center", Scope::PlaneHole, ValueKind::Vector3, "m", "", kAny,
           "Centre h of a circular hole, on the plane (give with hole_radius, or neither)",
           [](const SceneSpec& s, const Ctx& c) -> Value { return plane(s, c).hole_center; },
           [](SceneSpec& s, const Ctx& c, const Value& v) { plane(s, c).hole_center = vec(v); }),
      make("terrain.*.hole_radius", Scope::PlaneHole, ValueKind::Real, "m", "", kPositive,
           "Radius r_h of the hole, measured in the plane (give with hole_center, or neither)",
           [](const SceneSpec& s, const Ctx& c) -> Value { return plane(s, c).hole_radius; },
           [](SceneSpec& s, const Ctx& c, const Value& v) { plane(s, c).hole_radius = real(v); }),
      // Bowl geometry
      make("terrain.*.center", Scope::Bowl, ValueKind::Vector3, "m", "0,0,0", kAny,
           "Centre c of the bowl's sphere",
           [](const SceneSpec& s, const Ctx& c) -> Value { return bowl(s, c).center; },
           [](SceneSpec& s, const Ctx& c, const Value& v) { bowl(s, c).center = vec(v); }),
      make("terrain.*.radius", Scope::Bowl, ValueKind::Real, "m", "1", kPositive,
           "Radius R of the bowl's sphere",
           [](const SceneSpec& s, const Ctx& c) -> Value { return bowl(s, c).radius; },
           [](SceneSpec& s, const Ctx& c, const Value& v) { bowl(s, c).radius = real(v); }),
      make("terrain.*.rim_height", Scope::Bowl, ValueKind::Real, "m", "0", kAny,
           "Height y of the rim plane; needs center.y - radius < rim_height <= center.y",
           [](const SceneSpec& s, const Ctx& c) -> Value { return bowl(s, c).rim_height; },
           [](SceneSpec& s, const Ctx& c, const Value& v) { bowl(s, c).rim_height = real(v); }),
      // Sphere geometry
      make("terrain.*.center", Scope::Sphere, ValueKind::Vector3, "m", "0,0,0", kAny,
           "Centre of the sphere obstacle",
           [](const SceneSpec& s, const Ctx& c) -> Value { return sphere(s, c).center; },
           [](SceneSpec& s, const Ctx& c, const Value& v) { sphere(s, c).center = vec(v); }),
      make("terrain.*.radius", Scope::Sphere, ValueKind::Real, "m", "1", kPositive,
           "Radius of the sphere obstacle",
           [](const SceneSpec& s, const Ctx& c) -> Value { return sphere(s, c).radius; },
           [](SceneSpec& s, const Ctx& c, const Value& v) { sphere(s, c).radius = real(v); }),
      // Surface, every terrain
      make("terrain.*.epsilon", Scope::TerrainAny, ValueKind::Real, "m", "0.01", kPositive,
           "Collision tolerance ε",
           [](const SceneSpec& s, const Ctx& c) -> Value { return terrain(s, c).surface().epsilon; },
           [](SceneSpec& s, const Ctx& c, const Value& v) { surface(s, c).epsilon = real(v); }),
      make("terrain.*.restitution", Scope::TerrainAny, ValueKind::Real, "", "0.8", kUnitInterval,
           "Coefficient of restitution k_r: the share of normal velocity kept, reversed",
           [](const SceneSpec& s, const Ctx& c) -> Value { return terrain(s, c).surface().restitution; },
           [](SceneSpec& s, const Ctx& c, const Value& v) { surface(s, c).restitution = real(v); }),
      make("terrain.*.friction", Scope::TerrainAny, ValueKind::Real, "s/m", "0.2", kNonNegative,
           "Friction coefficient k_f: friction = -k_f (-N·f) v_T",
           [](const SceneSpec& s, const Ctx& c) -> Value { return terrain(s, c).surface().friction; },
           [](SceneSpec& s, const Ctx& c, const Value& v) { surface(s, c).friction = real(v); }),
      make("terrain.*.collision", Scope::TerrainAny, ValueKind::Bool, "", "true", kAny,
           "Apply the collision velocity response at the start of each step",
           [](const SceneSpec& s, const Ctx& c) -> Value { return terrain(s, c).collision; },
           [](SceneSpec& s, const Ctx& c, const Value& v) { terrain(s, c).collision = flag(v); }),
      make("terrain.*.contact", Scope::TerrainAny, ValueKind::Bool, "", "true", kAny,
           "Add the contact and friction forces in every evaluation",
           [](const SceneSpec& s, const Ctx& c) -> Value { return terrain(s, c).contact; },
           [](SceneSpec& s, const Ctx& c, const Value& v) { terrain(s, c).contact = flag(v); }),
      make("terrain.*.project", Scope::TerrainAny, ValueKind::Bool, "", "false", kAny,
           "After the response, move particles behind the surface onto it (not in the course)",
           [](const SceneSpec& s, const Ctx& c) -> Value { return terrain(s, c).project; },
           [](SceneSpec& s, const Ctx& c, const Value& v) { terrain(s, c).project = flag(v); }),
  };
  return table;
}

// ----- small helpers -----

const Decl* find_decl(std::string_view pattern) {
  for (const auto* table : {&global_decls(), &spring_decls(), &terrain_decls()})
    for (const Decl& d : *table)
      if (d.pattern == pattern) return &d;
  return nullptr;
}

std::optional<std::string> check_in_scene(const Bound& b, const SceneSpec& s, const Value& v) {
  if (b.decl->pattern == "body.rest_lengths") {
    const std::size_t given = std::get<std::vector<double>>(v).size();
    if (given != s.particles.springs.size())
      return "must give one rest length per spring (" + std::to_string(s.particles.springs.size()) +
             "), got " + std::to_string(given);
  }
  if (b.decl->pattern == "body.springs") {
    // Checked here, before the indices are narrowed to int by the setter.
    const Eigen::Index n = s.particles.positions.cols();
    const auto& pairs = std::get<std::vector<IndexPair>>(v);
    for (std::size_t i = 0; i < pairs.size(); ++i)
      if (pairs[i][0] >= n || pairs[i][1] >= n)
        return "spring " + std::to_string(i) + " joins particles " + std::to_string(pairs[i][0]) +
               " and " + std::to_string(pairs[i][1]) + "; expected two different indices in 0.." +
               std::to_string(n - 1);
  }
  if (b.decl->pattern == "body.velocities") {
    const auto given = static_cast<Eigen::Index>(std::get<std::vector<Vec3>>(v).size());
    if (given != s.particles.positions.cols())
      return "must give one velocity per position (" + std::to_string(s.particles.positions.cols()) +
             "), got " + std::to_string(given);
  }
  return std::nullopt;
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

bool valid_terrain_name(std::string_view name) {
  if (name.empty() || name.size() > 64) return false;
  return std::all_of(name.begin(), name.end(), [](char ch) {
    return (ch >= 'a' && ch <= 'z') || (ch >= 'A' && ch <= 'Z') || (ch >= '0' && ch <= '9') ||
           ch == '_' || ch == '-';
  });
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
  // Geometry defaults come from the declaration table, so they are written down once.
  SceneSpec holder;
  holder.terrains.push_back(std::move(t));
  const Ctx ctx{SpringType::Structural, 0};
  for (const Decl& d : terrain_decls()) {
    if (d.default_text.empty() || d.pattern == "terrain.*.type" || !applies(d, holder, ctx))
      continue;
    auto parsed = parse_text(d, d.default_text);
    if (const Value* v = std::get_if<Value>(&parsed)) d.set(holder, ctx, *v);
  }
  return std::move(holder.terrains.front());
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

// ----- text and values -----

std::string format_double(double v) {
  char buf[64];
  const auto res = std::to_chars(buf, buf + sizeof buf, v);
  return std::string(buf, res.ptr);
}

namespace {

std::string_view trim(std::string_view t) {
  const auto is_space = [](char ch) { return ch == ' ' || ch == '\t' || ch == '\n' || ch == '\r'; };
  while (!t.empty() && is_space(t.front())) t.remove_prefix(1);
  while (!t.empty() && is_space(t.back())) t.remove_suffix(1);
  return t;
}

std::optional<double> parse_double(std::string_view t) {
  t = trim(t);
  if (!t.empty() && t.front() == '+') t.remove_prefix(1);
  if (t.empty() || t.front() == '+') return std::nullopt;
  double v = 0.0;
#if defined(_LIBCPP_VERSION) && !defined(__cpp_lib_to_chars)
  // libc++ before LLVM 20 (Apple's Xcode, Debian 12's libc++) has no from_chars for double: read
  // it with the classic "C" locale (correctly rounded there too), the same number of characters.
  std::istringstream in{std::string(t)};
  in.imbue(std::locale::classic());
  in >> std::noskipws >> v;
  if (in.fail() || in.peek() != std::char_traits<char>::eof()) return std::nullopt;
#else
  const auto res = std::from_chars(t.data(), t.data() + t.size(), v);
  if (res.ec != std::errc() || res.ptr != t.data() + t.size()) return std::nullopt;
#endif
  return v;
}

std::optional<long long> parse_integer(std::string_view t) {
  t = trim(t);
  if (!t.empty() && t.front() == '+') t.remove_prefix(1);
  if (t.empty() || t.front() == '+') return std::nullopt;
  long long v = 0;
  const auto res = std::from_chars(t.data(), t.data() + t.size(), v);
  if (res.ec != std::errc() || res.ptr != t.data() + t.size()) return std::nullopt;
  return v;
}

std::vector<std::string_view> split(std::string_view t, char sep) {
  std::vector<std::string_view> out;
  std::size_t start = 0;
  while (true) {
    const std::size_t at = t.find(sep, start);
    out.push_back(trim(t.substr(start, at == std::string_view::npos ? at : at - start)));
    if (at == std::string_view::npos) break;
    start = at + 1;
  }
  return out;
}

std::string_view strip_brackets(std::string_view t) {
  t = trim(t);
  if (t.size() >= 2 && ((t.front() == '[' && t.back() == ']') || (t.front() == '(' && t.back() == ')')))
    t = trim(t.substr(1, t.size() - 2));
  return t;
}

std::optional<Vec3> parse_vec3(std::string_view t) {
  const auto parts = split(strip_brackets(t), ',');
  if (parts.size() != 3) return std::nullopt;
  Vec3 v;
  for (int i = 0; i < 3; ++i) {
    const auto d = parse_double(parts[static_cast<std::size_t>(i)]);
    if (!d) return std::nullopt;
    v[i] = *d;
  }
  return v;
}

bool valid_utf8(std::string_view s) {
  std::size_t i = 0;
  while (i < s.size()) {
    const auto c = static_cast<unsigned char>(s[i]);
    std::size_t len = 0;
    unsigned cp = 0;
    if (c < 0x80) { ++i; continue; }
    if ((c & 0xE0) == 0xC0) { len = 2; cp = c & 0x1Fu; }
    else if ((c & 0xF0) == 0xE0) { len = 3; cp = c & 0x0Fu; }
    else if ((c & 0xF8) == 0xF0) { len = 4; cp = c & 0x07u; }
    else return false;
    if (i + len > s.size()) return false;
    for (std::size_t k = 1; k < len; ++k) {
      const auto cc = static_cast<unsigned char>(s[i + k]);
      if ((cc & 0xC0) != 0x80) return false;
      cp = (cp << 6) | (cc & 0x3Fu);
    }
    if ((len == 2 && cp < 0x80) || (len == 3 && cp < 0x800) || (len == 4 && cp < 0x10000) ||
        cp > 0x10FFFF || (cp >= 0xD800 && cp <= 0xDFFF))
      return false;
    i += len;
  }
  return true;
}

std::string in_quotes(std::string_view t) {
  std::string s = "\"";
  s.append(t.substr(0, 60));
  if (t.size() > 60) s += "...";
  return s + "\"";
}

}  // namespace

std::string expected_text(const Decl& d) {
  switch (d.kind) {
    case ValueKind::Real: return "a number";
    case ValueKind::Integer: return "an integer";
    case ValueKind::Bool: return "true or false";
    case ValueKind::Vector3: return "three numbers x,y,z";
    case ValueKind::Choice: {
      std::string s = "one of ";
      for (std::size_t i = 0; i < d.choices.size(); ++i) {
        if (i) s += ", ";
        s += d.choices[i];
      }
      return s;
    }
    case ValueKind::Text: return "text";
    case ValueKind::Vec3List: return "a list of points \"x,y,z; x,y,z\"";
    case ValueKind::IndexPairList: return "a list of index pairs \"a,b; a,b\"";
    case ValueKind::RealList: return "a list of numbers \"r,r\"";
  }
  return "a value";
}

std::variant<Value, std::string> parse_text(const Decl& d, std::string_view raw) {
  const std::string_view t = trim(raw);
  const std::string bad = "must be " + expected_text(d) + ", got " + in_quotes(raw);
  switch (d.kind) {
    case ValueKind::Real: {
      if (auto v = parse_double(t)) return Value{*v};
      return bad;
    }
    case ValueKind::Integer: {
      if (auto v = parse_integer(t)) return Value{*v};
      return bad;
    }
    case ValueKind::Bool:
      if (t == "true") return Value{true};
      if (t == "false") return Value{false};
      return bad;
    case ValueKind::Vector3: {
      if (auto v = parse_vec3(t)) return Value{*v};
      return bad;
    }
    case ValueKind::Choice: return Value{std::string(t)};
    case ValueKind::Text:
      if (!valid_utf8(raw)) return std::string("must be valid UTF-8 text");
      return Value{std::string(raw)};
    case ValueKind::Vec3List: {
      std::vector<Vec3> out;
      if (!t.empty())
        for (std::string_view item : split(t, ';')) {
          auto v = parse_vec3(item);
          if (!v) return bad;
          out.push_back(*v);
        }
      return Value{std::move(out)};
    }
    case ValueKind::IndexPairList: {
      std::vector<IndexPair> out;
      if (!t.empty())
        for (std::string_view item : split(t, ';')) {
          const auto ab = split(strip_brackets(item), ',');
          if (ab.size() != 2) return bad;
          const auto a = parse_integer(ab[0]);
          const auto b = parse_integer(ab[1]);
          if (!a || !b) return bad;
          out.push_back({*a, *b});
        }
      return Value{std::move(out)};
    }
    case ValueKind::RealList: {
      std::vector<double> out;
      const std::string_view inner = strip_brackets(t);
      if (!inner.empty())
        for (std::string_view item : split(inner, ',')) {
          auto v = parse_double(item);
          if (!v) return bad;
          out.push_back(*v);
        }
      return Value{std::move(out)};
    }
  }
  return bad;
}

std::string format_text(ValueKind kind, const Value& v) {
  const auto vec3 = [](const Vec3& p) {
    return format_double(p.x()) + ',' + format_double(p.y()) + ',' + format_double(p.z());
  };
  switch (kind) {
    case ValueKind::Real: return format_double(std::get<double>(v));
    case ValueKind::Integer: return std::to_string(std::get<long long>(v));
    case ValueKind::Bool: return std::get<bool>(v) ? "true" : "false";
    case ValueKind::Vector3: return vec3(std::get<Vec3>(v));
    case ValueKind::Choice:
    case ValueKind::Text: return std::get<std::string>(v);
    case ValueKind::Vec3List: {
      std::string s;
      for (const Vec3& p : std::get<std::vector<Vec3>>(v)) s += (s.empty() ? "" : "; ") + vec3(p);
      return s;
    }
    case ValueKind::IndexPairList: {
      std::string s;
      for (const IndexPair& p : std::get<std::vector<IndexPair>>(v))
        s += (s.empty() ? "" : "; ") + std::to_string(p[0]) + ',' + std::to_string(p[1]);
      return s;
    }
    case ValueKind::RealList: {
      std::string s;
      for (double r : std::get<std::vector<double>>(v)) s += (s.empty() ? "" : ",") + format_double(r);
      return s;
    }
  }
  return {};
}

namespace {

/// "must be a number > 0 s, got 0" / "must be an integer ≥ 2, got 1"; nullopt when in range.
std::optional<std::string> check_number(const Decl& d, double x, std::string_view what) {
  const std::string got = ", got " + format_double(x);
  const std::string unit = d.unit.empty() ? std::string() : " " + std::string(d.unit);
  if (!std::isfinite(x)) return "must be a finite number" + got;
  if (!d.bounded) return std::nullopt;
  const bool low = d.min_inclusive ? x < d.min : x <= d.min;
  const bool high = d.max_inclusive ? x > d.max : x >= d.max;
  if (low) {
    return "must be " + std::string(what) + (d.min_inclusive ? " ≥ " : " > ") +
           format_double(d.min) + unit + got;
  }
  if (high) {
    return "must be " + std::string(what) + (d.max_inclusive ? " ≤ " : " < ") +
           format_double(d.max) + unit + got;
  }
  return std::nullopt;
}

std::optional<std::string> check_finite(const Vec3& v, std::string_view where) {
  if (v.allFinite()) return std::nullopt;
  return std::string(where) + "must be finite numbers, got " + format_double(v.x()) + ',' +
         format_double(v.y()) + ',' + format_double(v.z());
}

}  // namespace

std::optional<std::string> check_value(const Decl& d, const Value& v) {
  switch (d.kind) {
    case ValueKind::Real: return check_number(d, std::get<double>(v), "a number");
    case ValueKind::Integer:
      return check_number(d, static_cast<double>(std::get<long long>(v)), "an integer");
    case ValueKind::Bool:
    case ValueKind::Text: return std::nullopt;
    case ValueKind::Vector3: {
      const Vec3& p = std::get<Vec3>(v);
      if (auto e = check_finite(p, "")) return e;
      if (d.nonzero && !(p.norm() > 0.0))
        return "must have non-zero length, got " + format_text(d.kind, v);
      return std::nullopt;
    }
    case ValueKind::Choice: {
      const std::string& s = std::get<std::string>(v);
      for (std::string_view c : d.choices)
        if (c == s) return std::nullopt;
      std::vector<std::string> options(d.choices.begin(), d.choices.end());
      std::string msg = "must be " + expected_text(d) + ", got " + in_quotes(s);
      const std::string near = closest(s, options);
      if (!near.empty()) msg += " (did you mean \"" + near + "\"?)";
      return msg;
    }
    case ValueKind::Vec3List: {
      const auto& list = std::get<std::vector<Vec3>>(v);
      for (std::size_t i = 0; i < list.size(); ++i)
        if (auto e = check_finite(list[i], "point " + std::to_string(i) + ": ")) return e;
      return std::nullopt;
    }
    case ValueKind::IndexPairList: {
      const auto& list = std::get<std::vector<IndexPair>>(v);
      for (std::size_t i = 0; i < list.size(); ++i) {
        const IndexPair& p = list[i];
        if (p[0] < 0 || p[1] < 0)
          return "spring " + std::to_string(i) + ": indices must be ≥ 0, got " +
                 std::to_string(p[0]) + ',' + std::to_string(p[1]);
        if (p[0] == p[1])
          return "spring " + std::to_string(i) + ": must join two different particles, got " +
                 std::to_string(p[0]) + ',' + std::to_string(p[1]);
      }
      return std::nullopt;
    }
    case ValueKind::RealList: {
      const auto& list = std::get<std::vector<double>>(v);
      for (std::size_t i = 0; i < list.size(); ++i)
        if (auto e = check_number(d, list[i], "a number"))
          return "element " + std::to_string(i) + ": " + *e;
      return std::nullopt;
    }
  }
  return std::nullopt;
}

std::optional<CrossError> check_scene(const SceneSpec& s) {
  if (s.body_kind == BodyKind::Particles) {
    const ParticleBodySpec& p = s.particles;
    const Eigen::Index n = p.positions.cols();
    if (n < 1) return CrossError{"body.positions", "a particles body needs at least one position, got none"};
    if (p.velocities.cols() != n)
      return CrossError{"body.velocities", "must give one velocity per position (" +
                                               std::to_string(n) + "), got " +
                                               std::to_string(p.velocities.cols())};
    for (std::size_t i = 0; i < p.springs.size(); ++i) {
      const Spring& sp = p.springs[i];
      if (sp.a < 0 || sp.b < 0 || sp.a >= n || sp.b >= n || sp.a == sp.b)
        return CrossError{"body.springs", "spring " + std::to_string(i) + " joins particles " +
                                              std::to_string(sp.a) + " and " +
                                              std::to_string(sp.b) +
                                              "; expected two different indices in 0.." +
                                              std::to_string(n - 1)};
      if (!(std::isfinite(sp.rest_length) && sp.rest_length > 0.0))
        return CrossError{"body.rest_lengths",
                          "spring " + std::to_string(i) + " has rest length " +
                              format_double(sp.rest_length) +
                              "; must be > 0 m (particles that start at the same place need an "
                              "explicit rest length)"};
    }
    if (!p.springs.empty() && !spring_settings(s, p.spring_type).enabled) {
      const std::string type(to_string(p.spring_type));
      return CrossError{"body.spring_type", "the particles' springs use the [springs." + type +
                                                "] coefficients, but the scene has no [springs." +
                                                type + "] table"};
    }
  }
  for (std::size_t i = 0; i < s.terrains.size(); ++i) {
    const Terrain& t = s.terrains[i];
    const std::string key = "terrain." + t.name;
    if (!valid_terrain_name(t.name))
      return CrossError{"terrain", "terrain " + std::to_string(i) + " has name " + in_quotes(t.name) +
                                       "; names use letters, digits, '_' and '-' only"};
    for (std::size_t j = 0; j < i; ++j)
      if (s.terrains[j].name == t.name)
        return CrossError{key + ".name", "two terrains are named " + in_quotes(t.name) +
                                             "; terrain names must be unique"};
    if (const auto* pl = std::get_if<Plane>(&t.shape)) {
      if (pl->has_hole && !(pl->hole_radius > 0.0))
        return CrossError{key + ".hole_radius",
                          "a hole needs hole_radius > 0 m, got " + format_double(pl->hole_radius)};
    }
    if (const auto* b = std::get_if<Bowl>(&t.shape)) {
      const double lo = b->center.y() - b->radius;
      const double hi = b->center.y();
      if (!(b->rim_height > lo && b->rim_height <= hi))
        return CrossError{key + ".rim_height",
                          "must satisfy center.y - radius < rim_height ≤ center.y (here " +
                              format_double(lo) + " < rim_height ≤ " + format_double(hi) +
                              "), got " + format_double(b->rim_height)};
    }
  }
  return std::nullopt;
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

std::string closest(std::string_view word, const std::vector<std::string>& candidates) {
  // Optimal string alignment distance (edits, with adjacent swaps), bounded to short words.
  if (word.size() > 64) return {};
  std::string best;
  std::size_t best_d = std::numeric_limits<std::size_t>::max();
  for (const std::string& c : candidates) {
    if (c.size() > 64) continue;
    const std::size_t n = word.size(), m = c.size();
    std::vector<std::vector<std::size_t>> d(n + 1, std::vector<std::size_t>(m + 1));
    for (std::size_t i = 0; i <= n; ++i) d[i][0] = i;
    for (std::size_t j = 0; j <= m; ++j) d[0][j] = j;
    for (std::size_t i = 1; i <= n; ++i)
      for (std::size_t j = 1; j <= m; ++j) {
        const std::size_t cost = word[i - 1] == c[j - 1] ? 0 : 1;
        d[i][j] = std::min({d[i - 1][j] + 1, d[i][j - 1] + 1, d[i - 1][j - 1] + cost});
        if (i > 1 && j > 1 && word[i - 1] == c[j - 2] && word[i - 2] == c[j - 1])
          d[i][j] = std::min(d[i][j], d[i - 2][j - 2] + 1);
      }
    if (d[n][m] < best_d) {
      best_d = d[n][m];
      best = c;
    }
  }
  const std::size_t limit = std::max<std::size_t>(1, std::min<std::size_t>(3, word.size() / 3));
  return best_d <= limit ? best : std::string();
}

}  // namespace params_detail

// ----- the public interface (params.hpp) -----

using namespace params_detail;

namespace {

ParamInfo info_of(const Bound& b) {
  const Decl& d = *b.decl;
  ParamInfo p;
  p.key = b.key;
  switch (d.kind) {
    case ValueKind::Real: p.type = ParamType::Real; break;
    case ValueKind::Integer: p.type = ParamType::Integer; break;
    case ValueKind::Bool: p.type = ParamType::Bool; break;
    case ValueKind::Vector3: p.type = ParamType::Vector3; break;
    case ValueKind::Choice: p.type = ParamType::Choice; break;
    default: p.type = ParamType::Text; break;  // text and the particle lists (text forms)
  }
  p.unit = std::string(d.unit);
  p.default_text = std::string(d.default_text);
  p.bounded = d.bounded;
  p.min = d.min;
  p.max = d.max;
  p.min_inclusive = d.min_inclusive;
  p.max_inclusive = d.max_inclusive;
  for (std::string_view c : d.choices) p.choices.emplace_back(c);
  p.description = std::string(d.description);
  return p;
}

std::string expand(std::string_view pattern, std::string_view name) {
  const std::size_t star = pattern.find('*');
  if (star == std::string_view::npos) return std::string(pattern);
  return std::string(pattern.substr(0, star)) + std::string(name) +
         std::string(pattern.substr(star + 1));
}

}  // namespace

std::vector<ParamInfo> scene_parameters(const SceneSpec& scene) {
  std::vector<ParamInfo> out;
  for (const Decl& d : global_decls())
    if (applies(d, scene, Ctx{})) out.push_back(info_of(Bound{&d, Ctx{}, std::string(d.pattern)}));
  for (SpringType t : kSpringTypes) {
    const Ctx ctx{t, 0};
    for (const Decl& d : spring_decls())
      if (applies(d, scene, ctx)) out.push_back(info_of(Bound{&d, ctx, expand(d.pattern, to_string(t))}));
  }
  for (std::size_t i = 0; i < scene.terrains.size(); ++i) {
    const Ctx ctx{SpringType::Structural, i};
    for (const Decl& d : terrain_decls())
      if (applies(d, scene, ctx))
        out.push_back(info_of(Bound{&d, ctx, expand(d.pattern, scene.terrains[i].name)}));
  }
  return out;
}

std::optional<ParamInfo> find_parameter(const SceneSpec& scene, std::string_view key) {
  const auto b = resolve(scene, key);
  if (!b) return std::nullopt;
  return info_of(*b);
}

std::optional<std::string> get_parameter(const SceneSpec& scene, std::string_view key) {
  const auto b = resolve(scene, key);
  if (!b) return std::nullopt;
  return format_text(b->decl->kind, b->decl->get(scene, b->ctx));
}

std::optional<double> get_number(const SceneSpec& scene, std::string_view key) {
  const auto b = resolve(scene, key);
  if (!b) return std::nullopt;
  const Value v = b->decl->get(scene, b->ctx);
  if (b->decl->kind == ValueKind::Real) return std::get<double>(v);
  if (b->decl->kind == ValueKind::Integer) return static_cast<double>(std::get<long long>(v));
  return std::nullopt;
}

}  // namespace jelly

namespace jelly {

namespace {

std::string_view scope_text(params_detail::Scope s) {
  using params_detail::Scope;
  switch (s) {
    case Scope::Always: return "every scene";
    case Scope::GravityOn: return "with gravity";
    case Scope::Cube: return "cube body";
    case Scope::Particles: return "particles body";
    case Scope::SpringAny: return "every spring type";
    case Scope::SpringOn: return "present spring types";
    case Scope::TerrainAny: return "every terrain";
    case Scope::Plane: return "plane";
    case Scope::PlaneHole: return "plane with a hole";
    case Scope::Bowl: return "bowl";
    case Scope::Sphere: return "sphere";
  }
  return "";
}

std::string_view kind_text(params_detail::ValueKind k) {
  using params_detail::ValueKind;
  switch (k) {
    case ValueKind::Real: return "real";
    case ValueKind::Integer: return "integer";
    case ValueKind::Bool: return "bool";
    case ValueKind::Vector3: return "vector x,y,z";
    case ValueKind::Choice: return "choice";
    case ValueKind::Text: return "text";
    case ValueKind::Vec3List: return "list of points";
    case ValueKind::IndexPairList: return "list of index pairs";
    case ValueKind::RealList: return "list of reals";
  }
  return "";
}

std::string range_text(const params_detail::Decl& d) {
  using params_detail::format_double;
  using params_detail::ValueKind;
  if (d.kind == ValueKind::Choice) {
    std::string s;
    for (std::string_view c : d.choices) s += (s.empty() ? "" : ", ") + std::string(c);
    return s;
  }
  if (d.nonzero) return "non-zero length";
  if (d.kind == ValueKind::IndexPairList) return "indices of positions, a ≠ b";
  if (!d.bounded) {
    return d.kind == ValueKind::Bool || d.kind == ValueKind::Text ? "" : "finite";
  }
  const bool has_max = std::isfinite(d.max);
  std::string s;
  if (!has_max) {
    s = std::string(d.min_inclusive ? "≥ " : "> ") + format_double(d.min);
  } else {
    s = std::string(d.min_inclusive ? "[" : "(") + format_double(d.min) + ", " +
        format_double(d.max) + (d.max_inclusive ? "]" : ")");
  }
  return d.kind == ValueKind::RealList ? "each " + s : s;
}

}  // namespace

std::string parameter_reference_markdown() {
  using namespace params_detail;
  std::string out =
      "| key | applies to | type | unit | default | valid range | description |\n"
      "|---|---|---|---|---|---|---|\n";
  const auto row = [&](const Decl& d, std::string key) {
    const std::string def = d.default_text.empty() ? "—" : "`" + std::string(d.default_text) + "`";
    out += "| `" + key + "` | " + std::string(scope_text(d.scope)) + " | " +
           std::string(kind_text(d.kind)) + " | " + std::string(d.unit) + " | " + def + " | " +
           range_text(d) + " | " + std::string(d.description) + " |\n";
  };
  for (const Decl& d : global_decls()) row(d, std::string(d.pattern));
  for (const Decl& d : spring_decls()) {
    std::string key(d.pattern);
    key.replace(key.find('*'), 1, "<type>");
    row(d, key);
  }
  for (const Decl& d : terrain_decls()) {
    std::string key(d.pattern);
    key.replace(key.find('*'), 1, "<name>");
    row(d, key);
  }
  return out;
}

}  // namespace jelly
