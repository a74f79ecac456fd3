#include "build.hpp"

#include <fcntl.h>
#include <signal.h>
#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <fstream>
#include <mutex>
#include <regex>
#include <sstream>
#include <thread>

#include "cases.hpp"
#include "files.hpp"
#include "process.hpp"

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

// The shallowest file called `name` under `root` (symbolic links included, so that they are
// refused with a message rather than silently ignored).
std::vector<fs::path> find_named(const fs::path& root, const std::string& name) {
  std::vector<fs::path> hits;
  std::error_code ec;
  for (auto it = fs::recursive_directory_iterator(
           root, fs::directory_options::skip_permission_denied, ec);
       it != fs::recursive_directory_iterator(); it.increment(ec)) {
    if (ec) break;
    if (it->path().filename() == name && !it->is_directory(ec)) hits.push_back(it->path());
  }
  std::sort(hits.begin(), hits.end(), [](const fs::path& a, const fs::path& b) {
    const auto da = std::distance(a.begin(), a.end()), db = std::distance(b.begin(), b.end());
    return da != db ? da < db : a < b;
  });
  return hits;
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

BuildResult build_submission(const GradeConfig& config, const fs::path& submission,
                             const fs::path& work_dir, int jobs, const Isolation& iso,
                             const BuildLimits& limits, int gid) {
  const auto start = std::chrono::steady_clock::now();
  BuildResult r;
  const fs::path src = work_dir / "src", obj = work_dir / "obj";
  fs::create_directories(src);
  fs::create_directories(obj);
  fs::create_directories(config.cache_dir());

  // 1. Take exactly the five task files.
  std::map<std::string, std::string> shown;  // task file → name shown in messages
  std::string policy_errors;
  for (const std::string& name : task_files()) {
    std::vector<fs::path> hits =
        fs::is_directory(submission) ? find_named(submission, name) : std::vector<fs::path>{};
    fs::path from;
    if (hits.empty()) {
      from = config.assignments_dir() / name;
      r.used[name] = "stub";
      r.notes.push_back(name +
                        " was not found in the submission: graded as the unchanged stub "
                        "(its tasks score 0)");
      shown[name] = name;
    } else {
      from = hits.front();
      const std::string rel = fs::relative(from, submission).string();
      r.used[name] = rel;
      shown[name] = rel;
      if (hits.size() > 1)
        r.notes.push_back("several files are called " + name + "; graded " + rel +
                          " (the one nearest the top)");
    }
    std::string refused;
    const std::string text = r.used[name] == "stub"
                                 ? read_file(from)
                                 : read_submitted(from, shown[name], limits.source_bytes, refused);
    policy_errors += refused;
    policy_errors += include_policy(shown[name], text);
    std::ofstream(src / name, std::ios::binary) << text;
  }
  give_to_sandbox(iso, work_dir, gid);
  if (!policy_errors.empty()) {
    r.errors = policy_errors;
    r.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    return r;
  }

  // 2. Compile (cached by content and flags), in parallel.
  std::string flags_key = config.compiler + "\n" + config.compiler_id;
  std::vector<std::string> base = {config.compiler};
  for (const std::string& f : config.compile_flags) base.push_back(f);
  for (const std::string& d : config.defines) base.push_back("-D" + d);
  for (const std::string& i : config.include_dirs) base.push_back("-I" + i);
  base.push_back("-fdiagnostics-color=never");
  // Messages without quoted source lines: filter_diagnostics decides what a student may see.
  base.push_back("-fno-diagnostics-show-caret");
  for (const std::string& b : base) flags_key += "\n" + b;
  // The framework's own headers are part of what an object was compiled from: a changed struct
  // (e.g. a new TaskTable member) must not reuse objects built against the old layout.
  flags_key += "\n" + framework_headers_digest(config);
  // What the compiler could see is part of what an object was compiled from: an object made without
  // a sandbox may hold any file of the machine (`.incbin`), and must never serve a sandboxed run.
  flags_key += "\nsandbox " + iso.name;

  // What the compiler may see and what of its messages a student may see.
  auto tool_limits = [&]() {
    Limits lim;
    lim.timeout_s = limits.timeout_s;
    lim.cpu_s = limits.cpu_s;
    lim.memory_bytes = limits.memory_bytes;
    lim.file_size_bytes = limits.file_bytes;
    lim.limit_files = true;
    lim.result_pipe = false;
    lim.keep_output = 256 * 1024;
    lim.kill_output = limits.output_bytes;
    lim.max_open_files = limits.open_files;
    return lim;
  };
  auto hint = [](const std::string& hit) -> std::string {
    if (hit.find("memory") != std::string::npos || hit.find("CPU") != std::string::npos ||
        hit.find("longer") != std::string::npos)
      return " (a template or constexpr computation that never ends?)";
    return "";
  };
  SandboxView compile_view;
  compile_view.writable = {work_dir};
  compile_view.cwd = src;
  compile_view.gid = gid;
  std::vector<fs::path> allowed = {src, "/usr/include", "/usr/lib/gcc", "/tmp"};
  for (const std::string& i : config.include_dirs) {
    compile_view.read_only.push_back(i);
    allowed.push_back(i);
  }

  std::mutex mutex;
  std::vector<std::string> queue = task_files();
  std::map<std::string, std::string> messages;
  bool failed = false;
  auto worker = [&]() {
    for (;;) {
      std::string name;
      {
        std::lock_guard<std::mutex> lock(mutex);
        if (queue.empty()) return;
        name = queue.front();
        queue.erase(queue.begin());
      }
      const std::string text = read_file(src / name);
      const fs::path cached =
          config.cache_dir() / (fnv_hex(flags_key + "\n" + name + "\n" + text) + ".o");
      const fs::path out = obj / (name + ".o");
      std::error_code ec;
      if (fs::exists(cached)) {
        fs::copy_file(cached, out, fs::copy_options::overwrite_existing, ec);
        if (!ec) continue;
      }
      std::vector<std::string> argv = base;
      argv.insert(argv.end(), {"-c", name, "-o", (obj / (name + ".o")).string()});
      Limits lim = tool_limits();
      const ChildResult c = run_isolated(iso, argv, compile_view, lim);
      std::lock_guard<std::mutex> lock(mutex);
      std::string msg = filter_diagnostics(c.err + c.out, src, allowed);
      const std::string hit = limit_hit("compiling " + name, c, c.err + c.out, limits);
      if (!hit.empty()) msg = name + ": error: " + hit + hint(hit) + "\n" + msg;
      if (!c.started)
        msg += name + ": error: the grader could not start the compiler: " + c.start_error + "\n";
      if (c.exit_code != 0 || c.signal != 0 || c.timed_out || !c.started) {
        failed = true;
        messages[name] = msg;
      } else {
        if (!msg.empty()) messages[name] = msg;  // warnings
        const fs::path tmp = cached.string() + ".tmp" + std::to_string(getpid()) + name;
        fs::copy_file(out, tmp, fs::copy_options::overwrite_existing, ec);
        if (!ec) fs::rename(tmp, cached, ec);
      }
    }
  };
  std::vector<std::thread> threads;
  for (int i = 0; i < std::max(1, jobs); ++i) threads.emplace_back(worker);
  for (std::thread& t : threads) t.join();

  auto tidy = [&](std::string text) {
    // Paths as the student knows them: relative to their submission, framework paths relative
    // to the framework.
    text = replace_all(text, src.string() + "/", "");
    text = replace_all(text, config.source_dir.string() + "/", "");
    std::string out;
    std::istringstream in(text);
    std::string line;
    while (std::getline(in, line)) {
      for (const auto& [name, rel] : shown)
        if (line.rfind(name + ":", 0) == 0 && rel != name)
          line = rel + line.substr(name.size());
        else
          line = replace_all(line, "from " + name + ":", "from " + rel + ":");
      out += line + "\n";
    }
    return out;
  };
  if (failed) {
    for (const std::string& name : task_files())
      if (messages.count(name)) r.errors += tidy(messages[name]);
    r.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    return r;
  }

  // 3. Link with the prebuilt runner main, task table, harness and core.
  std::vector<std::string> argv = {config.compiler};
  for (const std::string& name : task_files()) argv.push_back((obj / (name + ".o")).string());
  for (const std::string& o : config.link_objects) argv.push_back(o);
  for (const std::string& l : config.link_libraries) argv.push_back(l);
  for (const std::string& f : config.link_flags) argv.push_back(f);
  r.runner = work_dir / "runner";
  argv.insert(argv.end(), {"-o", r.runner.string()});
  Limits lim = tool_limits();
  SandboxView link_view;
  link_view.writable = {work_dir};
  link_view.cwd = work_dir;
  link_view.gid = gid;
  for (const std::string& o : config.link_objects) link_view.read_only.push_back(o);
  for (const std::string& l : config.link_libraries) link_view.read_only.push_back(l);
  const ChildResult c = run_isolated(iso, argv, link_view, lim);
  if (c.exit_code != 0 || c.signal != 0 || c.timed_out || !c.started) {
    const std::string hit = limit_hit("linking", c, c.err + c.out, limits);
    r.errors = tidy(
        replace_all(filter_diagnostics(c.err + c.out, work_dir, allowed), obj.string() + "/", ""));
    if (!hit.empty()) r.errors = "error: " + hit + "\n" + r.errors;
    if (!c.started)
      r.errors += "error: the grader could not start the linker: " + c.start_error + "\n";
    if (r.errors.empty()) r.errors = "linking failed\n";
  } else {
    r.ok = true;
  }
  seal_for_sandbox(iso, work_dir, gid);  // no test may change the runner or leave files for another
  r.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return r;
}

}  // namespace jelly::grade
