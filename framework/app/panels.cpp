// The side panel: scenes, simulation and time, integrator and step, every declared parameter,
// drawing, plots, comparison mode, recording, and the student hints.
#include <algorithm>
#include <cfloat>
#include <cmath>
#include <cstdio>
#include <optional>
#include <string>
#include <vector>

#include <imgui.h>

#include "app.hpp"
#include "jelly/body_kind.hpp"
#include "jelly/params.hpp"

namespace jelly::app {

using namespace jelly::render;
using namespace jelly::session;

namespace {

const ImVec4 kRed{1.0f, 0.42f, 0.38f, 1.0f};
const ImVec4 kYellow{1.0f, 0.85f, 0.3f, 1.0f};
const ImVec4 kGreen{0.5f, 0.9f, 0.5f, 1.0f};

bool integrator_combo(const char* label, IntegratorKind& kind) {
  bool changed = false;
  if (ImGui::BeginCombo(label, std::string(display_name(kind)).c_str())) {
    for (IntegratorKind k : kAllIntegrators) {
      if (ImGui::Selectable(std::string(display_name(k)).c_str(), k == kind)) {
        changed = k != kind;
        kind = k;
      }
    }
    ImGui::EndCombo();
  }
  return changed;
}

bool step_input(const char* label, double& dt) {
  double ms = dt * 1e3;
  const double lo = 0.01, hi = 20.0;
  bool changed = ImGui::SliderScalar(label, ImGuiDataType_Double, &ms, &lo, &hi, "%.4g ms",
                                     ImGuiSliderFlags_Logarithmic);
  if (changed) dt = std::clamp(ms, lo, hi) * 1e-3;
  return ImGui::IsItemDeactivatedAfterEdit() || (changed && !ImGui::IsItemActive());
}

/// The group a parameter is shown under: the first part of its key ("springs", "body",
/// "terrain.floor", ...).
std::string parameter_group(const std::string& key) {
  std::string g = key.substr(0, key.find('.'));
  if (g == "terrain") g = key.substr(0, key.find('.', 8));
  return g;
}

// One widget per parameter type. Each shows the value of `p.key` in `scene` and, when the user
// finished an edit, returns the new value as text (what set_parameter reads).

std::optional<std::string> real_widget(const SceneSpec& scene, const ParamInfo& p,
                                       const std::string& label) {
  double v = get_number(scene, p.key).value_or(0.0);
  if (p.bounded && std::isfinite(p.min) && std::isfinite(p.max)) {
    const bool log = p.min > 0.0 && p.max / p.min > 100.0;
    ImGui::SliderScalar(label.c_str(), ImGuiDataType_Double, &v, &p.min, &p.max, "%.5g",
                        log ? ImGuiSliderFlags_Logarithmic : 0);
  } else {
    ImGui::InputDouble(label.c_str(), &v, 0.0, 0.0, "%.5g");
  }
  if (!ImGui::IsItemDeactivatedAfterEdit()) return std::nullopt;
  char buf[64];
  std::snprintf(buf, sizeof buf, "%.17g", v);
  return std::string(buf);
}

std::optional<std::string> integer_widget(const SceneSpec& scene, const ParamInfo& p,
                                          const std::string& label) {
  int v = static_cast<int>(get_number(scene, p.key).value_or(0.0));
  if (p.bounded && std::isfinite(p.max) && p.max - p.min <= 100) {
    const int lo = static_cast<int>(p.min), hi = static_cast<int>(p.max);
    ImGui::SliderInt(label.c_str(), &v, lo, hi);
  } else {
    ImGui::InputInt(label.c_str(), &v);
  }
  if (!ImGui::IsItemDeactivatedAfterEdit()) return std::nullopt;
  return std::to_string(v);
}

std::optional<std::string> bool_widget(const SceneSpec& scene, const ParamInfo& p,
                                       const std::string& label) {
  bool v = get_parameter(scene, p.key).value_or("false") == "true";
  if (!ImGui::Checkbox(label.c_str(), &v)) return std::nullopt;
  return std::string(v ? "true" : "false");
}

std::optional<std::string> vector3_widget(const SceneSpec& scene, const ParamInfo& p,
                                          const std::string& label) {
  double v[3] = {0, 0, 0};
  const std::string cur = get_parameter(scene, p.key).value_or("0,0,0");
  std::sscanf(cur.c_str(), "%lf , %lf , %lf", &v[0], &v[1], &v[2]);
  ImGui::InputScalarN(label.c_str(), ImGuiDataType_Double, v, 3, nullptr, nullptr, "%.4g");
  if (!ImGui::IsItemDeactivatedAfterEdit()) return std::nullopt;
  char buf[128];
  std::snprintf(buf, sizeof buf, "%.17g,%.17g,%.17g", v[0], v[1], v[2]);
  return std::string(buf);
}

std::optional<std::string> choice_widget(const SceneSpec& scene, const ParamInfo& p,
                                         const std::string& label) {
  std::optional<std::string> text;
  const std::string cur = get_parameter(scene, p.key).value_or("");
  if (ImGui::BeginCombo(label.c_str(), cur.c_str())) {
    for (const std::string& c : p.choices)
      if (ImGui::Selectable(c.c_str(), c == cur) && c != cur) text = c;
    ImGui::EndCombo();
  }
  return text;
}

std::optional<std::string> parameter_widget(const SceneSpec& scene, const ParamInfo& p,
                                            const std::string& label) {
  switch (p.type) {
    case ParamType::Real: return real_widget(scene, p, label);
    case ParamType::Integer: return integer_widget(scene, p, label);
    case ParamType::Bool: return bool_widget(scene, p, label);
    case ParamType::Vector3: return vector3_widget(scene, p, label);
    case ParamType::Choice: return choice_widget(scene, p, label);
    case ParamType::Text:
      ImGui::LabelText(label.c_str(), "%s", get_parameter(scene, p.key).value_or("").c_str());
      break;
  }
  return std::nullopt;
}

/// The tooltip of the widget just drawn: the parameter's meaning, default and range.
void parameter_tooltip(const ParamInfo& p) {
  if (!ImGui::IsItemHovered() || p.description.empty()) return;
  std::string tip = p.description + "\ndefault " + p.default_text;
  if (p.bounded) {
    char buf[96];
    std::snprintf(buf, sizeof buf, "\nrange %s%g, %g%s", p.min_inclusive ? "[" : "(", p.min, p.max,
                  p.max_inclusive ? "]" : ")");
    tip += buf;
  }
  ImGui::SetTooltip("%s", tip.c_str());
}

/// One widget per declared parameter, under a heading per group; applies the change through
/// set_parameter (so the panel validates exactly like a scene file). Returns true when a value
/// changed.
bool parameter_widgets(AppState& s) {
  bool changed = false;
  std::string group;
  for (const ParamInfo& p : scene_parameters(s.edited)) {
    if (std::string g = parameter_group(p.key); g != group) {
      group = g;
      ImGui::Separator();
      ImGui::TextDisabled("%s", group.c_str());
    }
    const std::string label = p.key.substr(group.size() + (p.key.size() > group.size() ? 1 : 0)) +
                              (p.unit.empty() ? "" : " [" + p.unit + "]") + "##" + p.key;
    const std::optional<std::string> text = parameter_widget(s.edited, p, label);
    parameter_tooltip(p);
    if (text) {
      if (auto err = set_parameter(s.edited, p.key, *text)) {
        s.scene_error = err->text();
      } else {
        s.scene_error.clear();
        changed = true;
      }
    }
  }
  return changed;
}

void plot(const char* label, const std::deque<RunSample>& h, double RunSample::*field,
          const char* unit) {
  const std::size_t n = std::min<std::size_t>(h.size(), 600);
  std::vector<float> v(n);
  for (std::size_t i = 0; i < n; ++i) v[i] = static_cast<float>(h[h.size() - n + i].*field);
  char overlay[64] = "";
  if (!v.empty()) std::snprintf(overlay, sizeof overlay, "%.4g %s", v.back(), unit);
  ImGui::PlotLines(label, v.data(), static_cast<int>(v.size()), 0, overlay, FLT_MAX, FLT_MAX,
                   ImVec2(0, 60));
}

/// A collapsing header that --open can open on the first frame.
bool header(AppState& s, const char* label, const char* key, bool open_by_default) {
  for (const std::string& name : s.open_panels)
    if (name == key) ImGui::SetNextItemOpen(true, ImGuiCond_Once);
  return ImGui::CollapsingHeader(label, open_by_default ? ImGuiTreeNodeFlags_DefaultOpen : 0);
}

/// The student's hints: the tasks the probe finds not implemented (shown only while some are).
void tasks_section(const AppState& s) {
  int missing = 0;
  for (const TaskStatus& t : s.tasks) missing += t.implemented ? 0 : 1;
  if (missing > 0 &&
      ImGui::CollapsingHeader("Tasks not implemented yet", ImGuiTreeNodeFlags_DefaultOpen)) {
    for (const TaskStatus& t : s.tasks)
      if (!t.implemented) {
        ImGui::TextColored(kYellow, "%s %s", t.id.c_str(), t.name.c_str());
        if (ImGui::IsItemHovered()) ImGui::SetTooltip("%s", t.evidence.c_str());
      }
  }
}

/// Scene: the scenes folder's list, a file to open, the description and the last load error.
void scene_section(AppState& s) {
  if (!header(s, "Scene", "scene", true)) return;
  const char* current =
      s.scene_index >= 0 ? s.scenes[s.scene_index].name.c_str() : s.edited.name.c_str();
  if (ImGui::BeginCombo("scene", current)) {
    for (std::size_t i = 0; i < s.scenes.size(); ++i)
      if (ImGui::Selectable(s.scenes[i].name.c_str(), static_cast<int>(i) == s.scene_index))
        load_scene_into(s, static_cast<int>(i));
    ImGui::EndCombo();
  }
  char path[512];
  std::snprintf(path, sizeof path, "%s", s.open_path.c_str());
  if (ImGui::InputText("file", path, sizeof path)) s.open_path = path;
  ImGui::SameLine();
  if (ImGui::Button("Open") && !s.open_path.empty()) load_scene_into(s, -1, s.open_path);
  if (!s.edited.description.empty()) ImGui::TextWrapped("%s", s.edited.description.c_str());
  if (!s.scene_error.empty()) ImGui::TextColored(kRed, "%s", s.scene_error.c_str());
}

/// Play, step, reset, camera; the time, step count and frame rate; the real-time factor and
/// whether the runs keep up with it.
void time_controls(AppState& s, const SimulationRun* main_run, double fps) {
  if (ImGui::Button(s.playing ? "Pause (space)" : "Play (space)")) s.playing = !s.playing;
  ImGui::SameLine();
  if (ImGui::Button("Step (N)")) s.step_requested = true;
  ImGui::SameLine();
  if (ImGui::Button("Reset (R)")) s.reset_requested = true;
  ImGui::SameLine();
  if (ImGui::Button("Camera (C)")) s.camera_reset_requested = true;
  if (main_run && main_run->simulator())
    ImGui::Text("t = %.3f s   step %ld   %.0f fps", main_run->time(),
                main_run->simulator()->steps(), fps);
  float factor = static_cast<float>(s.clock.factor);
  if (ImGui::SliderFloat("real-time factor", &factor, 0.1f, 4.0f, "%.2fx",
                         ImGuiSliderFlags_Logarithmic)) {
    s.clock.factor = factor;
    s.clock.restart();
  }
  if (s.scripted) {
    ImGui::TextDisabled("scripted run (not real time)");
  } else if (s.playing && !s.recording) {
    if (s.clock.behind())
      ImGui::TextColored(kRed, "can't keep up: running at %.2fx real time",
                         s.clock.achieved_factor());
    else
      ImGui::TextColored(kGreen, "running at %.2fx real time", s.clock.achieved_factor());
  }
}

/// The single run's integrator, step and automatic step, with the stable-step estimate (in
/// comparison mode each slot has its own: comparison_section).
void integrator_controls(AppState& s, SimulationRun* main_run) {
  if (integrator_combo("integrator", s.integrator)) s.reset_requested = true;
  if (step_input(s.edited.auto_dt ? "largest step h" : "step h", s.dt)) s.reset_requested = true;
  if (ImGui::Checkbox("automatic step (stability estimate)", &s.edited.auto_dt))
    s.reset_requested = true;
  s.edited.integrator = s.integrator;  // keep the parameter view in step
  s.edited.dt = s.dt;
  if (main_run && main_run->auto_step())
    ImGui::TextWrapped("%s", main_run->auto_step()->message().c_str());
  if (main_run && main_run->simulator()) {
    const double hc = main_run->simulator()->estimate().critical_step(s.integrator);
    if (std::isinf(hc))
      ImGui::TextDisabled("stable step estimate: any h");
    else if (hc > 0.0)
      ImGui::TextDisabled("stable step estimate: h <= %.3g s", hc);
  }
}

/// Each unstable run's report with a one-click retry at the recommended step, and each run that
/// could not start.
void run_problems(AppState& s, const std::vector<SimulationRun*>& runs) {
  for (SimulationRun* r : runs) {
    if (!r->simulator() || !r->simulator()->instability()) continue;
    const InstabilityReport& rep = *r->simulator()->instability();
    ImGui::PushStyleColor(ImGuiCol_Text, kRed);
    ImGui::TextWrapped("UNSTABLE: %s stopped at step %ld (t = %.3f s, h = %g s): %s",
                       std::string(display_name(rep.integrator)).c_str(), rep.step, rep.time,
                       rep.step_size, rep.reason.c_str());
    ImGui::PopStyleColor();
    char label[96];
    std::snprintf(label, sizeof label, "Retry at h = %.3g s##%p", rep.recommended_step,
                  static_cast<void*>(r));
    if (ImGui::Button(label) && rep.recommended_step > 0.0 && std::isfinite(rep.recommended_step)) {
      if (s.comparing) {
        for (CompareSlot& slot : s.slots)
          if (slot.integrator == rep.integrator) slot.dt = rep.recommended_step;
      } else {
        s.dt = rep.recommended_step;
      }
      s.reset_requested = true;
    }
  }
  for (SimulationRun* r : runs)
    if (!r->ok()) ImGui::TextColored(kRed, "cannot run: %s", r->error().c_str());
}

/// Simulation: time controls, the integrator and step (one run), instability banners.
void simulation_section(AppState& s, const std::vector<SimulationRun*>& runs, double fps) {
  if (!header(s, "Simulation", "simulation", true)) return;
  SimulationRun* main_run = runs.empty() ? nullptr : runs.front();
  time_controls(s, main_run, fps);
  // A kind that plays recorded frames integrates nothing (as in the caption): no integrator, step
  // or stable-step estimate to offer.
  const BodyKindModule* kind = find_body_kind(s.edited.body_kind.name);
  if (kind && kind->plays_frames())
    ImGui::TextDisabled("played frame by frame: no integrator or step");
  else if (!s.comparing)
    integrator_controls(s, main_run);
  run_problems(s, runs);
}

/// One comparison slot: integrator, step and the run's own parameters.
void comparison_slot(AppState& s, CompareSlot& slot) {
  if (integrator_combo("integrator", slot.integrator)) s.reset_requested = s.comparing;
  if (step_input("step h", slot.dt)) s.reset_requested = s.comparing;
  // This run's own parameters, e.g. "springs.structural.ks=1e5" beside an unchanged run.
  char buf[256];
  std::snprintf(buf, sizeof buf, "%s", slot.overrides.c_str());
  if (ImGui::InputTextWithHint("own parameters", "key=value; ... (jelly params)", buf, sizeof buf,
                               ImGuiInputTextFlags_EnterReturnsTrue)) {
    slot.overrides = buf;
    s.reset_requested = s.comparing;
  }
  if (!slot.error.empty()) ImGui::TextColored(kRed, "%s", slot.error.c_str());
}

/// Comparison mode: on or off, how many runs, each slot, and starting them together.
void comparison_section(AppState& s) {
  if (!header(s, "Comparison mode", "comparison", false)) return;
  if (ImGui::Checkbox("compare side by side", &s.comparing)) s.reset_requested = true;
  int count = static_cast<int>(s.slots.size());
  if (ImGui::SliderInt("runs", &count, 2, 4)) {
    s.slots.resize(count, CompareSlot{IntegratorKind::RK4, s.dt, {}, {}});
    s.reset_requested = s.comparing;
  }
  for (std::size_t i = 0; i < s.slots.size(); ++i) {
    ImGui::PushID(static_cast<int>(i));
    comparison_slot(s, s.slots[i]);
    ImGui::Separator();
    ImGui::PopID();
  }
  if (ImGui::Button("Start together")) {
    s.comparing = true;
    s.reset_requested = true;
    s.playing = true;
  }
}

/// Parameters: every declared parameter of the edited scene, and going back to the file's.
void parameters_section(AppState& s) {
  if (!header(s, "Parameters", "parameters", false)) return;
  if (ImGui::Button("Reset to the scene's values")) {
    s.edited = s.original;
    s.integrator = s.original.integrator;
    s.dt = s.original.dt;
    s.scene_error.clear();
    s.reset_requested = true;
  }
  if (parameter_widgets(s)) {
    // simulation.integrator and simulation.dt are the Simulation panel's integrator and step.
    s.integrator = s.edited.integrator;
    s.dt = s.edited.dt;
    s.reset_requested = true;
  }
}

/// The body kinds' sections (their controls), each shown only in a scene of its kind.
void body_sections(AppState& s) {
  const std::vector<const BodyView*> shown = shown_views(s);
  for (auto& [view, controls] : s.body_controls) {
    if (std::find(shown.begin(), shown.end(), view) == shown.end()) continue;
    if (view->panel_title().empty()) continue;
    const std::string title(view->panel_title()), id(view->panel_id());
    if (header(s, title.c_str(), id.c_str(), true)) controls->draw_panel(s.viewer_context());
  }
}

/// Draw: what the frame shows (each spring type in its colour).
void draw_section(AppState& s) {
  if (!header(s, "Draw", "draw", false)) return;
  // The shown body kind names its surface and markers, and the spring types it has.
  const std::vector<const BodyView*> shown = shown_views(s);
  const BodyView* view = shown.empty() ? nullptr : shown.front();
  const std::string surface(view ? view->surface_label() : "jelly surface");
  const std::string markers(view ? view->markers_label() : "");
  ImGui::Checkbox(surface.c_str(), &s.frame.draw.surface);
  ImGui::Checkbox("particles", &s.frame.draw.particles);
  if (!markers.empty()) ImGui::Checkbox(markers.c_str(), &s.frame.draw.markers);
  static const char* names[4] = {"structural springs", "shear springs", "body-diagonal shear",
                                 "bending springs"};
  for (int i = 0; i < 4; ++i) {
    if (view && !view->shows_spring_type(static_cast<SpringType>(i))) continue;
    const auto& c = colors::kSprings[i];
    ImGui::PushStyleColor(ImGuiCol_Text, ImVec4(c.x(), c.y(), c.z(), 1.0f));
    ImGui::Checkbox(names[i], &s.frame.draw.springs[i]);
    ImGui::PopStyleColor();
  }
  ImGui::Checkbox("ground grid", &s.frame.draw.grid);
  ImGui::Checkbox("parameters on the frame", &s.frame.caption);
}

/// Plots: energy, centre-of-mass height and cost per step of each run.
void plots_section(AppState& s, const std::vector<SimulationRun*>& runs) {
  if (!header(s, "Plots", "plots", true)) return;
  for (SimulationRun* r : runs) {
    if (runs.size() > 1)
      ImGui::TextDisabled("%s", std::string(display_name(r->setup().integrator)).c_str());
    ImGui::PushID(r);
    plot("energy", r->history(), &RunSample::energy, "J");
    plot("COM height", r->history(), &RunSample::com_height, "m");
    plot("ms / step", r->history(), &RunSample::ms_per_step, "ms");
    ImGui::PopID();
  }
}

/// Recording: start and stop PNG frames (and the MP4), a screenshot, and what they wrote.
void recording_section(AppState& s) {
  if (!header(s, "Recording", "recording", false)) return;
  if (ImGui::Button(s.recording ? "Stop recording" : "Record PNG frames")) toggle_recording(s);
  ImGui::SameLine();
  if (ImGui::Button("Screenshot (P)")) s.screenshot_requested = true;
  ImGui::TextWrapped(
      "Frames advance 1/30 s x factor each, so the video plays at the chosen speed; "
      "MP4 when ffmpeg is installed.");
  if (!s.record_message.empty()) ImGui::TextWrapped("%s", s.record_message.c_str());
  if (!s.screenshot_message.empty()) ImGui::TextWrapped("%s", s.screenshot_message.c_str());
}

}  // namespace

void draw_panels(AppState& s, double fps) {
  const ImGuiIO& io = ImGui::GetIO();
  ImGui::SetNextWindowPos(ImVec2(0, 0));
  ImGui::SetNextWindowSize(ImVec2(static_cast<float>(s.panel_width), io.DisplaySize.y));
  ImGui::Begin("Jelly Lab", nullptr,
               ImGuiWindowFlags_NoMove | ImGuiWindowFlags_NoResize | ImGuiWindowFlags_NoCollapse);
  ImGui::PushItemWidth(-170);
  tasks_section(s);
  scene_section(s);  // may load another scene, which rebuilds the runs: take them after it
  const std::vector<SimulationRun*> runs = s.run_pointers();
  simulation_section(s, runs, fps);
  body_sections(s);
  comparison_section(s);
  parameters_section(s);
  draw_section(s);
  plots_section(s, runs);
  recording_section(s);
  ImGui::PopItemWidth();
  ImGui::End();
}

}  // namespace jelly::app
