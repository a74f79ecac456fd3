// Linux mechanisms only (bubblewrap, setuid/setgid, file modes, cgroups); see isolation.hpp.
#include "sandbox/isolation.hpp"
#include "sandbox/lane_keeper.hpp"

#include <fcntl.h>
#include <pwd.h>
#include <signal.h>
#include <sys/file.h>
#include <sys/msg.h>
#include <sys/resource.h>
#include <sys/sem.h>
#include <sys/shm.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <atomic>
#include <cerrno>
#include <chrono>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <functional>
#include <iostream>
#include <map>
#include <mutex>
#include <set>
#include <sstream>
#include <stdexcept>
#include <thread>

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

std::string read_small(const fs::path& p) {
  std::ifstream in(p);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

bool write_small(const fs::path& p, const std::string& text) {
  const int fd = open(p.c_str(), O_WRONLY | O_CLOEXEC);
  if (fd < 0) return false;
  const bool ok = write(fd, text.data(), text.size()) == static_cast<ssize_t>(text.size());
  close(fd);
  return ok;
}

// "KEY N" in a cgroup's events file (pids.events, memory.events, memory.oom_control); 0 if absent.
long long read_key(const fs::path& p, const std::string& key) {
  std::istringstream in(read_small(p));
  std::string k;
  long long v = 0;
  while (in >> k >> v)
    if (k == key) return v;
  return 0;
}

std::string find_bwrap() {
  if (const char* env = std::getenv("JELLY_GRADE_BWRAP"))
    return env;  // another bwrap (tests: a broken one)
  for (const char* p : {"/usr/bin/bwrap", "/bin/bwrap", "/usr/local/bin/bwrap"})
    if (access(p, X_OK) == 0) return p;
  return "";
}

std::string find_program(std::initializer_list<const char*> paths) {
  for (const char* p : paths)
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
  const Limits lim = trusted_tool_limits(10.0);
  const ChildResult c = run_child(argv, lim);
  if (c.started && c.exit_code == 0) return true;
  why = bwrap + " cannot create a sandbox here (" +
        (c.err.empty() ? c.start_error : c.err.substr(0, c.err.find('\n'))) +
        "; user namespaces are often disabled in containers)";
  return false;
}

// The files only the grader may read, known by name: hidden even inside folders a sandbox may see
// (bwrap covers them; in user mode they are closed on top of the deny-by-default walk below).
std::vector<fs::path> secrets_of(const GradeConfig& config) {
  // Every assignment's hidden data, cases, reference, mutants and reference runner (a draft's
  // too): a sandbox grading one assignment sees no other assignment's secrets either.
  std::vector<fs::path> s = {config.grader_dir() / "data",
                             config.source_dir / "solutions",
                             config.cache_dir(),
                             config.binary_dir / "grader" / "mutants",
                             config.binary_dir / "grader" / "generate",
                             config.binary_dir / "grader" / "gradescope-zip",
                             config.source_dir / ".git"};
  for (const std::vector<AssignmentConfig>* list : {&config.assignments, &config.draft_assignments})
    for (const AssignmentConfig& a : *list) {
      s.push_back(a.dir / "grader" / "cases");
      s.push_back(a.dir / "grader" / "mutants");
      s.push_back(a.solutions_dir);
      s.push_back(a.reference_dir);
      if (!a.reference_runner.empty()) s.push_back(a.reference_runner);
    }
  std::vector<fs::path> out;
  for (const fs::path& p : s) out.push_back(absolute_clean(p));
  return out;
}

// ---- cgroups: the caps of each run, and a list of every process it started ----

struct Cgroups {
  fs::path memory, pids, cpu;  // v1: our own folder (jelly-grade-PID) in each hierarchy
  fs::path unified;  // v2: our own folder; holds the memory, pids and cpu files where v2 has them
  bool v2_memory = false, v2_pids = false, v2_cpu = false;

  bool any() const { return !memory.empty() || !pids.empty() || !cpu.empty() || !unified.empty(); }
  std::vector<fs::path> dirs() const {
    std::vector<fs::path> d;
    for (const fs::path& p : {memory, pids, cpu, unified})
      if (!p.empty()) d.push_back(p);
    return d;
  }
  bool caps_memory() const { return !memory.empty() || v2_memory; }
  bool caps_pids() const { return !pids.empty() || v2_pids; }
};

// One core's time per 100 ms period for all the processes of the cgroup `dir` together.
bool write_cpu_quota(const fs::path& dir, bool v2) {
  if (v2) return write_small(dir / "cpu.max", "100000 100000");
  return write_small(dir / "cpu.cfs_period_us", "100000") &&
         write_small(dir / "cpu.cfs_quota_us", "100000");
}

// Whether a lane under `parent` can get its quota (tried on a folder made and removed).
bool quota_writable(const fs::path& parent, bool v2) {
  const fs::path probe = parent / "lane-probe";
  if (mkdir(probe.c_str(), 0755) != 0) return false;
  const bool ok = write_cpu_quota(probe, v2);
  rmdir(probe.c_str());
  return ok;
}

// Where the cgroup file systems are mounted (/proc/self/mountinfo): cgroup v2's mount and root,
// and the v1 memory, pids and cpu hierarchies' (controller -> (mount, root)).
struct CgroupMounts {
  fs::path v2_mount;
  std::string v2_root;
  std::map<std::string, std::pair<fs::path, std::string>> v1;
};

CgroupMounts cgroup_mounts() {
  CgroupMounts m;
  std::istringstream in(read_small("/proc/self/mountinfo"));
  std::string line;
  while (std::getline(in, line)) {
    const auto dash = line.find(" - ");
    if (dash == std::string::npos) continue;
    std::istringstream a(line.substr(0, dash)), b(line.substr(dash + 3));
    std::string id, parent, dev, root, mount, fstype, source, super;
    a >> id >> parent >> dev >> root >> mount;
    b >> fstype >> source >> super;
    if (fstype == "cgroup2") {
      m.v2_mount = mount;
      m.v2_root = root;
    } else if (fstype == "cgroup") {
      std::istringstream opts(super);
      std::string o;
      while (std::getline(opts, o, ','))
        if (o == "memory" || o == "pids" || o == "cpu") m.v1[o] = {mount, root};
    }
  }
  return m;
}

// The cgroups this process is in (/proc/self/cgroup): controller ("" for v2) -> path.
std::map<std::string, std::string> own_cgroups() {
  std::map<std::string, std::string> own;
  std::istringstream in(read_small("/proc/self/cgroup"));
  std::string line;
  while (std::getline(in, line)) {
    const auto c1 = line.find(':'), c2 = line.find(':', c1 + 1);
    if (c1 == std::string::npos || c2 == std::string::npos) continue;
    const std::string ctrls = line.substr(c1 + 1, c2 - c1 - 1), path = line.substr(c2 + 1);
    if (ctrls.empty()) own[""] = path;
    std::istringstream cs(ctrls);
    std::string c;
    while (std::getline(cs, c, ',')) own[c] = path;
  }
  return own;
}

// Our folder `mine` under the cgroup `path` of the hierarchy mounted at `mount` (whose root is
// `root`); "" when it cannot be made. The folders of a jelly-grade that is gone go first, every
// process in them killed (its keeper, killed with it, could not).
fs::path our_cgroup_folder(const fs::path& mount, const std::string& root, const std::string& path,
                           const std::string& mine) {
  std::string rel = path;
  if (root != "/" && rel.compare(0, root.size(), root) == 0) rel = rel.substr(root.size());
  const fs::path parent = mount / fs::path(rel).relative_path();
  std::error_code ec;
  for (fs::directory_iterator it(parent, ec), end; !ec && it != end; it.increment(ec)) {
    const std::string n = it->path().filename().string();
    if (n.rfind("jelly-grade-", 0) != 0 || n == mine) continue;
    const std::string pid = n.substr(12);
    if (pid.empty() || pid.find_first_not_of("0123456789") != std::string::npos) continue;
    if (kill(std::stoi(pid), 0) == 0 || errno != ESRCH) continue;
    end_cgroup_tree(it->path());
  }
  fs::path dir = parent / mine;
  if (mkdir(dir.c_str(), 0755) != 0 && errno != EEXIST) return fs::path();
  if (!fs::exists(dir / "cgroup.procs")) return fs::path();
  return dir;
}

// The v2 folder and the controllers it has: asks for the controllers our children need (refused
// where this cgroup holds processes and is not the root: then v2 only lists and kills).
void make_v2_cgroup(Cgroups& cg, const CgroupMounts& m, const std::string& own_path,
                    const std::string& mine) {
  const fs::path parent = m.v2_mount / fs::path(own_path).relative_path();
  for (const char* c : {"+memory", "+pids", "+cpu"})
    write_small(parent / "cgroup.subtree_control", c);
  cg.unified = our_cgroup_folder(m.v2_mount, m.v2_root, own_path, mine);
  if (cg.unified.empty()) return;
  for (const char* c : {"+memory", "+pids", "+cpu"})
    write_small(cg.unified / "cgroup.subtree_control", c);
  const std::string have = read_small(cg.unified / "cgroup.subtree_control");
  std::istringstream words(have);
  for (std::string w; words >> w;) {
    cg.v2_memory = cg.v2_memory || w == "memory";
    cg.v2_pids = cg.v2_pids || w == "pids";
    cg.v2_cpu = cg.v2_cpu || w == "cpu";
  }
}

// Our cgroups, made under the ones this process is in (so that a container's own limits still
// hold), when the kernel and our privileges allow: cgroup v2 where it has the controllers, else
// the v1 memory, pids and cpu hierarchies (as on a root shell of a cgroup v1 machine); a v2 folder
// is made even without controllers, to find and kill every process of a run.
Cgroups make_cgroups() {
  Cgroups cg;
  CgroupMounts m = cgroup_mounts();
  std::map<std::string, std::string> own = own_cgroups();
  const std::string mine = "jelly-grade-" + std::to_string(getpid());
  if (!m.v2_mount.empty() && own.count("")) make_v2_cgroup(cg, m, own[""], mine);
  auto v1 = [&](const std::string& c) {
    return our_cgroup_folder(m.v1[c].first, m.v1[c].second, own[c], mine);
  };
  if (!cg.v2_memory && m.v1.count("memory") && own.count("memory")) cg.memory = v1("memory");
  if (!cg.v2_pids && m.v1.count("pids") && own.count("pids")) cg.pids = v1("pids");
  if (!cg.v2_cpu && m.v1.count("cpu") && own.count("cpu")) cg.cpu = v1("cpu");
  // The CPU share is said to be in force only where a lane's quota can be written.
  cg.v2_cpu = cg.v2_cpu && quota_writable(cg.unified, true);
  if (!cg.cpu.empty() && !quota_writable(cg.cpu, false)) {
    rmdir(cg.cpu.c_str());
    cg.cpu.clear();
  }
  return cg;
}

std::vector<int> procs_of(const fs::path& dir) {
  std::vector<int> pids;
  std::istringstream in(read_small(dir / "cgroup.procs"));
  int p;
  while (in >> p) pids.push_back(p);
  return pids;
}

bool lookup_user(const std::string& name, int& uid, int& gid) {
  passwd pw{}, *found = nullptr;
  std::vector<char> buf(16384);
  if (getpwnam_r(name.c_str(), &pw, buf.data(), buf.size(), &found) != 0 || !found) return false;
  uid = static_cast<int>(pw.pw_uid);
  gid = static_cast<int>(pw.pw_gid);
  return true;
}

// The sandbox user `name`, made when missing (as setup.sh does).
void ensure_user(const std::string& name, int& uid, int& gid) {
  if (lookup_user(name, uid, gid)) return;
  const std::string useradd = find_program({"/usr/sbin/useradd", "/sbin/useradd"});
  if (useradd.empty())
    throw std::runtime_error("--isolation user: no user " + name +
                             " and no useradd to make it (create users " + kSandboxUser +
                             "-0, -1, ... one per core, as the Gradescope setup.sh does)");
  const Limits lim = trusted_tool_limits(30.0);
  const ChildResult c = run_child({useradd, "--system", "--no-create-home", "--user-group",
                                   "--shell", "/usr/sbin/nologin", name},
                                  lim);
  if (!lookup_user(name, uid, gid))
    throw std::runtime_error("--isolation user: cannot create the sandbox user " + name + ": " +
                             c.err + c.start_error);
  if (uid == 0) throw std::runtime_error("the sandbox user " + name + " has uid 0");
}

// One lane: what one run at a time uses (a sandbox user in user mode, its cgroups).
struct Lane {
  int index = 0;
  int user_index = -1;  // jelly-sandbox-N (kind User)
  int uid = -1, gid = -1;
  fs::path memory, pids, cpu, unified;  // this lane's cgroups (empty: none)
  bool v2_memory = false, v2_pids = false, v2_cpu = false;
  long long oom_before = 0, max_before = 0;

  std::vector<fs::path> dirs() const {
    std::vector<fs::path> d;
    for (const fs::path& p : {memory, pids, cpu, unified})
      if (!p.empty()) d.push_back(p);
    return d;
  }
  // One core's time per period, all the lane's processes together: a submission's busy processes
  // take no more than a core from the submissions graded beside it. False where it cannot be set.
  bool share_cpu() const {
    if (v2_cpu) return write_cpu_quota(unified, true);
    return !cpu.empty() && write_cpu_quota(cpu, false);
  }
  fs::path memory_dir() const { return v2_memory ? unified : memory; }
  fs::path pids_dir() const { return v2_pids ? unified : pids; }

  // Caps of the next run; notes the counters it will be judged by.
  void arm(std::size_t memory_bytes, std::size_t processes) {
    const fs::path m = memory_dir(), p = pids_dir();
    if (!m.empty()) {
      const std::string v =
          memory_bytes ? std::to_string(memory_bytes) : std::string(v2_memory ? "max" : "-1");
      if (v2_memory) {
        write_small(m / "memory.max", v);
        write_small(m / "memory.swap.max", "0");
        oom_before = read_key(m / "memory.events", "oom_kill");
      } else {
        // Lowering below what is charged (page cache of the last run) is refused: empty it first.
        if (!write_small(m / "memory.limit_in_bytes", v)) {
          write_small(m / "memory.force_empty", "0");
          write_small(m / "memory.limit_in_bytes", v);
        }
        if (fs::exists(m / "memory.memsw.limit_in_bytes")) {
          write_small(m / "memory.memsw.limit_in_bytes", v);
          write_small(m / "memory.limit_in_bytes", v);
        }
        oom_before = read_key(m / "memory.oom_control", "oom_kill");
      }
    }
    if (!p.empty()) {
      write_small(p / "pids.max", std::to_string(processes));
      max_before = read_key(p / "pids.events", "max");
    }
  }
  bool oom_hit() const {
    const fs::path m = memory_dir();
    if (m.empty()) return false;
    return read_key(m / (v2_memory ? "memory.events" : "memory.oom_control"), "oom_kill") >
           oom_before;
  }
  bool pids_hit() const {
    const fs::path p = pids_dir();
    return !p.empty() && read_key(p / "pids.events", "max") > max_before;
  }

  // Ends every process of the lane (its cgroups, its user) and waits until they are gone; the
  // number it found (0 in bwrap, whose pid namespace ends them anyway: what is found there is the
  // sandbox's own init on its way out).
  int end_all() {
    std::set<int> seen;
    for (int round = 0; round < 400; ++round) {
      std::set<int> now;
      for (const fs::path& d : dirs())
        for (int p : procs_of(d)) now.insert(p);
      // Every process of a run is in its cgroups (it cannot leave them); without cgroups, every
      // process of its sandbox user is looked for.
      const std::vector<int> mine =
          uid >= 0 && (dirs().empty() || round > 0) ? processes_of_user(uid) : std::vector<int>{};
      now.insert(mine.begin(), mine.end());
      if (now.empty()) break;
      if (!unified.empty()) write_small(unified / "cgroup.kill", "1");
      if (!mine.empty()) kill_user(uid);  // one pass over every process: no fork escapes it
      for (int p : now) {
        kill(p, SIGKILL);
        seen.insert(p);
      }
      // bwrap: what is left is the sandbox's own init on its way out of its pid namespace, which
      // takes every process of the run with it; no need to wait for it.
      if (!count_leftovers) break;
      std::this_thread::sleep_for(std::chrono::milliseconds(std::min(round + 1, 5)));
    }
    return count_leftovers ? static_cast<int>(seen.size()) : 0;
  }
  bool count_leftovers = true;

  // Whether anything of a run is still in one of the lane's cgroups: a process, or a zombie that
  // init has not reaped yet (bwrap's own init after every run, a killed run's orphans). A zombie
  // is no longer in cgroup.procs, but it counts against pids.max until it is reaped, which a
  // container's init does only every second or so, later on a busy machine.
  bool holds_processes() const {
    for (const fs::path& d : dirs())
      if (!procs_of(d).empty()) return true;
    const fs::path p = pids_dir();
    if (p.empty()) return false;
    std::istringstream current(read_small(p / "pids.current"));
    long long charged = 0;
    return current >> charged && charged > 0;
  }
};

}  // namespace

