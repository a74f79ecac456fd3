// Scene files out: to_toml, a scene as TOML text that the reader (scene_reader.cpp) reads back to
// the same scene, bit for bit.
//
// It walks the declared keys (param_table.hpp's walk_keys) and writes each table as it comes:
// the global tables ([scene], [simulation], [gravity], [body]), then each collection's elements
// ([springs.<type>] tables, [[terrain]] entries). A table is written when at least one of its keys
// is; presence rows (gravity.enabled, springs.<type>.enabled) are written as their table being
// there.
//
// The text is formatted here rather than by toml++'s toml_formatter, on purpose:
//  - toml::table keeps its keys in a std::map, so toml++ would write every table's keys, and the
//    tables, in alphabetical order ([body] before [scene], kd before ks) instead of the
//    declaration order the docs and `jelly params` use;
//  - toml++ 3.3 prints floats through std::ostringstream with max_digits10 on GCC and Clang
//    (TOML_FLOAT_CHARCONV is 0 there), so 0.1 would become 0.10000000000000001; the shortest
//    round-trip form (std::to_chars, as format_double) is what users read and diff;
//  - toml++ cannot write the header comment, nor the one-point-per-line lists of body.positions.
// The written text is pinned by the round-trip tests (tests/core/test_scene_loader.cpp,
// test_scene_params.cpp, tests/fuzz: writing is a fixed point) and tests/hard keys its cache on it.
#include <cstdio>
#include <string>

#include "jelly/scene.hpp"
#include "param_table.hpp"

namespace jelly {

using namespace params_detail;

namespace {

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

std::string toml_value(const Decl& d, ValueKind kind, const Value& v) {
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
    case ValueKind::NameList: {
      std::string s = "[";
      const auto& list = std::get<std::vector<std::string>>(v);
      for (std::size_t i = 0; i < list.size(); ++i) s += (i ? ", " : "") + toml_string(list[i]);
      return s + "]";
    }
    case ValueKind::GridList: return toml_value(d, ValueKind::IndexPairList, v);
    case ValueKind::Schedule: {
      const auto& list = std::get<std::vector<ScheduleEntry>>(v);
      std::string s = "[";
      for (const ScheduleEntry& e : list)
        s += "\n  { time = " + toml_double(e.time) + ", " + std::string(d.schedule_value) + " = " +
             toml_vec3(e.velocity) + " },";
      return s + (list.empty() ? "]" : "\n]");
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

/// The header of the table a key belongs to: "[body]", "[springs.shear]", or for an element of
/// an array collection "[[terrain]]" and its name key.
std::string table_header(const Bound& b) {
  const std::string table(key_table(b.key));
  if (!b.collection || b.collection->layout == Layout::Tables) return "[" + table + "]\n";
  if (b.collection->layout == Layout::Indexed)
    return "[[" + std::string(b.collection->name) + "]]\n";
  const std::string name(b.collection->name);
  return "[[" + name + "]]\nname = " + toml_string(table.substr(name.size() + 1)) + "\n";
}

}  // namespace

std::string to_toml(const SceneSpec& scene) {
  std::string out = "# Written by jelly (to_toml); reads back to the same scene.\n";
  std::string table;  // the table written last
  walk_keys(&scene, Walk::Applicable, [&](const Bound& b) {
    if (b.decl->presence) return false;
    if (b.decl->written && !b.decl->written(scene, b.ctx)) return false;
    if (key_table(b.key) != table) {
      table = std::string(key_table(b.key));
      out += "\n" + table_header(b);
    }
    out += std::string(key_local(b.key)) + " = " +
           toml_value(*b.decl, b.decl->kind, b.decl->get(scene, b.ctx)) + "\n";
    return false;
  });
  return out;
}

}  // namespace jelly
