// The exit codes of every Jelly Lab program (jelly, jelly-lab, jelly-grade), documented in their
// --help texts and relied on by scripts (tools/selfcheck, the CTest tests, Gradescope's wrapper).
#pragma once

namespace jelly::cli {

enum ExitCode : int {
  kExitOk = 0,
  /// The command ran and failed: an unexpected error, a file that could not be written, no window,
  /// a self-test (mutants) that failed, `jelly-grade grade --strict` without full marks.
  kExitFailure = 1,
  /// Bad command line or bad input (scene, reference data): nothing was simulated or written.
  kExitUsage = 2,
  /// `jelly run`: the stability detector stopped the run (what was written is kept).
  kExitUnstable = 3,
};

/// `jelly`'s name for kExitFailure: "an unexpected failure" (a bug, or a file that could not be
/// written).
inline constexpr ExitCode kExitInternal = kExitFailure;

}  // namespace jelly::cli
