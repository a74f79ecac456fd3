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
  // The scene case: the last case that records frames (an output with rule "frames"); its frames
  // are drawn in the assignment's default scene (the manifest's default_scene).
  const auto records = [](const CaseSpec& spec) {
    for (const auto& [name, rule] : spec.rules)
      if (rule.kind == Rule::Kind::Frames) return true;
    return false;
  };
  const CaseResult* course = nullptr;
  for (const CaseResult& c : report.cases)
    if (records(*c.spec) && c.status != "skipped") course = &c;
  if (!course || !report.compiled) return result;
  result.shown = true;
  if (!course->spec->params.contains("frame_times")) {
    result.unavailable = "the course scene case records no frames (no frame_times in " +
                         (config.cases_dir() / course->spec->source).string() + ")";
    return result;
  }
  const std::string scene = config.assignment().manifest.default_scene;
  if (scene.empty()) {
    result.unavailable = "the assignment's manifest (" + config.rubric_path().string() +
                         ") names no default_scene to draw the frames in";
    return result;
  }
  if (config.jelly_cli.empty()) {
    result.unavailable =
        "this grader was built without the renderer (configure with -DJELLY_BUILD_VIEWER=ON, "
        "or set JELLY_GRADE_JELLY to a jelly program with `render --replay`)";
    return result;
  }
  std::error_code ec;
  if (!fs::exists(config.jelly_cli, ec)) {
    result.unavailable = config.jelly_cli.string() + " is missing (build the `jelly` target)";
    return result;
  }
  try {
    const fs::path dir = work / "frames";
    fs::remove_all(out_dir / "frames", ec);
    fs::create_directories(dir);
    // The student's frames (recorded in the sandbox; drawn here).
    std::vector<double> dropped;
    const std::vector<double> your_times =
        write_replay_csv(course->outputs, dir / "yours.csv", dropped);
    const bool yours = !your_times.empty();
    std::vector<double> ref_times;
    if (yours) {
      if (const std::string err = render(config.jelly_cli, scene, dir / "yours.csv",
                                         out_dir / "frames" / "yours", "yours");
          !err.empty()) {
        result.unavailable = err;
        return result;
      }
    }
    for (double t : dropped)
      result.notes.push_back("your frame at t = " + fmt_time(t) +
                             " s has NaN or infinity: not drawn");
    const std::vector<double> asked =
        course->spec->params["frame_times"].get<std::vector<double>>();
    if (!yours && dropped.empty())
      result.notes.push_back(
          course->outputs.is_null()
              ? "your run of the course scene produced no frames (it did not finish)"
              : "your run of the course scene recorded no frames (it stopped before t = " +
                    fmt_time(asked.empty() ? 0.0 : asked.front()) + " s)");
    // The reference's.
    std::string why;
    const Json ref = reference_frames(config, *course->spec, work, why);
    std::vector<double> ref_dropped;
    if (!ref.is_null() &&
        !(ref_times = write_replay_csv(ref, dir / "reference.csv", ref_dropped)).empty()) {
      if (const std::string err = render(config.jelly_cli, scene, dir / "reference.csv",
                                         out_dir / "frames" / "reference", "reference");
          !err.empty()) {
        result.unavailable = err;
        return result;
      }
    } else {
      result.notes.push_back("reference frames not available: " +
                             (why.empty() ? std::string("none recorded") : why));
    }
    // Rows: every requested time that either side reached; PNGs are numbered in file order.
    const auto index_of = [](const std::vector<double>& times, double t) -> long {
      for (std::size_t k = 0; k < times.size(); ++k)
        if (std::abs(times[k] - t) < 1e-9) return static_cast<long>(k);
      return -1;
    };
    char name[32];
    const auto png = [&](const char* side, long k) {
      std::snprintf(name, sizeof name, "frame_%05ld.png", k);
      return (fs::path("frames") / side / name).generic_string();
    };
    // Recorded times are the first step at or after each asked time: match within 10 ms.
    const auto recorded = [](const std::vector<double>& times, double asked_t) -> double {
      for (double t : times)
        if (t >= asked_t - 1e-9 && t < asked_t + 0.01) return t;
      return NAN;
    };
    for (double a : asked) {
      FrameRow row;
      const double ty = recorded(your_times, a), tr = recorded(ref_times, a);
      if (std::isnan(ty) && std::isnan(tr)) continue;
      row.time = std::isnan(tr) ? ty : tr;
      if (!std::isnan(ty)) row.yours = png("yours", index_of(your_times, ty));
      if (!std::isnan(tr)) row.reference = png("reference", index_of(ref_times, tr));
      const bool was_dropped = !std::isnan(recorded(dropped, a));
      if (std::isnan(ty) && yours && !was_dropped)
        result.notes.push_back("your run stopped before t = " + fmt_time(a) + " s");
      result.rows.push_back(row);
    }
    if (result.rows.empty() && result.unavailable.empty())
      result.unavailable = "neither run recorded a frame";
  } catch (const std::exception& e) {
    result.unavailable = std::string("the frames could not be made: ") + e.what();
    result.rows.clear();
  }
  return result;
}

}  // namespace jelly::grade
