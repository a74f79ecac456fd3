#include "build/build.hpp"

#include <fcntl.h>
#include <signal.h>
#include <sys/file.h>
#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <fstream>
#include <mutex>
#include <optional>
#include <regex>
#include <set>
#include <sstream>

#include "build/symbols.hpp"
#include "grading/parallel.hpp"
#include "inputs/cases.hpp"
#include "inputs/files.hpp"
#include "reports/text_safety.hpp"
#include "sandbox/process.hpp"

namespace jelly::grade {

namespace {

// Digest of every header under the include folders inside the framework checkout or the build
// (system folders such as /usr/include are left out: too large, and they change with the compiler).
std::string framework_headers_digest(const GradeConfig& config) {
  std::vector<fs::path> files;
  const auto inside = [](const fs::path& dir, const fs::path& root) {
    if (root.empty()) return false;
    const std::string d = fs::weakly_canonical(dir).string(),
                      r = fs::weakly_canonical(root).string();
    return d.compare(0, r.size(), r) == 0;
  };
  for (const std::string& inc : config.include_dirs) {
    std::error_code ec;
    if (!inside(inc, config.source_dir) && !inside(inc, config.binary_dir)) continue;
    for (fs::recursive_directory_iterator it(inc, ec), end; !ec && it != end; it.increment(ec)) {
      const std::string ext = it->path().extension().string();
      if (it->is_regular_file(ec) &&
          (ext == ".hpp" || ext == ".h" || ext == ".hh" || ext == ".inl"))
        files.push_back(it->path());
    }
  }
  std::sort(files.begin(), files.end());
  std::string all;
  for (const fs::path& f : files) {
    all += f.string() + "\n" + fnv_hex(read_file(f)) + "\n";
  }
  return fnv_hex(all);
}

// Reads a task file of the submission itself, never what it points to: no symbolic links
// (O_NOFOLLOW), no hard links (a second name of a grader file), no FIFOs or devices. "" and
// `refused` set otherwise.
std::string read_submitted(const fs::path& p, const std::string& shown, std::size_t max_bytes,
                           std::string& refused) {
  const int fd = open(p.c_str(), O_RDONLY | O_NOFOLLOW | O_NONBLOCK | O_CLOEXEC | O_NOCTTY);
  struct stat st {};
  if (fd < 0 || fstat(fd, &st) != 0) {
    refused = shown + ": error: " +
              (errno == ELOOP ? "is a symbolic link" : std::string("cannot be read")) +
              "; submit the file itself\n";
    if (fd >= 0) close(fd);
    return "";
  }
  std::string why;
  if (!S_ISREG(st.st_mode))
    why = "is not a regular file (a FIFO, device or socket)";
  else if (st.st_nlink > 1)
    why = "is a hard link (it has " + std::to_string(st.st_nlink) + " names)";
  else if (static_cast<std::size_t>(st.st_size) > max_bytes)
    why = "is larger than " + std::to_string(max_bytes >> 10) + " KiB";
  std::string text;
  if (why.empty()) {
    char buf[65536];
    ssize_t n;
    while ((n = read(fd, buf, sizeof buf)) > 0 && text.size() <= max_bytes)
      text.append(buf, static_cast<std::size_t>(n));
    if (text.size() > max_bytes) why = "is larger than " + std::to_string(max_bytes >> 10) + " KiB";
  }
  close(fd);
  if (!why.empty()) {
    refused = shown + ": error: " + why + "; submit the file itself\n";
    return "";
  }
  return text;
}

// Includes that name files outside the framework headers by a plain path are refused before
// compiling, with a clearer message than "file not found". A courtesy, not the defence: C++ has
// many other ways to name a file; the sandbox (isolation.hpp) is what keeps grader files
// unreadable.
std::string include_policy(const std::string& shown, const std::string& text) {
  static const std::regex inc(R"(^\s*#\s*include\s*[<"]([^>"]*)[>"])");
  std::istringstream in(text);
  std::string line, errors;
  int number = 0;
  while (std::getline(in, line)) {
    ++number;
    std::smatch m;
    if (!std::regex_search(line, m, inc)) continue;
    const std::string target = m[1];
    if (!target.empty() && (target[0] == '/' || target.find("..") != std::string::npos ||
                            target.find("data/") != std::string::npos))
      errors += shown + ":" + std::to_string(number) + ": error: #include \"" + target +
                "\" is not allowed in a graded file (only the standard library, Eigen and jelly/ "
                "headers)\n";
  }
  return errors;
}

// While it lives, an exclusive flock(2) on ARTEFACT.lock, a file beside a shared artefact of the
// cache (an object, a precompiled header): one builder of it at a time. The others wait, then find
// it made (the builder writes a temporary name and renames it), instead of each building it again:
// at the start of a batch every worker needs the same stubs and headers. flock holds between the
// threads of a batch (each opens its own file) and between processes sharing the cache (shards on
// one machine), and ends with its holder, whatever kills it. Where the lock file cannot be made
// (a read-only cache), nothing is held and each builds its own, as before.
class ArtefactLock {
 public:
  explicit ArtefactLock(const fs::path& artefact)
      : fd_(open((artefact.string() + ".lock").c_str(), O_RDWR | O_CREAT | O_CLOEXEC, 0644)) {
    if (fd_ >= 0)
      while (flock(fd_, LOCK_EX) != 0 && errno == EINTR) {
      }
  }
  ~ArtefactLock() {
    if (fd_ >= 0) close(fd_);  // releases the lock
  }
  ArtefactLock(const ArtefactLock&) = delete;
  ArtefactLock& operator=(const ArtefactLock&) = delete;

