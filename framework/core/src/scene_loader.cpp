// Scene files: reading (TOML via toml++), validating and writing back (`--set`: params.cpp).
//
// Every key is looked up in the declaration table (param_table.hpp): a key that is not declared
// is an error (with a "did you mean" when a declared key is close), and every value is converted
// and range-checked by its declaration. The first error (in file order) is returned with the
// file, the dotted key, and the line and column toml++ reports. Nothing here throws, exits or
// writes a file.
#include <toml++/toml.h>
#include <algorithm>
#include <cctype>
#include <fstream>
#include <map>
#include <sstream>

#include "jelly/scene.hpp"
#include "param_table.hpp"

namespace jelly {

using namespace params_detail;

namespace {

/// Where a node starts in the file (1-based; 0 when toml++ does not know).
struct Pos {
  int line = 0;
  int column = 0;
};
Pos pos_of(const toml::node& n) {
  const auto& b = n.source().begin;
  return Pos{static_cast<int>(b.line), static_cast<int>(b.column)};
}

/// Where a key is written (toml++ records it), else where its value starts.
Pos pos_of_key(const toml::key& k, const toml::node& value) {
  const auto& b = k.source().begin;
  if (b.line > 0) return Pos{static_cast<int>(b.line), static_cast<int>(b.column)};
  return pos_of(value);
}

/// "a string ("abc")", "an integer (5)", ... for "got ..." in messages.
std::string describe(const toml::node& n) {
  if (auto v = n.as_string()) return "a string (" + in_quotes(v->get()) + ")";
  if (auto v = n.as_integer()) return "an integer (" + std::to_string(v->get()) + ")";
  if (auto v = n.as_floating_point())
    return "a floating-point number (" + format_double(v->get()) + ")";
  if (auto v = n.as_boolean())
    return std::string("a boolean (") + (v->get() ? "true" : "false") + ")";
  if (auto v = n.as_array()) return "an array of " + std::to_string(v->size()) + " elements";
  if (n.is_table()) return "a table";
  return "a date or time";
}

std::string toml_expected(const Decl& d) {
  switch (d.kind) {
    case ValueKind::Real: return "a number";
    case ValueKind::Integer: return "an integer";
    case ValueKind::Bool: return "true or false";
    case ValueKind::Vector3: return "an array of 3 numbers [x, y, z]";
    case ValueKind::Choice: return "a string, " + expected_text(d);
    case ValueKind::Text: return "a string";
    case ValueKind::Vec3List: return "an array of points [[x, y, z], ...]";
    case ValueKind::IndexPairList: return "an array of index pairs [[a, b], ...]";
    case ValueKind::RealList: return "an array of numbers [r, ...]";
  }
  return "a value";
}

std::optional<double> number_of(const toml::node& n) {
  if (auto v = n.as_floating_point()) return v->get();
  if (auto v = n.as_integer()) return static_cast<double>(v->get());
  return std::nullopt;
}

std::optional<Vec3> vec3_of(const toml::node& n) {
  const toml::array* a = n.as_array();
  if (!a || a->size() != 3) return std::nullopt;
  Vec3 v;
  for (std::size_t i = 0; i < 3; ++i) {
    const auto x = number_of(*a->get(i));
    if (!x) return std::nullopt;
    v[static_cast<Eigen::Index>(i)] = *x;
  }
  return v;
}

/// TOML 1.0 allows non-ASCII characters only inside strings and comments. toml++ 3.3.0 (Debian 12)
/// reaches TOML_UNREACHABLE (undefined behaviour) when it classifies some of them, e.g. "é", as
/// possible whitespace outside a string, so such text is rejected here first, with the place.
std::optional<Pos> non_ascii_outside_strings(std::string_view text) {
  enum class In { Normal, Comment, Basic, Literal, MultiBasic, MultiLiteral };
  In state = In::Normal;
  int line = 1, column = 0;
  const auto starts = [&](std::size_t i, std::string_view what) {
    return text.substr(i, what.size()) == what;
  };
  for (std::size_t i = 0; i < text.size(); ++i) {
    const char ch = text[i];
    const auto byte = static_cast<unsigned char>(ch);
    if ((byte & 0xC0) != 0x80) ++column;  // count code points, as toml++ does
    if (ch == '\n') {
      ++line;
      column = 0;
      if (state != In::MultiBasic && state != In::MultiLiteral) state = In::Normal;
      continue;
    }
    switch (state) {
      case In::Normal:
        if (byte >= 0x80) return Pos{line, column};
        if (ch == '#') {
          state = In::Comment;
        } else if (starts(i, "\"\"\"") || starts(i, "'''")) {
          state = ch == '"' ? In::MultiBasic : In::MultiLiteral;
          i += 2;
          column += 2;
        } else if (ch == '"') {
          state = In::Basic;
        } else if (ch == '\'') {
          state = In::Literal;
        }
        break;
      case In::Comment: break;
      case In::Basic:
        if (ch == '\\' && i + 1 < text.size() && text[i + 1] != '\n') {
          ++i;  // an escaped character (only ASCII ones are valid escapes)
          ++column;
        } else if (ch == '"') {
          state = In::Normal;
        }
        break;
      case In::Literal:
        if (ch == '\'') state = In::Normal;
        break;
      case In::MultiBasic:
      case In::MultiLiteral: {
        const char quote = state == In::MultiBasic ? '"' : '\'';
        if (state == In::MultiBasic && ch == '\\' && i + 1 < text.size() && text[i + 1] != '\n') {
          ++i;
          ++column;
        } else if (ch == quote && starts(i, std::string(3, quote))) {
          // A closing delimiter may be preceded by up to two quotes that belong to the content.
          std::size_t run = 0;
          while (i + run < text.size() && text[i + run] == quote) ++run;
          i += run - 1;
          column += static_cast<int>(run) - 1;
          state = In::Normal;
        }
        break;
      }
    }
  }
  return std::nullopt;
}

/// The whole reading of one scene text; collects every key's error and reports the first.
class Loader {
 public:
  explicit Loader(std::string_view source) : source_(source) {}

