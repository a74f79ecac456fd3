// The public interface of the parameters (params.hpp): the parameters of a scene, and getting and
// setting one by its dotted key. The rows and the key walk are in param_rows.cpp, validation in
// scene_checks.cpp.
#include "jelly/params.hpp"

#include <exception>
#include <string>

#include "param_table.hpp"

namespace jelly {

using namespace params_detail;

namespace {

ParamInfo info_of(const Bound& b) {
  const Decl& d = *b.decl;
  ParamInfo p;
  p.key = b.key;
  switch (d.kind) {
    case ValueKind::Real: p.type = ParamType::Real; break;
    case ValueKind::Integer: p.type = ParamType::Integer; break;
    case ValueKind::Bool: p.type = ParamType::Bool; break;
    case ValueKind::Vector3: p.type = ParamType::Vector3; break;
    case ValueKind::Choice: p.type = ParamType::Choice; break;
    default: p.type = ParamType::Text; break;  // text and the particle lists (text forms)
  }
  p.unit = std::string(d.unit);
  p.default_text = std::string(d.default_text);
  p.bounded = d.bounded;
  p.min = d.min;
  p.max = d.max;
  p.min_inclusive = d.min_inclusive;
  p.max_inclusive = d.max_inclusive;
  for (std::string_view c : d.choices) p.choices.emplace_back(c);
  p.description = std::string(d.description);
  return p;
}

}  // namespace

std::vector<ParamInfo> scene_parameters(const SceneSpec& scene) {
  std::vector<ParamInfo> out;
  walk_keys(&scene, Walk::Applicable, [&](const Bound& b) {
    out.push_back(info_of(b));
    return false;
  });
  return out;
}

std::optional<ParamInfo> find_parameter(const SceneSpec& scene, std::string_view key) {
  const auto b = resolve(scene, key);
  if (!b) return std::nullopt;
  return info_of(*b);
}

std::optional<std::string> get_parameter(const SceneSpec& scene, std::string_view key) {
  const auto b = resolve(scene, key);
  if (!b) return std::nullopt;
  return format_text(b->decl->kind, b->decl->get(scene, b->ctx));
}

std::optional<SceneError> set_parameter(SceneSpec& scene, std::string_view key,
                                        std::string_view value) {
  const std::string k(key);
  const auto fail = [&](const std::string& at, std::string message) {
    return SceneError{"--set", at, 0, 0, std::move(message)};
  };
  try {
    const auto b = resolve(scene, key);
    if (!b) {
      if (const auto any = resolve_any(scene, key))
        return fail(k, inapplicable_reason(*any, scene));
      std::vector<std::string> keys;
      for (const ParamInfo& p : scene_parameters(scene)) keys.push_back(p.key);
      std::string msg = "not a parameter of this scene";
      const std::string near = closest(key, keys);
      if (!near.empty()) msg += " (did you mean \"" + near + "\"?)";
      return fail(k, msg);
    }
    auto parsed = parse_text(*b->decl, value);
    if (const auto* msg = std::get_if<std::string>(&parsed)) return fail(k, *msg);
    const Value& v = std::get<Value>(parsed);
    if (auto msg = check_row(*b, scene, v)) return fail(k, *msg);
    SceneSpec changed = scene;
    b->decl->set(changed, b->ctx, v);
    if (auto cross = check_scene(changed))
      return fail(cross->key,
                  cross->message + " (after setting " + k + "=" + std::string(value) + ")");
    scene = std::move(changed);
    return std::nullopt;
  } catch (const std::exception& e) {
    return fail(k, std::string("internal error: ") + e.what());
  }
}

std::optional<SceneError> set_assignment(SceneSpec& scene, std::string_view assignment) {
  const std::string_view item = trim(assignment);
  const std::size_t eq = item.find('=');
  if (eq == std::string_view::npos || trim(item.substr(0, eq)).empty())
    return SceneError{
        "--set", "", 0, 0,
        "expected key=value (e.g. springs.shear.ks=5000; keys: `jelly params SCENE`), got '" +
            std::string(item) + "'"};
  return set_parameter(scene, trim(item.substr(0, eq)), trim(item.substr(eq + 1)));
}

std::optional<double> get_number(const SceneSpec& scene, std::string_view key) {
  const auto b = resolve(scene, key);
  if (!b) return std::nullopt;
  const Value v = b->decl->get(scene, b->ctx);
  if (b->decl->kind == ValueKind::Real) return std::get<double>(v);
  if (b->decl->kind == ValueKind::Integer) return static_cast<double>(std::get<long long>(v));
  return std::nullopt;
}

}  // namespace jelly
