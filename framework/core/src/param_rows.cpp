// The declaration table: every scene parameter, declared once (house style §14).
//
// Each row gives the key (with '*' for the element of its collection), when it applies, its value
// kind, unit, whether it has a default, valid range, its own check against the scene where it has
// one, a one-line description, and how it is read from and written to a SceneSpec. Defaults are
// not typed here: they are read from the default-constructed structs of jelly/scene_spec.hpp and
// jelly/terrain.hpp, so each is written once. Rows are global ("simulation.dt") or belong to a
// declared collection (springs.*, terrain.*; collections() below): a new collection, such as a
// later assignment's sphere.*, is one more entry there with its element list and rows.
//
// Also here: the one key walk (walk_keys) that the scene reader and writer, set_parameter,
// get_parameter, scene_parameters and the reference table all use, and resolving a dotted key.
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
constexpr Range kClothN{true, 2.0, 200.0, true, true};

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

/// A row whose key is written as the presence of its table ([gravity], [springs.<type>]).
Decl presence(Decl d) {
  d.presence = true;
  return d;
}
/// A row the writer writes only when `when` holds.
Decl written_if(Decl d, bool (*when)(const SceneSpec&, const Ctx&)) {
  d.written = when;
  return d;
}
/// A row with its own check against the rest of the scene.
Decl checked(Decl d, RowCheck check) {
  d.check = check;
  return d;
}

// ----- accessors shared by several rows -----

SphereSpec& sphere_spec(SceneSpec& s, const Ctx& c) { return s.spheres[c.index]; }
const SphereSpec& sphere_spec(const SceneSpec& s, const Ctx& c) { return s.spheres[c.index]; }