 private:
  int fd_;
};

std::string replace_all(std::string s, const std::string& from, const std::string& to) {
  if (from.empty()) return s;
  for (std::size_t p = s.find(from); p != std::string::npos; p = s.find(from, p + to.size()))
    s.replace(p, from.size(), to);
  return s;
}

std::string human_bytes(std::size_t b) {
  if (b >= (1ULL << 30) && b % (1ULL << 30) == 0) return std::to_string(b >> 30) + " GiB";
  if (b >= (1ULL << 20)) return std::to_string(b >> 20) + " MiB";
  return std::to_string(b >> 10) + " KiB";
}

std::string seconds(double s) {
  char b[32];
  std::snprintf(b, sizeof b, "%g", s);
  return b;
}

// When a compiler or linker run hit one of its limits: the student's terms, else "".
std::string limit_hit(const std::string& what, const ChildResult& c, const std::string& text,
                      const BuildLimits& lim) {
  auto has = [&](const char* s) { return text.find(s) != std::string::npos; };
  if (c.process_cap)
    return what + " started more than " + std::to_string(kRunProcesses) +
           " processes or threads and was stopped";
  if (c.memory_cap)
    return what + " used more than " + human_bytes(lim.memory_bytes) +
           " of memory (all its processes together) and was stopped";
  if (c.timed_out)
    return what + " took longer than " + seconds(lim.timeout_s) + " s and was stopped";
  if (c.output_flood)
    return what + " printed more than " + human_bytes(lim.output_bytes) +
           " of messages and was stopped";
  if (c.signal == SIGXCPU || has("CPU time limit exceeded"))
    return what + " used more than " + seconds(lim.cpu_s) + " s of CPU time and was stopped";
  if (c.signal == SIGXFSZ || has("File size limit exceeded"))
    return what + " wrote a file larger than " + human_bytes(lim.file_bytes) + " and was stopped";
  if (has("memory exhausted") || has("out of memory") || has("Cannot allocate memory") ||
      has("bad_alloc") || has("Killed signal") || c.signal == SIGKILL || c.signal == SIGSEGV)
    return what + " used more than " + human_bytes(lim.memory_bytes) + " of memory and was stopped";
  return "";
}

// Why a tool's run in the sandbox gave no usable answer, in a few words for a message.
std::string tool_failure(const ChildResult& c) {
  if (!c.started) return "it could not start: " + c.start_error;
  if (c.process_cap) return "the sandbox refused it a process";
  if (c.timed_out) return "it took longer than its time limit";
  if (c.signal != 0) return "ended by " + describe_signal(c.signal);
  std::string first = c.err.substr(0, c.err.find('\n'));
  if (first.size() > 200) first = first.substr(0, 200) + "...";
  return "exit status " + std::to_string(c.exit_code) + (first.empty() ? "" : ": " + first);
}

}  // namespace

std::string filter_diagnostics(const std::string& messages, const fs::path& cwd,
                               const std::vector<fs::path>& allowed) {
  // Where a line says it is: "PATH:LINE:..." or "In file included from PATH:LINE" / "from
  // PATH:LINE".
  static const std::regex located(
      R"(^(In file included from |\s+from )?([^:\s][^:]*):(\d+)(:\d+)?[:,])");
  static const std::regex context(R"(^([^:\s][^:]*): (In |At )[^:]*:$)");
  auto allowed_path = [&](const std::string& p) {
    if (p == "<command-line>" || p == "<built-in>") return true;
    const fs::path abs = (fs::path(p).is_absolute() ? fs::path(p) : cwd / p).lexically_normal();
    const std::string a = abs.string();
    // The compiler's own temporary files (the assembly of the submission, "/tmp/ccAbC123.s"):
    // named cc..., directly in /tmp (bwrap's private /tmp, or no sandbox) or directly in a run's
    // private TMPDIR (user mode: SCRATCH/jelly-grade-XXXXXX/run-N, isolation.cpp), never any other
    // file there (a checkout under /tmp is not the submission's).
    if (abs.filename().string().rfind("cc", 0) == 0) {
      const fs::path dir = abs.parent_path();
      if (dir == "/tmp") return true;
      const std::string run = dir.filename().string();
      if (run.rfind("run-", 0) == 0 && run.size() > 4 &&
          run.find_first_not_of("0123456789", 4) == std::string::npos &&
          dir.parent_path().filename().string().rfind("jelly-grade-", 0) == 0)
        return true;
    }
    for (const fs::path& dir : allowed) {
      const std::string d = dir.lexically_normal().string();
      if (a.size() > d.size() && a.compare(0, d.size(), d) == 0 &&
          (a[d.size()] == '/' || d.back() == '/'))
        return true;
    }
    return false;
  };
  std::istringstream in(messages);
  std::string line, out;
  bool hiding = false;
  while (std::getline(in, line)) {
    std::smatch m;
    if (std::regex_search(line, m, located)) {
      hiding = !allowed_path(m[2]);
      if (hiding) {
        out +=
            m[0].str() + " [hidden: a message about a file that is not part of your submission]\n";
        continue;
      }
    } else if (std::regex_search(line, m, context)) {
      hiding = !allowed_path(m[1]);
    }
    if (!hiding) out += line + "\n";
  }
  return out;
}

namespace {

// The nm next to the compiler (the same binutils as the linker), else the system's; "" if none.
std::string find_nm(const GradeConfig& config) {
  std::error_code ec;
  const fs::path real = fs::canonical(config.compiler, ec);
  std::vector<fs::path> candidates;
  if (!ec) candidates.push_back(real.parent_path() / "nm");
  candidates.push_back(fs::path(config.compiler).parent_path() / "nm");
  candidates.push_back("/usr/bin/nm");
  candidates.push_back("/bin/nm");
  for (const fs::path& c : candidates)
    if (fs::is_regular_file(c, ec) && access(c.c_str(), X_OK) == 0) return c.string();
  return "";
}

std::string nm_text(const std::string& nm, const std::vector<std::string>& files, bool dynamic) {
  std::vector<std::string> argv = {nm, "-P", "-A", "-g", "--defined-only"};
  if (dynamic) argv.push_back("-D");
  argv.insert(argv.end(), files.begin(), files.end());
  const Limits lim = trusted_tool_limits(60.0, 64 << 20);
  return run_child(argv, lim, {}).out;
}

// The symbols the framework's link inputs define (trusted files: nm runs outside the sandbox),
// read once per process.
const FrameworkSymbols& framework_symbols(const GradeConfig& config, const std::string& nm) {
  static std::mutex mutex;
  static std::map<std::string, FrameworkSymbols> cache;
  std::lock_guard<std::mutex> lock(mutex);
  std::vector<std::string> statics, shared;
  std::string key;
  for (const std::string& f : config.link_objects) statics.push_back(f), key += f + "\n";
  for (const std::string& f : config.link_libraries) {
    (f.find(".so") != std::string::npos ? shared : statics).push_back(f);
    key += f + "\n";
  }
  const auto it = cache.find(key);
  if (it != cache.end()) return it->second;
  FrameworkSymbols fw;
  std::string text = nm_text(nm, statics, false);
  if (!shared.empty()) text += nm_text(nm, shared, true);
  for (const auto& [file, syms] : parse_nm(text))
    for (const DefinedSymbol& s : syms) (s.weak() ? fw.weak : fw.strong).insert(s.name);
  return cache[key] = fw;
}

}  // namespace

namespace {

// A refused symbol as the student reads it: its C++ name from a line of `nm -p -C -P` ("NAME
// TYPE VALUE [SIZE]", spaces in NAME) with the mangled name after it, or the mangled name alone.
std::string shown_symbol_name(std::string cxx, const DefinedSymbol& symbol) {
  // Drop the hexadecimal fields, then the type.
  for (int field = 0; field < 2; ++field) {
    const auto sp = cxx.rfind(' ');
    if (sp == std::string::npos ||
        cxx.find_first_not_of("0123456789abcdef", sp + 1) != std::string::npos)
      break;
    cxx.resize(sp);
  }
  const std::string type_field = std::string(" ") + symbol.type;
  if (cxx.size() > type_field.size() &&
      cxx.compare(cxx.size() - type_field.size(), type_field.size(), type_field) == 0)
    cxx.resize(cxx.size() - type_field.size());
  else
    cxx.clear();
  return cxx.empty() || cxx == symbol.name ? symbol.name : cxx + " (" + symbol.name + ")";
}

// One submission's build: what its steps share, and the steps, in the order build_submission
// takes them.
class SubmissionBuild {
 public:
  SubmissionBuild(const GradeConfig& config, const fs::path& submission, const fs::path& work_dir,
                  const Isolation& iso, const BuildLimits& limits, int gid)
      : config_(config),
        submission_(submission),
        work_dir_(work_dir),
        iso_(iso),
        limits_(limits),
        gid_(gid),
        src_(work_dir / "src"),
        stubs_(work_dir / "stubs"),
        obj_(work_dir / "obj"),
        files_(config.task_files()) {
    fs::create_directories(src_);
    fs::create_directories(stubs_);
    fs::create_directories(obj_);
    fs::create_directories(config.cache_dir());
  }

