#include "reports/frames.hpp"

#include <cmath>
#include <cstdio>
#include <fstream>
#include <sstream>

#ifdef _WIN32
#include <process.h>
#define getpid _getpid
#else
#include <unistd.h>
#endif

#include "inputs/files.hpp"
#include "sandbox/process.hpp"

namespace jelly::grade {

namespace {

constexpr int kWidth = 320,
              kHeight = 240;  // small: two renders of ~6 frames stay well under a second each

std::string fmt_time(double t) {
  char b[32];
  std::snprintf(b, sizeof b, "%.2f", t);
  return b;
}

std::string first_line(const std::string& text) {
  std::istringstream in(text);
  std::string line, last;
  // The last non-empty line of stderr is the error; earlier ones are often driver chatter.
  while (std::getline(in, line))
    if (!line.empty()) last = line;
  return last.empty() ? "no message" : last;
}

// FNV-1a of a file's bytes (the reference runner: its frames are cached per binary).
std::string file_digest(const fs::path& p) { return fnv_hex(read_file(p)); }

std::vector<double> numbers(const Json& outputs, const char* key) {
  std::vector<double> v;
  // The student's outputs come from the result channel: any shape (a forged result).
  if (!outputs.is_object() || !outputs.contains(key) || !outputs.at(key).is_object() ||
      !outputs.at(key).contains("value") || !outputs.at(key).at("value").is_array())
    return v;
  for (const Json& e : outputs.at(key).at("value"))
    v.push_back(e.is_number() ? e.get<double>() : NAN);
  return v;
}

/// Runs `jelly render builtin:SCENE --replay CSV --frames DIR ...` (SCENE: the manifest's
/// default_scene, the built-in copy so that the scenes folder cannot change it); "" or the reason
/// it failed.
std::string render(const fs::path& jelly, const std::string& scene, const fs::path& csv,
                   const fs::path& dir, const std::string& label) {
  const Limits lim = trusted_tool_limits(60.0);
  const ChildResult c =
      run_child({jelly.string(), "render", "builtin:" + scene, "--replay", csv.string(), "--frames",
                 dir.string(), "--width", std::to_string(kWidth), "--height",
                 std::to_string(kHeight), "--samples", "0", "--no-caption", "--label", label},
                lim);
  if (!c.started) return "cannot start " + jelly.string() + ": " + c.start_error;
  if (c.timed_out) return "`jelly render --replay` took longer than 60 s";
  if (c.signal != 0) return "`jelly render --replay` crashed with " + describe_signal(c.signal);
  if (c.exit_code != 0)
    return "`jelly render --replay` failed (exit " + std::to_string(c.exit_code) +
           "): " + first_line(c.err);
  return "";
}

/// The reference's recorded frames: from the cache, else by running the reference runner.
/// Returns its outputs (frame_times, frame_positions) or sets `why`.
Json reference_frames(const GradeConfig& config, const CaseSpec& spec, const fs::path& work,
                      std::string& why) {
  if (config.reference_runner.empty() || !fs::exists(config.reference_runner)) {
    why =
        "no reference runner in this copy of the grader (it is built only where solutions/ exists)";
    return Json();
  }
  const std::string key =
      fnv_hex(case_hash(spec, harness_digest(config)) + file_digest(config.reference_runner));
  const fs::path cache =
      config.binary_dir / "grader" / "reference-frames" / (spec.id + "-" + key + ".json");
  std::error_code ec;
  if (fs::exists(cache, ec)) {
    try {
      std::ifstream in(cache);
      return Json::parse(in);
    } catch (const std::exception&) {
      fs::remove(cache, ec);  // a torn write: make it again
    }
  }
  const std::optional<Json> ref = load_reference(config, spec);
  const Json input = ref && ref->contains("input") ? ref->at("input") : Json::object();
  fs::create_directories(work, ec);
  const ChildResult c = run_case(config.reference_runner, spec, &input, work, 120.0, 0);
  Json outputs;
  try {
    const Json result = Json::parse(c.result);
    outputs = result.at("outputs");
  } catch (const std::exception&) {
    why =
        "the reference runner failed on " + spec.id + " (exit " + std::to_string(c.exit_code) + ")";
    return Json();
  }
  Json kept = Json::object();
  for (const char* k : {"frame_times", "frame_positions"})
    if (outputs.contains(k)) kept[k] = outputs[k];
  fs::create_directories(cache.parent_path(), ec);
  const fs::path tmp = cache.string() + ".tmp" + std::to_string(::getpid());
  std::ofstream(tmp) << kept.dump();
  fs::rename(tmp, cache, ec);  // atomic: parallel batch workers may race here
  return kept;
}

// Whether the case records frames (an output with rule "frames").
bool records_frames(const CaseSpec& spec) {
  for (const auto& [name, rule] : spec.rules)
    if (rule.kind == Rule::Kind::Frames) return true;
  return false;
}

// The scene case: the last case that records frames; its frames are drawn in the assignment's
// default scene (the manifest's default_scene). Null when there is none.
const CaseResult* course_case(const GradeReport& report) {
  const CaseResult* course = nullptr;
  for (const CaseResult& c : report.cases)
    if (records_frames(*c.spec) && c.status != "skipped") course = &c;
  return course;
}

// Why the course case's frames cannot be drawn at all; "" when they can.
std::string frames_unavailable(const GradeConfig& config, const CaseResult& course) {
  if (!course.spec->params.contains("frame_times"))
    return "the course scene case records no frames (no frame_times in " +
           (config.cases_dir() / course.spec->source).string() + ")";
  if (config.assignment().manifest.default_scene.empty())
    return "the assignment's manifest (" + config.rubric_path().string() +
           ") names no default_scene to draw the frames in";
  if (config.jelly_cli.empty())
    return "this grader was built without the renderer (configure with -DJELLY_BUILD_VIEWER=ON, "
           "or set JELLY_GRADE_JELLY to a jelly program with `render --replay`)";
  std::error_code ec;
  if (!fs::exists(config.jelly_cli, ec))
    return config.jelly_cli.string() + " is missing (build the `jelly` target)";
  return "";
}

long index_of(const std::vector<double>& times, double t) {
  for (std::size_t k = 0; k < times.size(); ++k)
    if (std::abs(times[k] - t) < 1e-9) return static_cast<long>(k);
  return -1;
}

// The page's path of side's PNG number k.
std::string png(const char* side, long k) {
  char name[32];
  std::snprintf(name, sizeof name, "frame_%05ld.png", k);
  return (fs::path("frames") / side / name).generic_string();
}

// Recorded times are the first step at or after each asked time: match within 10 ms.
double recorded(const std::vector<double>& times, double asked_t) {
  for (double t : times)
    if (t >= asked_t - 1e-9 && t < asked_t + 0.01) return t;
  return NAN;
}

// Draws the course case's frames, the student's and the reference's, into out_dir/frames and lists
// them in `result` as rows at the asked times. Throws what the files it writes throw.
class FramesDrawing {
 public:
  FramesDrawing(const GradeConfig& config, const CaseResult& course, const fs::path& out_dir,
                const fs::path& work, CourseFrames& result)
      : config_(config),
        course_(course),
        scene_(config.assignment().manifest.default_scene),
        out_dir_(out_dir),
        work_(work),
        dir_(work / "frames"),
        result_(result) {}