  SceneResult run(std::string_view text) {
    SceneResult result;
    toml::table root;
    if (const auto at = non_ascii_outside_strings(text)) {
      result.error = SceneError{source_, "", at->line, at->column,
                                "malformed TOML: a non-ASCII character outside a string or comment "
                                "(TOML allows them only inside \"strings\" and # comments)"};
      return result;
    }
    try {
      root = toml::parse(text, source_);
    } catch (const toml::parse_error& e) {
      const Pos p{static_cast<int>(e.source().begin.line),
                  static_cast<int>(e.source().begin.column)};
      result.error = SceneError{source_, "", p.line, p.column,
                                "malformed TOML: " + std::string(e.description())};
      return result;
    }
    read_root(root);
    if (errors_.empty()) {
      if (auto cross = check_scene(spec_)) {
        const Pos p = position_for(cross->key);
        errors_.push_back(SceneError{source_, cross->key, p.line, p.column, cross->message});
      }
    }
    if (!errors_.empty()) {
      result.error = first_error();
      return result;
    }
    spec_.source = source_;
    result.scene = std::move(spec_);
    return result;
  }

 private:
  // ----- errors -----
  void error(const std::string& key, Pos p, std::string message) {
    errors_.push_back(SceneError{source_, key, p.line, p.column, std::move(message)});
  }
  /// The error that comes first in the file (errors without a position come last).
  SceneError first_error() const {
    const auto order = [](const SceneError& e) {
      return std::make_pair(e.line > 0 ? e.line : std::numeric_limits<int>::max(), e.column);
    };
    return *std::min_element(
        errors_.begin(), errors_.end(),
        [&](const SceneError& a, const SceneError& b) { return order(a) < order(b); });
  }
  /// Where a key (or, failing that, its enclosing table) was written.
  Pos position_for(std::string key) const {
    while (true) {
      const auto it = where_.find(key);
      if (it != where_.end()) return it->second;
      const auto dot = key.rfind('.');
      if (dot == std::string::npos) return Pos{};
      key.resize(dot);
    }
  }
  void unknown_key(const std::string& key, std::string_view local, Pos p,
                   const std::vector<std::string>& candidates, const std::string& context,
                   std::string_view noun = "key") {
    std::string msg = "unknown " + std::string(noun) + " " + in_quotes(local);
    if (!context.empty()) msg += " " + context;
    const std::string near = closest(local, candidates);
    if (!near.empty()) msg += " (did you mean \"" + near + "\"?)";
    if (!candidates.empty()) {
      msg += "; expected one of: ";
      for (std::size_t i = 0; i < candidates.size(); ++i) msg += (i ? ", " : "") + candidates[i];
    }
    error(key, p, std::move(msg));
  }

