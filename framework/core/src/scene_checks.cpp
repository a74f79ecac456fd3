// Validation of scene values, in one place: a value against its declaration (range, kind), the
// rows' own checks against the rest of the scene (list lengths, indices; param_rows.cpp names
// them per row), terrain names, and the scene as a whole (bowl rim, particle counts, spring
// tables). The scene reader and set_parameter both call these, through check_row.
#include <algorithm>
#include <cmath>
#include <string>

#include "jelly/body_kind.hpp"
#include "param_table.hpp"

namespace jelly::params_detail {

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

// check_value's kinds, each against its declaration d.
std::optional<std::string> check_vector3(const Decl& d, const Value& v) {
  const Vec3& p = std::get<Vec3>(v);
  if (auto e = check_finite(p, "")) return e;
  if (d.nonzero && !(p.norm() > 0.0))
    return "must have non-zero length, got " + format_text(d.kind, v);
  return std::nullopt;
}

std::optional<std::string> check_choice(const Decl& d, const std::string& s) {
  for (std::string_view c : d.choices)
    if (c == s) return std::nullopt;
  std::vector<std::string> options(d.choices.begin(), d.choices.end());
  std::string msg = "must be " + expected_text(d) + ", got " + in_quotes(s);
  const std::string near = closest(s, options);
  if (!near.empty()) msg += " (did you mean \"" + near + "\"?)";
  return msg;
}

std::optional<std::string> check_points(const std::vector<Vec3>& list) {
  for (std::size_t i = 0; i < list.size(); ++i)
    if (auto e = check_finite(list[i], "point " + std::to_string(i) + ": ")) return e;
  return std::nullopt;
}

std::optional<std::string> check_index_pairs(const std::vector<IndexPair>& list) {
  for (std::size_t i = 0; i < list.size(); ++i) {
    const IndexPair& p = list[i];
    if (p[0] < 0 || p[1] < 0)
      return "spring " + std::to_string(i) + ": indices must be ≥ 0, got " + std::to_string(p[0]) +
             ',' + std::to_string(p[1]);
    if (p[0] == p[1])
      return "spring " + std::to_string(i) + ": must join two different particles, got " +
             std::to_string(p[0]) + ',' + std::to_string(p[1]);
  }
  return std::nullopt;
}

std::optional<std::string> check_numbers(const Decl& d, const std::vector<double>& list) {
  for (std::size_t i = 0; i < list.size(); ++i)
    if (auto e = check_number(d, list[i], "a number"))
      return "element " + std::to_string(i) + ": " + *e;
  return std::nullopt;
}

std::optional<std::string> check_names(const Decl& d, const std::vector<std::string>& list) {
  std::vector<std::string> options(d.choices.begin(), d.choices.end());
  for (std::size_t i = 0; i < list.size(); ++i) {
    if (std::find(options.begin(), options.end(), list[i]) != options.end()) {
      if (std::find(list.begin(), list.begin() + static_cast<std::ptrdiff_t>(i), list[i]) !=
          list.begin() + static_cast<std::ptrdiff_t>(i))
        return "element " + std::to_string(i) + ": " + in_quotes(list[i]) + " is listed twice";
      continue;
    }
    std::string msg = "element " + std::to_string(i) + ": must be one of ";
    for (std::size_t k = 0; k < options.size(); ++k) msg += (k ? ", " : "") + options[k];
    msg += ", got " + in_quotes(list[i]);
    const std::string near = closest(list[i], options);
    if (!near.empty()) msg += " (did you mean \"" + near + "\"?)";
    return msg;
  }
  return std::nullopt;
}

std::optional<std::string> check_schedule(const Decl& d, const std::vector<ScheduleEntry>& list) {
  for (std::size_t i = 0; i < list.size(); ++i) {
    if (!std::isfinite(list[i].time))
      return "entry " + std::to_string(i) + ": time must be a finite number, got " +
             format_double(list[i].time);
    if (auto e = check_finite(list[i].velocity, "entry " + std::to_string(i) + ": " +
                                                    std::string(d.schedule_value) + " "))
      return e;
  }
  return std::nullopt;
}

}  // namespace

std::optional<std::string> check_value(const Decl& d, const Value& v) {
  switch (d.kind) {
    case ValueKind::Real: return check_number(d, std::get<double>(v), "a number");
    case ValueKind::Integer:
      return check_number(d, static_cast<double>(std::get<long long>(v)), "an integer");
    case ValueKind::Bool:
    case ValueKind::Text: return std::nullopt;
    case ValueKind::Vector3: return check_vector3(d, v);
    case ValueKind::Choice: return check_choice(d, std::get<std::string>(v));
    case ValueKind::Vec3List: return check_points(std::get<std::vector<Vec3>>(v));
    case ValueKind::IndexPairList: return check_index_pairs(std::get<std::vector<IndexPair>>(v));
    case ValueKind::RealList: return check_numbers(d, std::get<std::vector<double>>(v));
    case ValueKind::NameList: return check_names(d, std::get<std::vector<std::string>>(v));
    case ValueKind::GridList: return std::nullopt;  // against the grid: check_pin_points
    case ValueKind::Schedule: return check_schedule(d, std::get<std::vector<ScheduleEntry>>(v));
  }
  return std::nullopt;
}

namespace {

bool valid_terrain_name(std::string_view name) {
  if (name.empty() || name.size() > kMaxTerrainName) return false;
  return std::all_of(name.begin(), name.end(), [](char ch) {
    return (ch >= 'a' && ch <= 'z') || (ch >= 'A' && ch <= 'Z') || (ch >= '0' && ch <= '9') ||
           ch == '_' || ch == '-';
  });
}

}  // namespace

std::optional<std::string> check_row(const Bound& b, const SceneSpec& s, const Value& v) {
  if (auto msg = check_value(*b.decl, v)) return msg;
  if (b.decl->check) return b.decl->check(*b.decl, s, b.ctx, v);
  return std::nullopt;
}

std::optional<std::string> check_terrain_name(std::string_view name) {
  if (valid_terrain_name(name)) return std::nullopt;
  return "must use letters, digits, '_' and '-' only (at most " + std::to_string(kMaxTerrainName) +
         "), got " + in_quotes(name);
}

std::optional<std::string> check_unique_terrain_name(const SceneSpec& s, std::string_view name,
                                                     std::size_t before) {
  for (std::size_t j = 0; j < before && j < s.terrains.size(); ++j)
    if (s.terrains[j].name == name)
      return "two terrains are named " + in_quotes(name) +
             "; terrain names must be unique (give one another name = \"...\")";
  return std::nullopt;
}

std::optional<CrossError> check_scene(const SceneSpec& s) {
  // The body's own checks, then that no other kind's data is in the scene.
  const BodyKindModule& body = body_kind_of(s);
  if (auto e = body.check(s)) return e;
  for (const BodyKindModule* kind : body_kinds())
    if (kind != &body)
      if (auto e = kind->check_absent(s)) return e;
  for (std::size_t i = 0; i < s.terrains.size(); ++i) {
    const Terrain& t = s.terrains[i];
    const std::string key = "terrain." + t.name;
    if (auto msg = check_terrain_name(t.name))
      return CrossError{"terrain", "terrain " + std::to_string(i) + ": name " + *msg};
    if (auto msg = check_unique_terrain_name(s, t.name, i)) return CrossError{key + ".name", *msg};
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

}  // namespace jelly::params_detail