  void draw() {
    std::error_code ec;
    fs::remove_all(out_dir_ / "frames", ec);
    fs::create_directories(dir_);
    if (!draw_yours()) return;
    note_missing_frames();
    if (!draw_reference()) return;
    add_rows();
    if (result_.rows.empty() && result_.unavailable.empty())
      result_.unavailable = "neither run recorded a frame";
  }

 private:
  // The student's frames (recorded in the sandbox; drawn here).
  bool draw_yours() {
    your_times_ = write_replay_csv(course_.outputs, dir_ / "yours.csv", dropped_);
    return your_times_.empty() || draw_side("yours");
  }

  void note_missing_frames() {
    for (double t : dropped_)
      result_.notes.push_back("your frame at t = " + fmt_time(t) +
                              " s has NaN or infinity: not drawn");
    asked_ = course_.spec->params["frame_times"].get<std::vector<double>>();
    if (your_times_.empty() && dropped_.empty())
      result_.notes.push_back(
          course_.outputs.is_null()
              ? "your run of the course scene produced no frames (it did not finish)"
              : "your run of the course scene recorded no frames (it stopped before t = " +
                    fmt_time(asked_.empty() ? 0.0 : asked_.front()) + " s)");
  }

  // The reference's.
  bool draw_reference() {
    std::string why;
    const Json ref = reference_frames(config_, *course_.spec, work_, why);
    std::vector<double> ref_dropped;
    if (!ref.is_null() &&
        !(ref_times_ = write_replay_csv(ref, dir_ / "reference.csv", ref_dropped)).empty())
      return draw_side("reference");
    result_.notes.push_back("reference frames not available: " +
                            (why.empty() ? std::string("none recorded") : why));
    return true;
  }