  // ----- values -----
  /// Converts a TOML node by the declaration's kind; reports and returns nullopt when it does not
  /// fit.
  std::optional<Value> convert(const Decl& d, const std::string& key, const toml::node& n) {
    const auto wrong = [&](const toml::node& at, const std::string& prefix = "") {
      error(key, pos_of(at), prefix + "must be " + toml_expected(d) + ", got " + describe(at));
      return std::nullopt;
    };
    switch (d.kind) {
      case ValueKind::Real:
        if (auto x = number_of(n)) return Value{*x};
        return wrong(n);
      case ValueKind::Integer:
        if (auto x = n.as_integer()) return Value{static_cast<long long>(x->get())};
        return wrong(n);
      case ValueKind::Bool:
        if (auto x = n.as_boolean()) return Value{x->get()};
        return wrong(n);
      case ValueKind::Vector3:
        if (auto v = vec3_of(n)) return Value{*v};
        return wrong(n);
      case ValueKind::Choice:
      case ValueKind::Text:
        if (auto x = n.as_string()) return Value{std::string(x->get())};
        return wrong(n);
      case ValueKind::Vec3List: {
        const toml::array* a = n.as_array();
        if (!a) return wrong(n);
        std::vector<Vec3> out;
        for (std::size_t i = 0; i < a->size(); ++i) {
          auto v = vec3_of(*a->get(i));
          if (!v) return wrong(*a->get(i), "element " + std::to_string(i) + ": ");
          out.push_back(*v);
        }
        return Value{std::move(out)};
      }
      case ValueKind::IndexPairList: {
        const toml::array* a = n.as_array();
        if (!a) return wrong(n);
        std::vector<IndexPair> out;
        for (std::size_t i = 0; i < a->size(); ++i) {
          const toml::array* pair = a->get(i)->as_array();
          if (!pair || pair->size() != 2 || !pair->get(0)->is_integer() ||
              !pair->get(1)->is_integer())
            return wrong(*a->get(i), "element " + std::to_string(i) + ": ");
          out.push_back({pair->get(0)->as_integer()->get(), pair->get(1)->as_integer()->get()});
        }
        return Value{std::move(out)};
      }
      case ValueKind::RealList: {
        const toml::array* a = n.as_array();
        if (!a) return wrong(n);
        std::vector<double> out;
        for (std::size_t i = 0; i < a->size(); ++i) {
          auto x = number_of(*a->get(i));
          if (!x) return wrong(*a->get(i), "element " + std::to_string(i) + ": ");
          out.push_back(*x);
        }
        return Value{std::move(out)};
      }
    }
    return wrong(n);
  }

  /// Converts, validates and applies one key. Returns whether it was applied.
  bool apply(const Bound& b, const toml::node& n) {
    where_[b.key] = pos_of(n);
    auto v = convert(*b.decl, b.key, n);
    if (!v) return false;
    if (auto msg = check_value(*b.decl, *v)) {
      error(b.key, pos_of(n), *msg);
      return false;
    }
    if (auto msg = check_in_scene(b, spec_, *v)) {
      error(b.key, pos_of(n), *msg);
      return false;
    }
    b.decl->set(spec_, b.ctx, *v);
    return true;
  }

