// What several jelly-grade commands share (commands.hpp lists the commands).
#pragma once

#include <string>

namespace jelly::grade {

/// Points as every command prints them: two decimals ("12.50").
std::string pts(double v);

}  // namespace jelly::grade