Terrain& terrain(SceneSpec& s, const Ctx& c) { return s.terrains[c.index]; }
const Terrain& terrain(const SceneSpec& s, const Ctx& c) { return s.terrains[c.index]; }
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
  s.spheres.emplace_back();
  if (scope == Scope::KinematicSphere) s.spheres.back().kinematic = true;
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
      presence(make(
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
          })),
      make(
          "gravity.acceleration", Scope::GravityOn, ValueKind::Vector3, "m/s^2", Default::Yes, kAny,
          "Constant gravitational acceleration g (y is up)",
          [](const SceneSpec& s, const Ctx&) -> Value { return *s.gravity; },
          [](SceneSpec& s, const Ctx&, const Value& v) { s.gravity = vec(v); }),
      // [body]
      make(
          "body.type", Scope::Always, ValueKind::Choice, "", Default::Yes, kAny,
          "The body: a jelly cube, particles given one by one, or a cloth (assignment A2)",
          [](const SceneSpec& s, const Ctx&) -> Value {
            return std::string(body_kind_name(s.body_kind));
          },
          [](SceneSpec& s, const Ctx&, const Value& v) {
            s.body_kind = text(v) == "cube"        ? BodyKind::Cube
                          : text(v) == "particles" ? BodyKind::Particles
                                                   : BodyKind::Cloth;
          },
          {"cube", "particles", "cloth"}),
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
      checked(make(
                  "body.velocities", Scope::Particles, ValueKind::Vec3List, "m/s", Default::None,
                  kAny, "Initial velocities, one per position (optional: zero)",
                  [](const SceneSpec& s, const Ctx&) -> Value {
                    return columns(s.particles.velocities);
                  },
                  [](SceneSpec& s, const Ctx&, const Value& v) {
                    s.particles.velocities = matrix(std::get<std::vector<Vec3>>(v));
                  }),
              check_velocity_count),
      checked(
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
          check_spring_indices),
      checked(make(
                  "body.rest_lengths", Scope::Particles, ValueKind::RealList, "m", Default::None,
                  kPositive,
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
              check_rest_length_count),
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
      // [body] of a cloth (cloth contract §1)
      make(
          "body.n", Scope::Cloth, ValueKind::Integer, "", Default::Yes, kClothN,
          "Particles per cloth edge (n² particles)",
          [](const SceneSpec& s, const Ctx&) -> Value { return static_cast<long long>(s.cloth.n); },
          [](SceneSpec& s, const Ctx&, const Value& v) {
            s.cloth.n = static_cast<int>(std::get<long long>(v));
          }),
      make(
          "body.size", Scope::Cloth, ValueKind::Real, "m", Default::Yes, kPositive,
          "Side L of the square cloth; spacing L/(n-1)",
          [](const SceneSpec& s, const Ctx&) -> Value { return s.cloth.size; },
          [](SceneSpec& s, const Ctx&, const Value& v) { s.cloth.size = real(v); }),
      make(
          "body.mass", Scope::Cloth, ValueKind::Real, "kg", Default::Yes, kPositive,
          "Mass of every cloth particle",
          [](const SceneSpec& s, const Ctx&) -> Value { return s.cloth.mass; },
          [](SceneSpec& s, const Ctx&, const Value& v) { s.cloth.mass = real(v); }),
      make(
          "body.center", Scope::Cloth, ValueKind::Vector3, "m", Default::Yes, kAny,
          "Centre c0; the horizontal square grid is centred exactly on it",
          [](const SceneSpec& s, const Ctx&) -> Value { return s.cloth.center; },
          [](SceneSpec& s, const Ctx&, const Value& v) { s.cloth.center = vec(v); }),
      make(
          "body.velocity", Scope::Cloth, ValueKind::Vector3, "m/s", Default::Yes, kAny,
          "Initial velocity of every unpinned particle (not rotated)",
          [](const SceneSpec& s, const Ctx&) -> Value { return s.cloth.velocity; },
          [](SceneSpec& s, const Ctx&, const Value& v) { s.cloth.velocity = vec(v); }),
      make(
          "body.rotation_axis", Scope::Cloth, ValueKind::Vector3, "", Default::Yes, kAny,
          "Axis of the initial rotation about c0 (normalised when used)",
          [](const SceneSpec& s, const Ctx&) -> Value { return s.cloth.rotation_axis; },
          [](SceneSpec& s, const Ctx&, const Value& v) { s.cloth.rotation_axis = vec(v); }, {},
          /*nonzero=*/true),
      make(
          "body.rotation_degrees", Scope::Cloth, ValueKind::Real, "deg", Default::Yes, kAny,
          "Initial rotation angle about rotation_axis (90 about x: a curtain; 90 about z: a flag)",
          [](const SceneSpec& s, const Ctx&) -> Value { return s.cloth.rotation_degrees; },
          [](SceneSpec& s, const Ctx&, const Value& v) { s.cloth.rotation_degrees = real(v); }),
      make(
          "body.pins", Scope::Cloth, ValueKind::NameList, "", Default::Yes, kAny,
          "Named sets of pinned particles: corners (the four), edge (the row k = 0); [] for none",
          [](const SceneSpec& s, const Ctx&) -> Value { return s.cloth.pin_sets; },
          [](SceneSpec& s, const Ctx&, const Value& v) {
            s.cloth.pin_sets = std::get<std::vector<std::string>>(v);
          },
          {kPinSets.begin(), kPinSets.end()}),
      written_if(
          checked(make(
                      "body.pin_points", Scope::Cloth, ValueKind::GridList, "", Default::Yes, kAny,
                      "Further pinned particles by grid coordinates [[i, k], ...]",
                      [](const SceneSpec& s, const Ctx&) -> Value {
                        std::vector<IndexPair> out;
                        for (const GridCoord& p : s.cloth.pins) out.push_back({p[0], p[1]});
                        return out;
                      },
                      [](SceneSpec& s, const Ctx&, const Value& v) {
                        s.cloth.pins.clear();
                        for (const IndexPair& p : std::get<std::vector<IndexPair>>(v))
                          s.cloth.pins.push_back({static_cast<int>(p[0]), static_cast<int>(p[1])});
                      }),
                  check_pin_points),
          [](const SceneSpec& s, const Ctx&) { return !s.cloth.pins.empty(); }),
      make(
          "body.air_drag", Scope::Cloth, ValueKind::Real, "N*s/m", Default::Yes, kNonNegative,
          "Air drag k_air: force -k_air v on every cloth particle (the course: 3.4e-4)",
          [](const SceneSpec& s, const Ctx&) -> Value { return s.cloth.air_drag; },
          [](SceneSpec& s, const Ctx&, const Value& v) { s.cloth.air_drag = real(v); }),
      // [collision] of a cloth scene (cloth contract §4)
      make(
          "collision.cloth_restitution", Scope::Cloth, ValueKind::Real, "", Default::Yes,
          kUnitInterval, "Restitution e_cloth of cloth-sphere impulses (the course: 0)",
          [](const SceneSpec& s, const Ctx&) -> Value { return s.collisions.cloth_restitution; },
          [](SceneSpec& s, const Ctx&, const Value& v) {
            s.collisions.cloth_restitution = real(v);
          }),
      make(
          "collision.sphere_restitution", Scope::Cloth, ValueKind::Real, "", Default::Yes,
          kUnitInterval, "Restitution e_sphere of sphere-sphere impulses",
          [](const SceneSpec& s, const Ctx&) -> Value { return s.collisions.sphere_restitution; },
          [](SceneSpec& s, const Ctx&, const Value& v) {
            s.collisions.sphere_restitution = real(v);
          }),
      make(
          "collision.tolerance", Scope::Cloth, ValueKind::Real, "m", Default::Yes, kNonNegative,
          "Tolerance ε: a pair collides when its gap φ < ε and it approaches (both kinds of pair)",
          [](const SceneSpec& s, const Ctx&) -> Value { return s.collisions.tolerance; },
          [](SceneSpec& s, const Ctx&, const Value& v) { s.collisions.tolerance = real(v); }),
      make(
          "collision.friction", Scope::Cloth, ValueKind::Real, "", Default::Yes, kNonNegative,
          "Coulomb friction μ of every pair's impulse (the course's bonus; 0: none)",
          [](const SceneSpec& s, const Ctx&) -> Value { return s.collisions.friction; },
          [](SceneSpec& s, const Ctx&, const Value& v) { s.collisions.friction = real(v); }),
      make(
          "collision.push_out", Scope::Cloth, ValueKind::Real, "", Default::Yes, kUnitInterval,
          "Push-out β: a particle inside a sphere moves the share β of its depth out (0: none)",
          [](const SceneSpec& s, const Ctx&) -> Value { return s.collisions.push_out; },
          [](SceneSpec& s, const Ctx&, const Value& v) { s.collisions.push_out = real(v); }),
  });
  return table;
}

