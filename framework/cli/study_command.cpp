// `jelly study`: dispatch and command line of the numerical studies (accuracy, effects).
#include "study_command.hpp"

#include <cmath>
#include <cstdio>
#include <sstream>
#include <string>

#include "cli_args.hpp"
#include "commands.hpp"
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
  --levels K          number of steps in the halving sweep (default 5)
  --duration T        simulated time [s] (default: the scene's duration)
  --sample-dt S       error sample interval [s] (default 0.01); a whole multiple of every h
  --ref-factor F      h_ref = smallest h / F (default 16)
  --no-ref-check      skip the h_ref / 2 check run
  --repeats R         timing: minimum wall time of R runs (default 1)
  --set KEY=VALUE     change any scene parameter (repeatable), as for `jelly run`
  --out PREFIX        output files PREFIX.csv/.md/.dat/.gp/.svg/.png (default study-SCENENAME)
  --title TEXT        plot and table title (default: the scene's name)
  --quiet             no progress lines

exit codes: 0 done; 2 bad command line or scene; 1 a file could not be written or the
reference run blew up.
)";

constexpr const char* kEffectsHelp = R"(usage: jelly study effects SCENE [options]

What a parameter does to the jelly: sweeps one declared parameter over the given values (and/or
the integrator), runs the scene once per value and integrator, and measures what a student sees.
Writes PREFIX.csv (one row per run), PREFIX.md (a Markdown table), PREFIX.svg/.png (every measure
against the value) and PREFIX-time.svg/.png (each run over time), with their .gp/.dat.

  contact      first step at which any terrain's collision response or contact force acted
  impact speed centre-of-mass speed just before that step [m/s]
  turn         first time after contact at which the centre of mass stops moving down (along -g)
  peak speed   largest centre-of-mass speed from the turn on: the rebound or the slide [m/s]
  bounce       highest centre of mass from the turn on minus its height at the turn [m]
  cave-in      largest 1 - V(t)/V(0) over the run, V = volume inside the cube's outer surface
               (its six faces as triangles); cave-in at end = 1 - V(T)/V(0). Cube bodies only.
  at rest from start of the last stretch, lasting to the end and at least --rest-hold long, in
               which every particle is slower than --rest-speed [s]; "never" otherwise
  energy lost  E(0) - E(T), E = kinetic + gravitational + spring energy [J] (and % of E(0))
  stable       whether the stability detector (contract §8) fired; the run stops there, is
               marked, and its measures cover the time before (at rest: never)
  cost         wall time of the steps per simulated second (median of --repeats runs), force
               (acceleration) evaluations and backward Euler's CG iterations
  Measures needing a contact are nan (CSV) or – (table) when nothing touched a terrain.

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

/// Comma-separated items; `separator` ';' for lists of vectors.
std::vector<std::string> split(const std::string& text, char separator = ',') {
  std::vector<std::string> out;
  std::stringstream ss(text);
  for (std::string item; std::getline(ss, item, separator);)
    if (!item.empty()) out.push_back(item);
  return out;
}

std::optional<double> positive(const std::string& text) {
  char* end = nullptr;
  const double v = std::strtod(text.c_str(), &end);
  if (end == text.c_str() || *end != '\0' || !(v > 0.0) || !std::isfinite(v)) return std::nullopt;
  return v;
}

int accuracy(int argc, char** argv) {
  const Args args(argc, argv, 3,
                  {"--integrators", "--steps", "--h-max", "--levels", "--duration", "--sample-dt",
                   "--ref-factor", "--repeats", "--set", "--out", "--title"},
                  {"--help", "--no-ref-check", "--quiet"});
  if (args.has("--help")) {
    std::fputs(kStudyHelp, stdout);
    return kExitOk;
  }
  const auto usage = [](const std::string& what) {
    std::fprintf(stderr, "jelly study accuracy: %s\n(see jelly study --help)\n", what.c_str());
    return kExitUsage;
  };
  if (!args.error().empty()) return usage(args.error());
  if (args.positionals().size() != 1) return usage("expected exactly one SCENE file");
  const std::optional<SceneSpec> scene = load_with_overrides(args.positionals()[0], args);
  if (!scene) return kExitUsage;

  study::SweepOptions o;
  o.duration = scene->duration;
  if (const auto v = args.value("--integrators")) {
    for (const std::string& name : split(*v)) {
      const auto k = integrator_from_string(name);
      if (!k) return usage("--integrators: unknown integrator '" + name + "'");
      o.integrators.push_back(*k);
    }
  } else {
    o.integrators.assign(kAllIntegrators.begin(), kAllIntegrators.end());
  }
  if (const auto v = args.value("--steps")) {
    for (const std::string& t : split(*v)) {
      const auto h = positive(t);
      if (!h) return usage("--steps: expected positive numbers separated by commas, got '" + t + "'");
      o.steps.push_back(*h);
    }
  } else {
    double h = 4.0 * scene->dt;
    long levels = 5;
    if (const auto hm = args.value("--h-max")) {
      const auto p = positive(*hm);
      if (!p) return usage("--h-max: expected a number > 0, got '" + *hm + "'");
      h = *p;
    }
    if (const auto lv = args.value("--levels")) {
      const auto p = parse_positive_integer(*lv);
      if (!p || *p > 30) return usage("--levels: expected a whole number 1..30, got '" + *lv + "'");
      levels = *p;
    }
    for (long i = 0; i < levels; ++i, h /= 2.0) o.steps.push_back(h);
  }
  if (const auto v = args.value("--sample-dt")) {
    const auto p = positive(*v);
    if (!p) return usage("--sample-dt: expected a number > 0, got '" + *v + "'");
    o.sample_dt = *p;
  }
  if (const auto v = args.value("--ref-factor")) {
    const auto p = parse_positive_integer(*v);
    if (!p) return usage("--ref-factor: expected a whole number >= 1, got '" + *v + "'");
    o.reference_factor = static_cast<int>(*p);
  }
  if (const auto v = args.value("--repeats")) {
    const auto p = parse_positive_integer(*v);
    if (!p || *p > 100) return usage("--repeats: expected a whole number 1..100, got '" + *v + "'");
    o.repeats = static_cast<int>(*p);
  }
  o.check_reference = !args.has("--no-ref-check");
  const std::string prefix = args.value("--out").value_or("study-" + scene->name);
  const std::string title = args.value("--title").value_or(scene->name);

  study::SweepResult result;
  try {
    result = study::run_sweep(*scene, o, args.has("--quiet") ? nullptr : stdout);
  } catch (const std::invalid_argument& e) {
    return usage(e.what());
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
  if (!args.has("--quiet"))
    for (const auto& f : files) std::printf("wrote %s\n", f.string().c_str());
  return kExitOk;
}

int effects(int argc, char** argv) {
  const Args args(argc, argv, 3,
                  {"--param", "--values", "--integrators", "--duration", "--set", "--dt", "--rest-speed",
                   "--rest-hold", "--sample-dt", "--repeats", "--out", "--title"},
                  {"--help", "--quiet"});
  if (args.has("--help")) {
    std::fputs(kEffectsHelp, stdout);
    return kExitOk;
  }
  const auto usage = [](const std::string& what) {
    std::fprintf(stderr, "jelly study effects: %s\n(see jelly study effects --help)\n", what.c_str());
    return kExitUsage;
  };
  if (!args.error().empty()) return usage(args.error());
  if (args.positionals().size() != 1) return usage("expected exactly one SCENE file");
  const std::optional<SceneSpec> scene = load_with_overrides(args.positionals()[0], args);
  if (!scene) return kExitUsage;

  study::EffectsOptions o;
  o.duration = scene->duration;
  o.key = args.value("--param").value_or("");
  if (const auto v = args.value("--values")) o.values = split(*v, v->find(';') != std::string::npos ? ';' : ',');
  if (const auto v = args.value("--integrators")) {
    for (const std::string& name : split(*v)) {
      const auto k = integrator_from_string(name);
      if (!k) return usage("--integrators: unknown integrator '" + name + "'");
      o.integrators.push_back(*k);
    }
  }
  if (o.key.empty() && o.integrators.empty()) return usage("nothing to sweep: give --param KEY --values A,B,... or --integrators A,B");
  const std::pair<const char*, double*> reals[] = {
      {"--rest-speed", &o.rest_speed}, {"--rest-hold", &o.rest_hold}, {"--sample-dt", &o.series_dt}};
  for (const auto& [flag, target] : reals)
    if (const auto v = args.value(flag)) {
      const auto p = positive(*v);
      if (!p) return usage(std::string(flag) + ": expected a number > 0, got '" + *v + "'");
      *target = *p;
    }
  if (const auto v = args.value("--repeats")) {
    const auto p = parse_positive_integer(*v);
    if (!p || *p > 100) return usage("--repeats: expected a whole number 1..100, got '" + *v + "'");
    o.repeats = static_cast<int>(*p);
  }
  const std::string prefix = args.value("--out").value_or("effects-" + scene->name);
  const std::string title =
      args.value("--title").value_or(scene->name + (o.key.empty() ? std::string(": integrators") : ": " + o.key));

  study::EffectsResult result;
  try {
    result = study::run_effects(*scene, o, args.has("--quiet") ? nullptr : stdout);
  } catch (const std::invalid_argument& e) {
    return usage(e.what());
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
  if (!args.has("--quiet"))
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
  std::fprintf(stderr, "jelly study: unknown study '%s' (known: accuracy, effects)\n%s", what.c_str(), kStudyHelp);
  return kExitUsage;
}

}  // namespace jelly::cli
