// One student's result in a class (students/<id>/record.json) and the class files made from the
// records alone (scores.csv, the class report class.*): a batch, a resumed batch, and the merge of
// sharded batches all write the class files from the same records, so they write the same bytes.
#pragma once

#include <filesystem>
#include <string>
#include <vector>

#include "grading/grade.hpp"
#include "inputs/cases.hpp"
#include "inputs/submissions.hpp"

namespace jelly::grade {

/// What makes two gradings of one submission comparable: the assignment, the harness and the
/// reference data (harness_digest), the rubric's points, the cases run, the visibility and the
/// time limit. A record made under another fingerprint is graded again by --resume.
std::string grading_fingerprint(const GradeConfig& config, const CaseBook& book,
                                const GradeOptions& options);

/// A digest of every regular file under a submission folder (names and contents): a submission
/// changed since its record was made is graded again by --resume.
std::string submission_digest(const std::filesystem::path& dir);

/// The record of a graded submission (`report` given) or of one that could not be graded
/// (`error`: the submission's problem or the grader's error).
Json student_record(const Submission& sub, const GradeReport* report, const std::string& error,
                    const GradeConfig& config, const CaseBook& book,
                    const std::string& fingerprint);

/// The record file of student `id` under a batch's --out.
std::filesystem::path record_path(const std::filesystem::path& out, const std::string& id);

/// Reads a record file; throws std::runtime_error naming the file when it is not a record.
Json read_record(const std::filesystem::path& file);

/// scores.csv from the records (in the order given), for an LMS import: student (the id), points
/// (autograded, bonus left out), max_points (autograded_total), percent, [bonus,] total (points +
/// bonus: what the student earned), hand_graded (empty), hand_graded_max (the manifest's
/// hand_graded_points), compiled, each task's points (no column for a task worth 0 that is no
/// bonus), name, email, missing_files, error. A row not graded has no number at all.
std::string scores_csv(const std::vector<Json>& records, const CaseBook& book);

/// Writes the class files into `out` from `records`, each file whole or not at all: scores.csv and
/// the class report (class_report.hpp): class.json (all of it, for the instructor), class.md and
/// class.html (the lecture's view: no student, no hidden test) and class-instructor.md and
/// class-instructor.html (the instructor's). `title` is the manifest's title.
void write_class_files(const std::filesystem::path& out, const std::vector<Json>& records,
                       const CaseBook& book, const std::string& title);

}  // namespace jelly::grade
