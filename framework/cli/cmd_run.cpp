// `jelly run`: runs a scene headless and writes its trajectory and summary as CSV.
#include <chrono>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <memory>
#include <optional>
#include <string>
#include <system_error>

#include "commands.hpp"
#include "jelly/auto_step.hpp"
#include "jelly/body_kind.hpp"
#include "jelly/cli_common/command_line.hpp"
#include "jelly/recorder.hpp"
#include "jelly/session/assignments.hpp"
#include "jelly/session/scene_catalog.hpp"
#include "jelly/simulator.hpp"
#include "jelly/task_probe.hpp"

namespace jelly::cli {

namespace {

// `jelly run --help` in pieces: between them what each body kind adds (run_help).
constexpr const char* kRunHelp = R"(usage: jelly run SCENE [options]

Runs SCENE (a .toml scene file, or a scene's name in the scenes folder; the end of this text
names them) without a window and writes what happened as CSV.

options:
  --integrator NAME   explicit_euler | implicit_euler | midpoint | rk4 (the course's four, your
                      code) | symplectic_euler | backward_euler (the framework's); default: the scene's
  --dt H              fixed step [s], > 0; default: the scene's simulation.dt
  --duration T        simulated time [s], > 0; default: the scene's simulation.duration
  --set KEY=VALUE     overrides any declared parameter (repeatable), e.g.
                        --set body.center=-5,11,0   --set springs.shear.ks=5000
                        --set simulation.integrator=rk4   --set gravity.enabled=false
                      `jelly params SCENE` lists every key with its unit, range and meaning.
  --auto-dt           choose the step from the stability estimate (as simulation.auto_dt = true):
                      the largest h ≤ the scene's dt that is at most half of the integrator's
                      linearised limit, with whole substeps per 1/60 s frame; prints the choice
  --threads N         split the spring pass among N threads (default 1; )";
// ... each body kind's word on --threads (body_kinds_help) ...
constexpr const char* kRunHelpAfterThreads =
    R"(on an otherwise idle machine); the result is the same bits for any N
  --every K           record every K-th step (default: 60 frames per simulated second,
                      i.e. K = round(1 / (60 h)), at least 1); step 0 is always recorded
  --out FILE.csv      trajectory: frame,time,particle,x,y,z,vx,vy,vz (one row per particle per frame)
  --summary FILE.csv  per frame: time,com_x,com_y,com_z,kinetic,potential,spring,max_speed)";
// ... each body kind's own summary columns ...
constexpr const char* kRunHelpAfterSummary = R"(
  --no-detector       do not stop on instability (for experiments; NaN may follow)
  --quiet             print nothing but errors
  --help              this text

The stability detector (physics contract §8) stops a run whose state is not finite or whose total
energy rises above its start by more than 1 % (or grows exponentially), prints which integrator,
step size and step, and the step size the linearised system says is stable, and keeps what was
written so far.

exit codes: 0 finished; 2 bad command line or scene input (nothing is written); 3 stopped by the
stability detector; 1 unexpected failure (e.g. an output file could not be written).
)";

/// The help with the scenes this build finds (a release ships only its assignments' scenes).
std::string run_help() {
  const std::filesystem::path dir = session::default_scenes_dir();
  const std::string example = session::example_scene(dir);
  std::string threads, summary;
  for (const BodyKindModule* kind : body_kinds()) {
    threads += kind->run_help("--threads");
    summary += kind->run_help("--summary");
  }
  std::string text = kRunHelp + threads + kRunHelpAfterThreads + summary + kRunHelpAfterSummary;
  if (!example.empty())
    text += "\nexample: jelly run " + example + " --integrator rk4 --summary summary.csv\n";
  return text + session::scenes_line(dir) + "\n";
}

/// `jelly run` of a scene whose kind plays frames (a recorded motion) instead of simulating.
int play_command(const SceneSpec& scene, const BodyKindModule& kind,
                 const FramePlayOptions& options, const std::string& out_path, bool quiet) {
  if (!out_path.empty()) {
    std::fprintf(stderr,
                 "jelly run: --out writes particles, and %s scene has none; use --summary\n",
                 std::string(kind.body_phrase()).c_str());
    return kExitUsage;
  }
  // A build with no assignment for this kind plays with no tasks: the kind names the slot missing.
  TaskTable tasks;
  std::string no_assignment;
  try {
    tasks = session::tasks_for(scene);
  } catch (const std::exception& e) {
    no_assignment = e.what();
  }
  if (!quiet && no_assignment.empty()) print_missing_tasks_note(scene);
  std::string report;
  try {
    report = kind.play(scene, tasks, options);
  } catch (const std::system_error& e) {  // an output file that cannot be written
    std::fprintf(stderr, "jelly run: %s\n", e.what());
    return kExitInternal;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "jelly run: %s\n", e.what());
    if (!no_assignment.empty()) std::fprintf(stderr, "jelly run: %s\n", no_assignment.c_str());
    return kExitUsage;
  }
  if (!quiet) std::printf("%s", report.c_str());
  return kExitOk;
}