  // 1. Take exactly the manifest's task files, and the stubs (assignments/<id>/) that stand in for
  // a file
  //    that cannot be used.
  void take_files(BuildResult& r) {
    for (const std::string& name : files_) {
      std::vector<fs::path> hits =
          fs::is_directory(submission_) ? find_named(submission_, name) : std::vector<fs::path>{};
      fs::path from;
      if (hits.empty() && fs::is_directory(submission_))
        if (const fs::path lms = find_lms_named(submission_, name); !lms.empty()) {
          hits.push_back(lms);
          r.notes.push_back(fs::relative(lms, submission_).generic_string() + " was graded as " +
                            name + " (a learning-management system's bulk-download name)");
        }
      if (hits.empty()) {
        from = config_.assignments_dir() / name;
        r.used[name] = "stub";
        r.notes.push_back(name +
                          " was not found in the submission: graded as the unchanged stub "
                          "(its tasks score 0)");
        shown_[name] = name;
      } else {
        from = hits.front();
        const std::string rel = fs::relative(from, submission_).string();
        r.used[name] = rel;
        shown_[name] = rel;
        if (hits.size() > 1)
          r.notes.push_back("several files are called " + name + "; graded " + rel +
                            " (the one nearest the top)");
      }
      std::string refused;
      const std::string text =
          r.used[name] == "stub"
              ? read_file(from)
              : read_submitted(from, shown_[name], limits_.source_bytes, refused);
      const std::string policy = refused + include_policy(shown_[name], text);
      if (!policy.empty()) {
        messages_[name] = policy;
        broken_[name] = "was refused";
      }
      std::ofstream(src_ / name, std::ios::binary) << text;
      std::ofstream(stubs_ / name, std::ios::binary) << read_file(config_.assignments_dir() / name);
    }
  }

