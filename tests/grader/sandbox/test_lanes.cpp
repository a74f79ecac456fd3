// A sandbox lane is reused only when nothing is charged to it any more. A run's processes that
// lose their parent (bwrap's own init after every run, a killed run's orphans) are zombies until
// init reaps them, which a container's init does only every second or so, later on a busy
// machine. A zombie is no longer in cgroup.procs, but it still counts against pids.max: lanes
// reused while they held them made honest runs "start more than 64 processes", and nm fail on
// honest submissions' files, when the machine was busy (grader/src/sandbox/isolation.cpp,
// Lane::holds_processes). Needs root and a writable cgroup v1 pids hierarchy; skipped elsewhere.
#include <sys/wait.h>
#include <unistd.h>

#include <fstream>

#include <filesystem>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "inputs/config.hpp"
#include "sandbox/isolation.hpp"

namespace fs = std::filesystem;
using jelly::grade::ChildResult;
using jelly::grade::GradeConfig;
using jelly::grade::Isolation;
using jelly::grade::Limits;
using jelly::grade::SandboxView;

namespace {

const fs::path kConfig = fs::path(JELLY_BINARY_DIR) / "grader" / "grade-config.json";

// A process that leaves `children` sleeping children behind, each in a session of its own (their
// parent gone, init is theirs), and waits to be killed by the run's timeout.
std::vector<std::string> orphans_then_wait(int children) {
  return {"/bin/sh", "-c",
          "i=0; while [ $i -lt " + std::to_string(children) +
              " ]; do setsid sleep 60 & i=$((i+1)); done; sleep 60"};
}

Limits short_run(double timeout_s) {
  Limits lim;
  lim.timeout_s = timeout_s;
  lim.memory_bytes = 0;
  lim.result_pipe = false;
  return lim;
}

// Children of this process, each moved into `cgroup` and ended there unreaped: zombies charged to
// it, as a dead run's are. reap() ends them.
class Zombies {
 public:
  ~Zombies() { reap(); }
  void charge(const fs::path& cgroup, int count) {
    for (int i = 0; i < count; ++i) {
      const pid_t pid = fork();
      if (pid == 0) {
        std::ofstream(cgroup / "cgroup.procs") << getpid() << std::flush;
        _exit(0);
      }
      if (pid > 0) pids_.push_back(pid);
    }
    usleep(100000);  // until they have all ended
  }
  void reap() {
    for (pid_t p : pids_) waitpid(p, nullptr, 0);
    pids_.clear();
  }

 private:
  std::vector<pid_t> pids_;
};

// The lanes' pids folders of this process's sandbox.
std::vector<fs::path> our_lanes() {
  std::vector<fs::path> lanes;
  const fs::path ours =
      fs::path("/sys/fs/cgroup/pids") / ("jelly-grade-" + std::to_string(getpid()));
  std::error_code ec;
  for (fs::directory_iterator it(ours, ec), end; !ec && it != end; it.increment(ec))
    if (it->path().filename().string().rfind("lane-", 0) == 0) lanes.push_back(it->path());
  return lanes;
}

bool pids_cgroup_writable() {
  return geteuid() == 0 && access("/sys/fs/cgroup/pids/cgroup.procs", W_OK) == 0;
}

}  // namespace

// Every lane of the sandbox charged with 60 zombies after each run (what a busy machine's init
// leaves): each next run still gets its whole cap of 64, in a lane with nothing charged.
TEST(SandboxLanes, ARunNeverStartsInALaneChargedWithZombies) {
  if (!pids_cgroup_writable()) GTEST_SKIP() << "needs root and a cgroup v1 pids hierarchy";
  GradeConfig config = jelly::grade::load_config(kConfig.string());
  Isolation iso;
  try {
    iso = jelly::grade::choose_isolation(config, "bwrap");
  } catch (const std::exception& e) {
    GTEST_SKIP() << e.what();
  }
  SandboxView view;
  Zombies zombies;
  for (int run = 0; run < 12; ++run) {
    const ChildResult c = jelly::grade::run_isolated(
        iso, {"/bin/sh", "-c", "i=0; while [ $i -lt 8 ]; do /bin/true & i=$((i+1)); done; wait"},
        view, short_run(20.0));
    EXPECT_EQ(c.exit_code, 0) << "run " << run << ": " << c.err;
    EXPECT_FALSE(c.process_cap) << "run " << run << " started in a lane charged with zombies";
    zombies.reap();
    for (const fs::path& lane : our_lanes()) zombies.charge(lane, 60);
  }
}

// User mode, where a lane is also a sandbox user: runs that leave 50 orphans each, killed by their
// timeout, are zombies of init until it reaps them. Every later run must still get its whole cap
// (a shell that starts 20 processes succeeds each time), whether its lane is set aside meanwhile
// or not, and without a sandbox user of its own per run.
TEST(SandboxLanes, ZombiesOfAKilledRunDoNotCountAgainstTheNextRun) {
  if (!pids_cgroup_writable()) GTEST_SKIP() << "needs root and a cgroup v1 pids hierarchy";
  GradeConfig config = jelly::grade::load_config(kConfig.string());
  Isolation iso = jelly::grade::choose_isolation(config, "user");
  SandboxView view;
  for (int run = 0; run < 3; ++run) {
    const ChildResult killed =
        jelly::grade::run_isolated(iso, orphans_then_wait(50), view, short_run(2.0));
    EXPECT_TRUE(killed.timed_out) << "run " << run << ": " << killed.err;
    const ChildResult honest = jelly::grade::run_isolated(
        iso, {"/bin/sh", "-c", "i=0; while [ $i -lt 20 ]; do /bin/true & i=$((i+1)); done; wait"},
        view, short_run(20.0));
    EXPECT_EQ(honest.exit_code, 0) << "run " << run << ": " << honest.err;
    EXPECT_FALSE(honest.process_cap)
        << "run " << run << ": an honest run hit the process cap (zombies of the killed run?)";
  }
}