/// `jelly run`'s command line.
struct RunArgs {
  std::string scene_path, out_path, summary_path;
  SceneOverrides overrides;
  long every = 0, threads = 0;  // 0: not given
  bool quiet = false, no_detector = false, auto_dt = false;
};

/// Reads argv (argv[1] = "run") into `a`. nullopt: go on; else the exit code to return.
std::optional<int> parse_run_args(int argc, char** argv, RunArgs& a) {
  Command cmd("jelly run", run_help(), "(see jelly run --help)\n");
  cmd.add_option("SCENE", a.scene_path)->required();
  add_scene_overrides(cmd, a.overrides);
  cmd.add_option("--every", a.every)->type_name("K")->check(whole_number(1));
  cmd.add_option("--threads", a.threads)->type_name("N")->check(whole_number(1, 256));
  cmd.add_option("--out", a.out_path)->type_name("FILE.csv");
  cmd.add_option("--summary", a.summary_path)->type_name("FILE.csv");
  cmd.add_flag("--quiet", a.quiet);
  cmd.add_flag("--no-detector", a.no_detector);
  cmd.add_flag("--auto-dt", a.auto_dt);
  return cmd.parse_args(argc, argv, 2);
}

/// The scene's simulator, with the step --auto-dt (or the scene's auto_dt) chose in `auto_step`;
/// null after saying why.
std::unique_ptr<Simulator> make_simulator(const SceneSpec& scene, const RunArgs& a,
                                          std::optional<AutoStep>& auto_step) {
  try {
    Simulator::Options options(scene.integrator, scene.dt);
    options.detect_instability = !a.no_detector;
    std::unique_ptr<World> world = build_world(scene, session::tasks_for(scene));
    if (a.threads > 0) world->set_force_threads(static_cast<int>(a.threads));
    if (a.auto_dt || scene.auto_dt) {
      // One frame = 1/60 s, the default recording interval; the scene's dt is the largest step.
      auto_step = choose_step(*world, world->state(), scene.integrator, 1.0 / 60.0, scene.dt);
      options.dt = auto_step->chosen_h;
      std::printf("%s\n", auto_step->message().c_str());  // stdout, even with --quiet: what ran
    }
    return std::make_unique<Simulator>(std::move(world), options);
  } catch (const std::exception& e) {
    // A student's spring builder that produced a bad spring ends up here, with its name.
    std::fprintf(stderr, "jelly run: %s\n", e.what());
    return nullptr;
  }
}

/// Every how many steps a frame is recorded: --every, else the auto step's substeps per frame,
/// else the steps of step size h in 1/60 s (at least 1).
long record_interval(long every, const std::optional<AutoStep>& auto_step, double h) {
  return every > 0   ? every
         : auto_step ? auto_step->substeps_per_frame
                     : std::max(1L, std::lround(1.0 / (60.0 * h)));
}

/// The CSV files a run writes (--out, --summary) and the frames it records in them: the state
/// after every k-th step.
class Recording {
 public:
  Recording(const BodyKindModule& body, long k) : body_(body), k_(k) {}

  /// Opens the files asked for; false after saying why.
  bool open(const RunArgs& a, const World& world) {
    try {
      if (!a.out_path.empty()) out_ = std::make_unique<CsvWriter>(a.out_path, kTrajectoryHeader);
      if (!a.summary_path.empty())
        summary_ = std::make_unique<CsvWriter>(a.summary_path, body_.summary_header(world));
    } catch (const std::exception& e) {
      std::fprintf(stderr, "jelly run: %s\n", e.what());
      return false;
    }
    return true;
  }

  void record(const Simulator& s) {
    if (s.steps() % k_ != 0) return;
    if (out_) out_->write_particles(frame_, s.time(), s.state());
    if (summary_) body_.write_summary(*summary_, s.world(), s.state(), s.time());
    ++frame_;
  }

  void flush() {
    if (out_) out_->flush();
    if (summary_) summary_->flush();
  }

  bool writes() const { return out_ || summary_; }
  long frames() const { return frame_; }

  void print_written(const RunArgs& a) const {
    if (out_) std::printf("  wrote %ld frames to %s\n", frame_, a.out_path.c_str());
    if (summary_) std::printf("  wrote %ld summary rows to %s\n", frame_, a.summary_path.c_str());
  }

 private:
  const BodyKindModule& body_;
  long k_;
  std::unique_ptr<CsvWriter> out_, summary_;
  long frame_ = 0;
};