  // 2. Compile (cached by content and flags), `jobs` at once: the submission's files and the
  //    stubs. Throws when a stub does not compile (a grader error).
  void compile_all(int jobs) {
    choose_flags();
    std::vector<CompileJob> compiles;  // started in this order
    for (const std::string& name : files_) {
      if (!broken_.count(name)) compiles.push_back({name, false});
      compiles.push_back({name, true});
    }
    std::mutex mutex;
    std::map<std::string, std::string> stub_failed;  // stub → what the compiler (or system) said
    parallel_for(compiles.size(), std::max(1, jobs), [&](std::size_t k) {
      const CompileJob& job = compiles[k];
      try {
        compile(job, mutex, stub_failed);
      } catch (const std::exception& e) {
        std::lock_guard<std::mutex> lock(mutex);
        if (job.stub) {
          stub_failed[job.name] = e.what();
        } else {
          broken_[job.name] = "did not compile";
          messages_[job.name] +=
              job.name + ": error: the grader could not compile it: " + std::string(e.what()) +
              "\n";
        }
      }
    });
    if (!stub_failed.empty()) {
      // Not the student's fault: the grader cannot stand a stub in for a broken file (assignments/
      // changed, or the machine could not run the compiler: processes or memory exhausted).
      std::string why;
      for (const auto& [name, message] : stub_failed) why += "\n  " + name + ": " + message;
      throw std::runtime_error(
          "the stubs in " + config_.assignments_dir().string() +
          " could not be compiled, so no stub can stand in for a broken file:" + why);
    }
  }

