// What the instructor's grader reads from a class's archives with the libraries made for them:
// the names of a zip's entries (libzip). submission_metadata.yml (yaml-cpp) is read by
// read_gradescope_metadata (submissions.hpp). A build without these libraries (a student's
// self-check: JELLY_GRADER_SECCOMP=OFF, Windows, macOS) links class_archives_none.cpp, whose
// functions say so.
#pragma once

#include <filesystem>
#include <string>
#include <vector>

namespace jelly::grade {

/// The names of the entries of `zip`, in the zip's order, exactly as stored. Throws
/// std::runtime_error naming `shown` when the file is not a zip libzip can read.
std::vector<std::string> zip_entry_names(const std::filesystem::path& zip,
                                         const std::string& shown);

}  // namespace jelly::grade