  /// Reads a value of a declared key without applying it (for keys handled specially).
  std::optional<Value> read(const std::string& key, const toml::node& n) {
    const auto b = resolve_any(spec_, key);
    where_[key] = pos_of(n);
    auto v = convert(*b->decl, key, n);
    if (v) {
      if (auto msg = check_value(*b->decl, *v)) {
        error(key, pos_of(n), *msg);
        return std::nullopt;
      }
    }
    return v;
  }

  /// Applies every key of table t under prefix ("simulation", "springs.shear", "terrain.floor"),
  /// in declaration order, except the keys in `skip`. Unknown keys are reported.
  void apply_table(const toml::table& t, const std::string& prefix, const std::string& context,
                   const std::vector<std::string>& candidates,
                   const std::vector<std::string_view>& skip = {}) {
    std::vector<std::pair<Bound, const toml::node*>> found;
    for (auto&& [k, node] : t) {
      const std::string_view local = k.str();
      if (std::find(skip.begin(), skip.end(), local) != skip.end()) continue;
      const std::string key = prefix + "." + std::string(local);
      if (auto b = resolve(spec_, key)) {
        found.emplace_back(std::move(*b), &node);
      } else {
        unknown_key(key, local, pos_of_key(k, node), candidates, context);
      }
    }
    std::stable_sort(found.begin(), found.end(), [](const auto& a, const auto& b) {
      return a.first.decl < b.first.decl;  // rows of one table are contiguous in memory
    });
    for (const auto& [b, node] : found) apply(b, *node);
  }

  /// The keys of the declaration rows that apply, under `prefix`, as written in the file.
  std::vector<std::string> local_keys(const std::vector<Decl>& table, std::string_view group,
                                      const Ctx& ctx) const {
    std::vector<std::string> out;
    for (const Decl& d : table) {
      const std::string_view p = d.pattern;
      if (!group.empty() && p.substr(0, group.size() + 1) != std::string(group) + ".") continue;
      if (!applies(d, spec_, ctx)) continue;
      std::string local(p.substr(p.rfind('.') + 1));
      if (std::find(out.begin(), out.end(), local) == out.end()) out.push_back(std::move(local));
    }
    return out;
  }

  // ----- sections -----
  void read_root(const toml::table& root) {
    const std::vector<std::string> sections = {"scene", "simulation", "gravity",
                                               "body",  "springs",    "terrain"};
    for (auto&& [k, node] : root) {
      const std::string name(k.str());
      if (std::find(sections.begin(), sections.end(), name) == sections.end())
        unknown_key(name, name, pos_of_key(k, node), sections, "at the top level");
    }
    for (const std::string& name : sections) {
      const toml::node* node = root.get(name);
      if (!node) continue;
      where_[name] = pos_of(*node);
      if (name == "terrain") {
        read_terrains(*node);
        continue;
      }
      const toml::table* t = node->as_table();
      if (!t) {
        error(name, pos_of(*node), "must be a table [" + name + "], got " + describe(*node));
        continue;
      }
      if (name == "scene" || name == "simulation") {
        apply_table(*t, name, "in [" + name + "]", local_keys(global_decls(), name, Ctx{}));
      } else if (name == "gravity") {
        read_gravity(*t);
      } else if (name == "body") {
        read_body(*t);
      } else {
        read_springs(*t);
      }
    }
  }

  /// [gravity] present: gravity on with the default acceleration, then the keys; enabled = false
  /// turns it off again.
  void read_gravity(const toml::table& t) {
    find_decl("gravity.enabled")->set(spec_, Ctx{}, Value{true});
    apply_table(t, "gravity", "in [gravity]", {"acceleration", "enabled"}, {"enabled"});
    if (const toml::node* en = t.get("enabled")) {
      if (auto v = read("gravity.enabled", *en))
        find_decl("gravity.enabled")->set(spec_, Ctx{}, *v);
    }
  }

  void read_body(const toml::table& t) {
    if (const toml::node* type = t.get("type")) {
      if (auto b = resolve(spec_, "body.type"); b && !apply(*b, *type)) return;
    }
    const std::string kind = spec_.body_kind == BodyKind::Cube ? "cube" : "particles";
    std::vector<std::string> keys = local_keys(global_decls(), "body", Ctx{});
    apply_table(t, "body", "for a " + kind + " body", keys, {"type"});
  }