  // 3. The symbols each compiled file defines: only its task functions and its own helpers, never
  //    one of the grader's (nm, in the sandbox: the objects are the submission's).
  void check_symbols(BuildResult& r) {
#if defined(__linux__)
    const std::string nm = find_nm(config_);
#else
    const std::string nm;  // the policy reads ELF names (macOS prefixes every symbol with '_')
#endif
    if (nm.empty()) {
      r.notes.push_back(
          "the symbols of the submission were not checked (no nm for ELF objects here); the "
          "framework still comes first on the link line");
      return;
    }
    std::vector<std::string> argv = {nm, "-p", "-P", "-A", "-g", "--defined-only"};
    for (const std::string& name : files_) {
      if (!broken_.count(name)) argv.push_back(student_obj(name).filename().string());
      argv.push_back(stub_obj(name).filename().string());
    }
    SandboxView view;
    view.writable = {work_dir_};
    view.cwd = obj_;
    view.gid = gid_;
    Limits lim = tool_limits();
    lim.keep_output = 16 << 20;
    const ChildResult c = run_isolated(iso_, argv, view, lim);
    const auto defined = parse_nm(c.out);
    const std::string nm_failure = c.exit_code != 0 ? " (nm failed: " + tool_failure(c) + ")" : "";
    std::map<std::string, std::set<std::string>> own;
    std::map<std::string, std::string> task_of_symbol;
    for (const std::string& name : files_)
      if (defined.count(stub_obj(name).filename().string()))
        for (const DefinedSymbol& s : defined.at(stub_obj(name).filename().string()))
          if (!s.weak()) own[name].insert(s.name), task_of_symbol[s.name] = name;
    const FrameworkSymbols& fw = framework_symbols(config_, nm);
    for (const std::string& name : files_) {
      if (broken_.count(name)) continue;
      const std::string file = student_obj(name).filename().string();
      if (c.exit_code != 0 || !defined.count(file)) {
        broken_[name] = "could not be checked";
        messages_[name] = name + ": error: the grader could not list the symbols of " + name +
                          (nm_failure.empty() ? " (nm did not list them)" : nm_failure) +
                          "; its tasks were not run\n";
        continue;
      }
      std::map<std::string, std::string> others = task_of_symbol;
      for (const std::string& mine : own[name]) others.erase(mine);
      std::string why;
      std::vector<std::string> demangled;  // nm -C, in the same (symbol table) order
      const std::vector<DefinedSymbol>& syms = defined.at(file);
      for (std::size_t k = 0; k < syms.size(); ++k) {
        const std::string reason = refused_symbol(name, syms[k], own[name], others, fw);
        if (reason.empty()) continue;
        if (demangled.empty()) {
          const ChildResult d = run_isolated(
              iso_, {nm, "-p", "-C", "-P", "-g", "--defined-only", file}, view, tool_limits());
          std::istringstream in(d.out);
          for (std::string l; std::getline(in, l);) demangled.push_back(l);
        }
        const std::string shown_symbol =
            shown_symbol_name(k < demangled.size() ? demangled[k] : "", syms[k]);
        why += shown_[name] + ": error: defines the external symbol " + shown_symbol + ", which " +
               reason + ".\n";
        if (why.size() > 4000) break;
      }
      if (!why.empty()) {
        broken_[name] = "was refused (it defines a symbol it may not)";
        messages_[name] = why +
                          "  A graded file may define only its own task functions and helpers; put "
                          "helpers in an anonymous namespace or make them static.\n";
      }
    }
  }

  // 4. Link: the framework first (so that its definitions are the ones kept), the submission's
  //    usable files, the stubs in place of the broken ones, the libraries again for what the
  //    submission's code needs of them. When the files do not link together, each usable file
  //    is linked alone with the other stubs.
  void link_runners(BuildResult& r) {
    std::map<std::string, bool> all;
    for (const std::string& name : files_) all[name] = !broken_.count(name);
    std::string link_errors;
    const fs::path combined = work_dir_ / "runner";
    if (link(all, combined, link_errors)) {
      r.runner = combined;
      for (const std::string& name : files_)
        if (!broken_.count(name)) r.runners[name] = combined;
      return;
    }
    // The files do not link together (one calls a helper another file defines, or a helper that
    // is nowhere): each usable file is linked alone with the stubs, and graded with that runner.
    r.link_errors = link_errors;
    for (const std::string& name : files_) {
      if (broken_.count(name)) continue;
      std::map<std::string, bool> alone;
      for (const std::string& other : files_) alone[other] = other == name;
      std::string errors;
      const fs::path runner = work_dir_ / ("runner-" + name.substr(0, name.find('.')));
      if (link(alone, runner, errors)) {
        r.runners[name] = runner;
      } else {
        broken_[name] = "did not link";
        messages_[name] = name +
                          ": error: does not link with the framework and the other files' stubs "
                          "(does it use a function of another file that could not be used?):\n" +
                          errors;
      }
    }
  }

