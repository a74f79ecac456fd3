// `jelly study`: numerical studies on a scene: accuracy against cost, and the effects of a
// parameter.
#pragma once

namespace jelly::cli {

/// jelly study accuracy|effects SCENE ... (argv[1] is "study"). Returns an ExitCode
/// (jelly/cli_common/exit_codes.hpp).
int study_command(int argc, char** argv);

}  // namespace jelly::cli
