// Scene files in: reading (TOML via toml++) and validating. The writer is scene_writer.cpp,
// `--set` is params.cpp.
//
// Every key is looked up in the declaration table (param_table.hpp) through its key walk: a key
// that is not declared is an error (with a "did you mean" when a declared key is close), and every
// value is converted by its row's kind and checked by the row's checks. The first error (in file
// order) is returned with the file, the dotted key, and the line and column toml++ reports.
// Nothing here throws, exits or writes a file.
#include <toml++/toml.h>
#include <algorithm>
#include <cctype>
#include <fstream>
#include <map>
#include <sstream>

#include "jelly/body_kind.hpp"
#include "jelly/scene.hpp"
#include "jelly/toml_text.hpp"
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
    case ValueKind::NameList: return "an array of strings [\"name\", ...], " + expected_text(d);
    case ValueKind::GridList: return "an array of grid coordinates [[i, k], ...]";
    case ValueKind::Schedule:
      return "an array of { time = t, " + std::string(d.schedule_value) +
             " = [x, y, z] } tables, times in s";
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

std::optional<IndexPair> index_pair_of(const toml::node& n) {
  const toml::array* pair = n.as_array();
  if (!pair || pair->size() != 2 || !pair->get(0)->is_integer() || !pair->get(1)->is_integer())
    return std::nullopt;
  return IndexPair{pair->get(0)->as_integer()->get(), pair->get(1)->as_integer()->get()};
}

std::optional<std::string> string_of(const toml::node& n) {
  if (const auto* s = n.as_string()) return std::string(s->get());
  return std::nullopt;
}

/// The whole reading of one scene text; collects every key's error and reports the first.
class Loader {
 public:
  explicit Loader(std::string_view source) : source_(source) {}