  // 5. What the student reads: each replaced file's messages, the warnings of the others.
  void collect_messages(BuildResult& r) {
    for (const std::string& name : files_) {
      if (!messages_.count(name)) continue;
      if (broken_.count(name))
        r.failed_files[name] = tidy(messages_[name]), r.failed_what[name] = broken_[name];
      else
        r.warnings += tidy(messages_[name]);
    }
    for (const std::string& name : files_)
      if (r.failed_files.count(name)) r.errors += r.failed_files[name];
    r.ok = !r.runners.empty();
  }

 private:
  struct CompileJob {
    std::string name;
    bool stub;
  };

  // One compile of compile_all: from the cache when the same text was compiled with the same
  // flags, else in the sandbox; a stub's failure goes to `stub_failed`, a submission file's to
  // broken_ and messages_ (under `mutex`).
  void compile(const CompileJob& job, std::mutex& mutex,
               std::map<std::string, std::string>& stub_failed) {
    const fs::path dir = job.stub ? stubs_ : src_;
    const std::string text = read_file(dir / job.name);
    const fs::path cached =
        config_.cache_dir() / (fnv_hex(flags_key_ + "\n" + job.name + "\n" + text) + ".o");
    const fs::path out = job.stub ? stub_obj(job.name) : student_obj(job.name);
    std::error_code ec;
    const auto reuse = [&] {
      return fs::exists(cached, ec) &&
             fs::copy_file(cached, out, fs::copy_options::overwrite_existing, ec);
    };
    if (reuse()) return;
    // Not cached: whoever else needs the same object now (the stubs, at the start of a batch)
    // waits for this compile and copies its result.
    const ArtefactLock building(cached);
    if (reuse()) return;
    std::vector<std::string> argv = base_;
    argv.insert(argv.end(), {"-c", job.name, "-o", out.string()});
    SandboxView view;
    view.writable = {work_dir_};
    view.read_only = include_views_;
    view.cwd = dir;
    view.gid = gid_;
    const ChildResult c = run_isolated(iso_, argv, view, tool_limits());
    const bool ok = c.exit_code == 0 && c.signal == 0 && !c.timed_out && c.started;
    // An object that compiled goes to the cache: a stub's too, or every submission that hands in
    // all five files would compile the five stubs again (only a submission that handed in a
    // stub unchanged used to put it there).
    const auto keep = [&] {
      const fs::path tmp = cached.string() + ".tmp" + std::to_string(getpid()) + job.name +
                           (job.stub ? ".stub" : "");
      fs::copy_file(out, tmp, fs::copy_options::overwrite_existing, ec);
      if (!ec) fs::rename(tmp, cached, ec);
    };
    if (job.stub) {
      if (ok) keep();
      std::lock_guard<std::mutex> lock(mutex);
      if (!ok) {
        const std::string hit = limit_hit("compiling the stub " + job.name, c, c.err, limits_);
        stub_failed[job.name] = !c.started ? "the compiler could not be started: " + c.start_error
                                : !hit.empty() ? hit
                                               : cut_utf8(c.err + c.out, 600);
      }
      return;
    }
    std::string msg = filter_diagnostics(c.err + c.out, src_, allowed_);
    const std::string hit = limit_hit("compiling " + job.name, c, c.err + c.out, limits_);
    if (!hit.empty()) msg = job.name + ": error: " + hit + hint(hit) + "\n" + msg;
    if (!c.started)
      msg += job.name + ": error: the grader could not start the compiler: " + c.start_error + "\n";
    std::lock_guard<std::mutex> lock(mutex);
    if (!ok) {
      broken_[job.name] = "did not compile";
      messages_[job.name] = msg.empty() ? job.name + ": error: compiling failed\n" : msg;
    } else {
      if (!msg.empty()) messages_[job.name] = msg;  // warnings
      keep();
    }
  }

  // The compiler's command line and the cache key of what an object was compiled from; what the
  // compiler may see and what of its messages a student may see.
  void choose_flags() {
    flags_key_ = config_.compiler + "\n" + config_.compiler_id;
    base_ = {config_.compiler};
    for (const std::string& f : config_.compile_flags) base_.push_back(f);
    for (const std::string& d : config_.defines) base_.push_back("-D" + d);
    for (const std::string& i : config_.include_dirs) base_.push_back("-I" + i);
    base_.push_back("-fdiagnostics-color=never");
    // Messages without quoted source lines: filter_diagnostics decides what a student may see.
    // GCC's spelling; Clang (and Apple's) has its own and stops at GCC's as an unknown argument.
    const bool clang = config_.compiler_id.find("Clang") != std::string::npos;
    base_.push_back(clang ? "-fno-caret-diagnostics" : "-fno-diagnostics-show-caret");
    for (const std::string& b : base_) flags_key_ += "\n" + b;
    // The framework's own headers are part of what an object was compiled from: a changed struct
    // (e.g. a new TaskTable member) must not reuse objects built against the old layout.
    flags_key_ += "\n" + framework_headers_digest(config_);
    // What the compiler could see is part of what an object was compiled from: an object made
    // without a sandbox may hold any file of the machine (`.incbin`), and must never serve a
    // sandboxed run.
    flags_key_ += "\nsandbox " + iso_.name;
    allowed_ = {src_, "/usr/include", "/usr/lib/gcc"};
    for (const std::string& i : config_.include_dirs) {
      include_views_.push_back(i);
      allowed_.push_back(i);
    }
    if (!clang) use_precompiled_headers();
  }

