// The registry of body kinds (jelly/body_kind.hpp) and the defaults of a kind module.
#include <cstdarg>
#include <cstdio>
#include <stdexcept>

#include "jelly/body_kind.hpp"
#include "jelly/recorder.hpp"
#include "jelly/simulator.hpp"
#include "jelly/task_probe.hpp"
#include "param_table.hpp"

namespace jelly {

/// Written by CMake (framework/bodies/bodies.cmake): every kind this build links, in their
/// body.cmake's ORDER.
std::vector<const BodyKindModule*> linked_body_kinds();

std::vector<params_detail::Collection> BodyKindModule::collections() const { return {}; }

std::string BodyKindModule::foreign_key(const std::string& key, const std::string& local,
                                        std::string_view scene_body) const {
  (void)key;
  return local + " is a key of a " + std::string(name()) + " body, and this scene's body is " +
         std::string(scene_body);
}

std::string BodyKindModule::foreign_section(std::string_view section,
                                            std::string_view scene_body) const {
  return "[" + std::string(section) + "] is a table of " + std::string(name()) +
         " scenes (body.type = \"" + std::string(name()) + "\"), and this scene's body is " +
         std::string(scene_body);
}

std::optional<std::string> BodyKindModule::refuses_section(std::string_view) const {
  return std::nullopt;
}

std::vector<SpringType> BodyKindModule::spring_types() const {
  return {SpringType::Structural, SpringType::Shear, SpringType::ShearBody, SpringType::Bending};
}

std::optional<params_detail::CrossError> BodyKindModule::check(const SceneSpec&) const {
  return std::nullopt;
}

std::optional<params_detail::CrossError> BodyKindModule::check_absent(const SceneSpec&) const {
  return std::nullopt;
}

std::vector<std::string_view> BodyKindModule::probe_slots() const { return {}; }

TaskStatus BodyKindModule::probe_slot(std::string_view slot, std::string id, std::string,
                                      const TaskTable&) const {
  throw std::invalid_argument("task " + id + ": probe: the body kind " + std::string(name()) +
                              " has no slot \"" + std::string(slot) + "\"");
}

std::string BodyKindModule::summary_header(const World&) const { return kSummaryHeader; }

void BodyKindModule::write_summary(CsvWriter& out, const World& world, const State& s,
                                   double t) const {
  out.write_summary(summarize(world, s, t));
}

std::string BodyKindModule::end_report(const SceneSpec& scene, const Simulator& sim,
                                       double wall) const {
  const FrameSummary end = summarize(sim.world(), sim.state(), sim.time());
  return text_printf(
      "%s: %ld steps of %s, h = %g s, %g s simulated in %.3f s (%.0f steps/s)\n"
      "  %zu particles, %zu springs, %zu terrains; %ld acceleration evaluations\n"
      "  final centre of mass (%.6f, %.6f, %.6f), largest speed %.4g m/s\n"
      "  energy: kinetic %.6g J, gravitational %.6g J, spring %.6g J\n",
      scene.name.c_str(), sim.steps(), std::string(to_string(scene.integrator)).c_str(),
      sim.options().dt, sim.time(), wall, wall > 0 ? static_cast<double>(sim.steps()) / wall : 0.0,
      static_cast<std::size_t>(sim.state().size()), sim.world().spring_count(),
      sim.world().terrains().size(), sim.evaluations(), end.com.x(), end.com.y(), end.com.z(),
      end.max_speed, end.kinetic, end.potential, end.spring);
}

std::string BodyKindModule::check_report(const SceneSpec& scene, const World& world) const {
  std::string out = text_printf("; gravity %s; %zu terrains", scene.gravity ? "on" : "off",
                                world.terrains().size());
  for (const Terrain& t : world.terrains())
    out += text_printf(" [%s%s%s]", t.name.c_str(), t.collision ? " collision" : "",
                       t.contact ? " contact" : "");
  return out;
}

bool BodyKindModule::plays_frames() const { return false; }

std::string BodyKindModule::check_frames(const SceneSpec&) const {
  throw std::logic_error("the body kind " + std::string(name()) + " plays no frames");
}

std::string BodyKindModule::play(const SceneSpec&, const TaskTable&,
                                 const FramePlayOptions&) const {
  throw std::logic_error("the body kind " + std::string(name()) + " plays no frames");
}

std::string BodyKindModule::caption_body(const SceneSpec&) const {
  return "\n" + std::string(body_phrase()) + "\n";
}

std::string_view BodyKindModule::stability_reason() const { return "since the body stiffens"; }

std::string_view BodyKindModule::run_help(std::string_view) const { return ""; }

Eigen::Index BodyKindModule::measured_particles(const World& world) const {
  return world.particle_count();
}

std::unique_ptr<BodyStudy> BodyKindModule::study(const World&, const State&, const StudyLook&,
                                                 const std::vector<std::string>&) const {
  return nullptr;
}

const std::vector<BodyMeasure>& BodyKindModule::measures() const {
  static const std::vector<BodyMeasure> none;
  return none;
}

std::string_view BodyKindModule::contact_help() const { return ""; }

std::string text_printf(const char* format, ...) {
  std::va_list args;
  va_start(args, format);
  std::va_list again;
  va_copy(again, args);
  const int n = std::vsnprintf(nullptr, 0, format, args);
  va_end(args);
  std::string out(n > 0 ? static_cast<std::size_t>(n) : 0, '\0');
  if (n > 0) std::vsnprintf(&out[0], out.size() + 1, format, again);
  va_end(again);
  return out;
}

const std::vector<const BodyKindModule*>& body_kinds() {
  static const std::vector<const BodyKindModule*> kinds = linked_body_kinds();
  return kinds;
}

const BodyKindModule* find_body_kind(std::string_view name) {
  for (const BodyKindModule* k : body_kinds())
    if (k->name() == name) return k;
  return nullptr;
}

std::string body_kind_names() {
  std::string out;
  for (const BodyKindModule* k : body_kinds())
    out += (out.empty() ? "" : ", ") + std::string(k->name());
  return out.empty() ? std::string("none") : out;
}

BodyKind default_body_kind() {
  const std::vector<const BodyKindModule*>& kinds = body_kinds();
  return kinds.empty() ? BodyKind{} : BodyKind{kinds.front()->name()};
}

const BodyKindModule& body_kind_of(const SceneSpec& scene) {
  if (const BodyKindModule* k = find_body_kind(scene.body_kind.name)) return *k;
  throw std::runtime_error((scene.source.empty() ? std::string("<scene>") : scene.source) +
                           ": body.type: this program has no body kind \"" +
                           std::string(scene.body_kind.name) +
                           "\" (it links: " + body_kind_names() + ")");
}

}  // namespace jelly
