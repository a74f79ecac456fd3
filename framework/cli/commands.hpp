// The `jelly` subcommands. Each parses its own part of argv (argv[2], ... for `jelly run`) with a
// jelly::cli::Command (CLI11, jelly/cli_common/command_line.hpp) and returns a process exit code
// (jelly/cli_common/exit_codes.hpp).
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "jelly/cli_common/exit_codes.hpp"
#include "jelly/scene.hpp"

namespace jelly::cli {

class Command;

int run_command(int argc, char** argv);     ///< jelly run SCENE ...
int params_command(int argc, char** argv);  ///< jelly params SCENE [--set k=v ...]
int check_command(int argc, char** argv);   ///< jelly check SCENE [--set k=v ...]
int probe_command(int argc, char** argv);   ///< jelly probe

/// What a command line changes in a scene: --integrator, --dt, --duration and every --set.
struct SceneOverrides {
  std::string integrator, dt, duration;  ///< empty: the scene's own
  std::vector<std::string> sets;         ///< KEY=VALUE, in the order given
};

/// Declares --set KEY=VALUE (repeatable) on `command`, and --integrator, --dt and --duration when
/// `run_options`, all filling `into`. Their values are checked by load_with_overrides.
void add_scene_overrides(Command& command, SceneOverrides& into, bool run_options = true);

/// Loads SCENE (a path or a name under scenes/: session::resolve_scene) and applies --integrator,
/// --dt, --duration and every --set, in that order, through the parameter declarations. On error
/// prints the message (file, key, line; or the places tried and the known names) and returns
/// nullopt.
std::optional<SceneSpec> load_with_overrides(const std::string& scene_name,
                                             const SceneOverrides& overrides);

/// Prints a note naming the student tasks of the assignment that runs `scene` that still look
/// unimplemented (nothing when all are).
void print_missing_tasks_note(const SceneSpec& scene);

}  // namespace jelly::cli
