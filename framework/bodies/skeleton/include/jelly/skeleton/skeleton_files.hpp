// The ASF and AMC readers of the kinematics contract §1, §2 and §11. They never throw, never
// exit and never return a half-built result: either the whole skeleton or motion, or the first
// error with the file, the line and what was expected. docs/skeleton-files.md states what they
// accept.
#pragma once

#include <filesystem>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "jelly/skeleton/skeleton.hpp"

namespace jelly::skeleton {

/// What is wrong in a skeleton or motion file.
struct FileError {
  std::string file;     ///< the path as given, or the name passed with the text
  int line = 0;         ///< 1-based; the last line + 1 for the end of the file; 0 when none
  std::string message;  ///< what is wrong and what was expected

  /// "data/mocap/skeleton.asf:12: bone 'lfemur': expected ..."
  std::string text() const;
};

/// Something read but not used: an unknown section or key (`jelly check` lists them).
struct FileNote {
  int line = 0;
  std::string message;
};

struct SkeletonResult {
  std::optional<Skeleton> skeleton;
  std::optional<FileError> error;
  std::vector<FileNote> notes;
  explicit operator bool() const { return skeleton.has_value(); }
};

struct MotionResult {
  std::optional<Motion> motion;
  std::optional<FileError> error;
  std::vector<FileNote> notes;
  explicit operator bool() const { return motion.has_value(); }
};

/// Reads an ASF file; lengths are multiplied by `scale` (> 0, finite) in the derived data.
SkeletonResult read_asf(const std::filesystem::path& path, double scale);
/// Reads ASF text; `file_name` names it in errors.
SkeletonResult parse_asf(std::string_view text, std::string_view file_name, double scale);

/// Reads an AMC file of `skeleton`'s bones; root translations are multiplied by its scale.
MotionResult read_amc(const std::filesystem::path& path, const Skeleton& skeleton);
/// Reads AMC text; `file_name` names it in errors.
MotionResult parse_amc(std::string_view text, std::string_view file_name, const Skeleton& skeleton);

}  // namespace jelly::skeleton
