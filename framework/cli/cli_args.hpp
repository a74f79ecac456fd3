// A small command-line parser for the `jelly` subcommands: flags with values, repeated flags and
// positionals, with errors that say which argument was wrong.
#pragma once

#include <map>
#include <optional>
#include <string>
#include <vector>

namespace jelly::cli {

/// Parsed arguments of one subcommand.
class Args {
 public:
  /// `value_flags` take a value ("--dt 0.001" or "--dt=0.001"); `switch_flags` take none.
  /// Unknown flags and missing values become error().
  Args(int argc, char** argv, int first, const std::vector<std::string>& value_flags,
       const std::vector<std::string>& switch_flags);

  const std::vector<std::string>& positionals() const { return positionals_; }
  /// Last value given for a flag.
  std::optional<std::string> value(const std::string& flag) const;
  /// Every value given for a repeatable flag, in order.
  std::vector<std::string> values(const std::string& flag) const;
  bool has(const std::string& flag) const;
  /// Empty when the command line was well formed.
  const std::string& error() const { return error_; }

 private:
  std::vector<std::string> positionals_;
  std::map<std::string, std::vector<std::string>> flags_;
  std::string error_;
};

/// Parses a whole positive integer; nullopt when `text` is not one.
std::optional<long> parse_positive_integer(const std::string& text);

/// Exit codes of every `jelly` subcommand.
enum ExitCode : int {
  kExitOk = 0,
  kExitInternal = 1,   ///< an unexpected failure (a bug, or a file that could not be written)
  kExitUsage = 2,      ///< bad command line or bad scene input: nothing was simulated or written
  kExitUnstable = 3,   ///< the stability detector stopped the run (what was written is kept)
};

}  // namespace jelly::cli
