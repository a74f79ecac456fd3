#include "jelly/movie/render_command.hpp"

#include "jelly/cli_common/command_line.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <ctime>
#include <iostream>
#include <optional>
#include <sstream>
#include <string>
#include <vector>

#include "jelly/movie/mp4.hpp"
#include "jelly/render/backend.hpp"
#include "jelly/render/frame.hpp"
#include "jelly/session/assignments.hpp"
#include "jelly/session/replay.hpp"
#include "jelly/session/scene_catalog.hpp"
#include "jelly/task_probe.hpp"

namespace jelly::movie {

namespace {

namespace fs = std::filesystem;
using namespace jelly::render;
using jelly::cli::Command;
using jelly::cli::positive_number;
using jelly::cli::whole_number;
using namespace jelly::session;

constexpr const char* kUsage =
    "usage: jelly render SCENE --frames DIR [--width W] [--height H] [--fps F] [--duration T]\n"
    "                    [--integrator NAME] [--dt H] [--set key=value ...] [--compare a,b,c]\n"
    "                    [--backend offscreen|window|null] [--camera YAW,PITCH,DISTANCE]\n"
    "                    [--particles] [--springs] [--no-caption] [--no-video] [--benchmark N]\n"
    "                    [--samples 0|2|4]\n"
    "       jelly render SCENE --replay FILE.csv --frames DIR [--label TEXT] [--width W] [--height "
    "H]\n"
    "                    [--camera ...] [--particles] [--no-caption] [--samples 0|2|4]\n"
    "  SCENE    a scene's name in the scenes folder (listed at the end) or a .toml path\n"
    "  --replay   draw recorded positions instead of simulating: one PNG per recorded frame; the\n"
    "             CSV is frame,time,particle,x,y,z[,...] as `jelly run --out` writes it, and the\n"
    "             scene gives the terrains and the body the particles belong to";
/// After the replay text of each body kind (BodyView::replay_help).
constexpr const char* kUsageEnd =
    "\n"
    "  --label    text printed top-left of every replayed frame, before the time\n"
    "  --compare  2 to 4 integrators side by side, e.g. explicit_euler,midpoint,rk4\n"
    "  --benchmark N  draw N frames of the first state and print frames per second\n";

/// The usage with the scenes this build finds (a release ships only its assignments' scenes).
std::string usage_text() {
  const fs::path dir = default_scenes_dir();
  const std::string example = example_scene(dir);
  std::string text = kUsage;
  for (const BodyView* view : body_views()) text += view->replay_help();
  text += kUsageEnd;
  if (!example.empty()) text += "example: jelly render " + example + " --frames out/frames\n";
  return text + scenes_line(dir) + "\n";
}

struct Args {
  std::string scene;
  fs::path frames;
  int width = 1280, height = 720;
  double fps = 30.0;
  double duration = -1.0;  // < 0: the scene's; 0: only the frame at t = 0
  std::string integrator, backend = "offscreen", camera;
  double dt = 0.0;
  std::vector<std::string> sets, compare;
  bool particles = false, springs = false, caption = true, video = true;
  int benchmark = 0;
  int samples = 4;
  fs::path replay;    // --replay: recorded positions to draw
  std::string label;  // --label: printed on replayed frames
};

std::vector<std::string> split(const std::string& s, char sep) {
  std::vector<std::string> out;
  std::stringstream ss(s);
  std::string item;
  while (std::getline(ss, item, sep))
    if (!item.empty()) out.push_back(item);
  return out;
}

bool parse_number(const std::string& text, double& out) {
  char* end = nullptr;
  out = std::strtod(text.c_str(), &end);
  return end && *end == '\0' && !text.empty() && std::isfinite(out);
}

/// --camera YAW,PITCH,DISTANCE onto `camera`; says what was wrong and returns false otherwise.
bool apply_camera(const std::string& text, OrbitCamera& camera) {
  const auto parts = split(text, ',');
  double y = 0, p = 0, dist = 0;
  if (parts.size() != 3 || !parse_number(parts[0], y) || !parse_number(parts[1], p) ||
      !parse_number(parts[2], dist) || dist <= 0) {
    std::cerr << "jelly render: --camera needs YAW,PITCH,DISTANCE (degrees, degrees, metres)\n";
    return false;
  }
  camera.yaw_degrees = y;
  camera.pitch_degrees = p;
  camera.distance = dist;
  return true;
}

/// Reads argv (argv[0] = "render") into `a`. nullopt: go on; else the exit code to return.
std::optional<int> parse(int argc, char** argv, Args& a) {
  const std::string usage = usage_text();
  Command cmd("jelly render", usage, usage);
  std::string compare, frames, replay;
  cmd.add_option("SCENE", a.scene)->required();
  cmd.add_option("--frames", frames)->type_name("DIR");
  cmd.add_option("--width", a.width)->type_name("W")->check(whole_number(1));
  cmd.add_option("--height", a.height)->type_name("H")->check(whole_number(1));
  cmd.add_option("--fps", a.fps)->type_name("F")->check(positive_number());
  cmd.add_option("--duration", a.duration)->type_name("T")->check(positive_number(true));
  cmd.add_option("--dt", a.dt)->type_name("H")->check(positive_number());
  cmd.add_option("--benchmark", a.benchmark)->type_name("N")->check(whole_number(1));
  cmd.add_option("--samples", a.samples)->type_name("0|2|4")->check(whole_number(0));
  cmd.add_option("--replay", replay)->type_name("FILE.csv");
  cmd.add_option("--label", a.label)->type_name("TEXT");
  cmd.add_option("--integrator", a.integrator)->type_name("NAME");
  cmd.add_option("--backend", a.backend)->type_name("offscreen|window|null");
  cmd.add_option("--camera", a.camera)->type_name("YAW,PITCH,DISTANCE");
  cmd.repeated("--set", a.sets, "KEY=VALUE")
      ->check(CLI::Validator(
          [](std::string& kv) {
            return kv.find('=') != std::string::npos ? std::string()
                                                     : "expected KEY=VALUE, got '" + kv + "'";
          },
          ""));
  cmd.add_option("--compare", compare)->type_name("A,B[,C[,D]]");
  cmd.add_flag("--particles", a.particles);
  cmd.add_flag("--springs", a.springs);
  cmd.add_flag("--no-caption", [&a](std::int64_t) { a.caption = false; });
  cmd.add_flag("--no-video", [&a](std::int64_t) { a.video = false; });
  if (const auto code = cmd.parse_args(argc, argv, 1)) return code;
  a.frames = frames;
  a.replay = replay;
  if (!compare.empty()) {
    a.compare = split(compare, ',');
    if (a.compare.size() < 2 || a.compare.size() > 4)
      return cmd.error("--compare takes 2 to 4 integrators, got " +
                       std::to_string(a.compare.size()));
  }
  if (a.frames.empty() && a.benchmark == 0) return cmd.error("--frames DIR is required");
  if (!a.replay.empty() && (!a.compare.empty() || a.benchmark > 0 || !a.integrator.empty()))
    return cmd.error(
        "--replay draws recorded positions: --compare, --integrator and --benchmark do not apply");
  return std::nullopt;
}

/// Creates the frames folder (and its parents); false, after saying why on stderr, when it cannot.
bool make_folder(const fs::path& dir) {
  std::error_code ec;
  fs::create_directories(dir, ec);
  if (ec) {
    std::cerr << "jelly render: " << dir.string() << ": cannot create folder: " << ec.message()
              << "\n";
    return false;
  }
  return true;
}

/// Reads the finished frame back, shows it, and writes it as DIR/frame_NNNNN.png (the numbering
/// ffmpeg reads). False, after saying why on stderr, when the file cannot be written.
bool save_frame(Backend& be, const fs::path& dir, std::size_t k) {
  const Image img = be.read_pixels();
  be.present();
  char name[32];
  std::snprintf(name, sizeof name, "frame_%05zu.png", k);
  if (const std::string err = write_png(dir / name, img); !err.empty()) {
    std::cerr << "jelly render: " << err << "\n";
    return false;
  }
  return true;
}

/// Each body kind's replay points of frame `x`, after the state's `n` particles.
void place_replay_points(World& world, const Vec3Array& x, long n) {
  long first = n;
  for (const BodyView* view : views_in(world)) {
    view->place_replay_points(world, x, first);
    first += view->replay_points(world);
  }
}

/// --replay: the scene's world (terrains, the bodies' topology) drawn at each recorded frame's
/// positions, one PNG per frame (frame_00000.png, ... in file order). Nothing is simulated and no
/// task code runs but the spring builders the scene's world is built with.
int render_replay(const Args& a, const SceneSpec& scene, Backend& be, Renderer& renderer) {
  const ReplayResult loaded = load_replay(a.replay);
  if (!loaded) {
    std::cerr << "jelly render: " << loaded.error << "\n";
    return 2;
  }
  const Replay& replay = *loaded.replay;
  std::unique_ptr<World> world;
  try {
    world = build_world(scene, session::tasks_for(scene));
  } catch (const std::exception& e) {
    std::cerr << "jelly render: cannot build the scene's world: " << e.what() << "\n";
    return 1;
  }
  // A frame holds the state's particles, and may go on with the points a body kind records after
  // them (BodyView::replay_points: the grader records those of the course scenes); without them
  // those stay where the scene starts them.
  const long n = static_cast<long>(world->state().x.cols());
  long extra = 0;
  for (const BodyView* view : views_in(*world)) extra += view->replay_points(*world);
  if (replay.particles() != n && replay.particles() != n + extra) {
    std::cerr << "jelly render: " << a.replay.string() << ": " << replay.particles()
              << " particles per frame, but scene '" << scene.name << "' has " << n;
    for (const BodyView* view : views_in(*world))
      if (const long k = view->replay_points(*world); k > 0)
        std::cerr << " (or " << n + k << " with its " << k << " " << view->replay_points_name()
                  << " after them)";
    std::cerr << "\n";
    return 2;
  }
  if (!make_folder(a.frames)) return 1;
  // Framed on the scene at its start, so every frame of every replay of a scene has one view.
  std::unique_ptr<SceneDrawable> drawable = renderer.make_drawable(*world);
  OrbitCamera camera;
  const Viewport vp{0, 0, a.width, a.height};
  camera.frame(drawable->bounds(), vp.aspect());
  if (!a.camera.empty() && !apply_camera(a.camera, camera)) return 2;
  DrawOptions draw;
  draw.particles = a.particles;
  if (a.springs) draw.springs = {true, true, true, true};
  const float s = text_scale(a.height);
  const int pad = static_cast<int>(6 * s);
  const RunSetup setup = RunSetup::from_scene(scene);
  for (std::size_t k = 0; k < replay.frames.size(); ++k) {
    const ReplayFrame& f = replay.frames[k];
    world->state().x = f.x.leftCols(n);
    world->state().v.setZero(3, n);
    if (extra > 0 && f.x.cols() == n + extra) place_replay_points(*world, f.x, n);
    renderer.begin_frame(a.width, a.height);
    renderer.draw(*drawable, *world, camera, draw, vp);
    char when[48];
    std::snprintf(when, sizeof when, "t = %.2f s", f.time);
    const std::string label = a.label.empty() ? std::string(when) : a.label + "   " + when;
    renderer.draw_text(wrap_text(label, a.width - 3 * pad, s), pad, pad, s,
                       {1.0f, 0.95f, 0.75f, 1.0f});
    if (a.caption) {
      const std::string text =
          wrap_text(caption(setup, f.time, false), a.width - 3 * pad, s * 0.75f);
      const Eigen::Vector2i size = Renderer::text_size(text, s * 0.75f);
      renderer.draw_text(text, pad, a.height - size.y() - pad / 2, s * 0.75f,
                         {0.92f, 0.94f, 1.0f, 1.0f});
    }
    renderer.end_frame();
    if (!save_frame(be, a.frames, k)) return 1;
  }
  std::cout << "wrote " << replay.frames.size() << " replayed frames to " << a.frames.string()
            << "\n";
  return 0;
}

/// The scene SCENE names, with the --set assignments applied; nullopt after saying why.
std::optional<SceneSpec> load_scene(const Args& a) {
  SceneResult loaded = resolve_scene(a.scene, default_scenes_dir());
  if (!loaded) {
    std::cerr << "jelly render: " << loaded.error->text() << "\n";
    return std::nullopt;
  }
  SceneSpec scene = *loaded.scene;
  for (const std::string& kv : a.sets) {
    if (auto err = set_assignment(scene, kv)) {
      std::cerr << "jelly render: " << err->text() << "\n";
      return std::nullopt;
    }
  }
  return scene;
}

BackendOptions backend_options(const Args& a) {
  BackendOptions bo;
  bo.name = a.backend;
  bo.width = a.width;
  bo.height = a.height;
  return bo;
}

/// One run per integrator to draw (--compare's, else --integrator or the scene's) into `runs`.
/// nullopt: go on; else the exit code to return, after saying why.
std::optional<int> make_runs(const Args& a, const RunSetup& base,
                             std::vector<std::unique_ptr<SimulationRun>>& runs) {
  std::vector<std::string> names = a.compare;
  if (names.empty())
    names.push_back(a.integrator.empty() ? std::string(to_string(base.integrator)) : a.integrator);
  for (const std::string& name : names) {
    const auto kind = integrator_from_string(name);
    if (!kind) {
      std::cerr << "jelly render: unknown integrator '" << name
                << "' (explicit_euler, implicit_euler, midpoint, rk4, symplectic_euler, "
                   "backward_euler)\n";
      return 2;
    }
    RunSetup s = base;
    s.integrator = *kind;
    runs.push_back(std::make_unique<SimulationRun>(s, session::tasks_for(s.scene)));
    if (!runs.back()->ok()) {
      std::cerr << "jelly render: " << name << ": " << runs.back()->error() << "\n";
      return 1;
    }
  }
  return std::nullopt;
}

/// What every frame shows besides the bodies: the options asked for, and a hint naming the tasks
/// the scene's assignment does not implement yet.
FrameOptions frame_options(const Args& a, const RunSetup& base) {
  FrameOptions fo;
  fo.caption = a.caption;
  fo.draw.particles = a.particles;
  if (a.springs) fo.draw.springs = {true, true, true, true};
  const auto missing =
      missing_task_ids(session::probe_assignment(session::assignment_for(base.scene)));
  if (!missing.empty()) {
    std::string hint = "not implemented yet:";
    for (const auto& id : missing) hint += " " + id;
    fo.hints.push_back(hint);
  }
  return fo;
}

/// The runs drawn side by side, with one camera and one set of frame options.
struct RunFrames {
  Backend& be;
  Renderer& renderer;
  std::vector<SimulationRun*> runs;
  FrameOptions fo;
  OrbitCamera camera;