namespace {

std::vector<Decl> spring_rows() {
  return with_defaults({
      presence(make(
          "springs.*.enabled", Scope::Element, ValueKind::Bool, "", Default::Yes, kAny,
          "Whether springs of this type are built (the table is present); true adds them with "
          "the default coefficients",
          [](const SceneSpec& s, const Ctx& c) -> Value {
            return spring_settings(s, spring_type_at(s, c.index)).enabled;
          },
          [](SceneSpec& s, const Ctx& c, const Value& v) {
            SpringSettings& st = spring_settings(s, spring_type_at(s, c.index));
            if (flag(v) == st.enabled) return;
            st = SpringSettings{};  // on: defaults; off: back to the normal form of an absent table
            st.enabled = flag(v);
            if (st.enabled && s.body_kind == BodyKind::Cloth) {
              st.ks = kClothDefaultKs;  // cloth contract decision 10
              st.kd = kClothDefaultKd;
            }
          })),
      make(
          "springs.*.ks", Scope::SpringOn, ValueKind::Real, "N/m", Default::Yes, kNonNegative,
          "Stiffness of every spring of this type",
          [](const SceneSpec& s, const Ctx& c) -> Value {
            return spring_settings(s, spring_type_at(s, c.index)).ks;
          },
          [](SceneSpec& s, const Ctx& c, const Value& v) {
            spring_settings(s, spring_type_at(s, c.index)).ks = real(v);
          }),
      make(
          "springs.*.kd", Scope::SpringOn, ValueKind::Real, "N*s/m", Default::Yes, kNonNegative,
          "Damping along every spring of this type",
          [](const SceneSpec& s, const Ctx& c) -> Value {
            return spring_settings(s, spring_type_at(s, c.index)).kd;
          },
          [](SceneSpec& s, const Ctx& c, const Value& v) {
            spring_settings(s, spring_type_at(s, c.index)).kd = real(v);
          }),
  });
}

std::vector<Decl> terrain_rows() {
  return with_defaults({
      make(
          "terrain.*.type", Scope::Element, ValueKind::Choice, "", Default::None, kAny,
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
          "terrain.*.epsilon", Scope::Element, ValueKind::Real, "m", Default::Yes, kPositive,
          "Collision tolerance ε",
          [](const SceneSpec& s, const Ctx& c) -> Value { return terrain(s, c).surface().epsilon; },
          [](SceneSpec& s, const Ctx& c, const Value& v) { surface(s, c).epsilon = real(v); }),
      make(
          "terrain.*.restitution", Scope::Element, ValueKind::Real, "", Default::Yes, kUnitInterval,
          "Coefficient of restitution k_r: the share of normal velocity kept, reversed",
          [](const SceneSpec& s, const Ctx& c) -> Value {
            return terrain(s, c).surface().restitution;
          },
          [](SceneSpec& s, const Ctx& c, const Value& v) { surface(s, c).restitution = real(v); }),
      make(
          "terrain.*.friction", Scope::Element, ValueKind::Real, "s/m", Default::Yes, kNonNegative,
          "Friction coefficient k_f: friction = -k_f (-N·f) v_T",
          [](const SceneSpec& s, const Ctx& c) -> Value {
            return terrain(s, c).surface().friction;
          },
          [](SceneSpec& s, const Ctx& c, const Value& v) { surface(s, c).friction = real(v); }),
      make(
          "terrain.*.collision", Scope::Element, ValueKind::Bool, "", Default::Yes, kAny,
          "Apply the collision velocity response at the start of each step",
          [](const SceneSpec& s, const Ctx& c) -> Value { return terrain(s, c).collision; },
          [](SceneSpec& s, const Ctx& c, const Value& v) { terrain(s, c).collision = flag(v); }),
      make(
          "terrain.*.contact", Scope::Element, ValueKind::Bool, "", Default::Yes, kAny,
          "Add the contact and friction forces in every evaluation",
          [](const SceneSpec& s, const Ctx& c) -> Value { return terrain(s, c).contact; },
          [](SceneSpec& s, const Ctx& c, const Value& v) { terrain(s, c).contact = flag(v); }),
      make(
          "terrain.*.project", Scope::Element, ValueKind::Bool, "", Default::Yes, kAny,
          "After the response, move particles behind the surface onto it (not in the course)",
          [](const SceneSpec& s, const Ctx& c) -> Value { return terrain(s, c).project; },
          [](SceneSpec& s, const Ctx& c, const Value& v) { terrain(s, c).project = flag(v); }),
  });
}

std::vector<Decl> sphere_rows() {
  return with_defaults({
      make(
          "sphere.*.center", Scope::Element, ValueKind::Vector3, "m", Default::Yes, kAny,
          "Initial centre c",
          [](const SceneSpec& s, const Ctx& c) -> Value { return sphere_spec(s, c).center; },
          [](SceneSpec& s, const Ctx& c, const Value& v) { sphere_spec(s, c).center = vec(v); }),
      make(
          "sphere.*.radius", Scope::Element, ValueKind::Real, "m", Default::Yes, kPositive,
          "Radius r",
          [](const SceneSpec& s, const Ctx& c) -> Value { return sphere_spec(s, c).radius; },
          [](SceneSpec& s, const Ctx& c, const Value& v) { sphere_spec(s, c).radius = real(v); }),
      make(
          "sphere.*.kinematic", Scope::Element, ValueKind::Bool, "", Default::Yes, kAny,
          "Moved by its schedule with inverse mass 0 (true), or by gravity and impulses (false)",
          [](const SceneSpec& s, const Ctx& c) -> Value { return sphere_spec(s, c).kinematic; },
          [](SceneSpec& s, const Ctx& c, const Value& v) {
            sphere_spec(s, c).kinematic = flag(v);
          }),
      written_if(
          make(
              "sphere.*.mass", Scope::DynamicSphere, ValueKind::Real, "kg", Default::None,
              kPositive, "Mass M; when not given 1000 r^3 (the course's formula)",
              [](const SceneSpec& s, const Ctx& c) -> Value {
                const SphereSpec& sp = sphere_spec(s, c);
                return sp.mass.value_or(default_sphere_mass(sp.radius));
              },
              [](SceneSpec& s, const Ctx& c, const Value& v) {
                // 1000·r³ is the mass not given: it keeps following the radius (and `jelly params`
                // text set back leaves the scene as it was).
                SphereSpec& sp = sphere_spec(s, c);
                if (real(v) == default_sphere_mass(sp.radius)) {
                  sp.mass.reset();
                } else {
                  sp.mass = real(v);
                }
              }),
          [](const SceneSpec& s, const Ctx& c) { return sphere_spec(s, c).mass.has_value(); }),
      make(
          "sphere.*.velocity", Scope::DynamicSphere, ValueKind::Vector3, "m/s", Default::Yes, kAny,
          "Initial velocity u",
          [](const SceneSpec& s, const Ctx& c) -> Value { return sphere_spec(s, c).velocity; },
          [](SceneSpec& s, const Ctx& c, const Value& v) { sphere_spec(s, c).velocity = vec(v); }),
      checked(
          make(
              "sphere.*.schedule", Scope::KinematicSphere, ValueKind::Schedule, "s: m/s",
              Default::Yes, kAny,
              "From each time on, the velocity it moves at (zero before the first entry); "
              "TOML [{ time = t, velocity = [x, y, z] }, ...]",
              [](const SceneSpec& s, const Ctx& c) -> Value { return sphere_spec(s, c).schedule; },
              [](SceneSpec& s, const Ctx& c, const Value& v) {
                sphere_spec(s, c).schedule = std::get<std::vector<ScheduleEntry>>(v);
              }),
          check_schedule),
  });
}

std::vector<std::string> spring_type_names(const SceneSpec& s) {
  std::vector<std::string> out;
  if (s.body_kind == BodyKind::Cloth) {
    for (SpringType t : kClothSpringTypes) out.emplace_back(to_string(t));
  } else {
    for (SpringType t : kSpringTypes) out.emplace_back(to_string(t));
  }
  return out;
}

std::vector<std::string> sphere_names(const SceneSpec& s) {
  std::vector<std::string> out;
  for (std::size_t i = 0; i < s.spheres.size(); ++i) out.push_back(std::to_string(i));
  return out;
}

std::vector<std::string> terrain_names(const SceneSpec& s) {
  std::vector<std::string> out;
  for (const Terrain& t : s.terrains) out.push_back(t.name);
  return out;
}

Collection collection(std::string_view name, std::string_view placeholder, std::string_view noun,
                      Layout layout, std::vector<std::string> (*elements)(const SceneSpec&),
                      std::vector<Decl> rows) {
  Collection c;
  c.name = name;
  c.placeholder = placeholder;
  c.noun = noun;
  c.layout = layout;
  c.elements = elements;
  c.rows = std::move(rows);
  return c;
}

}  // namespace

