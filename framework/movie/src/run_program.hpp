// Starting a program with an argument vector and waiting for it: no shell between (nothing to
// quote, no `sh` needed on Windows). run_program.cpp is POSIX (posix_spawn), run_program_win.cpp
// Windows (CreateProcessW).
#pragma once

#include <filesystem>
#include <optional>
#include <string>
#include <vector>

namespace jelly::movie {

/// `name` found in a folder of PATH (with ".exe" on Windows), as a path to run; nullopt when no
/// folder of PATH holds a regular file of that name.
std::optional<std::filesystem::path> find_on_path(const std::string& name);

struct ProgramResult {
  bool started = false;
  int exit_code = -1;  ///< when started: the exit code, or -1 when it ended by a signal
  std::string error;   ///< why it did not start, or how it ended when not by exit
};

/// Runs `program` with `args` (argv[1..]; argv[0] is the program's path), stdin from the null
/// device, stdout and stderr this process's; waits for it.
ProgramResult run_program(const std::filesystem::path& program,
                          const std::vector<std::string>& args);

}  // namespace jelly::movie