  SceneResult run(std::string_view text) {
    SceneResult result;
    toml::table root;
    if (const auto at = toml_non_ascii_outside_strings(text)) {
      result.error =
          SceneError{source_, "", at->line, at->column, std::string(kTomlNonAsciiMessage)};
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
    switch (d.kind) {
      case ValueKind::Real:
        if (auto x = number_of(n)) return Value{*x};
        return wrong(d, key, n);
      case ValueKind::Integer:
        if (auto x = n.as_integer()) return Value{static_cast<long long>(x->get())};
        return wrong(d, key, n);
      case ValueKind::Bool:
        if (auto x = n.as_boolean()) return Value{x->get()};
        return wrong(d, key, n);
      case ValueKind::Vector3:
        if (auto v = vec3_of(n)) return Value{*v};
        return wrong(d, key, n);
      case ValueKind::Choice:
      case ValueKind::Text:
        if (auto x = n.as_string()) return Value{std::string(x->get())};
        return wrong(d, key, n);
      case ValueKind::Vec3List: return convert_list(d, key, n, &vec3_of);
      case ValueKind::IndexPairList:
      case ValueKind::GridList:  // both read as [[a, b], ...] of integers
        return convert_list(d, key, n, &index_pair_of);
      case ValueKind::NameList: return convert_list(d, key, n, &string_of);
      case ValueKind::Schedule: return convert_schedule(d, key, n);
      case ValueKind::RealList: return convert_list(d, key, n, &number_of);
    }
    return wrong(d, key, n);
  }

  /// Reports that `at` (the value, or one of its elements after `prefix`) does not fit d's kind.
  std::nullopt_t wrong(const Decl& d, const std::string& key, const toml::node& at,
                       const std::string& prefix = "") {
    error(key, pos_of(at), prefix + "must be " + toml_expected(d) + ", got " + describe(at));
    return std::nullopt;
  }

  /// An array whose every element `element` converts; the first that does not is reported.
  template <typename T>
  std::optional<Value> convert_list(const Decl& d, const std::string& key, const toml::node& n,
                                    std::optional<T> (*element)(const toml::node&)) {
    const toml::array* a = n.as_array();
    if (!a) return wrong(d, key, n);
    std::vector<T> out;
    for (std::size_t i = 0; i < a->size(); ++i) {
      std::optional<T> v = element(*a->get(i));
      if (!v) return wrong(d, key, *a->get(i), "element " + std::to_string(i) + ": ");
      out.push_back(std::move(*v));
    }
    return Value{std::move(out)};
  }

  /// An array of { time = t, <value> = [x, y, z] } tables (Decl::schedule_value), times
  /// increasing.
  std::optional<Value> convert_schedule(const Decl& d, const std::string& key,
                                        const toml::node& n) {
    const toml::array* a = n.as_array();
    if (!a) return wrong(d, key, n);
    std::vector<ScheduleEntry> out;
    for (std::size_t i = 0; i < a->size(); ++i) {
      const std::optional<ScheduleEntry> entry = schedule_entry(d, key, *a->get(i), i, out);
      if (!entry) return std::nullopt;
      out.push_back(*entry);
    }
    return Value{std::move(out)};
  }

  /// Entry i of a schedule, whose time comes after the entries `before` it.
  std::optional<ScheduleEntry> schedule_entry(const Decl& d, const std::string& key,
                                              const toml::node& item, std::size_t i,
                                              const std::vector<ScheduleEntry>& before) {
    const std::string at = "entry " + std::to_string(i) + ": ";
    const std::string name(d.schedule_value);
    const toml::table* e = item.as_table();
    if (!e) return wrong(d, key, item, at);
    if (!only_time_and_value(key, name, *e, at)) return std::nullopt;
    const toml::node* time = e->get("time");
    const toml::node* value = e->get(name);
    if (!time || !value) {
      error(key, pos_of(item),
            at + "needs both time (s) and " + name + " [x, y, z]" + schedule_unit(d) + "; " +
                (time ? name : "time") + " is missing");
      return std::nullopt;
    }
    const auto t = number_of(*time);
    if (!t) {
      error(key, pos_of(*time), at + "time must be a number (s), got " + describe(*time));
      return std::nullopt;
    }
    const auto u = vec3_of(*value);
    if (!u) {
      error(key, pos_of(*value),
            at + name + " must be an array of 3 numbers [x, y, z], got " + describe(*value));
      return std::nullopt;
    }
    if (!before.empty() && !(*t > before.back().time))
      return not_after(d, key, *time, i, *t, before.back().time);
    return ScheduleEntry{*t, *u};
  }

  /// " (m/s)": the unit of a schedule's value, from the row's unit "s: m/s"; "" when none.
  static std::string schedule_unit(const Decl& d) {
    const std::size_t colon = d.unit.find(": ");
    if (colon == std::string_view::npos) return "";
    return " (" + std::string(d.unit.substr(colon + 2)) + ")";
  }

  /// Reports a schedule entry's first key that is neither time nor the row's value key.
  bool only_time_and_value(const std::string& key, const std::string& name, const toml::table& e,
                           const std::string& at) {
    for (auto&& [k, v] : e) {
      if (k.str() != "time" && k.str() != name) {
        const std::string near = closest(k.str(), {"time", name});
        error(key, pos_of_key(k, v),
              at + "unknown key " + in_quotes(k.str()) +
                  (near.empty() ? "" : " (did you mean \"" + near + "\"?)") +
                  "; expected time and " + name);
        return false;
      }
    }
    return true;
  }

  /// Reports entry i's time t, which is not after the time of the entry before it.
  std::nullopt_t not_after(const Decl& d, const std::string& key, const toml::node& time,
                           std::size_t i, double t, double previous) {
    error(key, pos_of(time),
          "times must increase strictly" +
              (d.cites.empty() ? std::string() : " (" + std::string(d.cites) + ")") + ": entry " +
              std::to_string(i) + " has time " + format_double(t) + " s after " +
              format_double(previous) + " s");
    return std::nullopt;
  }

  /// Converts, validates and applies one key. Returns whether it was applied.
  bool apply(const Bound& b, const toml::node& n) {
    where_[b.key] = pos_of(n);
    auto v = convert(*b.decl, b.key, n);
    if (!v) return false;
    if (auto msg = check_row(b, spec_, *v)) {
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
      if (auto msg = check_row(*b, spec_, *v)) {
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
      } else if (const auto any =
                     explain_inapplicable(prefix) ? resolve_any(spec_, key) : std::nullopt) {
        error(key, pos_of_key(k, node), inapplicable_reason(*any, spec_));
      } else {
        unknown_key(key, local, pos_of_key(k, node), candidates, context);
      }
    }
    std::stable_sort(found.begin(), found.end(), [](const auto& a, const auto& b) {
      return a.first.decl < b.first.decl;  // rows of one table are contiguous in memory
    });
    for (const auto& [b, node] : found) apply(b, *node);
  }

  /// Whether a declared key that does not apply in table `prefix` is reported with the reason
  /// rather than as unknown: the scene's body kind says (BodyKindModule::explains_foreign_keys).
  bool explain_inapplicable(const std::string&) const {
    return body_kind_of(spec_).explains_foreign_keys();
  }

  /// The keys that apply in the table `prefix` ("body", "springs.shear", "terrain.floor"), as
  /// written in the file, in table order.
  std::vector<std::string> local_keys(std::string_view prefix) const {
    std::vector<std::string> out;
    walk_keys(
        &spec_, Walk::Applicable,
        [&](const Bound& b) {
          if (key_table(b.key) != prefix) return false;
          std::string local(key_local(b.key));
          if (std::find(out.begin(), out.end(), local) == out.end())
            out.push_back(std::move(local));
          return false;
        },
        prefix.substr(0, prefix.find('.')));
    return out;
  }

  // ----- sections -----
  /// The top-level names a scene file may use, in table order: the global rows' tables (scene,
  /// simulation, gravity, body), then the collections (springs, terrain).
  static std::vector<std::string> section_names() {
    std::vector<std::string> out;
    walk_keys(nullptr, Walk::All, [&](const Bound& b) {
      std::string name(b.key.substr(0, b.key.find('.')));
      if (std::find(out.begin(), out.end(), name) == out.end()) out.push_back(std::move(name));
      return false;
    });
    return out;
  }

  static const Collection* find_collection(std::string_view name) {
    for (const Collection& c : collections())
      if (c.name == name) return &c;
    return nullptr;
  }

  void read_root(const toml::table& root) {
    const std::vector<std::string> sections = section_names();
    for (auto&& [k, node] : root) {
      const std::string name(k.str());
      if (std::find(sections.begin(), sections.end(), name) == sections.end())
        unknown_key(name, name, pos_of_key(k, node), sections, "at the top level");
    }
    for (const std::string& name : sections) {
      const toml::node* node = root.get(name);
      if (!node) continue;
      where_[name] = pos_of(*node);
      if (auto why = section_not_here(name)) {
        error(name, pos_of(*node), *why);
        continue;
      }
      const Collection* collection = find_collection(name);
      if (collection && collection->layout != Layout::Tables) {
        read_array(*collection, *node);
        continue;
      }
      const toml::table* t = node->as_table();
      if (!t) {
        error(name, pos_of(*node), "must be a table [" + name + "], got " + describe(*node));
        continue;
      }
      if (collection) {
        read_tables(*collection, *t);
      } else if (name == "gravity") {
        read_gravity(*t);
      } else if (name == "body") {
        read_body(*t);
      } else {
        apply_table(*t, name, "in [" + name + "]", local_keys(name));
      }
    }
  }

  /// The body kind whose own table `section` is (a table of its rows other than [body], or one
  /// of its collections), or nullptr for a general table.
  static const BodyKindModule* section_owner(std::string_view section) {
    if (section == "body") return nullptr;
    for (const Collection& c : collections())
      if (c.name == section && !c.body.empty()) return find_body_kind(c.body);
    for (const Decl& d : global_decls())
      if (d.scope == Scope::Body && key_table(d.pattern) == section) return find_body_kind(d.body);
    return nullptr;
  }

  /// Why a section may not be in this scene: another kind's table (BodyKindModule::
  /// foreign_section), or a general one the scene's kind has none of (refuses_section). nullopt
  /// when it may.
  std::optional<std::string> section_not_here(const std::string& name) const {
    const BodyKindModule& body = body_kind_of(spec_);
    if (auto why = body.refuses_section(name)) return why;
    const BodyKindModule* owner = section_owner(name);
    if (owner && owner != &body) return owner->foreign_section(name, spec_.body_kind.name);
    return std::nullopt;
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
    const std::string kind(spec_.body_kind.name);
    apply_table(t, "body", "for a " + kind + " body", local_keys("body"), {"type"});
  }

  /// A collection written as one table per element ([springs.shear]): each table must name an
  /// element; its presence row (if the collection has one) is set on before the keys are read,
  /// and its own key (enabled = false) read last.
  void read_tables(const Collection& c, const toml::table& t) {
    const std::vector<std::string> names = c.elements(spec_);
    const Decl* presence = nullptr;
    std::vector<std::string> listed;  // the keys a table holds, for "must be a table ... with"
    for (const Decl& d : c.rows) {
      if (d.presence) {
        presence = &d;
      } else {
        listed.emplace_back(key_local(d.pattern));
      }
    }
    std::string with;
    for (std::size_t i = 0; i < listed.size(); ++i)
      with += (i == 0 ? "" : i + 1 == listed.size() ? " and " : ", ") + listed[i];
    for (auto&& [k, node] : t) {
      const std::string name(k.str());
      const std::string prefix = std::string(c.name) + "." + name;
      where_[prefix] = pos_of(node);
      const auto at = std::find(names.begin(), names.end(), name);
      if (at == names.end()) {
        unknown_key(prefix, name, pos_of_key(k, node), names, "", c.noun);
        continue;
      }
      const toml::table* element = node.as_table();
      if (!element) {
        error(prefix, pos_of(node),
              "must be a table [" + prefix + "] with " + with + ", got " + describe(node));
        continue;
      }
      const Ctx ctx{static_cast<std::size_t>(at - names.begin())};
      std::vector<std::string_view> skip;
      if (presence) {
        presence->set(spec_, ctx, Value{true});
        skip.push_back(key_local(presence->pattern));
      }
      apply_table(*element, prefix, "in [" + prefix + "]", local_keys(prefix), skip);
      if (presence) {
        if (const toml::node* en = element->get(key_local(presence->pattern))) {
          if (auto v = read(prefix + "." + std::string(key_local(presence->pattern)), *en))
            presence->set(spec_, ctx, *v);
        }
      }
    }
  }

  /// A collection written as an array of tables ([[terrain]]), each entry one element.
  void read_array(const Collection& c, const toml::node& node) {
    const std::string name(c.name);
    const toml::array* list = node.as_array();
    if (!list) {
      error(name, pos_of(node),
            "must be an array of tables [[" + name + "]], got " + describe(node));
      return;
    }
    for (std::size_t i = 0; i < list->size(); ++i) {
      const toml::node& entry = *list->get(i);
      const std::string label = name + "[" + std::to_string(i) + "]";
      const toml::table* t = entry.as_table();
      if (!t) {
        error(label, pos_of(entry), "must be a table [[" + name + "]], got " + describe(entry));
        continue;
      }
      // Making an element from its entry is the collection's own step: the terrain's (preset,
      // type, hole), an indexed one's (its first key first: a sphere's kinematic).
      if (c.layout == Layout::Indexed) {
        read_indexed(c, *t, i);
      } else {
        read_terrain(*t, label);
      }
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

  /// One entry of an indexed collection ([[sphere]]): the collection's first key is read first,
  /// since it decides which keys apply (a sphere's kinematic: velocity and mass for a dynamic
  /// sphere, schedule for a kinematic one).
  void read_indexed(const Collection& c, const toml::table& t, std::size_t index) {
    const std::string prefix = std::string(c.name) + "." + std::to_string(index);
    where_[prefix] = pos_of(t);
    c.append(spec_);
    std::vector<std::string_view> skip;
    if (!c.first_key.empty()) {
      if (const toml::node* k = t.get(c.first_key)) {
        if (auto b = resolve(spec_, prefix + "." + std::string(c.first_key))) apply(*b, *k);
      }
      skip.push_back(c.first_key);
    }
    apply_table(t, prefix, "for a " + std::string(c.noun), local_keys(prefix), skip);
  }

  void read_terrain(const toml::table& t, const std::string& label) {
    const std::size_t errors_before = errors_.size();
    const Pos entry_pos = pos_of(t);
    const auto preset = string_key(t, "preset", label);
    const auto type = string_key(t, "type", label);
    auto name = string_key(t, "name", label);
    if (errors_.size() != errors_before) return;
    if (type && !known_terrain_type(t, label, *type)) return;
    std::optional<Terrain> terrain = preset ? preset_terrain(t, label, *preset, type)
                                            : default_terrain_of(label, entry_pos, type, name);
    if (!terrain) return;
    if (name && !rename_terrain(t, label, *name, *terrain)) return;
    Terrain* added = add_terrain(t, entry_pos, std::move(*terrain));
    if (!added) return;
    const std::string prefix = "terrain." + added->name;
    if (!read_hole(t, prefix, *added)) return;
    const std::string type_name(terrain_type_name(*added));
    apply_table(t, prefix, "for a " + type_name + " terrain", terrain_keys(prefix, *added),
                {"preset", "name", "type"});
  }

  // read_terrain's steps; each returns false (or nothing) after an error.
  bool known_terrain_type(const toml::table& t, const std::string& label, const std::string& type) {
    const Decl& type_decl = *find_decl("terrain.*.type");
    if (!check_value(type_decl, Value{type}).has_value()) return true;  // a known type
    error(label + ".type", pos_of(*t.get("type")), *check_value(type_decl, Value{type}));
    return false;
  }

  std::optional<Terrain> preset_terrain(const toml::table& t, const std::string& label,
                                        const std::string& preset,
                                        const std::optional<std::string>& type) {
    auto p = terrain_preset(preset);
    if (!p) {
      std::vector<std::string> names;
      for (std::string_view n : terrain_preset_names()) names.emplace_back(n);
      unknown_key(label + ".preset", preset, pos_of(*t.get("preset")), names, "", "preset");
      return std::nullopt;
    }
    if (type && *type != terrain_type_name(*p)) {
      error(label + ".type", pos_of(*t.get("type")),
            "preset " + in_quotes(preset) + " is a " + std::string(terrain_type_name(*p)) +
                ", got type " + in_quotes(*type) + " (leave type out when using a preset)");
      return std::nullopt;
    }
    return p;
  }

  std::optional<Terrain> default_terrain_of(const std::string& label, const Pos& entry_pos,
                                            const std::optional<std::string>& type,
                                            const std::optional<std::string>& name) {
    if (!type) {
      error(label, entry_pos,
            "a terrain needs either preset = \"<name>\" or type = \"plane\", "
            "\"bowl\" or \"sphere\" (with a name)");
      return std::nullopt;
    }
    if (!name) {
      error(label, entry_pos, "a terrain needs a name (used in keys: terrain.<name>.<key>)");
      return std::nullopt;
    }
    return default_terrain(*name, *type);
  }

  bool rename_terrain(const toml::table& t, const std::string& label, const std::string& name,
                      Terrain& terrain) {
    if (auto msg = check_terrain_name(name)) {
      error(label + ".name", pos_of(*t.get("name")), *msg);
      return false;
    }
    terrain.name = name;
    return true;
  }

  /// The terrain added to the scene, or null when another terrain has its name.
  Terrain* add_terrain(const toml::table& t, const Pos& entry_pos, Terrain terrain) {
    const std::string prefix = "terrain." + terrain.name;
    const Pos name_pos = t.get("name") ? pos_of(*t.get("name")) : entry_pos;
    if (auto msg = check_unique_terrain_name(spec_, terrain.name, spec_.terrains.size())) {
      error(prefix, name_pos, *msg);
      return nullptr;
    }
    where_[prefix] = entry_pos;
    spec_.terrains.push_back(std::move(terrain));
    return &spec_.terrains.back();
  }

  /// A hole is given by both of its keys (a preset may already have one).
  bool read_hole(const toml::table& t, const std::string& prefix, Terrain& added) {
    auto* plane = std::get_if<Plane>(&added.shape);
    if (!plane) return true;
    const toml::node* hc = t.get("hole_center");
    const toml::node* hr = t.get("hole_radius");
    if ((hc || hr) && !plane->has_hole) {
      if (!hc || !hr) {
        const std::string missing = hc ? "hole_radius" : "hole_center";
        error(prefix + "." + (hc ? "hole_center" : "hole_radius"), pos_of(hc ? *hc : *hr),
              "a hole needs both hole_center and hole_radius; " + missing + " is missing");
        return false;
      }
      plane->has_hole = true;
    }
    return true;
  }

  /// The keys a terrain's table may hold.
  std::vector<std::string> terrain_keys(const std::string& prefix, const Terrain& added) {
    std::vector<std::string> keys = {"preset", "name"};
    for (std::string& k : local_keys(prefix)) keys.push_back(std::move(k));
    if (auto* plane = std::get_if<Plane>(&added.shape); plane && !plane->has_hole) {
      keys.emplace_back("hole_center");
      keys.emplace_back("hole_radius");
    }
    return keys;
  }

  std::string source_;
  SceneSpec spec_;
  std::vector<SceneError> errors_;
  std::map<std::string, Pos> where_;  // key → where it was written, for cross-key errors
};

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

}  // namespace jelly