// ----- the collections -----

const std::vector<Collection>& collections() {
  static const std::vector<Collection> list = [] {
    std::vector<Collection> out;
    // [springs.<type>]: one table per spring type the scene uses (every type has keys).
    out.push_back(collection("springs", "<type>", "spring type", Layout::Tables, spring_type_names,
                             spring_rows()));
    // [[terrain]]: the scene's terrains, each named by its `name` key.
    out.push_back(collection("terrain", "<name>", "terrain", Layout::ArrayOfTables, terrain_names,
                             terrain_rows()));
    // [[sphere]]: a cloth scene's spheres, named by their position: sphere.0.radius.
    out.push_back(
        collection("sphere", "<i>", "sphere", Layout::Indexed, sphere_names, sphere_rows()));
    return out;
  }();
  return list;
}

// ----- small helpers -----

const Decl* find_decl(std::string_view pattern) {
  for (const Decl& d : global_decls())
    if (d.pattern == pattern) return &d;
  for (const Collection& c : collections())
    for (const Decl& d : c.rows)
      if (d.pattern == pattern) return &d;
  return nullptr;
}

SpringType spring_type_at(const SceneSpec& s, std::size_t index) {
  if (s.body_kind == BodyKind::Cloth) return kClothSpringTypes[std::min<std::size_t>(index, 2)];
  return kSpringTypes[index];
}

