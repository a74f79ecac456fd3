// Internal to jelly::core and the body modules (framework/bodies/<kind>/): how a row of the
// parameter table is written (param_rows.cpp has the general rows, each body module its own).
#pragma once

#include <limits>
#include <string>
#include <string_view>
#include <vector>

#include "param_table.hpp"

namespace jelly::params_detail {

inline constexpr double kInf = std::numeric_limits<double>::infinity();

/// A valid range: [min, max] with each side inclusive or not; `bounded` false means any finite
/// value.
struct Range {
  bool bounded = false;
  double min = -kInf;
  double max = kInf;
  bool min_inclusive = true;
  bool max_inclusive = true;
};
inline constexpr Range kAny{};
inline constexpr Range kPositive{true, 0.0, kInf, false, true};
inline constexpr Range kNonNegative{true, 0.0, kInf, true, true};
inline constexpr Range kUnitInterval{true, 0.0, 1.0, true, true};

using Getter = Value (*)(const SceneSpec&, const Ctx&);
using Setter = void (*)(SceneSpec&, const Ctx&, const Value&);

/// Whether a row has a default. Its value is never typed in the table: it is read from
/// default-constructed scene structs (see with_defaults).
enum class Default { Yes, None };

Decl make(std::string_view pattern, Scope scope, ValueKind kind, std::string_view unit, Default def,
          Range range, std::string_view description, Getter get, Setter set,
          std::vector<std::string_view> choices = {}, bool nonzero = false);
/// A row of a body kind's section: it applies when the scene's body is `body`.
Decl of_body(std::string_view body, Decl d);
/// A row that applies when `when` holds (Scope::When; `text` says when, for the reference table);
/// `why_not` says why it does not.
Decl applies_when(Decl d, std::string_view text, bool (*when)(const SceneSpec&, const Ctx&),
                  std::string (*why_not)(const Bound&, const SceneSpec&));
/// A row whose key is written as the presence of its table ([gravity], [springs.<type>]).
Decl presence(Decl d);
/// A row the writer writes only when `when` holds.
Decl written_if(Decl d, bool (*when)(const SceneSpec&, const Ctx&));
/// A row with its own check against the rest of the scene.
Decl checked(Decl d, RowCheck check);
/// A row whose value kind's rules come from `source` (a contract's section), which their messages
/// cite.
Decl citing(Decl d, std::string_view source);

double real(const Value& v);
const Vec3& vec(const Value& v);
bool flag(const Value& v);
const std::string& text(const Value& v);
std::vector<Vec3> columns(const Vec3Array& a);
Vec3Array matrix(const std::vector<Vec3>& v);

/// Gives a default scene what a row needs to read its default from (an element of its
/// collection); nullptr: nothing.
using PrepareDefaults = void (*)(SceneSpec&, const Decl&);
/// A table with each row's default text filled in, read from default-constructed structs.
std::vector<Decl> with_defaults(std::vector<Decl> table, PrepareDefaults prepare = nullptr);

/// A body kind's rows (BodyKindModule::rows): each row of Scope::Body gets the kind's name, and
/// every row its default text.
std::vector<Decl> body_section(std::string_view body, std::vector<Decl> rows,
                               PrepareDefaults prepare = nullptr);

/// A collection: its name, placeholder and noun, its layout and elements, and its rows.
Collection collection(std::string_view name, std::string_view placeholder, std::string_view noun,
                      Layout layout, std::vector<std::string> (*elements)(const SceneSpec&),
                      std::vector<Decl> rows);

}  // namespace jelly::params_detail
