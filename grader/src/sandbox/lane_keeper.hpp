// What ends a submission's processes when the grader cannot: a grader killed by any signal
// (SIGKILL included: a scheduler's time limit, the OOM killer) runs no destructor, and
// PR_SET_PDEATHSIG reaches its children only, not what they forked (setsid + double fork). Linux
// only (isolation.cpp); docs/grader.md, "What stopping a batch stops".
#pragma once

#include <sys/types.h>

#include <filesystem>
#include <vector>

namespace jelly::grade {

namespace fs = std::filesystem;

/// SIGKILL to every process of `uid`, from a child that becomes that user: kill(-1) reaches exactly
/// its processes in one pass of the kernel over all processes, so no fork escapes it. Root only.
void kill_user(int uid);

/// The processes whose effective user is `uid` (the owner of /proc/PID).
std::vector<int> processes_of_user(int uid);

/// Kills every process in the cgroup folder `dir` and in the folders below it (cgroup.kill on
/// v2, else SIGKILL to each process of cgroup.procs until none is left, a few seconds at most),
/// then removes those folders, deepest first. Returns how many processes it found.
int end_cgroup_tree(const fs::path& dir);

/// The root-only folder of the sandbox users' lock files (/run/jelly-grade, else
/// /var/lib/jelly-grade), made when `create`; empty when there is none (and not `create`).
/// Throws when `create` and no such folder can be made.
fs::path sandbox_lock_dir(bool create);

/// Ends every process of the sandbox users whose lock file nobody holds (their grader is gone):
/// each such user is locked while its processes are killed, so no grader that claims it meanwhile
/// loses its own. Root only; does nothing elsewhere.
void sweep_abandoned_users();

/// Kills the processes of sandbox user `n` (uid `uid`) once its lock is free, trying for up to
/// `wait_s` seconds; false when another grader holds it all that time (then that grader ends them
/// when it claims the user).
bool end_user_when_free(int n, int uid, double wait_s);

/// A process forked from the grader, outside every sandbox (root when the grader is, its own
/// session, deaf to the terminal's signals), that holds the read end of a pipe. When the grader
/// is gone, whatever the way (read() returns 0), it ends every process in the grader's cgroup
/// folders and every process of the sandbox users it was told about, removes the folders and
/// exits. The grader tells it each user it takes (tell_user). Stopping the keeper (destructor)
/// closes the pipe and waits for it.
class LaneKeeper {
 public:
  LaneKeeper() = default;
  ~LaneKeeper();
  LaneKeeper(const LaneKeeper&) = delete;
  LaneKeeper& operator=(const LaneKeeper&) = delete;

  /// Forks the keeper of `cgroup_dirs` (the grader's own folders, jelly-grade-PID, one per
  /// hierarchy). Call while the grader has one thread.
  void start(const std::vector<fs::path>& cgroup_dirs);
  /// Sandbox user `n` (uid `uid`) runs submissions of this grader from now on.
  void tell_user(int n, int uid);
  bool running() const { return pid_ > 0; }

 private:
  pid_t pid_ = -1;
  int fd_ = -1;
};

}  // namespace jelly::grade
