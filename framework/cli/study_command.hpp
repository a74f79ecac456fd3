// `jelly study`: numerical studies of the integrators on a scene (accuracy against cost).
#pragma once

namespace jelly::cli {

/// jelly study accuracy SCENE ... (argv[1] is "study"). Returns an ExitCode (jelly/cli_common/exit_codes.hpp).
int study_command(int argc, char** argv);

}  // namespace jelly::cli