  // Most of a task file's compile is parsing the headers it includes first (its task header, the
  // framework, Eigen): ~0.9 of ~1.2 s of CPU. GCC reads a precompiled `H.gch` instead of the header
  // H when the #include of H is the first thing in the file and the .gch was made with the same
  // flags: the same code, byte for byte, as parsing H (GCC checks the flags and otherwise parses
  // H, so nothing changes for a file that starts otherwise). The headers the stubs include first
  // (the trusted framework's) are precompiled once per grader build and flags into the cache
  // (pch-KEY/<header>.gch), outside any sandbox (no student code in them), and put first on the
  // include path, read-only in the sandbox. Not in user mode, whose sandbox user cannot read the
  // grader's cache.
  void use_precompiled_headers() {
    if (iso_.kind == IsolationKind::User) return;
    const fs::path dir = config_.cache_dir() / ("pch-" + fnv_hex(flags_key_));
    bool any = false;
    for (const std::string& name : files_) {
      std::string header;
      try {
        header = first_include(read_file(config_.assignments_dir() / name));
      } catch (const std::exception&) {
        continue;
      }
      if (header.empty() || header.find("..") != std::string::npos) continue;
      fs::path source;
      for (const std::string& i : config_.include_dirs)
        if (std::error_code ec; fs::is_regular_file(fs::path(i) / header, ec)) {
          source = fs::path(i) / header;
          break;
        }
      if (source.empty()) continue;
      const fs::path gch = dir / (header + ".gch");
      std::error_code ec;
      std::optional<ArtefactLock> building;  // the workers of a batch build each header once
      if (!fs::is_regular_file(gch, ec)) {
        fs::create_directories(gch.parent_path(), ec);
        building.emplace(gch);
      }
      if (!fs::is_regular_file(gch, ec)) {
        const fs::path tmp = gch.string() + ".tmp" + std::to_string(getpid());
        std::vector<std::string> argv = base_;
        argv.insert(argv.end(), {"-x", "c++-header", source.string(), "-o", tmp.string()});
        Limits lim = tool_limits();
        lim.limit_files = false;  // a .gch is tens of MiB
        const ChildResult c = run_child(argv, lim, gch.parent_path());
        if (c.exit_code != 0 || c.signal != 0 || c.timed_out || !c.started) {
          fs::remove(tmp, ec);
          continue;
        }
        fs::rename(tmp, gch, ec);
        if (ec) continue;
      }
      any = true;
    }
    if (!any) return;
    base_.insert(base_.begin() + 1, "-I" + dir.string());
    include_views_.push_back(dir);
    flags_key_ += "\nprecompiled " + dir.filename().string();
  }

