// The keeper of a grader's lanes, and the sweep of lanes whose grader is gone; see lane_keeper.hpp.
#include "sandbox/lane_keeper.hpp"

#include <fcntl.h>
#include <pwd.h>
#include <signal.h>
#include <sys/file.h>
#include <sys/prctl.h>
#include <sys/stat.h>
#include <sys/syscall.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <chrono>
#include <fstream>
#include <set>
#include <sstream>
#include <stdexcept>
#include <string>
#include <thread>

#include "sandbox/isolation.hpp"

namespace jelly::grade {

namespace {

std::string read_small(const fs::path& p) {
  std::ifstream in(p);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

// A process on its way out (a zombie its parent has not reaped yet) is no longer running.
bool is_zombie(int pid) {
  const std::string stat = read_small("/proc/" + std::to_string(pid) + "/stat");
  const auto paren = stat.rfind(')');
  return paren == std::string::npos || stat.size() < paren + 3 || stat[paren + 2] == 'Z';
}

std::vector<int> live_procs_of(const fs::path& cgroup) {
  std::vector<int> pids;
  std::istringstream in(read_small(cgroup / "cgroup.procs"));
  for (int p; in >> p;)
    if (!is_zombie(p)) pids.push_back(p);
  return pids;
}

void sleep_ms(int ms) { std::this_thread::sleep_for(std::chrono::milliseconds(ms)); }

// The number N of a lock file "user-N.lock"; -1 for any other name.
int user_number(const std::string& name) {
  if (name.rfind("user-", 0) != 0 || name.size() <= 10 ||
      name.compare(name.size() - 5, 5, ".lock") != 0)
    return -1;
  const std::string n = name.substr(5, name.size() - 10);
  if (n.find_first_not_of("0123456789") != std::string::npos || n.size() > 6) return -1;
  return std::stoi(n);
}

int uid_of_sandbox_user(int n) {
  const std::string name = std::string(kSandboxUser) + "-" + std::to_string(n);
  passwd pw{}, *found = nullptr;
  std::vector<char> buf(16384);
  if (getpwnam_r(name.c_str(), &pw, buf.data(), buf.size(), &found) != 0 || !found) return -1;
  return static_cast<int>(pw.pw_uid);
}

// The keeper itself: waits for the grader's end, then ends what it leaves.
[[noreturn]] void keep(int fd, const std::vector<fs::path>& dirs) {
  setsid();  // out of the grader's process group: a kill of the group leaves it to do its work
  for (int s : {SIGINT, SIGTERM, SIGHUP, SIGQUIT, SIGPIPE, SIGTSTP, SIGTTIN, SIGTTOU})
    signal(s, SIG_IGN);
  prctl(PR_SET_NAME, "jelly-keeper");
  if (chdir("/") != 0) {
    // it holds no folder busy; where / cannot be entered it stays where it is
  }
  const int null = open("/dev/null", O_RDWR);
  for (int i = 0; i < 3 && null >= 0; ++i) dup2(null, i);
  if (fd != 3) {
    dup2(fd, 3);
    fd = 3;
  }
  syscall(SYS_close_range, 4U, ~0U, 0U);   // nothing else of the grader: its pipes, its locks
  std::vector<std::pair<int, int>> users;  // (N, uid)
  bool finished = false;                   // the grader ended its lanes itself
  std::string pending;
  char buf[256];
  for (;;) {
    const ssize_t got = read(fd, buf, sizeof buf);
    if (got < 0 && errno == EINTR) continue;
    if (got <= 0) break;  // the grader is gone (or closed the pipe at its end)
    pending.append(buf, static_cast<std::size_t>(got));
    for (auto nl = pending.find('\n'); nl != std::string::npos; nl = pending.find('\n')) {
      std::istringstream line(pending.substr(0, nl));
      pending.erase(0, nl + 1);
      if (line.str() == "end") finished = true;
      int n = -1, uid = -1;
      if (line >> n >> uid && n >= 0 && uid > 0) users.emplace_back(n, uid);
    }
  }
  for (const fs::path& d : dirs) end_cgroup_tree(d);
  // The grader's lock files close with it, in its own time: a few seconds for each.
  for (const auto& [n, uid] : users) end_user_when_free(n, uid, finished ? 0.0 : 3.0);
  _exit(0);
}

}  // namespace

void kill_user(int uid) {
  const pid_t pid = fork();
  if (pid < 0) return;
  if (pid == 0) {
    if (setuid(static_cast<uid_t>(uid)) != 0) _exit(2);
    kill(-1, SIGKILL);
    _exit(0);
  }
  int status = 0;
  while (waitpid(pid, &status, 0) < 0 && errno == EINTR) {
  }
}

std::vector<int> processes_of_user(int uid) {
  std::vector<int> pids;
  std::error_code ec;
  for (fs::directory_iterator it("/proc", ec), end; !ec && it != end; it.increment(ec)) {
    const std::string name = it->path().filename().string();
    if (name.empty() || name.find_first_not_of("0123456789") != std::string::npos) continue;
    struct stat st {};
    if (stat(it->path().c_str(), &st) == 0 && static_cast<int>(st.st_uid) == uid)
      pids.push_back(std::stoi(name));
  }
  return pids;
}

int end_cgroup_tree(const fs::path& dir) {
  std::vector<fs::path> folders = {dir};  // parents before their children
  std::error_code ec;
  for (fs::recursive_directory_iterator it(dir, ec), end; !ec && it != end; it.increment(ec))
    if (it->is_directory(ec) && !it->is_symlink(ec)) folders.push_back(it->path());
  std::set<int> seen;
  for (int round = 0; round < 500; ++round) {
    std::vector<int> now;
    for (const fs::path& f : folders)
      for (int p : live_procs_of(f)) now.push_back(p);
    if (now.empty()) break;
    for (const fs::path& f : folders) {
      const int fd = open((f / "cgroup.kill").c_str(), O_WRONLY | O_CLOEXEC);
      if (fd < 0) continue;
      if (write(fd, "1", 1) != 1) {
        // an older kernel: the SIGKILLs below do it
      }
      close(fd);
    }
    for (int p : now) {
      kill(p, SIGKILL);
      seen.insert(p);
    }
    sleep_ms(std::min(round + 1, 10));
  }
  // A folder still listing a killed process (a zombie its new parent has not reaped yet) cannot be
  // removed: a second at most.
  for (auto f = folders.rbegin(); f != folders.rend(); ++f)
    for (int tries = 0; rmdir(f->c_str()) != 0 && errno == EBUSY && tries < 100; ++tries)
      sleep_ms(10);
  return static_cast<int>(seen.size());
}

fs::path sandbox_lock_dir(bool create) {
  for (const char* base : {"/run", "/var/lib"}) {
    const fs::path d = fs::path(base) / "jelly-grade";
    if (create && access(base, W_OK) == 0) mkdir(d.c_str(), 0700);
    struct stat st {};
    if (lstat(d.c_str(), &st) == 0 && S_ISDIR(st.st_mode) && st.st_uid == 0 &&
        !(st.st_mode & (S_IWGRP | S_IWOTH)))
      return d;
  }
  if (create)
    throw std::runtime_error(
        "--isolation user: no root-only folder for the sandbox users' locks (/run/jelly-grade)");
  return {};
}

bool end_user_when_free(int n, int uid, double wait_s) {
  const fs::path dir = sandbox_lock_dir(false);
  if (dir.empty() || uid <= 0) return false;
  const int fd = open((dir / ("user-" + std::to_string(n) + ".lock")).c_str(),
                      O_RDWR | O_CLOEXEC | O_NOFOLLOW);
  if (fd < 0) return false;
  const auto until = std::chrono::steady_clock::now() + std::chrono::duration<double>(wait_s);
  bool locked = false;
  while (!(locked = flock(fd, LOCK_EX | LOCK_NB) == 0) && std::chrono::steady_clock::now() < until)
    sleep_ms(10);
  if (locked)
    for (int round = 0; round < 50 && !processes_of_user(uid).empty(); ++round) {
      kill_user(uid);
      sleep_ms(std::min(round + 1, 10));
    }
  close(fd);  // releases the lock
  return locked;
}

void sweep_abandoned_users() {
  if (geteuid() != 0) return;
  const fs::path dir = sandbox_lock_dir(false);
  if (dir.empty()) return;
  std::error_code ec;
  for (fs::directory_iterator it(dir, ec), end; !ec && it != end; it.increment(ec)) {
    const int n = user_number(it->path().filename().string());
    const int uid = n < 0 ? -1 : uid_of_sandbox_user(n);
    if (uid > 0) end_user_when_free(n, uid, 0.0);
  }
}

void LaneKeeper::start(const std::vector<fs::path>& cgroup_dirs) {
  int fds[2];
  if (pipe2(fds, O_CLOEXEC) != 0) return;
  const pid_t pid = fork();
  if (pid == 0) {
    close(fds[1]);
    keep(fds[0], cgroup_dirs);
  }
  close(fds[0]);
  if (pid < 0) {
    close(fds[1]);
    return;
  }
  pid_ = pid;
  fd_ = fds[1];
}

void LaneKeeper::tell_user(int n, int uid) {
  if (fd_ < 0) return;
  const std::string line = std::to_string(n) + " " + std::to_string(uid) + "\n";
  if (write(fd_, line.data(), line.size()) != static_cast<ssize_t>(line.size())) {
    // the keeper is gone: the next grader's sweep ends what is left
  }
}

LaneKeeper::~LaneKeeper() {
  if (fd_ >= 0) {
    const char end[] = "end\n";
    if (write(fd_, end, sizeof end - 1) != sizeof end - 1) {
      // the keeper is gone already
    }
    close(fd_);
  }
  if (pid_ > 0)
    while (waitpid(pid_, nullptr, 0) < 0 && errno == EINTR) {
    }
}

}  // namespace jelly::grade
