// Starting a program: an argument vector, never a shell (nothing to quote, no `sh` or cmd.exe),
// with limits, its output captured. The one launcher of the grader (every grading case and every
// compiler call), the movie writer (ffmpeg) and the studies (gnuplot); and the one PATH search.
// process_posix.cpp is POSIX (fork/exec), process_win.cpp Windows (CreateProcessW).
#pragma once

#include <cstddef>
#include <filesystem>
#include <functional>
#include <optional>
#include <string>
#include <vector>

namespace jelly::process {

struct Limits {
  double timeout_s = 10.0;                ///< wall clock; the process group is SIGKILLed after it
  double cpu_s = 0.0;                     ///< RLIMIT_CPU (0: timeout + 1 s)
  std::size_t memory_bytes = 1ULL << 30;  ///< RLIMIT_AS (0: unlimited)
  std::size_t file_size_bytes = 0;        ///< RLIMIT_FSIZE (the runner writes no files)
  bool limit_files = true;                ///< apply RLIMIT_FSIZE
  std::size_t keep_output = 64 * 1024;    ///< bytes of stdout/stderr kept for the report
  std::size_t kill_output = 64ULL << 20;  ///< more output than this (both streams) kills the child
  bool result_pipe = true;                ///< give the child a pipe as fd 3 for its result
  std::size_t max_processes = 0;          ///< RLIMIT_NPROC (0: unchanged); counts per user, so
                                          ///< only meaningful for a dedicated user (isolation.hpp)
  std::size_t max_open_files = 0;         ///< RLIMIT_NOFILE (0: unchanged)
  int run_as_uid = -1, run_as_gid = -1;   ///< drop to this user and group before exec (-1: stay)
  std::vector<std::string> env;           ///< the child's whole environment (empty: inherit ours)
  std::string stdin_data;                 ///< what the child reads on fd 0 (empty: /dev/null); an
                                          ///< anonymous in-memory file only this child has
  /// The child joins these cgroups (their cgroup.procs files) before it drops privileges and
  /// execs; one it cannot join ends it (exit status 124) rather than letting it run uncapped.
  std::vector<std::string> cgroup_procs;
  /// Called (in the calling thread) once the child has exited or been killed: ends every other
  /// process it left behind (isolation.cpp: its cgroup, its sandbox user). Its output is then read
  /// for at most `drain_s` more seconds: a process that kept a copy of a pipe cannot stall us.
  /// Generous, because an honest run may still hold its pipes for a moment after the child was
  /// reaped (bwrap's own init leaves its pid namespace after the outer bwrap has exited) and a busy
  /// machine can stretch that moment: hitting the limit fails the test, so it must only ever be
  /// hit by a process that survived end_leftovers, which kills every process a holder could be.
  std::function<void()> end_leftovers;
  double drain_s = 5.0;
};

/// Limits for a trusted tool the grader runs itself (nm, zip, useradd, the sandbox probe, the
/// renderer): a wall-clock timeout and no other cap, no result pipe.
inline Limits trusted_tool_limits(double timeout_s,
                                  std::size_t keep_output = Limits{}.keep_output) {
  Limits lim;
  lim.timeout_s = timeout_s;
  lim.memory_bytes = 0;
  lim.limit_files = false;
  lim.result_pipe = false;
  lim.keep_output = keep_output;
  return lim;
}

struct ChildResult {
  bool started = false;
  std::string start_error;
  int exit_code = -1;  ///< when it exited normally
  int signal = 0;      ///< when a signal ended it
  bool timed_out = false;
  bool output_flood = false;  ///< killed for printing more than kill_output
  std::string out, err;       ///< the first keep_output bytes of each stream
  std::size_t out_bytes = 0, err_bytes = 0;
  std::string result;       ///< everything written to fd 3
  double seconds = 0.0;     ///< wall time
  bool pipes_held = false;  ///< a pipe was still open `drain_s` after the child ended (abandoned)
  // Filled by the sandbox (isolation.cpp) from the run's cgroup or sandbox user:
  bool memory_cap = false;     ///< the run's processes together hit its memory cap (OOM kill)
  bool process_cap = false;    ///< a fork or thread was refused at the run's process cap
  int leftover_processes = 0;  ///< processes still running when the child had ended (killed)
  int leftover_files = 0;      ///< files it left in the shared temporary folders (removed)
};

/// Runs argv[0] with the arguments, stdin from /dev/null (or limits.stdin_data), in its own process
/// group, with the limits; `cwd` empty means the current directory. Only fds 0, 1, 2 (and 3, the
/// result pipe) reach the child. Never throws for a child's failure.
ChildResult run_child(const std::vector<std::string>& argv, const Limits& limits,
                      const std::filesystem::path& cwd = {});

/// `name` found in a folder of PATH (with ".exe" on Windows), as a path to run: a regular file the
/// user may execute. Empty folders of PATH (the working folder) are not searched. nullopt when no
/// folder of PATH holds it.
std::optional<std::filesystem::path> find_on_path(const std::string& name);

/// "SIGSEGV (segmentation fault)" and the like.
std::string describe_signal(int sig);

}  // namespace jelly::process