  // The header a C++ file includes first with #include "..." when nothing but blank lines and
  // comments come before it, or "".
  static std::string first_include(const std::string& text) {
    std::istringstream in(text);
    std::string line;
    bool comment = false;
    while (std::getline(in, line)) {
      std::size_t i = 0;
      for (;;) {
        i = line.find_first_not_of(" \t\r", i);
        if (i == std::string::npos) break;
        if (comment) {
          const std::size_t end = line.find("*/", i);
          if (end == std::string::npos) break;
          comment = false;
          i = end + 2;
        } else if (line.compare(i, 2, "/*") == 0) {
          comment = true;
          i += 2;
        } else {
          break;
        }
      }
      if (i == std::string::npos || comment || line.compare(i, 2, "//") == 0) continue;
      static const std::regex include(R"re(#\s*include\s*"([^"]+)"\s*(//.*)?)re");
      std::smatch m;
      const std::string rest = line.substr(i);
      return std::regex_match(rest, m, include) ? m[1].str() : std::string();
    }
    return "";
  }

  Limits tool_limits() const {
    Limits lim;
    lim.timeout_s = limits_.timeout_s;
    lim.cpu_s = limits_.cpu_s;
    lim.memory_bytes = limits_.memory_bytes;
    lim.file_size_bytes = limits_.file_bytes;
    lim.limit_files = true;
    lim.result_pipe = false;
    lim.keep_output = 256 * 1024;
    lim.kill_output = limits_.output_bytes;
    lim.max_open_files = limits_.open_files;
    return lim;
  }

  static std::string hint(const std::string& hit) {
    if (hit.find("memory") != std::string::npos || hit.find("CPU") != std::string::npos ||
        hit.find("longer") != std::string::npos)
      return " (a template or constexpr computation that never ends?)";
    return "";
  }

  fs::path student_obj(const std::string& name) const { return obj_ / (name + ".o"); }
  fs::path stub_obj(const std::string& name) const { return obj_ / ("stub-" + name + ".o"); }

  // Paths as the student knows them: relative to their submission, framework paths relative
  // to the framework.
  std::string tidy(std::string text) const {
    text = replace_all(text, src_.string() + "/", "");
    text = replace_all(text, obj_.string() + "/", "");
    text = replace_all(text, config_.source_dir.string() + "/", "");
    std::string out;
    std::istringstream in(text);
    std::string line;
    while (std::getline(in, line)) {
      for (const auto& [name, rel] : shown_)
        if (line.rfind(name + ":", 0) == 0 && rel != name)
          line = rel + line.substr(name.size());
        else
          line = replace_all(line, "from " + name + ":", "from " + rel + ":");
      out += line + "\n";
    }
    return out;
  }

  // Links the files `use_student` marks with the student's objects, the others with their stubs,
  // into `runner`; false with the messages in `errors` when it does not link.
  bool link(const std::map<std::string, bool>& use_student, const fs::path& runner,
            std::string& errors) const {
    std::vector<std::string> argv = {config_.compiler};
    for (const std::string& o : config_.link_objects) argv.push_back(o);
    for (const std::string& l : config_.link_libraries) argv.push_back(l);
    for (const std::string& name : files_)
      argv.push_back((use_student.at(name) ? student_obj(name) : stub_obj(name)).string());
    for (const std::string& l : config_.link_libraries) argv.push_back(l);
    for (const std::string& f : config_.link_flags) argv.push_back(f);
    argv.insert(argv.end(), {"-o", runner.string()});
    SandboxView view;
    view.writable = {work_dir_};
    view.cwd = work_dir_;
    view.gid = gid_;
    for (const std::string& o : config_.link_objects) view.read_only.push_back(o);
    for (const std::string& l : config_.link_libraries) view.read_only.push_back(l);
    const ChildResult c = run_isolated(iso_, argv, view, tool_limits());
    if (c.exit_code == 0 && c.signal == 0 && !c.timed_out && c.started) return true;
    const std::string hit = limit_hit("linking", c, c.err + c.out, limits_);
    errors = tidy(filter_diagnostics(c.err + c.out, work_dir_, allowed_));
    errors = replace_all(errors, "stub-", "the stub of ");
    if (!hit.empty()) errors = "error: " + hit + "\n" + errors;
    if (!c.started)
      errors += "error: the grader could not start the linker: " + c.start_error + "\n";
    if (errors.empty()) errors = "linking failed\n";
    return false;
  }

  const GradeConfig& config_;
  const fs::path& submission_;
  const fs::path& work_dir_;
  const Isolation& iso_;
  const BuildLimits& limits_;
  const int gid_;
  const fs::path src_, stubs_, obj_;
  const std::vector<std::string>& files_;
  std::map<std::string, std::string> shown_;     // task file → name shown in messages
  std::map<std::string, std::string> messages_;  // task file → why it cannot be used, or warnings
  std::map<std::string, std::string> broken_;    // task files replaced by their stub → why
  std::string flags_key_;                        // what an object is compiled from, but its text
  std::vector<std::string> base_;                // the compiler's command line, but its files
  std::vector<fs::path> allowed_;                // folders whose files a compiler message may quote
  std::vector<fs::path> include_views_;  // what the sandboxed compiler sees besides the sources
};

}  // namespace

BuildResult build_submission(const GradeConfig& config, const fs::path& submission,
                             const fs::path& work_dir, int jobs, const Isolation& iso,
                             const BuildLimits& limits, int gid) {
  const auto start = std::chrono::steady_clock::now();
  BuildResult r;
  SubmissionBuild build(config, submission, work_dir, iso, limits, gid);
  build.take_files(r);
  give_to_sandbox(iso, work_dir, gid);
  build.compile_all(jobs);
  build.check_symbols(r);
  build.link_runners(r);
  build.collect_messages(r);
  seal_for_sandbox(iso, work_dir, gid);  // no test may change the runner or leave files for another
  r.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return r;
}

}  // namespace jelly::grade
