// Reading a whole file, the one way the grader does it (digests, reports, task files).
#pragma once

#include <filesystem>
#include <string>

namespace jelly::grade {

/// The bytes of file `p` as they are (binary: no line-end conversion); "" when it cannot be read.
std::string read_file(const std::filesystem::path& p);

}  // namespace jelly::grade