namespace {

// Files and System V IPC objects of `uid` in the folders every user may write to; removed, counted.
int remove_shared_leftovers(int uid) {
  int count = 0;
  std::function<void(const fs::path&, int)> sweep = [&](const fs::path& dir, int depth) {
    std::error_code ec;
    for (fs::directory_iterator it(dir, ec), end; !ec && it != end; it.increment(ec)) {
      struct stat st {};
      if (lstat(it->path().c_str(), &st) != 0) continue;
      if (static_cast<int>(st.st_uid) == uid) {
        std::error_code rc;
        count += static_cast<int>(fs::remove_all(it->path(), rc));
      } else if (S_ISDIR(st.st_mode) && (st.st_mode & S_IWOTH) && depth < 4) {
        sweep(it->path(), depth + 1);
      }
    }
  };
  for (const char* d : {"/tmp", "/var/tmp", "/dev/shm", "/dev/mqueue", "/run/lock", "/var/lock"})
    sweep(d, 0);
  // /proc/sysvipc/{shm,msg,sem}: the owner's uid is the column named "uid" (and "cuid").
  for (const char* kind : {"shm", "msg", "sem"}) {
    std::istringstream in(read_small(std::string("/proc/sysvipc/") + kind));
    std::string header, line;
    std::getline(in, header);
    std::vector<std::string> names;
    std::istringstream hs(header);
    for (std::string h; hs >> h;) names.push_back(h);
    while (std::getline(in, line)) {
      std::istringstream ls(line);
      std::map<std::string, long long> v;
      for (const std::string& n : names) {
        long long x = 0;
        ls >> x;
        v[n] = x;
      }
      if (v["uid"] != uid && v["cuid"] != uid) continue;
      const int id = static_cast<int>(std::string(kind) == "shm"   ? v["shmid"]
                                      : std::string(kind) == "msg" ? v["msqid"]
                                                                   : v["semid"]);
      if (std::string(kind) == "shm") shmctl(id, IPC_RMID, nullptr);
      if (std::string(kind) == "msg") msgctl(id, IPC_RMID, nullptr);
      if (std::string(kind) == "sem") semctl(id, 0, IPC_RMID);
      ++count;
    }
  }
  return count;
}

// ---- deny by default: the checkout and build tree closed to other users (kind User) ----

// Every mode we change is written to a root-only file first and restored by the last jelly-grade
// run that uses the tree (flock: shared while grading, exclusive to change or restore), so runs
// at the same time on one tree neither open it early nor keep it closed; a run that was killed
// leaves the tree closed (the safe side) and the file, which the next run restores from.
class TreeModes {
 public:
  void close(const GradeConfig& config, const std::vector<fs::path>& secrets) {
    const fs::path dir = absolute_clean(config.binary_dir / "grader");
    fs::create_directories(dir);
    file_ = dir / ".sandbox-modes";
    fd_ = open((dir / ".sandbox-lock").c_str(), O_CREAT | O_RDWR | O_CLOEXEC, 0600);
    if (fd_ < 0) throw std::runtime_error("cannot open " + (dir / ".sandbox-lock").string());
    if (flock(fd_, LOCK_EX | LOCK_NB) != 0) {
      flock(fd_, LOCK_SH);  // another run closed the tree and still grades: it stays closed
      return;
    }
    // Alone: a modes file left by a killed run holds the originals; the tree is closed (again).
    std::map<std::string, mode_t> saved = load();
    std::vector<std::pair<fs::path, mode_t>> changes;
    plan(config, secrets, changes);
    std::ofstream out(file_, std::ios::app);
    chmod(file_.c_str(), 0600);
    for (const auto& [p, m] : changes) {
      struct stat st {};
      if (lstat(p.c_str(), &st) != 0 || (st.st_mode & 07777) == m) continue;
      if (!saved.count(p.string()) && p.string().find('\n') == std::string::npos) {
        out << std::oct << (st.st_mode & 07777) << std::dec << '\t' << p.string() << '\n';
        saved[p.string()] = st.st_mode & 07777;
      }
    }
    out.flush();
    if (!out) throw std::runtime_error("cannot write " + file_.string());
    for (const auto& [p, m] : changes)
      if (chmod(p.c_str(), m) != 0 && errno != ENOENT)
        throw std::runtime_error("cannot close " + p.string() +
                                 " to other users: " + std::strerror(errno));
    flock(fd_, LOCK_SH);
  }

