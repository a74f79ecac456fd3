// Runs the `jelly` command line as a user would (tests of the CLI): JELLY_CLI names the binary.
#pragma once

#include <sys/wait.h>

#include <array>
#include <cstdio>
#include <string>

#include "shell_quote.hpp"

namespace jelly::testing {

/// Exit code and everything the command printed (stdout and stderr together).
struct CliResult {
  int code = -1;
  std::string output;
};

/// Runs `JELLY_CLI arguments` through the shell and collects its output and exit code.
inline CliResult run_jelly(const std::string& arguments) {
  const std::string command = shell_quoted(JELLY_CLI) + " " + quote_tree_paths(arguments) + " 2>&1";
  CliResult r;
  FILE* pipe = popen(command.c_str(), "r");
  std::array<char, 4096> buf{};
  while (pipe && std::fgets(buf.data(), buf.size(), pipe)) r.output += buf.data();
  const int status = pipe ? pclose(pipe) : -1;
  r.code = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  return r;
}

/// Path of a shipped scene file.
inline std::string scene_path(const std::string& name) {
  return std::string(JELLY_SOURCE_DIR) + "/scenes/" + name;
}

}  // namespace jelly::testing
