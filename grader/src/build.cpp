#include "build.hpp"

#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <fstream>
#include <mutex>
#include <regex>
#include <sstream>
#include <thread>

#include "cases.hpp"
#include "process.hpp"

namespace jelly::grade {

namespace {

// Digest of every header under the include folders inside the framework checkout or the build
// (system folders such as /usr/include are left out: too large, and they change with the compiler).
std::string framework_headers_digest(const GradeConfig& config) {
  std::vector<fs::path> files;
  const auto inside = [](const fs::path& dir, const fs::path& root) {
    if (root.empty()) return false;
    const std::string d = fs::weakly_canonical(dir).string(), r = fs::weakly_canonical(root).string();
    return d.compare(0, r.size(), r) == 0;
  };
  for (const std::string& inc : config.include_dirs) {
    std::error_code ec;
    if (!inside(inc, config.source_dir) && !inside(inc, config.binary_dir)) continue;
    for (fs::recursive_directory_iterator it(inc, ec), end; !ec && it != end; it.increment(ec)) {
      const std::string ext = it->path().extension().string();
      if (it->is_regular_file(ec) && (ext == ".hpp" || ext == ".h" || ext == ".hh" || ext == ".inl"))
        files.push_back(it->path());
    }
  }
  std::sort(files.begin(), files.end());
  std::string all;
  for (const fs::path& f : files) {
    std::ifstream in(f, std::ios::binary);
    std::ostringstream text;
    text << in.rdbuf();
    all += f.string() + "\n" + fnv_hex(text.str()) + "\n";
  }
  return fnv_hex(all);
}

std::string read_file(const fs::path& p) {
  std::ifstream in(p, std::ios::binary);
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

// The shallowest regular file (not a symlink) called `name` under `root`.
std::vector<fs::path> find_named(const fs::path& root, const std::string& name) {
  std::vector<fs::path> hits;
  std::error_code ec;
  for (auto it = fs::recursive_directory_iterator(root, fs::directory_options::skip_permission_denied, ec);
       it != fs::recursive_directory_iterator(); it.increment(ec)) {
    if (ec) break;
    if (it->is_symlink()) continue;
    if (it->is_regular_file() && it->path().filename() == name) hits.push_back(it->path());
  }
  std::sort(hits.begin(), hits.end(), [](const fs::path& a, const fs::path& b) {
    const auto da = std::distance(a.begin(), a.end()), db = std::distance(b.begin(), b.end());
    return da != db ? da < db : a < b;
  });
  return hits;
}

// Includes that could reach files outside the framework headers (e.g. the hidden reference data,
// whose text a compiler error would then print) are refused before compiling.
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
                "\" is not allowed in a graded file (only the standard library, Eigen and jelly/ headers)\n";
  }
  return errors;
}

std::string replace_all(std::string s, const std::string& from, const std::string& to) {
  if (from.empty()) return s;
  for (std::size_t p = s.find(from); p != std::string::npos; p = s.find(from, p + to.size()))
    s.replace(p, from.size(), to);
  return s;
}

}  // namespace

BuildResult build_submission(const GradeConfig& config, const fs::path& submission,
                             const fs::path& work_dir, int jobs) {
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
    std::vector<fs::path> hits = fs::is_directory(submission) ? find_named(submission, name) : std::vector<fs::path>{};
    fs::path from;
    if (hits.empty()) {
      from = config.assignments_dir() / name;
      r.used[name] = "stub";
      r.notes.push_back(name + " was not found in the submission: graded as the unchanged stub "
                               "(its tasks score 0)");
      shown[name] = name;
    } else {
      from = hits.front();
      const std::string rel = fs::relative(from, submission).string();
      r.used[name] = rel;
      shown[name] = rel;
      if (hits.size() > 1)
        r.notes.push_back("several files are called " + name + "; graded " + rel + " (the one nearest the top)");
    }
    const std::string text = read_file(from);
    policy_errors += include_policy(shown[name], text);
    std::ofstream(src / name, std::ios::binary) << text;
  }
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
  for (const std::string& b : base) flags_key += "\n" + b;
  // The framework's own headers are part of what an object was compiled from: a changed struct
  // (e.g. a new TaskTable member) must not reuse objects built against the old layout.
  flags_key += "\n" + framework_headers_digest(config);

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
      const fs::path cached = config.cache_dir() / (fnv_hex(flags_key + "\n" + name + "\n" + text) + ".o");
      const fs::path out = obj / (name + ".o");
      std::error_code ec;
      if (fs::exists(cached)) {
        fs::copy_file(cached, out, fs::copy_options::overwrite_existing, ec);
        if (!ec) continue;
      }
      std::vector<std::string> argv = base;
      argv.insert(argv.end(), {"-c", name, "-o", (obj / (name + ".o")).string()});
      Limits lim;
      lim.timeout_s = 300.0;
      lim.memory_bytes = 0;
      lim.limit_files = false;
      lim.result_pipe = false;
      lim.keep_output = 256 * 1024;
      const ChildResult c = run_child(argv, lim, src);
      std::lock_guard<std::mutex> lock(mutex);
      std::string msg = c.err + c.out;
      if (c.timed_out) msg += name + ": error: compiling took longer than 300 s\n";
      if (c.exit_code != 0 || c.signal != 0 || c.timed_out) {
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
        if (line.rfind(name + ":", 0) == 0 && rel != name) line = rel + line.substr(name.size());
        else line = replace_all(line, "from " + name + ":", "from " + rel + ":");
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
  Limits lim;
  lim.timeout_s = 120.0;
  lim.memory_bytes = 0;
  lim.limit_files = false;
  lim.result_pipe = false;
  const ChildResult c = run_child(argv, lim, work_dir);
  if (c.exit_code != 0 || c.signal != 0 || c.timed_out) {
    r.errors = tidy(replace_all(c.err + c.out, obj.string() + "/", ""));
    if (r.errors.empty()) r.errors = "linking failed\n";
  } else {
    r.ok = true;
  }
  r.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return r;
}

}  // namespace jelly::grade