  ~TreeModes() {
    if (fd_ < 0) return;
    flock(fd_, LOCK_UN);
    if (flock(fd_, LOCK_EX | LOCK_NB) == 0) {
      for (const auto& [p, m] : load()) chmod(p.c_str(), m);
      std::error_code ec;
      fs::remove(file_, ec);
    }
    ::close(fd_);
  }

 private:
  std::map<std::string, mode_t> load() const {
    std::map<std::string, mode_t> m;
    std::ifstream in(file_);
    std::string line;
    while (std::getline(in, line)) {
      const auto tab = line.find('\t');
      if (tab == std::string::npos) continue;
      const std::string p = line.substr(tab + 1);
      if (!m.count(p)) m[p] = static_cast<mode_t>(std::stoul(line.substr(0, tab), nullptr, 8));
    }
    return m;
  }

  // What a submission's tools may read in the tree: the include folders, the objects and libraries
  // it is linked with, and the folders on the way to them (enter only, no listing). Everything
  // else, whatever it is (the reference runner, a runner built from solutions/, the reference task
  // library, the mutation table, a zip, staging folders, data, reports), gets no access for others.
  static void plan(const GradeConfig& config, const std::vector<fs::path>& secrets,
                   std::vector<std::pair<fs::path, mode_t>>& changes) {
    std::vector<fs::path> roots, allowed;
    for (const fs::path& r : {config.source_dir, config.binary_dir}) {
      const fs::path a = absolute_clean(r);
      if (std::none_of(roots.begin(), roots.end(), [&](const fs::path& x) { return under(a, x); }))
        roots.push_back(a);
    }
    roots.erase(std::remove_if(roots.begin(), roots.end(),
                               [&](const fs::path& r) {
                                 return std::any_of(
                                     roots.begin(), roots.end(),
                                     [&](const fs::path& x) { return x != r && under(r, x); });
                               }),
                roots.end());
    auto allow = [&](const std::string& p) {
      const fs::path a = absolute_clean(p);
      for (const fs::path& r : roots)
        if (under(a, r)) allowed.push_back(a);
    };
    for (const std::string& i : config.include_dirs) allow(i);
    for (const std::string& o : config.link_objects) allow(o);
    for (const std::string& l : config.link_libraries) allow(l);
    allow(config.compiler);
    auto is_allowed = [&](const fs::path& p) {
      return std::any_of(allowed.begin(), allowed.end(),
                         [&](const fs::path& a) { return under(p, a); });
    };
    auto leads_to_allowed = [&](const fs::path& p) {
      return std::any_of(allowed.begin(), allowed.end(),
                         [&](const fs::path& a) { return under(a, p); });
    };
    std::function<void(const fs::path&)> walk = [&](const fs::path& p) {
      struct stat st {};
      if (lstat(p.c_str(), &st) != 0 || S_ISLNK(st.st_mode)) return;
      const mode_t m = st.st_mode & 07777;
      if (is_allowed(p)) return;
      if (S_ISDIR(st.st_mode) && leads_to_allowed(p)) {
        changes.emplace_back(p, (m & ~(S_IROTH | S_IWOTH)) | S_IXOTH);
        std::error_code ec;
        for (fs::directory_iterator it(p, ec), end; !ec && it != end; it.increment(ec))
          walk(it->path());
      } else {
        changes.emplace_back(p, m & ~S_IRWXO);
      }
    };
    for (const fs::path& r : roots) walk(r);
    // The named secrets also where a public folder holds them (0700 for the owner alone).
    for (const fs::path& s : secrets) {
      struct stat st {};
      if (lstat(s.c_str(), &st) != 0 || S_ISLNK(st.st_mode)) continue;
      changes.emplace_back(s, st.st_mode & 07777 & ~(S_IRWXG | S_IRWXO));
    }
  }