std::string_view body_kind_name(BodyKind k) {
  switch (k) {
    case BodyKind::Cube: return "cube";
    case BodyKind::Particles: return "particles";
    case BodyKind::Cloth: return "cloth";
  }
  return "cube";
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
  const bool has_terrain = c.index < s.terrains.size();
  switch (d.scope) {
    case Scope::Always: return true;
    case Scope::GravityOn: return s.gravity.has_value();
    case Scope::Cube: return s.body_kind == BodyKind::Cube;
    case Scope::Particles: return s.body_kind == BodyKind::Particles;
    case Scope::Cloth: return s.body_kind == BodyKind::Cloth;
    case Scope::DynamicSphere: return c.index < s.spheres.size() && !s.spheres[c.index].kinematic;
    case Scope::KinematicSphere: return c.index < s.spheres.size() && s.spheres[c.index].kinematic;
    case Scope::Element: return true;  // walk_keys visits only the elements a scene has
    case Scope::SpringOn: return spring_settings(s, spring_type_at(s, c.index)).enabled;
    case Scope::Plane:
      return has_terrain && std::holds_alternative<Plane>(s.terrains[c.index].shape);
    case Scope::PlaneHole:
      return has_terrain && std::holds_alternative<Plane>(s.terrains[c.index].shape) &&
             std::get<Plane>(s.terrains[c.index].shape).has_hole;
    case Scope::Bowl: return has_terrain && std::holds_alternative<Bowl>(s.terrains[c.index].shape);
    case Scope::Sphere:
      return has_terrain && std::holds_alternative<Sphere>(s.terrains[c.index].shape);
  }
  return false;
}