  // Renders dir/<side>.csv into out_dir/frames/<side>; false, the reason in the result, when that
  // fails.
  bool draw_side(const std::string& side) {
    const std::string err =
        render(config_.jelly_cli, scene_, dir_ / (side + ".csv"), out_dir_ / "frames" / side, side);
    if (!err.empty()) result_.unavailable = err;
    return err.empty();
  }

  // Rows: every requested time that either side reached; PNGs are numbered in file order.
  void add_rows() {
    for (double a : asked_) {
      FrameRow row;
      const double ty = recorded(your_times_, a), tr = recorded(ref_times_, a);
      if (std::isnan(ty) && std::isnan(tr)) continue;
      row.time = std::isnan(tr) ? ty : tr;
      if (!std::isnan(ty)) row.yours = png("yours", index_of(your_times_, ty));
      if (!std::isnan(tr)) row.reference = png("reference", index_of(ref_times_, tr));
      const bool was_dropped = !std::isnan(recorded(dropped_, a));
      if (std::isnan(ty) && !your_times_.empty() && !was_dropped)
        result_.notes.push_back("your run stopped before t = " + fmt_time(a) + " s");
      result_.rows.push_back(row);
    }
  }

  const GradeConfig& config_;
  const CaseResult& course_;
  const std::string& scene_;
  const fs::path& out_dir_;
  const fs::path& work_;
  const fs::path dir_;
  CourseFrames& result_;
  std::vector<double> your_times_, dropped_, ref_times_, asked_;
};

}  // namespace

std::vector<double> write_replay_csv(const Json& outputs, const fs::path& path,
                                     std::vector<double>& dropped) {
  const std::vector<double> times = numbers(outputs, "frame_times");
  const std::vector<double> xs = numbers(outputs, "frame_positions");
  std::ofstream out(path);
  out << "frame,time,particle,x,y,z\n";
  std::vector<double> written;
  if (times.empty() || xs.size() % (3 * times.size()) != 0) return written;
  const std::size_t n = xs.size() / (3 * times.size());
  std::size_t frame = 0;  // numbered as written, so that frame k is frame_0000k.png
  char line[160];
  for (std::size_t f = 0; f < times.size(); ++f) {
    const double* x = xs.data() + 3 * n * f;
    bool finite = std::isfinite(times[f]);
    for (std::size_t k = 0; k < 3 * n && finite; ++k) finite = std::isfinite(x[k]);
    if (!finite) {
      dropped.push_back(times[f]);
      continue;
    }
    for (std::size_t i = 0; i < n; ++i) {
      std::snprintf(line, sizeof line, "%zu,%.17g,%zu,%.17g,%.17g,%.17g\n", frame, times[f], i,
                    x[3 * i], x[3 * i + 1], x[3 * i + 2]);
      out << line;
    }
    ++frame;
    written.push_back(times[f]);
  }
  return written;
}

CourseFrames render_course_frames(const GradeConfig& config, const GradeReport& report,
                                  const fs::path& out_dir, const fs::path& work) {
  CourseFrames result;
  const CaseResult* course = course_case(report);
  if (!course || !report.compiled) return result;
  result.shown = true;
  result.unavailable = frames_unavailable(config, *course);
  if (!result.unavailable.empty()) return result;
  try {
    FramesDrawing(config, *course, out_dir, work, result).draw();
  } catch (const std::exception& e) {
    result.unavailable = std::string("the frames could not be made: ") + e.what();
    result.rows.clear();
  }
  return result;
}

}  // namespace jelly::grade