  int fd_ = -1;
  fs::path file_;
};

}  // namespace

class SandboxPool {
 public:
  // Where there are lanes to keep (cgroups, sandbox users), their keeper is forked here, while
  // the grader has one thread: it ends them if the grader dies (lane_keeper.hpp).
  SandboxPool(IsolationKind kind, Cgroups cg) : kind_(kind), cg_(std::move(cg)) {
    if (cg_.any() || kind_ == IsolationKind::User) keeper_.start(cg_.dirs());
  }

  ~SandboxPool() {
    for (auto& l : lanes_) {
      l->end_all();
      for (const fs::path& d : l->dirs()) rmdir(d.c_str());
    }
    for (const fs::path& d : cg_.dirs()) rmdir(d.c_str());
    if (!scratch_.empty()) {
      std::error_code ec;
      fs::remove_all(scratch_, ec);
    }
    for (const auto& [n, fd] : claimed_) ::close(fd);
    // keeper_ goes last (declared first): it finds nothing left, and is waited for.
  }

  // User mode: the private scratch folder (root's, others may only enter it) and the closed tree.
  void prepare_user_mode(const GradeConfig& config, const std::vector<fs::path>& secrets) {
    const char* t = std::getenv("TMPDIR");
    std::string templ = std::string(t && *t ? t : "/tmp") + "/jelly-grade-XXXXXX";
    if (!mkdtemp(templ.data()))
      throw std::runtime_error("cannot make a scratch folder " + templ + ": " +
                               std::strerror(errno));
    scratch_ = absolute_clean(templ);
    chmod(scratch_.c_str(), 0711);
    for (fs::path p = scratch_.parent_path(); !p.empty() && p != p.parent_path();
         p = p.parent_path()) {
      struct stat st {};
      if (stat(p.c_str(), &st) == 0 && !(st.st_mode & S_IXOTH))
        throw std::runtime_error("the sandbox's scratch folder " + scratch_.string() +
                                 " cannot be reached by the sandbox users (" + p.string() +
                                 " is closed to other users): set TMPDIR to an open folder");
    }
    tree_.close(config, secrets);
  }