  void draw() { draw_frame(renderer, runs, camera, fo, be.width(), be.height()); }
};

/// --benchmark: frames per second of drawing and reading back the first state (no stepping).
/// Wall time and process CPU time (all of llvmpipe's threads) per frame; on a shared machine the
/// CPU time is the steadier figure.
int benchmark(const Args& a, RunFrames& view) {
  std::vector<double> ms, cpu_ms;
  for (int i = 0; i < a.benchmark + 3; ++i) {
    const auto t0 = std::chrono::steady_clock::now();
    const std::clock_t c0 = std::clock();
    view.draw();
    const Image img = view.be.read_pixels();
    view.be.present();
    const double dt =
        std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count();
    if (i >= 3) {  // the first frames compile shaders and warm caches
      ms.push_back(dt);
      cpu_ms.push_back(1000.0 * static_cast<double>(std::clock() - c0) / CLOCKS_PER_SEC);
    }
  }
  std::sort(ms.begin(), ms.end());
  std::sort(cpu_ms.begin(), cpu_ms.end());
  const double median = ms[ms.size() / 2];
  const Backend& be = view.be;
  std::printf(
      "backend %s, %dx%d, %d samples, %s\nframes %d: median %.2f ms/frame = %.1f fps (min %.2f, "
      "max %.2f ms); "
      "median CPU %.2f ms/frame\n",
      std::string(be.name()).c_str(), be.width(), be.height(), view.renderer.samples(),
      be.gl() ? be.gl()->describe().c_str() : "no GL", a.benchmark, median, 1000.0 / median,
      ms.front(), ms.back(), cpu_ms[cpu_ms.size() / 2]);
  return 0;
}

/// Steps the runs to each frame's time and saves the frame; false, after saying why, when a frame
/// cannot be written.
bool save_frames(const Args& a, int frames, RunFrames& view) {
  for (int k = 0; k < frames; ++k) {
    const double t = k / a.fps;
    for (SimulationRun* r : view.runs) r->advance_to(t);
    view.draw();
    if (!save_frame(view.be, a.frames, static_cast<std::size_t>(k))) return false;
  }
  return true;
}

/// Says which runs the stability detector stopped; 1 if any, else 0.
int report_instability(const std::vector<SimulationRun*>& runs) {
  int status = 0;
  for (SimulationRun* r : runs)
    if (const auto& inst = r->simulator()->instability()) {
      std::cerr << inst->message() << "\n";
      status = 1;
    }
  return status;
}

/// DIR/video.mp4 from the frames, when ffmpeg is there; says what became of it.
void write_video(const Args& a) {
  const fs::path mp4 = a.frames / "video.mp4";
  const Mp4Result video = encode_mp4(a.frames, a.fps, mp4);
  switch (video.status) {
    case Mp4Result::Status::Written: std::cout << "wrote " << mp4.string() << "\n"; break;
    case Mp4Result::Status::Failed:
      std::cerr << "jelly render: ffmpeg failed (" << video.detail << "); the PNG frames are in "
                << a.frames.string() << "\n";
      break;
    case Mp4Result::Status::NoFfmpeg:
      std::cout << "(no ffmpeg on PATH: PNG frames only; for video.mp4, " << kFfmpegInstallHint
                << ")\n";
      break;
  }
}

/// The frames of the runs from t = 0 to the duration, then the video.
int render_movie(const Args& a, const SceneSpec& scene, RunFrames& view) {
  const double duration = a.duration >= 0.0 ? a.duration : scene.duration;
  const int frames = static_cast<int>(std::floor(duration * a.fps + 1e-9)) + 1;
  if (!make_folder(a.frames)) return 1;
  if (!save_frames(a, frames, view)) return 1;
  const int status = report_instability(view.runs);
  std::cout << "wrote " << frames << " frames to " << a.frames.string() << "\n";
  if (a.video) write_video(a);
  return status;
}

/// The scene simulated with each integrator asked for, drawn side by side: its frames and video,
/// or with --benchmark the drawing speed.
int render_runs(const Args& a, const SceneSpec& scene, Backend& be, Renderer& renderer) {
  RunSetup base = RunSetup::from_scene(scene);
  if (a.dt > 0.0) base.dt = a.dt;
  std::vector<std::unique_ptr<SimulationRun>> runs;
  if (const auto code = make_runs(a, base, runs)) return *code;
  std::vector<SimulationRun*> run_ptrs;
  for (auto& r : runs) run_ptrs.push_back(r.get());
  RunFrames view{be, renderer, run_ptrs, frame_options(a, base), OrbitCamera()};
  ensure_drawables(renderer, run_ptrs);
  const auto vps = frame_viewports(static_cast<int>(runs.size()), a.width, a.height, view.fo);
  view.camera.frame(drawable_of(*runs.front())->bounds(), vps.front().aspect());
  if (!a.camera.empty() && !apply_camera(a.camera, view.camera)) return 2;
  if (a.benchmark > 0) return benchmark(a, view);
  return render_movie(a, scene, view);
}

}  // namespace

int render_command(int argc, char** argv) {
  Args a;
  if (const auto code = parse(argc, argv, a)) return *code;
  const std::optional<SceneSpec> scene = load_scene(a);
  if (!scene) return 2;
  // The backend and renderer outlive the runs (whose draw proxies hold GL objects).
  BackendResult backend = create_backend(backend_options(a));
  if (!backend.backend) {
    std::cerr << "jelly render: " << backend.error << "\n";
    return 1;
  }
  Backend& be = *backend.backend;
  Renderer renderer(be.gl(), a.samples);
  if (!a.replay.empty()) return render_replay(a, *scene, be, renderer);
  return render_runs(a, *scene, be, renderer);
}

}  // namespace jelly::movie
