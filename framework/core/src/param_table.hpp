// Internal to jelly::core: the parameter declaration table behind params.hpp and the scene files.
//
// Every scene parameter is declared once in param_rows.cpp (key pattern, value kind, unit, default,
// range, description, its own check, and how to read and write it in a SceneSpec). Keys are global
// ("simulation.dt") or belong to a named collection ("springs.<type>.ks", "terrain.<name>.radius"):
// a collection is declared once (its name, its elements in a scene, its rows), so a new one is a
// new declaration. Every user of the table (the scene reader and writer, set_parameter,
// get_parameter, scene_parameters, docs/scenes.md) goes through one key walk, walk_keys.
#pragma once

#include <array>
#include <functional>
#include <optional>
#include <string>
#include <string_view>
#include <variant>
#include <vector>

#include "jelly/params.hpp"
#include "jelly/scene_spec.hpp"
#include "jelly/schedule.hpp"

namespace jelly::params_detail {

/// What a value looks like. Finer than the public ParamType: the particle body's lists show up
/// publicly as Text in the form "x,y,z; x,y,z" (Vec3List), "a,b; a,b" (IndexPairList), "r, r"
/// (RealList).
enum class ValueKind {
  Real,
  Integer,
  Bool,
  Vector3,
  Choice,
  Text,
  Vec3List,
  IndexPairList,
  RealList,
  NameList,  ///< names from `choices` ("corners, edge"; body.pins)
  GridList,  ///< grid coordinates "i,k; i,k" (a body's points on its grid), stored as IndexPair
  Schedule   ///< a kinematic sphere's velocity schedule "t: x,y,z; t: x,y,z"
};

using IndexPair = std::array<long long, 2>;
/// A typed value: double (Real), long long (Integer), bool, Vec3, string (Choice, Text), or a list.
using Value = std::variant<double, long long, bool, Vec3, std::string, std::vector<Vec3>,
                           std::vector<IndexPair>, std::vector<double>, std::vector<std::string>,
                           std::vector<ScheduleEntry>>;

/// When a declared key belongs to a scene.
enum class Scope {
  Always,     ///< every scene
  GravityOn,  ///< scenes with gravity
  Body,       ///< the scene's body is the row's kind (Decl::body): its module's rows
  Element,    ///< every element of the row's collection ("every spring type", "every terrain")
  SpringOn,   ///< springs.<type>.*, only when that type is in the scene
  Plane,      ///< plane terrains
  PlaneHole,  ///< plane terrains with a hole
  Bowl,       ///< bowl terrains
  Sphere,     ///< sphere terrains
  When,       ///< when the row's own test holds (Decl::when; a body module's collection)
};

/// Which element of its collection a row's key refers to: the position in the collection's
/// elements (the scene's spring types for springs, SceneSpec::terrains for terrain,
/// SceneSpec::spheres for sphere); 0 for global rows.
struct Ctx {
  std::size_t index = 0;
};

struct Decl;
struct Bound;
/// A row's own check of a value against the rest of the scene (list lengths that must match,
/// indices in range): the message ("must give one velocity per position (8), got 2") or nullopt.
using RowCheck = std::optional<std::string> (*)(const Decl&, const SceneSpec&, const Ctx&,
                                                const Value&);

/// One declared parameter.
struct Decl {
  std::string_view pattern;  ///< "simulation.dt", "springs.*.ks", "terrain.*.radius"
  Scope scope = Scope::Always;
  ValueKind kind = ValueKind::Real;
  std::string_view unit;     ///< "m", "s", "N/m", "" for dimensionless
  bool has_default = false;  ///< whether the parameter has a default
  std::string default_text;  ///< the default in set_parameter's text form (read from the
                             ///< default-constructed structs); "" when there is none
  bool bounded = false;      ///< whether min/max apply (Real, Integer, RealList elements)
  double min = 0.0;
  double max = 0.0;
  bool min_inclusive = true;
  bool max_inclusive = true;
  bool nonzero = false;   ///< Vector3 that must have non-zero length
  bool presence = false;  ///< true: the key is written as its table's presence ([gravity],
                          ///< [springs.<type>]), not as a key of its own
  std::vector<std::string_view> choices;  ///< Choice values
  std::string_view description;
  Value (*get)(const SceneSpec&, const Ctx&) = nullptr;
  void (*set)(SceneSpec&, const Ctx&, const Value&) = nullptr;
  RowCheck check = nullptr;  ///< the row's own check against the scene (after the range check)
  /// Where the rules of its value kind come from, for their messages (a Schedule's "times must
  /// increase strictly (<cites>)"); "" when nowhere in particular.
  std::string_view cites;
  /// A Schedule's value key beside `time` in each entry ({ time = t, velocity = [x, y, z] }); its
  /// unit is the part of `unit` after "s: " ("s: m/s"), none when `unit` is only "s".
  std::string_view schedule_value = "velocity";
  /// Whether the writer writes the key (nullptr: always when it applies). A key whose value is
  /// derived from others unless given (sphere.<i>.mass: 1000·r³) is written only when given.
  bool (*written)(const SceneSpec&, const Ctx&) = nullptr;
  std::string_view body;  ///< Scope::Body: the body kind whose section the row is in (its name())
  /// Scope::When: when the row applies in words (the reference table), whether it applies, and
  /// why not (for messages).
  std::string_view when_text;
  bool (*when)(const SceneSpec&, const Ctx&) = nullptr;
  std::string (*why_not)(const Bound&, const SceneSpec&) = nullptr;
};

/// How a collection's elements are written in a scene file.
enum class Layout {
  Tables,         ///< one table per element, named by it: [springs.shear]
  ArrayOfTables,  ///< an array of tables whose `name` key names the element: [[terrain]]
  Indexed,        ///< an array of tables named by their position 0, 1, ...: [[sphere]]
};

/// A named collection of keys: "<name>.<element>.<row>" for each element a scene has.
struct Collection {
  std::string_view name;         ///< the first part of its keys: "springs", "terrain"
  std::string_view placeholder;  ///< the element in the reference table: "<type>", "<name>"
  std::string_view noun;         ///< one element in messages and docs: "spring type", "terrain"
  Layout layout = Layout::Tables;
  /// The element names of a scene, in key order (Ctx::index is the position in this list).
  std::vector<std::string> (*elements)(const SceneSpec&) = nullptr;
  std::vector<Decl> rows;  ///< patterns "<name>.*.<key>", in table order
  /// Layout::Indexed: appends a default element to a scene (the reader, before the keys of an
  /// entry), and the key read first (it decides which other keys apply); may be empty.
  void (*append)(SceneSpec&) = nullptr;
  std::string_view first_key;
  std::string_view body;  ///< the body kind that declares it; empty for a general collection
};

/// A declaration resolved against one scene: the declaration, its context, the full key, and the
/// collection it belongs to (nullptr for a global row).
struct Bound {
  const Decl* decl = nullptr;
  Ctx ctx;
  std::string key;
  const Collection* collection = nullptr;
};

/// The global declarations in table order: scene, simulation, gravity, body.
const std::vector<Decl>& global_decls();
/// The declared collections in table order (springs, terrain).
const std::vector<Collection>& collections();

/// Which keys walk_keys visits.
enum class Walk {
  Applicable,  ///< the keys that apply to the scene
  All,         ///< every key the scene's elements could have, applicable or not
};
/// The one key walk: calls visit for every key of `scene` in table order (the global rows, then
/// each collection's rows for each of its elements), stopping early when visit returns true;
/// returns whether it stopped. With scene == nullptr it walks the declarations themselves, each
/// collection once with its placeholder as the element ("springs.<type>.ks"), every row. A
/// non-empty `section` ("body", "springs", "terrain") limits the walk to the keys that start with
/// it, which saves building the others' keys when one key is looked up.
bool walk_keys(const SceneSpec* scene, Walk which, const std::function<bool(const Bound&)>& visit,
               std::string_view section = {});

/// The part of a key or pattern before its last '.' ("terrain.floor" of "terrain.floor.radius")
/// and after it ("radius").
std::string_view key_table(std::string_view key);
std::string_view key_local(std::string_view key);

/// The spring types in the order scenes list them, and their key names.
inline constexpr std::array<SpringType, 4> kSpringTypes = {
    SpringType::Structural, SpringType::Shear, SpringType::ShearBody, SpringType::Bending};
/// The spring type of element `index` of the springs collection in scene `s`.
SpringType spring_type_at(const SceneSpec& s, std::size_t index);
SpringSettings& spring_settings(SceneSpec& s, SpringType t);
const SpringSettings& spring_settings(const SceneSpec& s, SpringType t);
std::optional<SpringType> spring_type_from_string(std::string_view name);
/// "plane", "bowl" or "sphere".
std::string_view terrain_type_name(const Terrain& t);

/// The declaration with this exact pattern ("terrain.*.epsilon"), or nullptr.
const Decl* find_decl(std::string_view pattern);
/// The checks of a value a row carries: its kind and range (check_value), then its own check
/// against the rest of the scene (Decl::check); the message or nullopt.
std::optional<std::string> check_row(const Bound& b, const SceneSpec& s, const Value& v);
/// Whether a declaration applies to the scene in context ctx.
bool applies(const Decl& d, const SceneSpec& s, const Ctx& ctx);

/// Resolves a full key ("springs.shear.ks") against a scene. nullopt when no applicable
/// declaration.
std::optional<Bound> resolve(const SceneSpec& s, std::string_view key);
/// Resolves ignoring scope: finds which declaration a key would be, for "not used by this kind"
/// hints.
std::optional<Bound> resolve_any(const SceneSpec& s, std::string_view key);

/// Checks a value against a declaration's range; returns the message ("must be an integer ≥ 2,
/// got 1") or nullopt.
std::optional<std::string> check_value(const Decl& d, const Value& v);
/// Parses set_parameter text by kind; returns the value or a message saying what was expected.
std::variant<Value, std::string> parse_text(const Decl& d, std::string_view text);
/// Formats a value in the text form parse_text accepts.
std::string format_text(ValueKind kind, const Value& v);

/// Why a key that names a declaration does not apply to this scene (the key's kind and the
/// scene's, BodyKindModule::foreign_key), for error messages.
std::string inapplicable_reason(const Bound& b, const SceneSpec& s);

/// A problem that involves several keys (bowl rim, particle counts, spring table presence).
struct CrossError {
  std::string key;
  std::string message;
};
/// Checks the scene as a whole; the first problem or nullopt.
std::optional<CrossError> check_scene(const SceneSpec& s);

/// Terrain names must be usable inside dotted keys: letters, digits, '_' and '-', at most this
/// many.
inline constexpr std::size_t kMaxTerrainName = 64;
/// Why `name` cannot name a terrain ("must use letters, ..."), or nullopt when it can.
std::optional<std::string> check_terrain_name(std::string_view name);
/// The message when terrains[0 … before−1] of `s` already use `name`, else nullopt.
std::optional<std::string> check_unique_terrain_name(const SceneSpec& s, std::string_view name,
                                                     std::size_t before);

/// A terrain of the given type with that type's default geometry and default surface.
Terrain default_terrain(std::string_view name, std::string_view type);

/// Shortest text that reads back to the same double ("0.001", "2000", "1e-07").
std::string format_double(double v);
/// Text without leading and trailing white space (' ', \t, \n, \v, \f, \r).
std::string_view trim(std::string_view t);
/// Text in double quotes for messages, cut after 60 characters ("...").
std::string in_quotes(std::string_view t);
/// Describes the kind for messages: "a number", "an integer", "true or false", ...
std::string expected_text(const Decl& d);

/// Closest candidate within a small edit distance, or "" when none is close.
std::string closest(std::string_view word, const std::vector<std::string>& candidates);

}  // namespace jelly::params_detail