  void read_springs(const toml::table& t) {
    std::vector<std::string> names;
    for (SpringType st : kSpringTypes) names.emplace_back(to_string(st));
    for (auto&& [k, node] : t) {
      const std::string name(k.str());
      const std::string prefix = "springs." + name;
      where_[prefix] = pos_of(node);
      const auto type = spring_type_from_string(name);
      if (!type) {
        unknown_key(prefix, name, pos_of_key(k, node), names, "", "spring type");
        continue;
      }
      const toml::table* st = node.as_table();
      if (!st) {
        error(prefix, pos_of(node),
              "must be a table [" + prefix + "] with ks and kd, got " + describe(node));
        continue;
      }
      const Ctx ctx{*type, 0};
      const Decl& enabled = *find_decl("springs.*.enabled");
      enabled.set(spec_, ctx, Value{true});
      apply_table(*st, prefix, "in [" + prefix + "]", local_keys(spring_decls(), "", ctx),
                  {"enabled"});
      if (const toml::node* en = st->get("enabled")) {
        if (auto v = read(prefix + ".enabled", *en)) enabled.set(spec_, ctx, *v);
      }
    }
  }

  void read_terrains(const toml::node& node) {
    const toml::array* list = node.as_array();
    if (!list) {
      error("terrain", pos_of(node),
            "must be an array of tables [[terrain]], got " + describe(node));
      return;
    }
    for (std::size_t i = 0; i < list->size(); ++i) {
      const toml::node& entry = *list->get(i);
      const std::string label = "terrain[" + std::to_string(i) + "]";
      const toml::table* t = entry.as_table();
      if (!t) {
        error(label, pos_of(entry), "must be a table [[terrain]], got " + describe(entry));
        continue;
      }
      read_terrain(*t, label);
    }
  }

  /// Reads a string-valued structural key of a terrain entry (preset, name, type).
  std::optional<std::string> string_key(const toml::table& t, std::string_view key,
                                        const std::string& label) {
    const toml::node* n = t.get(key);
    if (!n) return std::nullopt;
    if (auto s = n->as_string()) return std::string(s->get());
    error(label + "." + std::string(key), pos_of(*n), "must be a string, got " + describe(*n));
    return std::nullopt;
  }