  const fs::path& scratch() const { return scratch_; }
  IsolationKind kind() const { return kind_; }
  const Cgroups& cgroups() const { return cg_; }
  unsigned next_id() { return counter_++; }

  Lane* acquire() {
    std::lock_guard<std::mutex> lock(mutex_);
    for (std::size_t i = 0; i < lanes_.size(); ++i)
      if (!busy_[i]) {
        busy_[i] = true;
        return lanes_[i].get();
      }
    // A retired lane whose remains are gone by now (still busy_: nobody else takes it).
    for (std::size_t i = 0; i < lanes_.size(); ++i)
      if (retired_[i] && !lanes_[i]->holds_processes()) {
        retired_[i] = false;
        return lanes_[i].get();
      }
    auto lane = std::make_unique<Lane>();
    lane->index = static_cast<int>(lanes_.size());
    if (kind_ == IsolationKind::User) {
      int n = 0;
      while (std::any_of(lanes_.begin(), lanes_.end(),
                         [&](const std::unique_ptr<Lane>& l) { return l->user_index == n; }) ||
             !claim_user(n))
        ++n;
      lane->user_index = n;
      ensure_user(std::string(kSandboxUser) + "-" + std::to_string(n), lane->uid, lane->gid);
      keeper_.tell_user(n, lane->uid);
    }
    open_cgroups(*lane);
    lane->count_leftovers = kind_ != IsolationKind::Bwrap;
    lanes_.push_back(std::move(lane));
    busy_.push_back(true);
    retired_.push_back(false);
    return lanes_.back().get();
  }
  void release(Lane* l) {
    std::lock_guard<std::mutex> lock(mutex_);
    // bwrap: end_all does not wait for the sandbox's init, which leaves its pid namespace after the
    // run and is a zombie until the container's init reaps it; a killed run's orphans are zombies
    // too. A lane whose cgroups still hold a process or a zombie is retired until they are gone:
    // they would count against the next run's caps (a fork bomb's remains, or the zombies of a
    // busy machine, made honest compiles "start more than 64 processes" and nm fail).
    const auto i = static_cast<std::size_t>(l->index);
    if (l->holds_processes()) {
      retired_[i] = true;
      return;
    }
    busy_[i] = false;
  }

