#include "grading/grade.hpp"

#if JELLY_HAVE_SECCOMP
#include <seccomp.h>
#endif

#include <algorithm>
#include <chrono>
#include <cmath>
#include <csignal>
#include <cstdio>
#include <fstream>
#include <optional>
#include <sstream>
#include <stdexcept>

#include "grading/hints.hpp"
#include "grading/parallel.hpp"
#include "grading/tolerance.hpp"
#include "reports/text_safety.hpp"

namespace jelly::grade {

namespace {

std::string fmt(double v) {
  char buf[40];
  std::snprintf(buf, sizeof buf, "%.10g", v);
  return buf;
}

// Entry k of n: " (y)" of a 3-vector, " [particle 4, y]" of a 3×N array whose columns the
// case calls `word` (its `element`, "particle" unless the case file says), else " [13]".
std::string element_name(std::size_t k, std::size_t n, const std::string& word) {
  static const char* axis[] = {"x", "y", "z"};
  if (n == 1) return "";
  if (n == 3) return std::string(" (") + axis[k] + ")";
  if (n % 3 == 0 && !word.empty())
    return " [" + word + " " + std::to_string(k / 3) + ", " + axis[k % 3] + "]";
  return " [" + std::to_string(k) + "]";
}

std::string describe_syscall_purpose(const std::string& name) {
  if (name.find("open") != std::string::npos || name == "creat") return "open a file";
  if (name.find("exec") != std::string::npos) return "start another program";
  if (name == "fork" || name == "vfork" || name.find("clone") != std::string::npos)
    return "start a process or thread";
  if (name == "socket" || name == "connect" || name == "bind" || name == "socketpair")
    return "use the network";
  if (name.find("io_uring") != std::string::npos) return "use asynchronous I/O (io_uring)";
  if (name == "ptrace" || name.find("process_vm") != std::string::npos)
    return "inspect another process";
  if (name.find("unlink") != std::string::npos || name.find("rename") != std::string::npos ||
      name.find("mkdir") != std::string::npos)
    return "change files or folders";
  if (name.find("kill") != std::string::npos) return "signal another process";
  return "make a system call the grader does not allow";
}

// Judges one output; appends failures. Returns false on failure.
bool judge(const std::string& name, const Json& mine, const Json& ref, const Rule& rule,
           const std::string& word, const std::map<std::string, Tolerance>& tols,
           std::vector<std::string>& failures) {
  const std::string note = ref.value("note", std::string());
  const std::string what = note.empty() ? name : name + " — " + note;
  if (rule.kind == Rule::Kind::Info) return true;
  const Json& r = ref.at("value");
  if (mine.is_null() || !mine.contains("value")) {
    failures.push_back(what + ": your code produced no value");
    return false;
  }
  const Json& m = mine.at("value");
  if (r.is_string()) {
    if (m != r) {
      failures.push_back(what + ": differs from the reference (expected " + r.get<std::string>() +
                         ", got " + (m.is_string() ? m.get<std::string>() : m.dump()) + ")");
      return false;
    }
    return true;
  }
  std::vector<double> a, b;
  auto flatten = [](const Json& j, std::vector<double>& out) {
    if (j.is_array())
      for (const Json& e : j) out.push_back(e.is_number() ? e.get<double>() : std::nan(""));
    else
      out.push_back(j.is_number() ? j.get<double>() : std::nan(""));
  };
  flatten(m, a);
  flatten(r, b);
  if (rule.kind == Rule::Kind::Range) {
    for (std::size_t k = 0; k < a.size(); ++k)
      if (!(a[k] >= rule.lo && a[k] <= rule.hi)) {
        failures.push_back(what + element_name(k, a.size(), word) + ": got " +
                           (std::isfinite(a[k]) ? fmt(a[k]) : std::string("NaN or infinity")) +
                           ", expected between " + fmt(rule.lo) + " and " + fmt(rule.hi));
        return false;
      }
    return true;
  }
  if (a.size() != b.size()) {
    failures.push_back(what + ": expected " + std::to_string(b.size()) + " numbers, got " +
                       std::to_string(a.size()));
    return false;
  }
  const Tolerance& tol = tols.at(rule.tolerance);
  std::size_t bad = 0, first = 0, worst = 0;
  double worst_excess = -1.0;
  for (std::size_t k = 0; k < a.size(); ++k) {
    const double allowed = allowed_difference(b[k], tol.atol, tol.rtol);
    const double diff = std::abs(a[k] - b[k]);
    if (!std::isfinite(a[k]) || !within_tolerance(a[k], b[k], tol.atol, tol.rtol)) {
      if (bad == 0) first = k;
      ++bad;
      const double excess =
          std::isfinite(diff) ? diff / (allowed > 0 ? allowed : 1e-300) : INFINITY;
      if (excess > worst_excess) worst_excess = excess, worst = k;
    }
  }
  if (bad == 0) return true;
  const std::size_t k = std::isfinite(a[first]) ? worst : first;
  std::string msg =
      what + element_name(k, a.size(), word) + ": expected " + fmt(b[k]) + ", got " +
      (std::isfinite(a[k]) ? fmt(a[k]) : std::string("NaN or infinity (not a number)"));
  if (std::isfinite(a[k]))
    msg += " (difference " + fmt(std::abs(a[k] - b[k])) + ", allowed " +
           fmt(allowed_difference(b[k], tol.atol, tol.rtol)) + " by tolerance '" + tol.name + "')";
  if (a.size() > 1)
    msg += "; " + std::to_string(bad) + " of " + std::to_string(a.size()) + " numbers differ";
  // What the value is made of, when the case says (e.g. which springs are missing or extra).
  if (a.size() == 1 && std::isfinite(a[0])) {
    const char* side = a[0] < b[0] ? "detail_low" : "detail_high";
    if (mine.contains(side) && mine.at(side).is_string())
      msg += "; " + mine.at(side).get<std::string>();
  }
  failures.push_back(msg);
  return false;
}

std::string mib(std::size_t bytes) {
  if (bytes >= (1ULL << 30) && bytes % (1ULL << 30) == 0)
    return std::to_string(bytes >> 30) + " GiB";
  return std::to_string(bytes >> 20) + " MiB";
}

// The caps of a test and what it left behind (isolation.hpp), in the student's terms.
std::vector<std::string> sandbox_problems(const ChildResult& c, std::size_t memory_bytes,
                                          const std::string& in_task) {
  std::vector<std::string> p;
  if (c.process_cap)
    p.push_back("your code tried to start more than " + std::to_string(kRunProcesses) +
                " processes or threads (the limit of one test; fork in a loop?)" + in_task);
  if (c.memory_cap)
    p.push_back("your code used more than " + mib(memory_bytes) +
                " of memory with all its processes together and was stopped" + in_task);
  if (c.leftover_processes > 0)
    p.push_back("your code left " + std::to_string(c.leftover_processes) +
                " process(es) running after the test ended (fork, setsid?); they were stopped" +
                in_task);
  if (c.leftover_files > 0)
    p.push_back("your code left " + std::to_string(c.leftover_files) +
                " file(s) in /tmp, /var/tmp or /dev/shm; they were removed (a test may not "
                "write files)" +
                in_task);
  if (c.pipes_held)
    p.push_back("a process of your code kept the test's output open after the test ended" +
                in_task);
  return p;
}

}  // namespace

std::string task_file_of(const TaskSpec& task) { return task.file; }

namespace {

// Everything a report shows that the submission controls, as valid UTF-8 without terminal
// controls: what its tests printed, its messages (exceptions, details, forged results), the
// compiler's messages about its code, its file and folder names.
void make_safe(GradeReport& rep) {
  rep.submission = safe_text(rep.submission);
  for (std::string& n : rep.notes) n = safe_text(n);
  rep.build.errors = safe_text(rep.build.errors);
  rep.build.warnings = safe_text(rep.build.warnings);
  rep.build.link_errors = safe_text(rep.build.link_errors);
  for (FileFailure& f : rep.failed_files) f.message = safe_text(f.message);
  for (CaseResult& c : rep.cases) {
    for (std::string& f : c.failures) f = safe_text(f);
    c.printed = safe_text(c.printed);
  }
}

// A run the stability detector stopped (contract §8; the runners' output "finished" is 0 then),
// said plainly instead of as its failed check ("reached 10 s without the detector firing: got 0,
// expected between 1 and 1"), first, since the case's other failures follow from it. When the run
// was sampled ("com_time": the last sample before the detector fired), it says when.
void say_blow_up_plainly(CaseResult& r) {
  const Json& mine = r.outputs.contains("finished") ? r.outputs["finished"] : Json();
  if (!mine.is_object() || !mine.contains("value") || !mine["value"].is_number() ||
      mine["value"].get<double>() != 0.0 || !r.reference.contains("finished"))
    return;
  const std::string name = "finished";
  const auto old = std::find_if(r.failures.begin(), r.failures.end(), [&](const std::string& f) {
    return f.rfind(name + " — ", 0) == 0 || f.rfind(name + ":", 0) == 0;
  });
  if (old == r.failures.end()) return;  // a case where stopping early passes
  std::string when;
  const Json& t = r.outputs.contains("com_time") ? r.outputs["com_time"] : Json();
  if (t.is_object() && t.contains("value") && t["value"].is_array() && !t["value"].empty() &&
      t["value"].back().is_number())
    when = " shortly after t = " + fmt(t["value"].back().get<double>()) + " s";
  else if (t.is_object() && t.contains("value") && t["value"].is_array())
    when = " before its first sample";
  const Json& d = r.spec->params.contains("duration") ? r.spec->params["duration"] : Json();
  const std::string of =
      d.is_number() ? " (the run was to last " + fmt(d.get<double>()) + " s)" : "";
  r.failures.erase(old);
  r.failures.insert(r.failures.begin(),
                    "the stability detector fired" + when + of +
                        ": the simulation blew up (its energy or positions ran away); this "
                        "test's other failures follow from that");
}

// The runner's result channel (file descriptor 3) read as JSON; `parsed` when it is an object.
Json read_result(const ChildResult& c, bool& parsed) {
  Json result;
  parsed = false;
  if (!c.result.empty()) {
    try {
      result = Json::parse(c.result);
      parsed = result.is_object();
    } catch (const std::exception&) {
    }
  }
  return result;
}

// Why a run is no result to judge ("" when it is one): it did not start, was stopped, crashed,
// ended early, threw, or its result is unreadable.
std::string run_problem(const ChildResult& c, const Json& result, bool parsed, double timeout,
                        const std::string& in_task) {
  const bool malformed = !c.result.empty() && !parsed;
  if (!c.started) return "the grader could not start your program: " + c.start_error;
  if (parsed && result.contains("forbidden_syscall") &&
      result["forbidden_syscall"].is_number_integer()) {
    const std::string name = syscall_name(result["forbidden_syscall"].get<int>());
    return "your code tried to " + describe_syscall_purpose(name) + " (system call " + name + ")" +
           in_task +
           "; reading or writing files, starting programs and networking are not allowed "
           "while grading";
  }
  if (c.timed_out)
    return "took longer than " + fmt(timeout) + " s and was stopped (an infinite loop?)" + in_task;
  if (c.output_flood)
    return "printed more than 64 MiB and was stopped (printing inside a loop?)" + in_task;
#ifdef SIGXCPU
  if (c.signal == SIGXCPU) return "used more than its CPU time limit (an infinite loop?)" + in_task;
#endif
  if (c.signal != 0) return "crashed with " + describe_signal(c.signal) + in_task;
  if (malformed)
    return "the test's result could not be read (something wrote to the grader's result "
           "channel, file descriptor 3?)" +
           in_task;
  if (!parsed && c.exit_code == 0)
    return "your code ended the program before the test finished (exit() called?)" + in_task;
  if (!parsed)
    return "the program ended with exit code " + std::to_string(c.exit_code) +
           " before the test finished (exit() called, or out of memory?)" + in_task;
  if (result.contains("error")) {
    std::string e =
        result["error"].is_string() ? result["error"].get<std::string>() : result["error"].dump();
    if (e.find("bad_alloc") != std::string::npos) e += " (more than the memory limit of 1 GiB?)";
    return e + in_task;
  }
  if (!result.contains("outputs") || !result["outputs"].is_object())
    return "the test's result has no outputs (something wrote to the grader's result channel, "
           "file descriptor 3?)" +
           in_task;
  return "";
}

// The kind of an abnormal end, as the reports group them ("" when none of them).
std::string abnormal_kind(const ChildResult& c, const Json& result, bool parsed,
                          const std::vector<std::string>& caps) {
  if (c.timed_out) return "timed out";
#ifdef SIGXCPU
  if (c.signal == SIGXCPU) return "timed out";
#endif
  if (!caps.empty() || (parsed && result.contains("forbidden_syscall")) || c.output_flood)
    return "refused";
  if (c.signal != 0) return "crashed";
  if (!parsed) return "ended early";
  if (result.contains("error")) return "threw";
  return "";
}

// Judges every reference output of `r` against its outputs.
void judge_outputs(CaseResult& r, const CaseBook& book) {
  bool ok = true;
  for (const auto& [name, refout] : r.reference.items()) {
    const Json mine = r.outputs.contains(name) ? r.outputs[name] : Json();
    ok = judge(name, mine.is_object() ? mine : Json(), refout, r.spec->rule_for(name),
               r.spec->element, book.tolerances, r.failures) &&
         ok;
  }
  if (!ok) say_blow_up_plainly(r);
  r.status = ok ? "passed" : "failed";
  r.score = ok ? r.max_score : 0.0;
}

// Runs case `r` with `runner` and judges it against `ref`. Throws on a result it cannot digest;
// the caller makes that the test's failure.
void run_and_judge(CaseResult& r, const Json& ref, const fs::path& runner, const CaseBook& book,
                   const fs::path& work_dir, const GradeOptions& options, int gid) {
  const TaskSpec* task = book.rubric.find(r.spec->task);
  const std::string in_task = task && !task->functions.empty() ? " in " + task->functions : "";
  const Json input = ref.contains("input") ? ref.at("input") : Json::object();
  const double timeout =
      r.spec->timeout_s > 0 ? std::max(r.spec->timeout_s, options.timeout_s) : options.timeout_s;
  const ChildResult c = run_case(runner, *r.spec, &input, work_dir, timeout, options.memory_bytes,
                                 false, &options.isolation, gid);
  r.seconds = c.seconds;
  r.reference = ref.at("outputs");
  // Cut on a character boundary; made safe to show by make_safe.
  r.printed = safe_excerpt(c.out, 2000);
  if (!c.err.empty()) r.printed += (r.printed.empty() ? "" : "\n") + safe_excerpt(c.err, 2000);
  bool parsed = false;
  const Json result = read_result(c, parsed);
  const std::string problem = run_problem(c, result, parsed, timeout, in_task);
  // What the run did to the machine fails the test whatever its outputs.
  const std::vector<std::string> caps = sandbox_problems(c, options.memory_bytes, in_task);
  if (!problem.empty() || !caps.empty()) {
    r.status = "failed";
    if (const std::string kind = abnormal_kind(c, result, parsed, caps); !kind.empty())
      r.abnormal = kind;
    r.failures = caps;
    if (!problem.empty()) r.failures.push_back(problem);
    return;
  }
  r.outputs = result.at("outputs");
  judge_outputs(r, book);
}

}  // namespace

Isolation own_machine_isolation() {
  Isolation iso;
  iso.description = "your own code on your own machine: no sandbox";
  return iso;
}

std::string syscall_name(int nr) {
#if JELLY_HAVE_SECCOMP
  char* name = seccomp_syscall_resolve_num_arch(SCMP_ARCH_NATIVE, nr);
  std::string s = name ? name : "syscall " + std::to_string(nr);
  std::free(name);
  return s;
#else
  return "syscall " + std::to_string(nr);  // only the seccomp sandbox reports system calls
#endif
}

ChildResult run_case(const fs::path& runner, const CaseSpec& spec, const Json* input,
                     const fs::path& work_dir, double timeout_s, std::size_t memory_bytes,
                     bool prepare, const Isolation* iso, int gid) {
  Json request = Json::object();
  request["case"] = spec.id;
  request["generator"] = spec.generator;
  request["params"] = spec.params;
  if (input && !input->empty()) request["input"] = *input;
  std::vector<std::string> argv = {runner.string(), "--request", "-", "--result-fd", "3"};
  if (prepare) argv.push_back("--prepare");
  Limits lim;
  lim.timeout_s = timeout_s;
  lim.memory_bytes = memory_bytes;
  lim.max_open_files = 64;
  lim.stdin_data = request.dump();
  if (!iso) return run_child(argv, lim, work_dir);  // the trusted reference
  SandboxView view;
  view.read_only = {runner};
  // bwrap: its private /tmp; user: a private empty folder of the run (no test finds a file another
  // test left); none: the work folder.
  if (iso->kind == IsolationKind::None) view.cwd = work_dir;
  view.gid = gid;
  return run_isolated(*iso, argv, view, lim);
}

namespace {

// The steps of grade_submission, in the order it takes them.

// Whether this copy of the grader has hidden reference data for the assignment (any file).
bool has_hidden_data(const GradeConfig& config) {
  std::error_code ec;
  for (fs::directory_iterator it(config.data_dir("hidden"), ec), end; !ec && it != end;
       it.increment(ec))
    if (it->path().extension() == ".json") return true;
  return false;
}

// 1. Selects the cases (rep.cases, in case-book order) and loads their reference data, one entry
//    per case (none for a skipped one). Grader errors (missing or stale data) throw here, before
//    anything is compiled.
std::vector<std::optional<Json>> select_cases(const GradeConfig& config, const CaseBook& book,
                                              const GradeOptions& options, GradeReport& rep) {
  const std::string digest = harness_digest(config);
  std::vector<std::optional<Json>> refs;
  for (const CaseSpec& c : book.cases) {
    CaseResult r;
    r.spec = &c;
    std::optional<Json> ref;
    if (c.hidden && !options.include_hidden) {
      r.status = "skipped";
    } else {
      ref = load_reference(config, c);
      if (!ref) {
        // A public case's data always ships. A hidden case's is missing from a copy of the grader
        // without hidden data (the note below says so); beside other hidden cases' data it is an
        // instructor's case whose data was never generated: an error, not a silent skip.
        if (!c.hidden || has_hidden_data(config))
          throw std::runtime_error(
              "reference data " + reference_path(config, c).string() + " is missing" +
              (c.hidden ? " (the other hidden cases have theirs)" : "") +
              "; run `jelly-grade generate-reference --assignment " + config.assignment().id + "`");
        r.status = "skipped";
      } else if (ref->value("format_version", 0) != kReferenceFormat) {
        throw std::runtime_error(reference_path(config, c).string() + ": format_version " +
                                 std::to_string(ref->value("format_version", 0)) +
                                 ", this grader reads " + std::to_string(kReferenceFormat) +
                                 "; run `jelly-grade generate-reference`");
      } else if (ref->value("harness_digest", std::string()) != digest) {
        throw std::runtime_error(
            reference_path(config, c).string() +
            " was generated from different case code (grader/runner changed); run "
            "`jelly-grade generate-reference`");
      } else if (ref->value("case_hash", std::string()) != case_hash(c, digest)) {
        throw std::runtime_error(
            reference_path(config, c).string() + " was generated for a different version of case " +
            c.id + " (its generator or params in " + (config.cases_dir() / c.source).string() +
            " changed); run `jelly-grade generate-reference`");
      }
    }
    rep.cases.push_back(std::move(r));
    refs.push_back(std::move(ref));
  }
  const bool hidden_missing =
      std::any_of(rep.cases.begin(), rep.cases.end(), [&](const CaseResult& r) {
        return r.status == "skipped" && r.spec->hidden && options.include_hidden;
      });
  if (hidden_missing)
    rep.notes.push_back(
        "hidden tests were not run: their reference data is not in this copy of the grader");
  if (!options.include_hidden)
    rep.notes.push_back(
        "only the public tests were run (--visibility public); the final grade also has hidden "
        "tests");
  return refs;
}

// 2. Builds the submission's runner (or takes the prebuilt one of --runner): rep.build,
//    rep.compiled and the build's notes.
void build_runner(const GradeConfig& config, const fs::path& submission, const fs::path& work_dir,
                  int jobs, int gid, const GradeOptions& options, GradeReport& rep) {
  if (!rep.isolation_warning.empty()) rep.notes.push_back("WARNING: " + rep.isolation_warning);
  if (options.runner.empty()) {
    rep.build = build_submission(config, submission, work_dir / "build", jobs, options.isolation,
                                 options.build_limits, gid);
  } else {
    // The self-check: CMake built the runner from the student's tasks (jelly-grade-student-runner).
    if (!fs::is_regular_file(options.runner))
      throw std::runtime_error(
          "--runner " + options.runner.string() +
          ": no such program (build the target jelly-grade-student-runner first)");
    rep.build.ok = true;
    rep.build.runner = fs::absolute(options.runner);
    rep.prebuilt_runner = true;
  }
  for (const std::string& n : rep.build.notes) rep.notes.push_back(n);
  rep.compiled = rep.build.ok && rep.build.failed_files.empty() && !rep.build.runner.empty();
}

// 3. Points: a task's points are shared by its selected cases in proportion to their weights
//    (rep.tasks, in rubric order, pointing into rep.cases).
void share_points(const CaseBook& book, GradeReport& rep) {
  const double scale = book.rubric.scale();
  for (const TaskSpec& t : book.rubric.tasks) {
    TaskResult tr;
    tr.spec = &t;
    rep.tasks.push_back(tr);
  }
  for (CaseResult& r : rep.cases) {
    for (TaskResult& t : rep.tasks)
      if (t.spec->id == r.spec->task) t.cases.push_back(&r);
  }
  for (TaskResult& t : rep.tasks) {
    double wsum = 0.0;
    for (CaseResult* c : t.cases)
      if (c->status != "skipped") wsum += c->spec->weight;
    t.max_score = wsum > 0 ? t.spec->points * scale : 0.0;
    for (CaseResult* c : t.cases)
      if (c->status != "skipped") c->max_score = t.max_score * c->spec->weight / wsum;
  }
}

// 4. A file that could not be used costs its own tasks only: the runner has its stub in its
//    place (rep.failed_files and their notes).
void note_failed_files(const GradeConfig& config, GradeReport& rep) {
  for (const std::string& file : config.task_files()) {
    const auto it = rep.build.failed_files.find(file);
    if (it == rep.build.failed_files.end()) continue;
    FileFailure f;
    f.file = file;
    f.message = it->second;
    f.what = rep.build.failed_what.count(file) ? rep.build.failed_what.at(file)
                                               : std::string("did not compile");
    for (const TaskResult& t : rep.tasks)
      if (task_file_of(*t.spec) == file) f.tasks.push_back(t.spec->id), f.points += t.max_score;
    std::string tasks;
    for (const std::string& t : f.tasks) tasks += (tasks.empty() ? "" : ", ") + t;
    char points[32];
    std::snprintf(points, sizeof points, "%.2f", f.points);
    rep.notes.push_back(
        file + " " + f.what + ": its tasks (" + tasks + ", " + points + " points) score 0" +
        (rep.build.ok
             ? "; the other files' tasks were graded with the stub of " + file + " in its place"
             : ""));
    rep.failed_files.push_back(f);
  }
  if (rep.build.ok && rep.build.runner.empty())
    rep.notes.push_back(
        "your files do not link together (see below): each file's tasks were graded with that "
        "file alone and the other files' stubs; the course scene, which needs all of them, was "
        "not run");
}

void not_run(CaseResult& r, const std::string& why, const std::string& message) {
  r.status = "failed";
  r.not_run = true;
  r.failures.push_back(why);
  if (!message.empty()) r.failures.push_back(message);
}

// 5a. One case: not run when its file could not be used or no runner has it, else run and
//     judged; whatever goes wrong is this test's failure.
void grade_case(CaseResult& r, const std::optional<Json>& ref, const CaseBook& book,
                const BuildResult& build, const fs::path& work_dir, const GradeOptions& options,
                int gid) {
  if (r.status == "skipped") return;  // the only cases without reference data
  const TaskSpec* task = book.rubric.find(r.spec->task);
  const std::string file = task ? task_file_of(*task) : "";
  if (!file.empty() && build.failed_files.count(file)) {
    const std::string& msg = build.failed_files.at(file);
    const std::string what =
        build.failed_what.count(file) ? build.failed_what.at(file) : std::string("did not compile");
    not_run(r,
            "not run: " + file + " " + what.substr(0, what.find(" (")) + ", so its tasks score 0",
            "the message about " + file + ":\n" + cut_utf8(msg, 3000));
    return;
  }
  const fs::path runner =
      !file.empty() && build.runners.count(file) ? build.runners.at(file) : build.runner;
  if (runner.empty()) {
    not_run(r,
            build.ok ? "not run: it needs all of your files, and they do not link "
                       "together"
                     : "not run: your code did not compile (see the compiler errors)",
            cut_utf8(build.ok ? build.link_errors : std::string(), 3000));
    return;
  }
  try {
    run_and_judge(r, *ref, runner, book, work_dir, options, gid);
  } catch (const std::exception& e) {
    r.status = "failed";
    r.score = 0.0;
    r.outputs = Json();
    r.failures.push_back(std::string("the grader could not digest this test's result (") +
                         e.what() + "); the test fails");
  } catch (...) {
    r.status = "failed";
    r.score = 0.0;
    r.outputs = Json();
    r.failures.push_back("the grader could not digest this test's result; the test fails");
  }
}

// 5. Runs every selected case, `jobs` at once (rep.grading_seconds).
void run_cases(const std::vector<std::optional<Json>>& refs, const CaseBook& book,
               const fs::path& work_dir, int jobs, int gid, const GradeOptions& options,
               GradeReport& rep) {
  const auto start = std::chrono::steady_clock::now();
  // Outside bwrap, runs at the same time share the machine (abstract sockets, the process list):
  // no hidden test runs while a public one does, so none can hand a hidden test's parameters
  // to a public test's output. bwrap gives every run its own namespaces.
  std::vector<std::size_t> phases[2];
  const bool separate = options.isolation.kind != IsolationKind::Bwrap;
  for (std::size_t i = 0; i < rep.cases.size(); ++i)
    phases[separate && rep.cases[i].spec->hidden ? 1 : 0].push_back(i);
  for (const std::vector<std::size_t>& phase : phases)
    parallel_for(phase.size(), jobs, [&](std::size_t k) {
      const std::size_t i = phase[k];
      grade_case(rep.cases[i], refs[i], book, rep.build, work_dir, options, gid);
    });
  rep.grading_seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

// 6. The task and total scores, sums of the cases' scaled shares; a bonus task's apart.
void add_up(GradeReport& rep) {
  for (TaskResult& t : rep.tasks) {
    for (CaseResult* c : t.cases) t.score += c->score;
    (t.spec->bonus ? rep.bonus_score : rep.score) += t.score;
    (t.spec->bonus ? rep.bonus_max : rep.max_score) += t.max_score;
  }
  // Sums of scaled shares: round to 1e-9 so that full marks print as full marks.
  auto tidy = [](double v) { return std::round(v * 1e9) / 1e9; };
  for (TaskResult& t : rep.tasks) t.score = tidy(t.score), t.max_score = tidy(t.max_score);
  rep.score = tidy(rep.score);
  rep.max_score = tidy(rep.max_score);
  rep.bonus_score = tidy(rep.bonus_score);
  rep.bonus_max = tidy(rep.bonus_max);
}

}  // namespace

GradeReport grade_submission(const GradeConfig& config, const CaseBook& book,
                             const fs::path& submission, const fs::path& requested_work_dir,
                             const GradeOptions& options) {
  // User mode: a private folder of the sandbox that no other submission's runs can read. Absolute:
  // the compiler, the linker and the runs start in other folders (`--out` may be relative).
  const Workspace workspace(options.isolation, fs::absolute(requested_work_dir));
  const fs::path& work_dir = workspace.dir();
  GradeReport rep;
  rep.submission = submission.string();
  rep.visibility = options.include_hidden ? "all" : "public";
  rep.isolation = options.isolation.name;
  rep.isolation_description = options.isolation.description;
  rep.isolation_warning = options.isolation.warning;
  const int jobs = worker_count(options.jobs);

  // A malformed hints.json is a grader error before anything runs, like stale reference data.
  const HintBook hints = options.hints ? load_hints(hints_path(config)) : HintBook();
  const std::vector<std::optional<Json>> refs = select_cases(config, book, options, rep);
  build_runner(config, submission, work_dir, jobs, workspace.gid(), options, rep);
  share_points(book, rep);
  note_failed_files(config, rep);
  run_cases(refs, book, work_dir, jobs, workspace.gid(), options, rep);
  add_up(rep);
  apply_hints(hints, book, harness_digest(config), rep);
  rep.contracts = config.assignment().manifest.contracts;
  const fs::path terms = config.assignments_dir() / "handout" / "reading-your-report.md";
  std::error_code ec;
  if (fs::is_regular_file(terms, ec)) {
    const fs::path rel =
        terms.lexically_normal().lexically_relative(config.source_dir.lexically_normal());
    rep.terms_page =
        rel.empty() || *rel.begin() == ".." ? terms.generic_string() : rel.generic_string();
  }
  make_safe(rep);
  return rep;
}

}  // namespace jelly::grade
