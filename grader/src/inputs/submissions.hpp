// Which submissions a class holds (jelly-grade batch, similarity): one Submission per student,
// each with the id the class files use and the folder its task files are in. Reads a folder of
// student folders, a Gradescope export (its zip or its folder: submission_metadata.yml and one
// folder per submission) and a folder of GitHub Classroom clones (`gh classroom clone
// student-repos`). docs/grader.md, "Inputs", says how ids are chosen and what bad input gives.
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
  /// The entry of the class this submission came from (the student's folder, the Gradescope
  /// submission folder): the members of a Gradescope group share it (and `dir`).
  std::string source;
  std::string email;  ///< the submitter's email where the export gives one, else ""
};

/// The submissions in `in`: one per student, in id order. Entries that cannot be graded are listed
/// with their problem, never dropped, so that every student has a row. `in` is a folder, or a .zip
/// (a Gradescope export), which is extracted into `scratch` (emptied first; required then).
/// `warnings`, when given, gets what concerns the class rather than one student (a zip entry that
/// names no submission and was refused). Throws std::runtime_error naming the file (and line) when
/// `in` cannot be read at all: not a folder or zip, a zip unzip cannot read, a malformed
/// submission_metadata.yml.
std::vector<Submission> find_submissions(const std::filesystem::path& in,
                                         const std::filesystem::path& scratch = {},
                                         std::vector<std::string>* warnings = nullptr);

/// One Gradescope submitter as submission_metadata.yml gives it.
struct GradescopeSubmitter {
  std::string name, sid, email;
};
/// One entry of submission_metadata.yml: the submission folder and its submitters.
struct GradescopeEntry {
  std::string folder;
  int line = 0;  ///< where the entry starts in the file
  std::vector<GradescopeSubmitter> submitters;
};

/// Reads the subset of YAML Gradescope writes into submission_metadata.yml (Ruby's Psych: a
/// mapping of folder names to mappings with a `:submitters:` list of `:name:`/`:sid:`/`:email:`
/// mappings; plain, single- and double-quoted scalars, anchors and aliases, comments; every other
/// key is skipped whatever it holds). `file` names the file in errors ("FILE:LINE: ...").
std::vector<GradescopeEntry> read_gradescope_metadata(const std::string& text,
                                                      const std::string& file);

/// `raw` made safe as a folder name and a CSV id: no '/', '\\', control characters or characters
/// Windows refuses in names (<>:"|?*), not starting with '.', not empty, at most 100 bytes.
/// Returns `raw` itself when it already is.
std::string safe_id(const std::string& raw);

}  // namespace jelly::grade