  // A group for one submission: the primary group of a sandbox user, no other submission's.
  int acquire_group() {
    std::lock_guard<std::mutex> lock(mutex_);
    for (std::size_t i = 0;; ++i) {
      if (i == group_busy_.size()) {
        int n = group_users_.empty() ? 0 : group_users_.back() + 1;
        while (!claim_user(n)) ++n;
        int uid = -1, gid = -1;
        ensure_user(std::string(kSandboxUser) + "-" + std::to_string(n), uid, gid);
        group_users_.push_back(n);
        groups_.push_back(gid);
        group_busy_.push_back(false);
      }
      if (!group_busy_[i]) {
        group_busy_[i] = true;
        return groups_[i];
      }
    }
  }
  void release_group(int gid) {
    std::lock_guard<std::mutex> lock(mutex_);
    for (std::size_t i = 0; i < groups_.size(); ++i)
      if (groups_[i] == gid) group_busy_[i] = false;
  }

 private:
  // The lane's own cgroups under ours, with one core's quota.
  void open_cgroups(Lane& lane) {
    const std::string name = "lane-" + std::to_string(lane.index);
    auto sub = [&](const fs::path& base) {
      if (base.empty()) return fs::path();
      const fs::path d = base / name;
      return (mkdir(d.c_str(), 0755) == 0 || errno == EEXIST) ? d : fs::path();
    };
    lane.memory = sub(cg_.memory);
    lane.pids = sub(cg_.pids);
    lane.unified = sub(cg_.unified);
    lane.v2_memory = cg_.v2_memory && !lane.unified.empty();
    lane.v2_pids = cg_.v2_pids && !lane.unified.empty();
    lane.cpu = sub(cg_.cpu);
    lane.v2_cpu = cg_.v2_cpu && !lane.unified.empty();
    lane.share_cpu();
    // The lanes together weigh as much as as many ordinary processes (a nested cgroup weighs as
    // one): grading keeps its share of a machine busy with other work.
    const std::size_t lanes = lanes_.size() + 1;
    if (cg_.v2_cpu)
      write_small(cg_.unified / "cpu.weight",
                  std::to_string(std::min<std::size_t>(100 * lanes, 10000)));
    else if (!cg_.cpu.empty())
      write_small(cg_.cpu / "cpu.shares", std::to_string(1024 * lanes));
  }

  // Sandbox user N serves one jelly-grade process at a time (a lock file per user, held until the
  // end): two gradings on one machine never share a user, so neither kills the other's processes
  // nor reads the other's files. A process may use its users both for lanes and for groups.
  bool claim_user(int n) {
    if (claimed_.count(n)) return true;
    if (n > 4096) throw std::runtime_error("--isolation user: no free sandbox user");
    const fs::path dir = lock_dir();
    const int fd = open((dir / ("user-" + std::to_string(n) + ".lock")).c_str(),
                        O_CREAT | O_RDWR | O_CLOEXEC | O_NOFOLLOW, 0600);
    if (fd < 0) throw std::runtime_error("cannot open a lock file in " + dir.string());
    if (flock(fd, LOCK_EX | LOCK_NB) != 0) {
      ::close(fd);
      return false;
    }
    claimed_[n] = fd;
    // Whatever a dead grader's run left as this user (its keeper found the lock taken) ends now:
    // the user is ours alone from here on.
    int uid = -1, gid = -1;
    if (lookup_user(std::string(kSandboxUser) + "-" + std::to_string(n), uid, gid) && uid > 0)
      for (int round = 0; round < 50 && !processes_of_user(uid).empty(); ++round) kill_user(uid);
    return true;
  }
  static fs::path lock_dir() { return sandbox_lock_dir(true); }

  LaneKeeper keeper_;  // first: destroyed last, after the lanes are ended and the locks released
  IsolationKind kind_;
  Cgroups cg_;
  std::map<int, int> claimed_;  // user number -> its lock file
  std::vector<int> group_users_;
  fs::path scratch_;
  TreeModes tree_;
  std::mutex mutex_;
  std::vector<std::unique_ptr<Lane>> lanes_;
  std::vector<bool> busy_;
  std::vector<bool> retired_;  // busy until what its last run left is gone (release)
  std::vector<int> groups_;
  std::vector<bool> group_busy_;
  std::atomic<unsigned> counter_{0};
};