  void read_terrain(const toml::table& t, const std::string& label) {
    const std::size_t errors_before = errors_.size();
    const Pos entry_pos = pos_of(t);
    const auto preset = string_key(t, "preset", label);
    const auto type = string_key(t, "type", label);
    auto name = string_key(t, "name", label);
    if (errors_.size() != errors_before) return;

    const Decl& type_decl = *find_decl("terrain.*.type");
    if (type && !check_value(type_decl, Value{*type}).has_value()) {
      // fine: a known type
    } else if (type) {
      error(label + ".type", pos_of(*t.get("type")), *check_value(type_decl, Value{*type}));
      return;
    }

    Terrain terrain;
    if (preset) {
      auto p = terrain_preset(*preset);
      if (!p) {
        std::vector<std::string> names;
        for (std::string_view n : terrain_preset_names()) names.emplace_back(n);
        unknown_key(label + ".preset", *preset, pos_of(*t.get("preset")), names, "", "preset");
        return;
      }
      terrain = std::move(*p);
      if (type && *type != terrain_type_name(terrain)) {
        error(label + ".type", pos_of(*t.get("type")),
              "preset " + in_quotes(*preset) + " is a " + std::string(terrain_type_name(terrain)) +
                  ", got type " + in_quotes(*type) + " (leave type out when using a preset)");
        return;
      }
    } else {
      if (!type) {
        error(label, entry_pos,
              "a terrain needs either preset = \"<name>\" or type = \"plane\", "
              "\"bowl\" or \"sphere\" (with a name)");
        return;
      }
      if (!name) {
        error(label, entry_pos, "a terrain needs a name (used in keys: terrain.<name>.<key>)");
        return;
      }
      terrain = default_terrain(*name, *type);
    }
    if (name) {
      if (auto msg = check_terrain_name(*name)) {
        error(label + ".name", pos_of(*t.get("name")), *msg);
        return;
      }
      terrain.name = *name;
    }
    const std::string prefix = "terrain." + terrain.name;
    const Pos name_pos = t.get("name") ? pos_of(*t.get("name")) : entry_pos;
    if (auto msg = check_unique_terrain_name(spec_, terrain.name, spec_.terrains.size())) {
      error(prefix, name_pos, *msg);
      return;
    }
    where_[prefix] = entry_pos;
    spec_.terrains.push_back(std::move(terrain));
    const Ctx ctx{SpringType::Structural, spec_.terrains.size() - 1};
    Terrain& added = spec_.terrains.back();

    // A hole is given by both of its keys (a preset may already have one).
    if (auto* plane = std::get_if<Plane>(&added.shape)) {
      const toml::node* hc = t.get("hole_center");
      const toml::node* hr = t.get("hole_radius");
      if ((hc || hr) && !plane->has_hole) {
        if (!hc || !hr) {
          const std::string missing = hc ? "hole_radius" : "hole_center";
          error(prefix + "." + (hc ? "hole_center" : "hole_radius"), pos_of(hc ? *hc : *hr),
                "a hole needs both hole_center and hole_radius; " + missing + " is missing");
          return;
        }
        plane->has_hole = true;
      }
    }
    const std::string type_name(terrain_type_name(added));
    std::vector<std::string> keys = {"preset", "name"};
    for (std::string& k : local_keys(terrain_decls(), "", ctx)) keys.push_back(std::move(k));
    if (auto* plane = std::get_if<Plane>(&added.shape); plane && !plane->has_hole) {
      keys.emplace_back("hole_center");
      keys.emplace_back("hole_radius");
    }
    apply_table(t, prefix, "for a " + type_name + " terrain", keys, {"preset", "name", "type"});
  }

