// Parameter values as text: what `--set` and `jelly params` read and write ("5000", "-5,11,0",
// "x,y,z; x,y,z"), parsed by a declaration's kind, and the shortest text of a double.
#include <charconv>
#include <optional>
#include <string>

#include "jelly/number_text.hpp"
#include "param_table.hpp"

namespace jelly::params_detail {

std::string format_double(double v) {
  char buf[64];
  const auto res = std::to_chars(buf, buf + sizeof buf, v);
  return std::string(buf, res.ptr);
}

std::string_view trim(std::string_view t) {
  const auto is_space = [](char ch) {
    return ch == ' ' || ch == '\t' || ch == '\n' || ch == '\v' || ch == '\f' || ch == '\r';
  };
  while (!t.empty() && is_space(t.front())) t.remove_prefix(1);
  while (!t.empty() && is_space(t.back())) t.remove_suffix(1);
  return t;
}

std::string in_quotes(std::string_view t) {
  std::string s = "\"";
  s.append(t.substr(0, 60));
  if (t.size() > 60) s += "...";
  return s + "\"";
}

namespace {

std::optional<double> parse_double(std::string_view t) { return read_double(trim(t)); }

std::optional<long long> parse_integer(std::string_view t) { return read_integer(trim(t)); }

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
  if (t.size() >= 2 &&
      ((t.front() == '[' && t.back() == ']') || (t.front() == '(' && t.back() == ')')))
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
    if (c < 0x80) {
      ++i;
      continue;
    }
    if ((c & 0xE0) == 0xC0) {
      len = 2;
      cp = c & 0x1Fu;
    } else if ((c & 0xF0) == 0xE0) {
      len = 3;
      cp = c & 0x0Fu;
    } else if ((c & 0xF8) == 0xF0) {
      len = 4;
      cp = c & 0x07u;
    } else
      return false;
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
    case ValueKind::NameList: {
      std::string s = "a list of names from ";
      for (std::size_t i = 0; i < d.choices.size(); ++i)
        s += (i ? ", " : "") + std::string(d.choices[i]);
      return s + " (\"name,name\"; empty for none)";
    }
    case ValueKind::GridList: return "a list of grid coordinates \"i,k; i,k\"";
    case ValueKind::Schedule: return "a schedule \"time: x,y,z; time: x,y,z\"";
  }
  return "a value";
}

namespace {

// The list kinds: the value, or nothing when an item is not one.
std::optional<Value> vec3_list(std::string_view t) {
  std::vector<Vec3> out;
  if (!t.empty())
    for (std::string_view item : split(t, ';')) {
      auto v = parse_vec3(item);
      if (!v) return std::nullopt;
      out.push_back(*v);
    }
  return Value{std::move(out)};
}

std::optional<Value> name_list(std::string_view t) {
  std::vector<std::string> out;
  const std::string_view inner = strip_brackets(t);
  if (!inner.empty())
    for (std::string_view item : split(inner, ',')) {
      if (item.size() >= 2 && item.front() == '"' && item.back() == '"')
        item = item.substr(1, item.size() - 2);
      if (item.empty()) return std::nullopt;
      out.emplace_back(item);
    }
  return Value{std::move(out)};
}

std::optional<Value> schedule(std::string_view t) {
  std::vector<ScheduleEntry> out;
  if (!t.empty())
    for (std::string_view item : split(t, ';')) {
      const std::size_t colon = item.find(':');
      if (colon == std::string_view::npos) return std::nullopt;
      const auto time = parse_double(item.substr(0, colon));
      const auto velocity = parse_vec3(item.substr(colon + 1));
      if (!time || !velocity) return std::nullopt;
      out.push_back(ScheduleEntry{*time, *velocity});
    }
  return Value{std::move(out)};
}

std::optional<Value> index_pairs(std::string_view t) {
  std::vector<IndexPair> out;
  if (!t.empty())
    for (std::string_view item : split(t, ';')) {
      const auto ab = split(strip_brackets(item), ',');
      if (ab.size() != 2) return std::nullopt;
      const auto a = parse_integer(ab[0]);
      const auto b = parse_integer(ab[1]);
      if (!a || !b) return std::nullopt;
      out.push_back({*a, *b});
    }
  return Value{std::move(out)};
}

std::optional<Value> real_list(std::string_view t) {
  std::vector<double> out;
  const std::string_view inner = strip_brackets(t);
  if (!inner.empty())
    for (std::string_view item : split(inner, ',')) {
      auto v = parse_double(item);
      if (!v) return std::nullopt;
      out.push_back(*v);
    }
  return Value{std::move(out)};
}

/// A value of every kind but text from its trimmed text, or nothing when it is not one.
std::optional<Value> parse_trimmed(ValueKind kind, std::string_view t) {
  switch (kind) {
    case ValueKind::Real:
      if (auto v = parse_double(t)) return Value{*v};
      return std::nullopt;
    case ValueKind::Integer:
      if (auto v = parse_integer(t)) return Value{*v};
      return std::nullopt;
    case ValueKind::Bool:
      if (t == "true") return Value{true};
      if (t == "false") return Value{false};
      return std::nullopt;
    case ValueKind::Vector3:
      if (auto v = parse_vec3(t)) return Value{*v};
      return std::nullopt;
    case ValueKind::Choice: return Value{std::string(t)};
    case ValueKind::Text: return std::nullopt;  // parse_text keeps text untrimmed
    case ValueKind::Vec3List: return vec3_list(t);
    case ValueKind::NameList: return name_list(t);
    case ValueKind::Schedule: return schedule(t);
    case ValueKind::GridList:
    case ValueKind::IndexPairList: return index_pairs(t);
    case ValueKind::RealList: return real_list(t);
  }
  return std::nullopt;
}

}  // namespace

std::variant<Value, std::string> parse_text(const Decl& d, std::string_view raw) {
  const std::string_view t = trim(raw);
  const std::string bad = "must be " + expected_text(d) + ", got " + in_quotes(raw);
  if (d.kind == ValueKind::Text) {
    if (!valid_utf8(raw)) return std::string("must be valid UTF-8 text");
    return Value{std::string(raw)};
  }
  if (auto v = parse_trimmed(d.kind, t)) return std::move(*v);
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
    case ValueKind::NameList: {
      std::string s;
      for (const std::string& name : std::get<std::vector<std::string>>(v))
        s += (s.empty() ? "" : ",") + name;
      return s;
    }
    case ValueKind::Schedule: {
      std::string s;
      for (const ScheduleEntry& e : std::get<std::vector<ScheduleEntry>>(v))
        s += (s.empty() ? "" : "; ") + format_double(e.time) + ": " + vec3(e.velocity);
      return s;
    }
    case ValueKind::GridList:
    case ValueKind::IndexPairList: {
      std::string s;
      for (const IndexPair& p : std::get<std::vector<IndexPair>>(v))
        s += (s.empty() ? "" : "; ") + std::to_string(p[0]) + ',' + std::to_string(p[1]);
      return s;
    }
    case ValueKind::RealList: {
      std::string s;
      for (double r : std::get<std::vector<double>>(v))
        s += (s.empty() ? "" : ",") + format_double(r);
      return s;
    }
  }
  return {};
}

}  // namespace jelly::params_detail
