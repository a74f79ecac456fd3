// Points as the grader writes them, in every report and every command's lines.
#pragma once

#include <string>

namespace jelly::grade {

/// Points as every command prints them: two decimals ("12.50").
std::string pts(double v);

}  // namespace jelly::grade
