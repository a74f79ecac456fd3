// `jelly study`: dispatch and command line of the numerical studies.
#include "study_command.hpp"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdio>
#include <iterator>
#include <sstream>
#include <string>
#include <string_view>

#include "commands.hpp"
#include "jelly/body_kind.hpp"
#include "jelly/cli_common/command_line.hpp"
#include "jelly/linked_assignments.hpp"
#include "jelly/session/assignments.hpp"
#include "study_accuracy.hpp"
#include "study_effects.hpp"

namespace jelly::cli {

namespace {

constexpr const char* kStudyHelp = R"(usage: jelly study accuracy SCENE [options]
       jelly study effects SCENE [options]     (jelly study effects --help)

Accuracy against cost: runs every integrator over a sweep of step sizes, measures the error
against a converged reference run, the wall time per simulated second and the number of force
evaluations, and writes PREFIX.csv, PREFIX.md (a Markdown table) and a work-precision plot
PREFIX.svg (+ PREFIX.png) drawn by gnuplot from PREFIX.gp and PREFIX.dat.

  reference   RK4 at h_ref = (smallest swept h) / F, checked by a second RK4 run at h_ref / 2
  errors      error_rms: RMS over particles and sample times of |x - x_ref| [m];
              error_final: largest |x - x_ref| over particles at the final time [m]
  stability   the contract's detector (§8) is watched, not obeyed: a run it flags keeps going so
              its error is still measured (it stops only when the state is no longer finite);
              such runs are marked unstable in every output and drawn as crosses, not dropped
  auto step   the step `jelly run --auto-dt` would choose for each integrator is printed and
              written into PREFIX.md, to compare with the sweep
  plot        x = RMS error, y = wall time per simulated second / force evaluations / h, log-log
              (SciML's work-precision convention: error on x, work on y)

options:
  --integrators A,B   subset, in order (default: all six: explicit_euler, implicit_euler,
                      midpoint, rk4, symplectic_euler, backward_euler)
  --steps H1,H2,...   step sizes [s] (default: 4 x the scene's dt halved --levels times)
  --h-max H           coarsest step of a halving sweep [s] (default 4 x the scene's dt)
  --levels K          number of steps in the halving sweep, 1 to 30 (default 5)
  --duration T        simulated time [s] (default: the scene's duration)
  --sample-dt S       error sample interval [s] (default 0.01); a whole multiple of every h
  --ref-factor F      h_ref = smallest h / F (default 16)
  --no-ref-check      skip the h_ref / 2 check run
  --repeats R         timing: minimum wall time of R runs, 1 to 100 (default 1)
  --set KEY=VALUE     change any scene parameter (repeatable), as for `jelly run`
  --out PREFIX        output files PREFIX.csv/.md/.dat/.gp/.svg/.png (default study-SCENENAME)
  --title TEXT        plot and table title (default: the scene's name)
  --quiet             no progress lines

exit codes: 0 done; 2 bad command line or scene; 1 a file could not be written or the
reference run blew up.
)";

// `jelly study effects --help` in pieces: between them each body kind's lines for the measures it
// takes (effects_help).
constexpr const char* kEffectsHelpHead = R"(usage: jelly study effects SCENE [options]

What a parameter does to the jelly: sweeps one declared parameter over the given values (and/or
the integrator), runs the scene once per value and integrator, and measures what a student sees.
Writes PREFIX.csv (one row per run), PREFIX.md (a Markdown table), PREFIX.svg/.png (every measure
against the value) and PREFIX-time.svg/.png (each run over time), with their .gp/.dat.

  contact      first step at which any terrain's collision response or contact force acted
  impact speed centre-of-mass speed just before that step [m/s]
  turn         first time after contact at which the centre of mass stops moving down (along -g)
  peak speed   largest centre-of-mass speed from the turn on: the rebound or the slide [m/s]
  bounce       highest centre of mass from the turn on minus its height at the turn [m]
)";
constexpr const char* kEffectsHelpRest =
    R"(  at rest from start of the last stretch, lasting to the end and at least --rest-hold long, in
               which every particle is slower than --rest-speed [s]; "never" otherwise
  energy lost  E(0) - E(T), E = kinetic + gravitational + spring energy [J] (and % of E(0))
)";
constexpr const char* kEffectsHelpRun =
    R"(  stable       whether the stability detector (contract §8) fired; the run stops there, is
               marked, and its measures cover the time before (at rest: never)
  cost         wall time of the steps per simulated second (median of --repeats runs), force
               (acceleration) evaluations and backward Euler's CG iterations
  Measures needing a contact are nan (CSV) or – (table) when nothing touched a terrain)";
constexpr const char* kEffectsHelpTail = R"(

options:
  --param KEY         the parameter to sweep, as `jelly params SCENE` lists it; '*' stands for
                      one part (springs.*.ks sets ks of every spring type), and .x/.y/.z after a
                      vector key sets one component (body.center.y: the drop height)
  --values A,B,...    its values (for a whole vector separate them with ';': '0,9,0;0,30,0')
  --integrators A,B   run each value with each of these integrators (default: the scene's);
                      alone (without --param) it compares integrators
  --duration T        simulated time per run [s] (default: the scene's)
  --set KEY=VALUE     change any scene parameter first (repeatable), as for `jelly run`
  --dt H              the step for every run [s] (default: the scene's)
  --rest-speed V      at-rest threshold on every particle's speed [m/s] (default 0.3: above the
                      chatter of particles resting on a floor, about 0.2 m/s with explicit Euler)
  --rest-hold S       how long it must hold, up to the end [s] (default 0.5)
  --sample-dt S       interval of the time plot's samples [s] (default 1/60)
  --repeats R         timing: median wall time of R runs (default 1)
  --out PREFIX        output files (default effects-SCENENAME)
  --title TEXT        plot and table title (default: the scene's name and the key)
  --quiet             no progress line per run

exit codes: 0 done (also when runs were unstable: they are marked); 2 bad command line, scene,
key or value (nothing is run or written); 1 a file could not be written.
)";

/// --integrators A,B: each name must be an integrator's.
CLI::Validator integrator_name() {
  return CLI::Validator(
      [](std::string& name) {
        return integrator_from_string(name) ? std::string() : "unknown integrator '" + name + "'";
      },
      "");
}

int accuracy(int argc, char** argv) {
  Command cmd("jelly study accuracy", kStudyHelp, "(see jelly study --help)\n");
  std::string scene_path, prefix, title;
  SceneOverrides overrides;
  std::vector<std::string> integrators;
  std::vector<double> steps;
  double h_max = 0.0, sample_dt = 0.0;  // 0: not given
  long levels = 5, ref_factor = 0, repeats = 0;
  bool no_ref_check = false, quiet = false;
  cmd.add_option("SCENE", scene_path)->required();
  cmd.add_option("--integrators", integrators)
      ->type_name("A,B")
      ->delimiter(',')
      ->check(integrator_name())
      ->multi_option_policy(CLI::MultiOptionPolicy::TakeAll);
  cmd.add_option("--steps", steps)
      ->type_name("H1,H2")
      ->delimiter(',')
      ->check(positive_number())
      ->multi_option_policy(CLI::MultiOptionPolicy::TakeAll);
  cmd.add_option("--h-max", h_max)->type_name("H")->check(positive_number());
  cmd.add_option("--levels", levels)->type_name("K")->check(whole_number(1, 30));
  cmd.add_option("--duration", overrides.duration)->type_name("T");
  cmd.add_option("--sample-dt", sample_dt)->type_name("S")->check(positive_number());
  cmd.add_option("--ref-factor", ref_factor)->type_name("F")->check(whole_number(1));
  cmd.add_option("--repeats", repeats)->type_name("R")->check(whole_number(1, 100));
  add_scene_overrides(cmd, overrides, false);
  cmd.add_option("--out", prefix)->type_name("PREFIX");
  cmd.add_option("--title", title)->type_name("TEXT");
  cmd.add_flag("--no-ref-check", no_ref_check);
  cmd.add_flag("--quiet", quiet);
  if (const auto code = cmd.parse_args(argc, argv, 3)) return *code;
  const std::optional<SceneSpec> scene = load_with_overrides(scene_path, overrides);
  if (!scene) return kExitUsage;

  study::SweepOptions o;
  o.duration = scene->duration;
  for (const std::string& name : integrators)
    o.integrators.push_back(*integrator_from_string(name));
  if (integrators.empty()) o.integrators.assign(kAllIntegrators.begin(), kAllIntegrators.end());
  o.steps = steps;
  if (steps.empty()) {
    double h = h_max > 0.0 ? h_max : 4.0 * scene->dt;
    for (long i = 0; i < levels; ++i, h /= 2.0) o.steps.push_back(h);
  }
  if (sample_dt > 0.0) o.sample_dt = sample_dt;
  if (ref_factor > 0) o.reference_factor = static_cast<int>(ref_factor);
  if (repeats > 0) o.repeats = static_cast<int>(repeats);
  o.check_reference = !no_ref_check;
  if (prefix.empty()) prefix = "study-" + scene->name;
  if (title.empty()) title = scene->name;

  study::SweepResult result;
  try {
    result = study::run_sweep(*scene, o, quiet ? nullptr : stdout);
  } catch (const std::invalid_argument& e) {
    return cmd.error(e.what());
  } catch (const std::runtime_error& e) {
    std::fprintf(stderr, "jelly study accuracy: %s\n", e.what());
    return kExitInternal;
  }
  std::string note;
  std::vector<std::filesystem::path> files;
  try {
    files = study::write_outputs(result, prefix, title, note);
  } catch (const std::exception& e) {
    std::fprintf(stderr, "jelly study accuracy: %s\n", e.what());
    return kExitInternal;
  }
  if (!note.empty()) std::fprintf(stderr, "jelly study accuracy: %s\n", note.c_str());
  if (!quiet)
    for (const auto& f : files) std::printf("wrote %s\n", f.string().c_str());
  return kExitOk;
}

/// --values: comma-separated, or ';'-separated when any value is a vector ("0,9,0;0,30,0").
std::vector<std::string> split_values(const std::string& text) {
  const char separator = text.find(';') != std::string::npos ? ';' : ',';
  std::vector<std::string> out;
  std::string item;
  for (std::size_t i = 0; i <= text.size(); ++i)
    if (i == text.size() || text[i] == separator) {
      if (!item.empty()) out.push_back(item);
      item.clear();
    } else {
      item += text[i];
    }
  return out;
}

/// `names` as a sentence lists them ("a, b and c").
std::string listed(const std::vector<std::string>& names) {
  std::string out;
  for (std::size_t i = 0; i < names.size(); ++i)
    out += (i == 0 ? "" : i + 1 == names.size() ? " and " : ", ") + names[i];
  return out;
}

/// What each linked assignment's manifest lists under [studies] measures ("A1 lists the first
/// five, A2 ..."); `known` is the known measures' list.
std::string assignments_measures(const std::vector<std::string>& known) {
  static const char* const kCount[] = {"", "one", "two", "three", "four", "five", "six", "seven"};
  std::string out;
  for (const LinkedAssignment& a : linked_assignments()) {
    const std::vector<std::string>& names = session::manifest_of(a).study_measures;
    if (names.empty()) continue;
    std::string id(a.id);
    for (char& c : id) c = static_cast<char>(std::toupper(static_cast<unsigned char>(c)));
    const bool first = names.size() > 2 && names.size() < std::size(kCount) &&
                       names.size() <= known.size() &&
                       std::equal(names.begin(), names.end(), known.begin());
    out += (out.empty() ? "" : ", ") + id + (out.empty() ? " lists " : " ") +
           (first ? std::string("the first ") + kCount[names.size()] : listed(names));
  }
  return out;
}

/// `text` in lines of at most 92 characters, each indented by two spaces.
std::string wrapped(const std::string& text) {
  std::istringstream words(text);
  std::string out, line;
  for (std::string word; words >> word;) {
    if (!line.empty() && line.size() + 1 + word.size() > 92) {
      out += line + '\n';
      line.clear();
    }
    line += (line.empty() ? "  " : " ") + word;
  }
  return out + line;
}

/// `jelly study effects --help`: the general measures, and each linked body kind's lines for the
/// measures it takes (the landing ones with the bounce, the others after the energy).
std::string effects_help() {
  const auto kinds_lines = [](MeasurePlace place) {
    std::string out;
    for (const study::KindMeasure& k : study::kind_measures())
      if (k.measure->place == place) out += k.measure->help;
    return out;
  };
  std::string contact;
  for (const BodyKindModule* kind : body_kinds()) contact += kind->contact_help();
  const std::vector<std::string> known = study::known_measures();
  std::string names;
  for (const std::string& name : known) names += (names.empty() ? "" : ", ") + name;
  const std::string which =
      "Which of these are measured and written is the scene's assignment's choice: its "
      "manifest's [studies] measures (" +
      names + "; " + assignments_measures(known) + ").";
  return kEffectsHelpHead + kinds_lines(MeasurePlace::kLanding) + kEffectsHelpRest +
         kinds_lines(MeasurePlace::kMotion) + kEffectsHelpRun + contact + ".\n" + wrapped(which) +
         kEffectsHelpTail;
}

int effects(int argc, char** argv) {
  Command cmd("jelly study effects", effects_help(), "(see jelly study effects --help)\n");
  std::string scene_path, prefix, title, key, values;
  SceneOverrides overrides;
  std::vector<std::string> integrators;
  double rest_speed = 0.0, rest_hold = 0.0, sample_dt = 0.0;  // 0: not given
  long repeats = 0;
  bool quiet = false;
  cmd.add_option("SCENE", scene_path)->required();
  cmd.add_option("--param", key)->type_name("KEY");
  cmd.add_option("--values", values)->type_name("A,B");
  cmd.add_option("--integrators", integrators)
      ->type_name("A,B")
      ->delimiter(',')
      ->check(integrator_name())
      ->multi_option_policy(CLI::MultiOptionPolicy::TakeAll);
  cmd.add_option("--rest-speed", rest_speed)->type_name("V")->check(positive_number());
  cmd.add_option("--rest-hold", rest_hold)->type_name("S")->check(positive_number());
  cmd.add_option("--sample-dt", sample_dt)->type_name("S")->check(positive_number());
  cmd.add_option("--repeats", repeats)->type_name("R")->check(whole_number(1, 100));
  add_scene_overrides(cmd, overrides);
  cmd.add_option("--out", prefix)->type_name("PREFIX");
  cmd.add_option("--title", title)->type_name("TEXT");
  cmd.add_flag("--quiet", quiet);
  if (const auto code = cmd.parse_args(argc, argv, 3)) return *code;
  const std::optional<SceneSpec> scene = load_with_overrides(scene_path, overrides);
  if (!scene) return kExitUsage;

  study::EffectsOptions o;
  try {
    // What the scene's assignment studies: its manifest's [studies] measures.
    const LinkedAssignment& assignment = session::assignment_for(*scene);
    o.measures = study::measures_from(session::manifest_of(assignment).study_measures,
                                      std::string(assignment.manifest_path));
  } catch (const std::exception& e) {
    return cmd.error(e.what());
  }
  o.duration = scene->duration;
  o.key = key;
  o.values = split_values(values);
  for (const std::string& name : integrators)
    o.integrators.push_back(*integrator_from_string(name));
  if (o.key.empty() && o.integrators.empty())
    return cmd.error("nothing to sweep: give --param KEY --values A,B,... or --integrators A,B");
  if (rest_speed > 0.0) o.rest_speed = rest_speed;
  if (rest_hold > 0.0) o.rest_hold = rest_hold;
  if (sample_dt > 0.0) o.series_dt = sample_dt;
  if (repeats > 0) o.repeats = static_cast<int>(repeats);
  if (prefix.empty()) prefix = "effects-" + scene->name;
  if (title.empty())
    title = scene->name + (o.key.empty() ? std::string(": integrators") : ": " + o.key);

  study::EffectsResult result;
  try {
    result = study::run_effects(*scene, o, quiet ? nullptr : stdout);
  } catch (const std::invalid_argument& e) {
    return cmd.error(e.what());
  }
  std::string note;
  std::vector<std::filesystem::path> files;
  try {
    files = study::write_effects(result, prefix, title, note);
  } catch (const std::exception& e) {
    std::fprintf(stderr, "jelly study effects: %s\n", e.what());
    return kExitInternal;
  }
  if (!note.empty()) std::fprintf(stderr, "jelly study effects: %s\n", note.c_str());
  if (!quiet)
    for (const auto& f : files) std::printf("wrote %s\n", f.string().c_str());
  return kExitOk;
}
}  // namespace

int study_command(int argc, char** argv) {
  if (argc < 3 || std::string(argv[2]) == "--help" || std::string(argv[2]) == "-h") {
    std::fputs(kStudyHelp, argc < 3 ? stderr : stdout);
    return argc < 3 ? kExitUsage : kExitOk;
  }
  const std::string what = argv[2];
  if (what == "accuracy") return accuracy(argc, argv);
  if (what == "effects") return effects(argc, argv);
  std::fprintf(stderr, "jelly study: unknown study '%s' (known: accuracy, effects)\n%s",
               what.c_str(), kStudyHelp);
  return kExitUsage;
}

}  // namespace jelly::cli