namespace {

std::string expand(std::string_view pattern, std::string_view element) {
  const std::size_t star = pattern.find('*');
  if (star == std::string_view::npos) return std::string(pattern);
  return std::string(pattern.substr(0, star)) + std::string(element) +
         std::string(pattern.substr(star + 1));
}

std::optional<Bound> find_key(const SceneSpec& s, std::string_view key, Walk which) {
  std::optional<Bound> found;
  walk_keys(
      &s, which,
      [&](const Bound& b) {
        if (b.key != key) return false;
        found = b;
        return true;
      },
      key.substr(0, key.find('.')));
  return found;
}

}  // namespace

std::string_view key_table(std::string_view key) {
  const std::size_t dot = key.rfind('.');
  return dot == std::string_view::npos ? std::string_view() : key.substr(0, dot);
}
std::string_view key_local(std::string_view key) { return key.substr(key.rfind('.') + 1); }

bool walk_keys(const SceneSpec* scene, Walk which, const std::function<bool(const Bound&)>& visit,
               std::string_view section) {
  const auto each = [&](const Decl& d, Ctx ctx, std::string key, const Collection* of) {
    if (scene && which == Walk::Applicable && !applies(d, *scene, ctx)) return false;
    return visit(Bound{&d, ctx, std::move(key), of});
  };
  const auto in_section = [&](std::string_view name) { return section.empty() || name == section; };
  for (const Decl& d : global_decls())
    if (in_section(d.pattern.substr(0, d.pattern.find('.'))) &&
        each(d, Ctx{}, std::string(d.pattern), nullptr))
      return true;
  for (const Collection& c : collections()) {
    if (!in_section(c.name)) continue;
    const std::vector<std::string> elements =
        scene ? c.elements(*scene) : std::vector<std::string>{std::string(c.placeholder)};
    for (std::size_t i = 0; i < elements.size(); ++i)
      for (const Decl& d : c.rows)
        if (each(d, Ctx{i}, expand(d.pattern, elements[i]), &c)) return true;
  }
  return false;
}

