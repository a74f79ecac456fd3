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

#include "jelly/body_kind.hpp"
#include "param_rows.hpp"

namespace jelly::params_detail {

Decl make(std::string_view pattern, Scope scope, ValueKind kind, std::string_view unit, Default def,
          Range range, std::string_view description, Getter get, Setter set,
          std::vector<std::string_view> choices, bool nonzero) {
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

Decl of_body(std::string_view body, Decl d) {
  d.scope = Scope::Body;
  d.body = body;
  return d;
}
Decl applies_when(Decl d, std::string_view text, bool (*when)(const SceneSpec&, const Ctx&),
                  std::string (*why_not)(const Bound&, const SceneSpec&)) {
  d.scope = Scope::When;
  d.when_text = text;
  d.when = when;
  d.why_not = why_not;
  return d;
}
Decl presence(Decl d) {
  d.presence = true;
  return d;
}
Decl written_if(Decl d, bool (*when)(const SceneSpec&, const Ctx&)) {
  d.written = when;
  return d;
}
Decl checked(Decl d, RowCheck check) {
  d.check = check;
  return d;
}

Decl citing(Decl d, std::string_view source) {
  d.cites = source;
  return d;
}

double real(const Value& v) { return std::get<double>(v); }
const Vec3& vec(const Value& v) { return std::get<Vec3>(v); }
bool flag(const Value& v) { return std::get<bool>(v); }
const std::string& text(const Value& v) { return std::get<std::string>(v); }

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

namespace {

// ----- accessors shared by several rows -----

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

/// Unit normal of what a scene gives. A vector already unit length to within a few ulps is kept
/// as it is, so that writing a scene and reading it back gives the same bits.
Vec3 normalised(const Vec3& n) {
  const double len = n.norm();
  if (std::abs(len - 1.0) <= 4.0 * std::numeric_limits<double>::epsilon()) return n;
  return n / len;
}

// The scene whose values are the defaults: default-constructed structs (no gravity, as a scene
// without a [gravity] table), with gravity's default acceleration for the rows that need gravity
// and one terrain of the row's shape, so that every row reads its default from what the structs
// say; `prepare` adds what a body module's row needs.
SceneSpec defaults_scene(const Decl& d, PrepareDefaults prepare) {
  const Scope scope = d.scope;
  SceneSpec s;
  if (scope == Scope::GravityOn) s.gravity = default_gravity();
  Terrain t;
  t.name = "default";
  if (scope == Scope::Bowl) t.shape = Bowl{};
  if (scope == Scope::Sphere) t.shape = Sphere{};
  s.terrains.push_back(std::move(t));
  if (prepare) prepare(s, d);
  return s;
}

}  // namespace

std::vector<Decl> with_defaults(std::vector<Decl> table, PrepareDefaults prepare) {
  for (Decl& d : table)
    if (d.has_default)
      d.default_text = format_text(d.kind, d.get(defaults_scene(d, prepare), Ctx{}));
  return table;
}

std::vector<Decl> body_section(std::string_view body, std::vector<Decl> rows,
                               PrepareDefaults prepare) {
  for (Decl& d : rows)
    if (d.scope == Scope::Body) d.body = body;
  return with_defaults(std::move(rows), prepare);
}

namespace {

// body.type: "The body: " and what each linked kind says it is (its description()), joined in
// registry order.
std::string_view body_type_description() {
  static const std::string text = [] {
    std::string out = "The body: ";
    const auto& kinds = body_kinds();
    for (std::size_t i = 0; i < kinds.size(); ++i)
      out += std::string(i == 0                  ? ""
                         : i + 1 == kinds.size() ? ", or "
                                                 : ", ") +
             std::string(kinds[i]->description());
    return out;
  }();
  return text;
}

std::vector<std::string_view> body_type_names() {
  std::vector<std::string_view> out;
  for (const BodyKindModule* kind : body_kinds()) out.push_back(kind->name());
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
  static const std::vector<Decl> general = with_defaults({
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
      // [body]: its type here; the rest of it (and any table of its own) is the kind's
      make(
          "body.type", Scope::Always, ValueKind::Choice, "", Default::Yes, kAny,
          body_type_description(),
          [](const SceneSpec& s, const Ctx&) -> Value { return std::string(s.body_kind.name); },
          [](SceneSpec& s, const Ctx&, const Value& v) {
            if (const BodyKindModule* kind = find_body_kind(text(v)))
              s.body_kind = BodyKind{kind->name()};
          },
          body_type_names()),
  });
  static const std::vector<Decl> table = [] {
    std::vector<Decl> out = general;
    for (const BodyKindModule* kind : body_kinds())
      for (Decl& d : kind->rows()) out.push_back(std::move(d));
    return out;
  }();
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
            if (st.enabled) body_kind_of(s).spring_defaults(st);
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

std::vector<std::string> spring_type_names(const SceneSpec& s) {
  std::vector<std::string> out;
  for (SpringType t : body_kind_of(s).spring_types()) out.emplace_back(to_string(t));
  return out;
}

std::vector<std::string> terrain_names(const SceneSpec& s) {
  std::vector<std::string> out;
  for (const Terrain& t : s.terrains) out.push_back(t.name);
  return out;
}

}  // namespace

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
    // Then each body kind's own (BodyKindModule::collections).
    for (const BodyKindModule* kind : body_kinds())
      for (Collection& c : kind->collections()) {
        c.body = kind->name();
        out.push_back(std::move(c));
      }
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
  const std::vector<SpringType> types = body_kind_of(s).spring_types();
  if (types.empty()) return SpringType::Structural;
  return types[std::min<std::size_t>(index, types.size() - 1)];
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
    case Scope::Body: return s.body_kind.name == d.body;
    case Scope::When: return d.when(s, c);
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
  const std::string_view body = body_kind_of(s).body_phrase();
  const auto terrain_label = [&] {
    const Terrain& t = s.terrains[b.ctx.index];
    return "terrain \"" + t.name + "\" is a " + std::string(terrain_type_name(t));
  };
  switch (b.decl->scope) {
    case Scope::GravityOn:
      return "the scene has no gravity (no [gravity] table); turn it on with gravity.enabled=true";
    case Scope::Body: return find_body_kind(b.decl->body)->foreign_key(b.key, local, body);
    case Scope::When: return b.decl->why_not(b, s);
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
