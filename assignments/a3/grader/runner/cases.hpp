// A3's case generators (grader/runner/harness.hpp), one register_* per file.
#pragma once

#include "harness.hpp"

namespace jelly::grade {}  // namespace jelly::grade