  std::string source_;
  SceneSpec spec_;
  std::vector<SceneError> errors_;
  std::map<std::string, Pos> where_;  // key → where it was written, for cross-key errors
};

// ----- writing -----

std::string toml_string(std::string_view s) {
  std::string out = "\"";
  for (const char ch : s) {
    const auto c = static_cast<unsigned char>(ch);
    switch (ch) {
      case '"': out += "\\\""; break;
      case '\\': out += "\\\\"; break;
      case '\n': out += "\\n"; break;
      case '\t': out += "\\t"; break;
      case '\r': out += "\\r"; break;
      default:
        if (c < 0x20 || c == 0x7F) {
          char buf[8];
          std::snprintf(buf, sizeof buf, "\\u%04X", c);
          out += buf;
        } else {
          out += ch;
        }
    }
  }
  return out + "\"";
}

/// A double as a TOML float ("2000.0", "0.001", "1e-07").
std::string toml_double(double v) {
  std::string s = format_double(v);
  if (s.find_first_of(".eEni") == std::string::npos) s += ".0";
  return s;
}

std::string toml_vec3(const Vec3& v) {
  return "[" + toml_double(v.x()) + ", " + toml_double(v.y()) + ", " + toml_double(v.z()) + "]";
}

std::string toml_value(ValueKind kind, const Value& v) {
  switch (kind) {
    case ValueKind::Real: return toml_double(std::get<double>(v));
    case ValueKind::Integer: return std::to_string(std::get<long long>(v));
    case ValueKind::Bool: return std::get<bool>(v) ? "true" : "false";
    case ValueKind::Vector3: return toml_vec3(std::get<Vec3>(v));
    case ValueKind::Choice:
    case ValueKind::Text: return toml_string(std::get<std::string>(v));
    case ValueKind::Vec3List: {
      const auto& list = std::get<std::vector<Vec3>>(v);
      std::string s = "[";
      for (std::size_t i = 0; i < list.size(); ++i)
        s += (i ? ",\n  " : "\n  ") + toml_vec3(list[i]);
      return s + (list.empty() ? "]" : ",\n]");
    }
    case ValueKind::IndexPairList: {
      std::string s = "[";
      const auto& list = std::get<std::vector<IndexPair>>(v);
      for (std::size_t i = 0; i < list.size(); ++i)
        s += (i ? ", [" : "[") + std::to_string(list[i][0]) + ", " + std::to_string(list[i][1]) +
             "]";
      return s + "]";
    }
    case ValueKind::RealList: {
      std::string s = "[";
      const auto& list = std::get<std::vector<double>>(v);
      for (std::size_t i = 0; i < list.size(); ++i) s += (i ? ", " : "") + toml_double(list[i]);
      return s + "]";
    }
  }
  return "\"\"";
}

/// Writes the rows of `table` that apply under ctx, except `skip`, as "key = value" lines.
void write_rows(std::string& out, const SceneSpec& scene, const std::vector<Decl>& table,
                std::string_view group, const Ctx& ctx, const std::vector<std::string_view>& skip) {
  for (const Decl& d : table) {
    const std::string_view p = d.pattern;
    if (!group.empty() && p.substr(0, group.size() + 1) != std::string(group) + ".") continue;
    const std::string_view local = p.substr(p.rfind('.') + 1);
    if (std::find(skip.begin(), skip.end(), local) != skip.end()) continue;
    if (!applies(d, scene, ctx)) continue;
    out += std::string(local) + " = " + toml_value(d.kind, d.get(scene, ctx)) + "\n";
  }
}

}  // namespace

SceneResult parse_scene(std::string_view text, std::string_view source_name) {
  try {
    return Loader(source_name).run(text);
  } catch (const std::exception& e) {
    SceneResult r;
    r.error = SceneError{std::string(source_name), "", 0, 0,
                         std::string("internal error while reading the scene: ") + e.what()};
    return r;
  }
}

SceneResult load_scene(const std::filesystem::path& path) {
  SceneResult r;
  const std::string file = path.string();
  try {
    std::error_code ec;
    const auto status = std::filesystem::status(path, ec);
    if (ec || !std::filesystem::exists(status)) {
      r.error = SceneError{file, "", 0, 0, "cannot read the scene file: no such file"};
      return r;
    }
    if (std::filesystem::is_directory(status)) {
      r.error = SceneError{file, "", 0, 0, "is a directory; expected a .toml scene file"};
      return r;
    }
    std::ifstream in(path, std::ios::binary);
    if (!in) {
      r.error = SceneError{file, "", 0, 0, "cannot open the scene file for reading"};
      return r;
    }
    std::ostringstream text;
    text << in.rdbuf();
    if (in.bad()) {
      r.error = SceneError{file, "", 0, 0, "error while reading the scene file"};
      return r;
    }
    return parse_scene(text.str(), file);
  } catch (const std::exception& e) {
    r.error = SceneError{file, "", 0, 0, std::string("cannot read the scene file: ") + e.what()};
    return r;
  }
}

std::string to_toml(const SceneSpec& scene) {
  std::string out = "# Written by jelly (to_toml); reads back to the same scene.\n";
  const Ctx none{};
  out += "\n[scene]\n";
  write_rows(out, scene, global_decls(), "scene", none, {});
  out += "\n[simulation]\n";
  write_rows(out, scene, global_decls(), "simulation", none, {});
  if (scene.gravity) {
    out += "\n[gravity]\n";
    write_rows(out, scene, global_decls(), "gravity", none, {"enabled"});
  }
  out += "\n[body]\n";
  write_rows(out, scene, global_decls(), "body", none, {});
  for (SpringType t : kSpringTypes) {
    if (!spring_settings(scene, t).enabled) continue;
    out += "\n[springs." + std::string(to_string(t)) + "]\n";
    write_rows(out, scene, spring_decls(), "", Ctx{t, 0}, {"enabled"});
  }
  for (std::size_t i = 0; i < scene.terrains.size(); ++i) {
    out += "\n[[terrain]]\nname = " + toml_string(scene.terrains[i].name) + "\n";
    write_rows(out, scene, terrain_decls(), "", Ctx{SpringType::Structural, i}, {});
  }
  return out;
}

}  // namespace jelly
