// Linux mechanisms only (bubblewrap, setuid/setgid, file modes); see isolation.hpp.
#include "isolation.hpp"

#include <pwd.h>
#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <cstdlib>
#include <iostream>
#include <stdexcept>

namespace jelly::grade {

namespace {

bool under(const fs::path& p, const fs::path& root) {
  const std::string a = p.lexically_normal().string(), b = root.lexically_normal().string();
  if (b == "/") return true;
  return a == b || (a.size() > b.size() && a.compare(0, b.size(), b) == 0 && a[b.size()] == '/');
}

fs::path absolute_clean(const fs::path& p) {
  std::error_code ec;
  fs::path a = fs::weakly_canonical(fs::absolute(p), ec);
  return ec ? fs::absolute(p).lexically_normal() : a;
}

std::string find_bwrap() {
  if (const char* env = std::getenv("JELLY_GRADE_BWRAP"))
    return env;  // another bwrap (tests: a broken one)
  for (const char* p : {"/usr/bin/bwrap", "/bin/bwrap", "/usr/local/bin/bwrap"})
    if (access(p, X_OK) == 0) return p;
  return "";
}

// Environment a sandboxed tool gets: a fixed PATH, the locale and the OpenMP thread count (same
// bits every run); nothing else of the grader's (tokens, paths) gets in.
std::vector<std::pair<std::string, std::string>> clean_env() {
  std::vector<std::pair<std::string, std::string>> env = {{"PATH", "/usr/bin:/bin"}};
  for (const char* name : {"LANG", "LC_ALL", "OMP_NUM_THREADS"})
    if (const char* v = std::getenv(name)) env.emplace_back(name, v);
  return env;
}

// bwrap's fixed part: namespaces, no capabilities, the toolchain read-only, a private /tmp.
std::vector<std::string> bwrap_base(const std::string& bwrap) {
  std::vector<std::string> a = {
      bwrap,   "--unshare-all", "--unshare-user", "--die-with-parent", "--new-session", "--uid",
      "65534", "--gid",         "65534"};
  if (geteuid() == 0) a.insert(a.end(), {"--cap-drop", "ALL"});
  a.insert(a.end(), {"--ro-bind", "/usr", "/usr"});
  for (const char* top : {"/bin", "/sbin", "/lib", "/lib32", "/lib64", "/libx32"}) {
    std::error_code ec;
    const fs::file_status st = fs::symlink_status(top, ec);
    if (ec || !fs::exists(st)) continue;
    if (fs::is_symlink(st))
      a.insert(a.end(), {"--symlink", fs::read_symlink(top, ec).string(), top});
    else if (fs::is_directory(st))
      a.insert(a.end(), {"--ro-bind", top, top});
  }
  // The dynamic loader's cache and the compiler's alternatives (/usr/bin/c++ -> /etc/alternatives).
  a.insert(a.end(), {"--ro-bind-try", "/etc/ld.so.cache", "/etc/ld.so.cache", "--ro-bind-try",
                     "/etc/alternatives", "/etc/alternatives", "--proc", "/proc", "--dev", "/dev",
                     "--tmpfs", "/tmp", "--clearenv"});
  for (const auto& [k, v] : clean_env()) a.insert(a.end(), {"--setenv", k, v});
  return a;
}

bool bwrap_works(const std::string& bwrap, std::string& why) {
  if (bwrap.empty()) {
    why = "bwrap is not installed (Debian package bubblewrap)";
    return false;
  }
  std::vector<std::string> argv = bwrap_base(bwrap);
  argv.insert(argv.end(), {"--chdir", "/tmp", "/usr/bin/true"});
  Limits lim;
  lim.timeout_s = 10.0;
  lim.memory_bytes = 0;
  lim.limit_files = false;
  lim.result_pipe = false;
  const ChildResult c = run_child(argv, lim);
  if (c.started && c.exit_code == 0) return true;
  why = bwrap + " cannot create a sandbox here (" +
        (c.err.empty() ? c.start_error : c.err.substr(0, c.err.find('\n'))) +
        "; user namespaces are often disabled in containers)";
  return false;
}

// The files only the grader may read.
std::vector<fs::path> secrets_of(const GradeConfig& config) {
  std::vector<fs::path> s = {config.data_dir(),
                             config.cases_dir(),
                             config.solutions_dir(),
                             config.cache_dir(),
                             config.grader_dir() / "mutants",
                             config.binary_dir / "grader" / "mutants",
                             config.binary_dir / "grader" / "generate",
                             config.source_dir / ".git"};
  if (!config.reference_runner.empty()) s.push_back(config.reference_runner);
  std::vector<fs::path> out;
  for (const fs::path& p : s) out.push_back(absolute_clean(p));
  return out;
}

}  // namespace

Isolation choose_isolation(const GradeConfig& config, const std::string& mode) {
  if (mode != "auto" && mode != "bwrap" && mode != "user" && mode != "none")
    throw std::runtime_error("--isolation must be auto, bwrap, user or none (got '" + mode + "')");
  Isolation iso;
  iso.secrets = secrets_of(config);
  std::string why_not_bwrap;
  if (mode == "auto" || mode == "bwrap") {
    const std::string bwrap = find_bwrap();
    if (bwrap_works(bwrap, why_not_bwrap)) {
      iso.kind = IsolationKind::Bwrap;
      iso.name = "bwrap";
      iso.bwrap = bwrap;
      iso.description =
          "bubblewrap sandbox (own user, mount, pid and network namespaces; the compiler and the "
          "tests see only the toolchain, the public headers and the submission)";
      return iso;
    }
    if (mode == "bwrap") throw std::runtime_error("--isolation bwrap: " + why_not_bwrap);
  }
  if (mode == "auto" || mode == "user") {
    if (geteuid() != 0) {
      if (mode == "user")
        throw std::runtime_error(
            "--isolation user needs jelly-grade to run as root (it drops to an unprivileged "
            "user for the compiler and the tests)");
    } else {
      const passwd* pw = getpwnam(kSandboxUser);
      if (!pw) pw = getpwnam("nobody");
      if (!pw || pw->pw_uid == 0)
        throw std::runtime_error(std::string("no user ") + kSandboxUser + " or nobody");
      iso.kind = IsolationKind::User;
      iso.name = "user";
      iso.user = pw->pw_name;
      iso.uid = static_cast<int>(pw->pw_uid);
      iso.gid = static_cast<int>(pw->pw_gid);
      // Root-only secrets: a folder 0700 cannot be entered by anyone else, whatever its files'
      // modes.
      for (const fs::path& s : iso.secrets) {
        struct stat st {};
        if (lstat(s.c_str(), &st) != 0) continue;
        if (static_cast<int>(st.st_uid) == iso.uid)
          throw std::runtime_error(s.string() + " belongs to " + iso.user +
                                   ", the user student code runs as");
        if (chmod(s.c_str(), S_ISDIR(st.st_mode) ? 0700 : 0700 & st.st_mode) != 0)
          throw std::runtime_error("cannot make " + s.string() + " readable by its owner only");
      }
      iso.description = "unprivileged user " + iso.user + " (uid " + std::to_string(iso.uid) +
                        "); the hidden data, case files and reference are readable by root only";
      if (!why_not_bwrap.empty()) iso.description += "; bubblewrap unusable: " + why_not_bwrap;
      return iso;
    }
  }
  iso.description = "none";
  // A student's copy of the grader (a release) has no hidden data and no solutions/: nothing to
  // warn about.
  bool secrets = fs::exists(config.solutions_dir()) || fs::exists(config.reference_runner);
  std::error_code ec;
  for (fs::directory_iterator it(config.data_dir() / "hidden", ec), end; !ec && it != end;
       it.increment(ec))
    secrets = true;
  if (!secrets) {
    iso.description = "none (this copy of the grader holds no hidden data and no solutions)";
    return iso;
  }
  iso.warning =
      "hidden tests are NOT protected: student code is compiled and run without isolation (" +
      (why_not_bwrap.empty() ? std::string("--isolation none") : why_not_bwrap) +
      (geteuid() == 0 ? "" : "; not root, so no unprivileged user either") +
      "). Install bubblewrap or grade as root.";
  std::cerr << "\n*** jelly-grade WARNING: " << iso.warning << " ***\n\n";
  return iso;
}

std::vector<std::string> isolate(const Isolation& iso, const std::vector<std::string>& argv,
                                 const SandboxView& view, Limits& limits) {
  if (iso.kind == IsolationKind::User) {
    limits.run_as_uid = iso.uid;
    limits.run_as_gid = iso.gid;
    limits.env.clear();
    for (const auto& [k, v] : clean_env()) limits.env.push_back(k + "=" + v);
    // Counted per user: with a dedicated user this bounds the processes and threads of all its
    // sandboxes together (bwrap runs as the grader's own user, where such a limit means nothing).
    if (limits.max_processes == 0) limits.max_processes = 512;
    return argv;
  }
  if (iso.kind != IsolationKind::Bwrap) return argv;
  std::vector<std::string> a = bwrap_base(iso.bwrap);
  std::vector<fs::path> bound = {"/usr"};
  auto bind = [&](const fs::path& raw, const char* how) {
    const fs::path p = absolute_clean(raw);
    if (!fs::exists(p)) return;
    for (const fs::path& b : bound)
      if (under(p, b) && std::string(how) == "--ro-bind") return;  // already visible
    a.insert(a.end(), {how, p.string(), p.string()});
    bound.push_back(p);
  };
  for (const fs::path& p : view.writable) bind(p, "--bind");
  for (const fs::path& p : view.read_only) bind(p, "--ro-bind");
  // A secret that happens to lie inside a bound folder is covered up.
  for (const fs::path& s : iso.secrets) {
    if (!fs::exists(s)) continue;
    if (std::none_of(bound.begin(), bound.end(), [&](const fs::path& b) { return under(s, b); }))
      continue;
    if (fs::is_directory(s))
      a.insert(a.end(), {"--tmpfs", s.string()});
    else
      a.insert(a.end(), {"--ro-bind", "/dev/null", s.string()});
  }
  if (!view.cwd.empty()) a.insert(a.end(), {"--chdir", absolute_clean(view.cwd).string()});
  a.insert(a.end(), argv.begin(), argv.end());
  return a;
}

ChildResult run_isolated(const Isolation& iso, const std::vector<std::string>& argv,
                         const SandboxView& view, Limits limits) {
  const std::vector<std::string> command = isolate(iso, argv, view, limits);
  ChildResult c = run_child(command, limits, view.cwd);
  // bwrap's own init reaps the tool and exits with 128 + the signal that ended it.
  if (iso.kind == IsolationKind::Bwrap && c.signal == 0 && c.exit_code > 128 &&
      c.exit_code <= 128 + 64) {
    c.signal = c.exit_code - 128;
    c.exit_code = -1;
  }
  return c;
}

void give_to_sandbox(const Isolation& iso, const fs::path& dir) {
  fs::create_directories(dir);
  if (iso.kind != IsolationKind::User) return;
  const fs::path abs = absolute_clean(dir);
  for (fs::path p = abs.parent_path(); !p.empty() && p != p.parent_path(); p = p.parent_path()) {
    struct stat st {};
    if (stat(p.c_str(), &st) == 0 && !(st.st_mode & S_IXOTH))
      throw std::runtime_error("the work folder " + abs.string() + " cannot be reached by user " +
                               iso.user + " (" + p.string() +
                               " is closed to other users): use --out in an open folder");
  }
  auto own = [&](const fs::path& p) {
    if (lchown(p.c_str(), static_cast<uid_t>(iso.uid), static_cast<gid_t>(iso.gid)) != 0)
      throw std::runtime_error("cannot give " + p.string() + " to user " + iso.user);
  };
  own(abs);
  for (const auto& e : fs::recursive_directory_iterator(abs)) own(e.path());
}

}  // namespace jelly::grade
