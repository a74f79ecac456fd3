// The keeper of a grader's lanes and the sweep of a dead grader's cgroup
// (grader/src/sandbox/lane_keeper.cpp) on a cgroup folder of their own: a process a run detached
// (setsid + double fork) ends when the grader that owns the folder is killed with SIGKILL, and the
// folder goes. Needs a writable cgroup (root on cgroup v1 or v2); skipped elsewhere. A second or
// two.
#include <signal.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <filesystem>
#include <fstream>
#include <functional>
#include <sstream>
#include <string>
#include <thread>
#include <vector>

#include <gtest/gtest.h>

#include "sandbox/lane_keeper.hpp"

namespace fs = std::filesystem;

namespace {

std::string read_text(const fs::path& p) {
  std::ifstream in(p);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

// A new cgroup folder under this process's own cgroup, in the first hierarchy that lets us make
// one (v1 pids, v2 at /sys/fs/cgroup or /sys/fs/cgroup/unified); empty when none does.
fs::path make_test_cgroup(const std::string& name) {
  std::istringstream in(read_text("/proc/self/cgroup"));
  for (std::string line; std::getline(in, line);) {
    const auto c1 = line.find(':'), c2 = line.find(':', c1 + 1);
    if (c1 == std::string::npos || c2 == std::string::npos) continue;
    const std::string ctrls = line.substr(c1 + 1, c2 - c1 - 1);
    const fs::path own = fs::path(line.substr(c2 + 1)).relative_path();
    std::vector<fs::path> mounts;
    if (ctrls == "pids") mounts.push_back("/sys/fs/cgroup/pids");
    if (ctrls.empty()) mounts = {"/sys/fs/cgroup/unified", "/sys/fs/cgroup"};
    for (const fs::path& m : mounts) {
      const fs::path d = m / own / name;
      if (fs::exists(m / own / "cgroup.procs") && mkdir(d.c_str(), 0755) == 0) return d;
    }
  }
  return {};
}

bool alive(pid_t pid) {
  const std::string stat = read_text("/proc/" + std::to_string(pid) + "/stat");
  const auto paren = stat.rfind(')');
  return paren != std::string::npos && paren + 2 < stat.size() && stat[paren + 2] != 'Z';
}

bool gone_within(double s, const std::function<bool()>& gone) {
  const auto until = std::chrono::steady_clock::now() + std::chrono::duration<double>(s);
  while (!gone()) {
    if (std::chrono::steady_clock::now() > until) return false;
    std::this_thread::sleep_for(std::chrono::milliseconds(20));
  }
  return true;
}

// In a child of the caller (returned, to be reaped): joins `cgroup`, forks a detached sleeper
// (setsid, double fork) and writes its pid to `fd`.
pid_t start_detached_sleeper(const fs::path& cgroup, int fd) {
  const pid_t child = fork();
  if (child != 0) return child;
  // As jelly-grade's runs do (run_child), nothing of the grader's is inherited: the keeper's pipe.
  for (int other = 3; other < 1024; ++other)
    if (other != fd) close(other);
  std::ofstream(cgroup / "cgroup.procs") << "0" << std::flush;
  if (fork() == 0) {
    setsid();
    if (fork() == 0) {
      const pid_t me = getpid();
      if (write(fd, &me, sizeof me) != sizeof me) _exit(1);
      for (;;) pause();
    }
    _exit(0);
  }
  _exit(0);
}

}  // namespace

TEST(LaneKeeper, EndsADetachedProcessWhenItsGraderIsKilled) {
  const fs::path cg = make_test_cgroup("jelly-keeper-test-" + std::to_string(getpid()));
  if (cg.empty()) GTEST_SKIP() << "no writable cgroup here (root on cgroup v1 pids or v2)";
  int fds[2];
  ASSERT_EQ(pipe(fds), 0);
  // The "grader": starts its keeper, then a run that leaves a detached sleeper, then waits.
  const pid_t grader = fork();
  if (grader == 0) {
    jelly::grade::LaneKeeper keeper;
    keeper.start({cg});
    start_detached_sleeper(cg, fds[1]);
    for (;;) pause();
  }
  close(fds[1]);
  pid_t sleeper = -1;
  ASSERT_EQ(read(fds[0], &sleeper, sizeof sleeper), static_cast<ssize_t>(sizeof sleeper));
  close(fds[0]);
  ASSERT_TRUE(alive(sleeper));
  kill(grader, SIGKILL);
  waitpid(grader, nullptr, 0);
  EXPECT_TRUE(gone_within(5, [&] { return !alive(sleeper); }))
      << "the detached process " << sleeper << " outlived its grader";
  EXPECT_TRUE(gone_within(5, [&] { return !fs::exists(cg); })) << cg << " is still there";
  if (alive(sleeper)) kill(sleeper, SIGKILL);
  jelly::grade::end_cgroup_tree(cg);
}

TEST(LaneKeeper, TheSweepEndsADeadGradersProcessesAndRemovesItsFolders) {
  const fs::path cg = make_test_cgroup("jelly-keeper-sweep-" + std::to_string(getpid()));
  if (cg.empty()) GTEST_SKIP() << "no writable cgroup here (root on cgroup v1 pids or v2)";
  ASSERT_EQ(mkdir((cg / "lane-0").c_str(), 0755), 0);
  int fds[2];
  ASSERT_EQ(pipe(fds), 0);
  const pid_t child = start_detached_sleeper(cg / "lane-0", fds[1]);
  close(fds[1]);
  waitpid(child, nullptr, 0);
  pid_t sleeper = -1;
  ASSERT_EQ(read(fds[0], &sleeper, sizeof sleeper), static_cast<ssize_t>(sizeof sleeper));
  close(fds[0]);
  EXPECT_GE(jelly::grade::end_cgroup_tree(cg), 1);
  EXPECT_TRUE(gone_within(5, [&] { return !alive(sleeper); }));
  EXPECT_FALSE(fs::exists(cg));
}