std::optional<Bound> resolve(const SceneSpec& s, std::string_view key) {
  return find_key(s, key, Walk::Applicable);
}
std::optional<Bound> resolve_any(const SceneSpec& s, std::string_view key) {
  return find_key(s, key, Walk::All);
}

std::string inapplicable_reason(const Bound& b, const SceneSpec& s) {
  const std::string local(key_local(b.decl->pattern));
  const std::string body = s.body_kind == BodyKind::Cube        ? "a cube"
                           : s.body_kind == BodyKind::Particles ? "particles"
                                                                : "a cloth";
  const auto terrain_label = [&] {
    const Terrain& t = s.terrains[b.ctx.index];
    return "terrain \"" + t.name + "\" is a " + std::string(terrain_type_name(t));
  };
  switch (b.decl->scope) {
    case Scope::GravityOn:
      return "the scene has no gravity (no [gravity] table); turn it on with gravity.enabled=true";
    case Scope::Cube: return local + " is a key of a cube body, and this scene's body is " + body;
    case Scope::Particles:
      return local + " is a key of a particles body, and this scene's body is " + body;
    case Scope::Cloth:
      return b.key +
             " is a key of cloth scenes (body.type = \"cloth\"), and this scene's body is " + body;
    case Scope::DynamicSphere:
      return local + " is a key of a dynamic sphere, and sphere " + std::to_string(b.ctx.index) +
             " is kinematic (kinematic = true: it moves by its schedule)";
    case Scope::KinematicSphere:
      return local + " is a key of a kinematic sphere (kinematic = true), and sphere " +
             std::to_string(b.ctx.index) + " is dynamic";
    case Scope::SpringOn: {
      const std::string type(to_string(spring_type_at(s, b.ctx.index)));
      return "the scene has no [springs." + type + "] table; add it with springs." + type +
             ".enabled=true";
    }
    case Scope::Plane: return local + " is a key of a plane terrain, and " + terrain_label();
    case Scope::PlaneHole:
      if (std::holds_alternative<Plane>(s.terrains[b.ctx.index].shape))
        return "terrain \"" + s.terrains[b.ctx.index].name +
               "\" has no hole; a hole needs both hole_center and hole_radius in the scene file";
      return local + " is a key of a plane terrain, and " + terrain_label();
    case Scope::Bowl: return local + " is a key of a bowl terrain, and " + terrain_label();
    case Scope::Sphere: return local + " is a key of a sphere terrain, and " + terrain_label();
    default: return "not a parameter of this scene";
  }
}

}  // namespace jelly::params_detail
