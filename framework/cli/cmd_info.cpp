// `jelly params`, `jelly check` and `jelly probe`: what a scene declares, what it builds and which
// step sizes its linearised system allows, and which student tasks look implemented.
#include <cmath>
#include <cstdio>

#include "commands.hpp"
#include "jelly/body_kind.hpp"
#include "jelly/cli_common/command_line.hpp"
#include "jelly/cli_common/text_table.hpp"
#include "jelly/params.hpp"
#include "jelly/session/assignments.hpp"
#include "jelly/simulator.hpp"
#include "jelly/task_probe.hpp"

namespace jelly::cli {

namespace {

const char* type_name(ParamType t) {
  switch (t) {
    case ParamType::Real: return "real";
    case ParamType::Integer: return "integer";
    case ParamType::Bool: return "bool";
    case ParamType::Vector3: return "x,y,z";
    case ParamType::Choice: return "choice";
    case ParamType::Text: return "text";
  }
  return "?";
}

std::string range_text(const ParamInfo& p) {
  if (p.type == ParamType::Choice) {
    std::string s;
    for (const auto& c : p.choices) s += (s.empty() ? "" : "|") + c;
    return s;
  }
  if (!p.bounded) return "";
  char buf[96];
  std::snprintf(buf, sizeof buf, "%s%g, %g%s", p.min_inclusive ? "[" : "(", p.min, p.max,
                p.max_inclusive ? "]" : ")");
  return buf;
}

}  // namespace

int params_command(int argc, char** argv) {
  const std::string usage =
      "usage: jelly params SCENE [--set KEY=VALUE ...]\n"
      "Lists every parameter SCENE declares: key, value, unit, valid range, meaning.\n"
      "Any key can be changed with `jelly run SCENE --set KEY=VALUE`.\n";
  Command cmd("jelly params", usage, usage);
  std::string scene_path;
  SceneOverrides overrides;
  cmd.add_option("SCENE", scene_path)->required();
  add_scene_overrides(cmd, overrides, false);
  if (const auto code = cmd.parse_args(argc, argv, 2)) return *code;
  const auto scene = load_with_overrides(scene_path, overrides);
  if (!scene) return kExitUsage;
  TextTable table(" ");
  table.add_row({"key", "value", "unit", "type", "range", "description"});
  for (const ParamInfo& p : scene_parameters(*scene))
    table.add_row({p.key, get_parameter(*scene, p.key).value_or(""), p.unit, type_name(p.type),
                   range_text(p), p.description});
  std::printf("%s", table.str().c_str());
  return kExitOk;
}

int check_command(int argc, char** argv) {
  const std::string usage =
      "usage: jelly check SCENE [--set KEY=VALUE ...] [--integrator NAME] [--dt H] [--duration T]\n"
      "Validates SCENE, prints what it builds (particles, springs by type, terrains) and\n"
      "the stable step size of every integrator from the linearised system (contract §8).\n";
  Command cmd("jelly check", usage, usage);
  std::string scene_path;
  SceneOverrides overrides;
  cmd.add_option("SCENE", scene_path)->required();
  add_scene_overrides(cmd, overrides);
  if (const auto code = cmd.parse_args(argc, argv, 2)) return *code;
  const auto scene = load_with_overrides(scene_path, overrides);
  if (!scene) return kExitUsage;
  if (const BodyKindModule& kind = body_kind_of(*scene); kind.plays_frames()) {
    try {
      std::printf("%s", kind.check_frames(*scene).c_str());  // what it reads: no World, no steps
    } catch (const std::exception& e) {
      std::fprintf(stderr, "jelly check: %s\n", e.what());
      return kExitUsage;
    }
    return kExitOk;
  }
  std::unique_ptr<World> world;
  try {
    world = build_world(*scene, session::tasks_for(*scene));
  } catch (const std::exception& e) {
    std::fprintf(stderr, "jelly check: %s\n", e.what());
    return kExitUsage;
  }
  std::printf("%s: valid. %lld particles, %zu springs", scene->name.c_str(),
              static_cast<long long>(world->particle_count()), world->spring_count());
  for (const SpringGroup& g : world->spring_groups())
    std::printf(", %zu %s (ks %g, kd %g)", g.springs.size(), std::string(to_string(g.type)).c_str(),
                g.ks, g.kd);
  const BodyKindModule& body = body_kind_of(*scene);
  std::printf("%s", body.check_report(*scene, *world).c_str());
  std::printf("\n");
  const StabilityEstimate e = estimate_stability(*world, world->state());
  std::printf(
      "linearised at rest: omega_max = %.4g rad/s, tau = kd/ks = %.4g s, top-mode damping "
      "ratio %.3g\n",
      e.omega_max, e.tau, e.zeta_top);
  TextTable table(" ");
  table.add_row({"integrator", "limit h [s]", "recommended", "scene h"});
  for (IntegratorKind k : kAllIntegrators) {
    const double crit = e.critical_step(k), rec = e.recommended_step(k);
    auto fmt = [](double v) {
      char b[32];
      if (std::isinf(v)) return std::string("any");
      std::snprintf(b, sizeof b, "%.4g", v);
      return std::string(b);
    };
    const char* verdict = scene->dt <= rec   ? "ok"
                          : scene->dt < crit ? "near the limit"
                                             : "UNSTABLE";
    char h[64];
    std::snprintf(h, sizeof h, "%g: %s", scene->dt, verdict);
    table.add_row({std::string(to_string(k)), fmt(crit), fmt(rec), h});
  }
  std::printf("%s", table.str().c_str());
  std::printf(
      "(limit: the linearised rest state's modes leave the stability region; recommended: half "
      "of it, %s)\n",
      std::string(body.stability_reason()).c_str());
  return kExitOk;
}

int probe_command(int argc, char** argv) {
  const char* usage =
      "usage: jelly probe\n"
      "Lists which student tasks of each assignment look implemented in this build.\n";
  Command cmd("jelly probe", usage, usage);
  if (const auto code = cmd.parse_args(argc, argv, 2)) return *code;
  for (const LinkedAssignment& a : linked_assignments()) {
    const AssignmentManifest& manifest = session::manifest_of(a);
    const auto statuses = session::probe_assignment(a);
    std::printf("student tasks of %s (%s) linked into this build (%s):\n", manifest.id.c_str(),
                manifest.title.c_str(), std::string(a.tasks().origin).c_str());
    TextTable table(" ");
    for (const TaskStatus& s : statuses)
      table.add_row(
          {s.id, s.name, s.implemented ? "looks implemented" : "NOT implemented yet", s.evidence});
    std::printf("%s", table.str("  ").c_str());
  }
  return kExitOk;
}

}  // namespace jelly::cli
