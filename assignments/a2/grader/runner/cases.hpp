// A2's case generators (cases_*.cpp), registered by register.cpp.
#pragma once

#include "harness.hpp"

namespace jelly::grade {}  // namespace jelly::grade
