// The `jelly` subcommands. Each returns a process exit code (cli_args.hpp, ExitCode).
#pragma once

#include <optional>
#include <string>

#include "cli_args.hpp"
#include "jelly/scene.hpp"

namespace jelly::cli {

int run_command(int argc, char** argv);     ///< jelly run SCENE ...
int params_command(int argc, char** argv);  ///< jelly params SCENE [--set k=v ...]
int check_command(int argc, char** argv);   ///< jelly check SCENE [--set k=v ...]
int probe_command(int argc, char** argv);   ///< jelly probe

/// Loads SCENE (a path or a name under scenes/: session::resolve_scene) and applies --integrator,
/// --dt, --duration and every --set, in that order, through the parameter declarations. On error
/// prints the message (file, key, line; or the places tried and the known names) and returns nullopt.
std::optional<SceneSpec> load_with_overrides(const std::string& scene_name, const Args& args);

/// Prints a note naming the student tasks that still look unimplemented (nothing when all are).
void print_missing_tasks_note();

}  // namespace jelly::cli
