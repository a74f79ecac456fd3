// Which submissions a class folder holds (jelly-grade batch, similarity): one Submission per
// student, each with the id the class files use and the folder its task files are in.
#pragma once

#include <filesystem>
#include <string>
#include <vector>

namespace jelly::grade {

struct Submission {
  /// The student's id in every class file (scores.csv, class report, students/<id>/): the export's
  /// id where it has one, else the folder's name. Unique within a class; safe as a folder name.
  std::string id;
  std::string name;           ///< the student's name where the export gives one, else ""
  std::filesystem::path dir;  ///< the folder whose files are graded
  /// What the reader did that the instructor should know ("renamed ...", "picked the latest ...").
  std::vector<std::string> notes;
  /// Non-empty: this entry cannot be graded (a file where a folder was expected, an empty folder,
  /// an id another submission has): the reason, shown in its scores.csv row and the class report.
  std::string problem;
};

/// The submissions in `dir`: one per folder, in id order. Entries that cannot be graded are
/// listed with their problem, never dropped, so that every student has a row.
std::vector<Submission> find_submissions(const std::filesystem::path& dir);

}  // namespace jelly::grade