namespace {

std::string describe_caps(const Cgroups& cg, IsolationKind kind, bool prlimit) {
  const std::string n = std::to_string(kRunProcesses);
  std::string mem, procs;
  if (cg.v2_memory)
    mem = "memory of all its processes together (cgroup v2 memory.max)";
  else if (!cg.memory.empty())
    mem = "memory of all its processes together (cgroup v1 memory.limit_in_bytes)";
  else
    mem = "memory per process only (RLIMIT_AS; no memory cgroup available)";
  if (cg.v2_pids)
    procs = n + " processes and threads (cgroup v2 pids.max)";
  else if (!cg.pids.empty())
    procs = n + " processes and threads (cgroup v1 pids.max)";
  else if (kind == IsolationKind::User)
    procs = n + " processes and threads per sandbox user (RLIMIT_NPROC; no pids cgroup)";
  else if (kind == IsolationKind::Bwrap && prlimit)
    procs = n + " processes and threads in the sandbox's user namespace (RLIMIT_NPROC)";
  else
    procs = "no process cap (no pids cgroup)";
  const std::string cpu = cg.v2_cpu         ? "one core's time (cgroup v2 cpu.max)"
                          : !cg.cpu.empty() ? "one core's time (cgroup v1 cpu.cfs_quota_us)"
                                            : "no CPU share per lane: no cpu cgroup";
  std::string kill = cg.any()                      ? "leftover processes found by cgroup"
                     : kind == IsolationKind::User ? "leftover processes found by user"
                     : kind == IsolationKind::Bwrap
                         ? "leftover processes end with the pid namespace"
                         : "leftover processes not tracked";
  return "per compile and per test: " + mem + ", " + procs + ", " + cpu + "; " + kill;
}

struct LaneLease {
  SandboxPool* pool;
  Lane* lane = nullptr;
  explicit LaneLease(SandboxPool* p) : pool(p) {
    if (pool) lane = pool->acquire();
  }
  ~LaneLease() {
    if (lane) pool->release(lane);
  }
};

}  // namespace

Isolation choose_isolation(const GradeConfig& config, const std::string& mode) {
  if (mode != "auto" && mode != "bwrap" && mode != "user" && mode != "none")
    throw std::runtime_error("--isolation must be auto, bwrap, user or none (got '" + mode + "')");
  // Whatever a grader that is gone left running as a sandbox user ends first, in every mode (its
  // cgroups are swept by make_cgroups).
  sweep_abandoned_users();
  Isolation iso;
  iso.secrets = secrets_of(config);
  const bool prlimit = !find_program({"/usr/bin/prlimit"}).empty();
  auto finish = [&](IsolationKind kind) {
    iso.pool = std::make_shared<SandboxPool>(kind, make_cgroups());
    iso.caps = describe_caps(iso.pool->cgroups(), kind, prlimit);
    if (kind == IsolationKind::User) iso.pool->prepare_user_mode(config, iso.secrets);
    iso.description += "; " + iso.caps;
    return iso;
  };
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
      return finish(iso.kind);
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
      iso.kind = IsolationKind::User;
      iso.name = "user";
      iso.user = std::string(kSandboxUser) + "-N";
      iso.description = "unprivileged users " + std::string(kSandboxUser) +
                        "-0, -1, ... (one per concurrent run); the checkout and the build tree "
                        "are closed to them except the public headers and the objects a "
                        "submission is linked with; a private temporary folder per run";
      if (!why_not_bwrap.empty()) iso.description += "; bubblewrap unusable: " + why_not_bwrap;
      return finish(iso.kind);
    }
  }
  iso.description = "none";
  // A student's copy of the grader (a release) has no hidden data and no solutions/: nothing to
  // warn about.
  bool secrets = false;
  for (const std::vector<AssignmentConfig>* list : {&config.assignments, &config.draft_assignments})
    for (const AssignmentConfig& a : *list) {
      secrets = secrets || fs::exists(a.solutions_dir) || fs::exists(a.reference_dir) ||
                fs::exists(a.reference_runner);
      std::error_code ec;
      for (fs::directory_iterator it(config.grader_dir() / "data" / a.id / "hidden", ec), end;
           !ec && it != end; it.increment(ec))
        secrets = true;
    }
  if (!secrets) {
    iso.description = "none (this copy of the grader holds no hidden data and no solutions)";
    return finish(iso.kind);
  }
  iso.warning =
      "hidden tests are NOT protected: student code is compiled and run without isolation (" +
      (why_not_bwrap.empty() ? std::string("--isolation none") : why_not_bwrap) +
      (geteuid() == 0 ? "" : "; not root, so no unprivileged user either") +
      "). Install bubblewrap or grade as root.";
  std::cerr << "\n*** jelly-grade WARNING: " << iso.warning << " ***\n\n";
  return finish(iso.kind);
}