/// Runs the simulation to the scene's end, recording as it goes, and says how it ended.
int simulate(const RunArgs& a, const SceneSpec& scene, Simulator& sim, const BodyKindModule& body,
             Recording& rec) {
  rec.record(sim);
  const auto t0 = std::chrono::steady_clock::now();
  const StepResult result =
      sim.run_until(scene.duration, [&rec](const Simulator& s) { rec.record(s); });
  const double wall = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  rec.flush();
  if (result == StepResult::Unstable) {
    std::fprintf(stderr, "jelly run: %s\n", sim.instability()->message().c_str());
    if (rec.writes())
      std::fprintf(stderr, "jelly run: kept the %ld frames written before the detector fired.\n",
                   rec.frames());
    return kExitUnstable;
  }
  if (!a.quiet) {
    std::printf("%s", body.end_report(scene, sim, wall).c_str());
    rec.print_written(a);
  }
  return kExitOk;
}

}  // namespace

int run_command(int argc, char** argv) {
  RunArgs a;
  if (const auto code = parse_run_args(argc, argv, a)) return *code;
  const std::optional<SceneSpec> scene = load_with_overrides(a.scene_path, a.overrides);
  if (!scene) return kExitUsage;
  if (const BodyKindModule& kind = body_kind_of(*scene); kind.plays_frames())
    return play_command(*scene, kind, {a.summary_path, a.every > 0 ? a.every : 1}, a.out_path,
                        a.quiet);
  if (!a.quiet) print_missing_tasks_note(*scene);
  std::optional<AutoStep> auto_step;
  const std::unique_ptr<Simulator> sim = make_simulator(*scene, a, auto_step);
  if (!sim) return kExitUsage;
  const long k = record_interval(a.every, auto_step, sim->options().dt);
  const BodyKindModule& body = body_kind_of(*scene);  // what its summary and report hold
  // Outputs are opened only now, after every input was validated: bad input writes nothing.
  Recording rec(body, k);
  if (!rec.open(a, sim->world())) return kExitInternal;
  return simulate(a, *scene, *sim, body, rec);
}

void add_scene_overrides(Command& command, SceneOverrides& into, bool run_options) {
  command.repeated("--set", into.sets, "KEY=VALUE");
  if (!run_options) return;
  command.add_option("--integrator", into.integrator)->type_name("NAME");
  command.add_option("--dt", into.dt)->type_name("H");
  command.add_option("--duration", into.duration)->type_name("T");
}

std::optional<SceneSpec> load_with_overrides(const std::string& scene_name,
                                             const SceneOverrides& overrides) {
  SceneResult loaded = session::resolve_scene(scene_name, session::default_scenes_dir());
  if (!loaded) {
    std::fprintf(stderr, "error: %s\n", loaded.error->text().c_str());
    return std::nullopt;
  }
  SceneSpec scene = std::move(*loaded.scene);
  auto apply = [&](const std::string& key, const std::string& value) {
    if (const auto err = set_parameter(scene, key, value)) {
      std::fprintf(stderr, "error: %s\n", err->text().c_str());
      return false;
    }
    return true;
  };
  if (!overrides.integrator.empty() && !apply("simulation.integrator", overrides.integrator))
    return std::nullopt;
  if (!overrides.dt.empty() && !apply("simulation.dt", overrides.dt)) return std::nullopt;
  if (!overrides.duration.empty() && !apply("simulation.duration", overrides.duration))
    return std::nullopt;
  for (const std::string& kv : overrides.sets) {
    if (const auto err = set_assignment(scene, kv)) {
      std::fprintf(stderr, "error: %s\n", err->text().c_str());
      return std::nullopt;
    }
  }
  return scene;
}

void print_missing_tasks_note(const SceneSpec& scene) {
  const LinkedAssignment& assignment = session::assignment_for(scene);
  const auto missing = missing_task_ids(session::probe_assignment(assignment));
  if (missing.empty()) return;
  std::string list;
  for (const std::string& id : missing) list += (list.empty() ? "" : ", ") + id;
  // The handout the manifest names, beside the manifest the program was built with (relative to
  // the working folder when it is below it: "assignments/<id>/handout/README.md" from the
  // checkout).
  const AssignmentManifest& manifest = session::manifest_of(assignment);
  std::string handout = manifest.id + "'s handout";
  if (!manifest.handout.empty()) {
    const std::filesystem::path file =
        std::filesystem::path(std::string(assignment.manifest_path)).parent_path() /
        manifest.handout;
    std::error_code ec;
    const std::filesystem::path here = std::filesystem::current_path(ec);
    const std::filesystem::path relative = ec ? file : file.lexically_relative(here);
    handout = !relative.empty() && *relative.begin() != ".." ? relative.generic_string()
                                                             : file.generic_string();
  }
  std::fprintf(stderr,
               "note: these student tasks still return the stub's neutral value: %s.\n"
               "      Until they are done the scene does not move as it should (what they compute\n"
               "      is missing from every step). See %s.\n",
               list.c_str(), handout.c_str());
}

}  // namespace jelly::cli
