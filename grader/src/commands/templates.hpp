// The scripts `jelly-grade gradescope-zip` writes, as the templates grader/templates/*.in hold them
// (embedded byte for byte at build time by grader/templates/embed.cmake). A template's
// @SANDBOX_SETUP_LINES@ line stands for sandbox_setup_lines("/autograder/source") (commands.hpp).
#pragma once

#include <string_view>

namespace jelly::grade {

/// grader/templates/setup.sh.in: Gradescope's image setup, run once.
std::string_view gradescope_setup_template();

/// grader/templates/run_autograder.in: Gradescope's entry point, run for every submission.
std::string_view gradescope_run_autograder_template();

}  // namespace jelly::grade
