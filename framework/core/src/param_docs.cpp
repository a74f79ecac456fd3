// The reference table of every declared parameter as Markdown (docs/scenes.md, `jelly params`).
#include <cmath>
#include <string>

#include "param_table.hpp"

namespace jelly {

namespace {

std::string scope_text(const params_detail::Bound& b) {
  using params_detail::Scope;
  switch (b.decl->scope) {
    case Scope::Always: return "every scene";
    case Scope::GravityOn: return "with gravity";
    case Scope::Body: return std::string(b.decl->body) + " body";
    case Scope::Element:
      return "every " + std::string(b.collection ? b.collection->noun : "element");
    case Scope::SpringOn: return "present spring types";
    case Scope::Plane: return "plane";
    case Scope::PlaneHole: return "plane with a hole";
    case Scope::Bowl: return "bowl";
    case Scope::Sphere: return "sphere";
    case Scope::When: return std::string(b.decl->when_text);
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
    case ValueKind::NameList: return "list of names";
    case ValueKind::GridList: return "list of grid coordinates";
    case ValueKind::Schedule: return "schedule";
  }
  return "";
}

std::string range_text(const params_detail::Decl& d) {
  using params_detail::format_double;
  using params_detail::ValueKind;
  if (d.kind == ValueKind::Choice || d.kind == ValueKind::NameList) {
    std::string s;
    for (std::string_view c : d.choices) s += (s.empty() ? "" : ", ") + std::string(c);
    return s;
  }
  if (d.nonzero) return "non-zero length";
  if (d.kind == ValueKind::IndexPairList) return "indices of positions, a ≠ b";
  if (d.kind == ValueKind::GridList) return "0 ≤ i, k < n";
  if (d.kind == ValueKind::Schedule) return "times strictly increasing";
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
  // The declarations themselves: each collection once, its element shown as "<type>", "<name>".
  walk_keys(nullptr, Walk::All, [&](const Bound& b) {
    const Decl& d = *b.decl;
    const std::string def = d.default_text.empty() ? "—" : "`" + std::string(d.default_text) + "`";
    out += "| `" + b.key + "` | " + scope_text(b) + " | " + std::string(kind_text(d.kind)) + " | " +
           std::string(d.unit) + " | " + def + " | " + range_text(d) + " | " +
           std::string(d.description) + " |\n";
    return false;
  });
  return out;
}

}  // namespace jelly