namespace {

// The command line and limits of one run in `lane`; `tmp` is its private folder (user mode).
std::vector<std::string> isolate(const Isolation& iso, const Lane* lane, const fs::path& tmp,
                                 const std::vector<std::string>& argv, const SandboxView& view,
                                 Limits& limits) {
  const bool pids_cgroup = lane && !lane->pids_dir().empty();
  if (iso.kind == IsolationKind::User) {
    limits.run_as_uid = lane->uid;
    limits.run_as_gid = view.gid >= 0 ? view.gid : lane->gid;
    limits.env.clear();
    for (const auto& [k, v] : clean_env()) limits.env.push_back(k + "=" + v);
    limits.env.push_back("TMPDIR=" + tmp.string());
    limits.env.push_back("HOME=" + tmp.string());
    // Counted per user: a user per lane, its processes killed after every run, so this is a cap
    // per run too (and the only one where there is no pids cgroup).
    // With a pids cgroup that is the cap (and says so); this is then only a backstop.
    if (limits.max_processes == 0)
      limits.max_processes = pids_cgroup ? 4 * kRunProcesses : kRunProcesses;
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
  a.insert(a.end(),
           {"--chdir", view.cwd.empty() ? std::string("/tmp") : absolute_clean(view.cwd).string()});
  // No pids cgroup: RLIMIT_NPROC set inside the sandbox counts the processes of the sandbox's own
  // user namespace only (Linux 5.14+), so it caps this run and nothing else.
  if (!pids_cgroup && access("/usr/bin/prlimit", X_OK) == 0)
    a.insert(a.end(),
             {"/usr/bin/prlimit", "--nproc=" + std::to_string(kRunProcesses), "--core=0", "--"});
  a.insert(a.end(), argv.begin(), argv.end());
  return a;
}

}  // namespace

ChildResult run_isolated(const Isolation& iso, const std::vector<std::string>& argv,
                         const SandboxView& view, Limits limits) {
  SandboxPool* pool = iso.pool.get();
  LaneLease lease(pool);
  Lane* lane = lease.lane;
  const bool user = iso.kind == IsolationKind::User;
  if (user && !lane) throw std::runtime_error("--isolation user without its sandbox state");
  fs::path tmp;
  if (user) {
    // The run's own temporary folder: empty, its user's alone, removed after it.
    tmp = pool->scratch() / ("run-" + std::to_string(pool->next_id()));
    if (mkdir(tmp.c_str(), 0700) != 0 ||
        lchown(tmp.c_str(), static_cast<uid_t>(lane->uid),
               static_cast<gid_t>(view.gid >= 0 ? view.gid : lane->gid)) != 0)
      throw std::runtime_error("cannot make the private folder " + tmp.string() + ": " +
                               std::strerror(errno));
  }
  int leftovers = 0;
  if (lane) {
    lane->arm(limits.memory_bytes, kRunProcesses);
    for (const fs::path& d : lane->dirs()) limits.cgroup_procs.push_back((d / "cgroup.procs"));
    limits.end_leftovers = [&leftovers, lane] { leftovers += lane->end_all(); };
  }
  const std::vector<std::string> command = isolate(iso, lane, tmp, argv, view, limits);
  fs::path cwd = view.cwd;
  if (iso.kind == IsolationKind::Bwrap) cwd = "/tmp";  // outside; --chdir sets the inside one
  if (user && cwd.empty()) cwd = tmp;
  ChildResult c = run_child(command, limits, cwd);
  if (lane) {
    leftovers += lane->end_all();  // also when the child never started or was never reaped
    c.memory_cap = lane->oom_hit();
    c.process_cap = lane->pids_hit();
  }
  c.leftover_processes = leftovers;
  if (user) {
    std::error_code ec;
    fs::remove_all(tmp, ec);
    c.leftover_files = remove_shared_leftovers(lane->uid);
  }
  // bwrap's own init reaps the tool and exits with 128 + the signal that ended it.
  if (iso.kind == IsolationKind::Bwrap && c.signal == 0 && c.exit_code > 128 &&
      c.exit_code <= 128 + 64) {
    c.signal = c.exit_code - 128;
    c.exit_code = -1;
  }
  return c;
}

Workspace::Workspace(const Isolation& iso, const fs::path& dir) : iso_(iso), dir_(dir) {
  if (iso.kind == IsolationKind::User && iso.pool) {
    gid_ = iso.pool->acquire_group();
    dir_ = iso.pool->scratch() / ("sub-" + std::to_string(iso.pool->next_id()));
    scratch_ = true;
    fs::create_directories(dir_);
    if (chown(dir_.c_str(), 0, static_cast<gid_t>(gid_)) != 0 || chmod(dir_.c_str(), 0750) != 0)
      throw std::runtime_error("cannot prepare the work folder " + dir_.string());
  } else {
    fs::create_directories(dir_);
  }
}

Workspace::~Workspace() {
  if (!scratch_) return;
  std::error_code ec;
  fs::remove_all(dir_, ec);
  iso_.pool->release_group(gid_);
}

namespace {

void set_tree(const fs::path& dir, int gid, bool writable) {
  auto one = [&](const fs::path& p) {
    struct stat st {};
    if (lstat(p.c_str(), &st) != 0 || S_ISLNK(st.st_mode)) return;
    if (lchown(p.c_str(), 0, static_cast<gid_t>(gid)) != 0)
      throw std::runtime_error("cannot give " + p.string() + " to the sandbox's group");
    const bool exec = S_ISDIR(st.st_mode) || (st.st_mode & S_IXUSR);
    mode_t m = exec ? 0750 : 0640;
    if (writable) m |= 0020;
    chmod(p.c_str(), m);
  };
  one(dir);
  for (const auto& e : fs::recursive_directory_iterator(dir)) one(e.path());
}

}  // namespace

void give_to_sandbox(const Isolation& iso, const fs::path& dir, int gid) {
  fs::create_directories(dir);
  if (iso.kind != IsolationKind::User) return;
  const fs::path abs = absolute_clean(dir);
  for (fs::path p = abs.parent_path(); !p.empty() && p != p.parent_path(); p = p.parent_path()) {
    struct stat st {};
    if (stat(p.c_str(), &st) == 0 && !(st.st_mode & S_IXOTH) && !(st.st_mode & S_IXGRP))
      throw std::runtime_error("the work folder " + abs.string() +
                               " cannot be reached by the sandbox users (" + p.string() +
                               " is closed to other users): use --out in an open folder");
  }
  if (gid < 0) throw std::runtime_error("give_to_sandbox: no group for " + abs.string());
  set_tree(abs, gid, true);
}

void seal_for_sandbox(const Isolation& iso, const fs::path& dir, int gid) {
  if (iso.kind != IsolationKind::User || gid < 0 || !fs::exists(dir)) return;
  set_tree(absolute_clean(dir), gid, false);
}

}  // namespace jelly::grade
