// The jelly-grade commands, one file each in commands/ (main.cpp reads the command line and calls
// one of them; reports/points.hpp writes the points they print).
#pragma once

#include <filesystem>
#include <set>
#include <string>
#include <tuple>
#include <vector>

#include "class/similarity.hpp"
#include "grading/grade.hpp"
#include "inputs/cases.hpp"
#include "inputs/submissions.hpp"

namespace jelly::grade {

/// What `jelly-grade grade` was asked for besides the grading options.
struct GradeOneArgs {
  std::filesystem::path submission;  ///< SUBMISSION_DIR
  std::filesystem::path out;         ///< --out ("": grade-results)
  std::set<std::string> formats;     ///< --format: "terminal" prints, the others are files in out
  bool verbose = false;              ///< --verbose: every failure message, and the passed tests
  bool frames = true;                ///< false with --no-frames
  bool strict = false;               ///< --strict: exit status 1 unless the score is full
};

/// `grade` (commands/grade.cpp): grades one submission, writes its reports to args.out and prints
/// the terminal summary. The exit status (0, or 1 with --strict when the score is not full).
int grade_one(const GradeConfig& config, const CaseBook& book, const GradeOneArgs& args,
              const GradeOptions& options);

/// `prairielearn` (commands/prairielearn.cpp): PrairieLearn's external grader, grades `student`
/// ("": /grade/student) into `results`/results.json ("": /grade/results).
int prairielearn(const GradeConfig& config, const CaseBook& book, const std::string& student,
                 const std::string& results, const GradeOptions& options);

/// `generate-reference` (commands/generate_reference.cpp): regenerates
/// grader/data/{public,hidden}/*.json from solutions/ with the reference runner.
int generate_reference(const GradeConfig& config, const CaseBook& book);

/// What `jelly-grade batch` was asked for besides the grading options.
struct BatchArgs {
  std::filesystem::path in;   ///< SUBMISSIONS: a folder of submissions (find_submissions)
  std::filesystem::path out;  ///< --out
  int jobs = 0;               ///< --jobs: submissions graded at once (0: one per core)
  bool frames = true;         ///< false with --no-frames
  bool resume = false;        ///< --resume: keep the records a stopped batch made
  int shard_index = 1;        ///< --shard I/N: grade the I-th of N disjoint parts
  int shard_count = 1;
  /// --similarity P: also the class's similarity report at threshold P percent (< 0: none).
  double similarity = -1.0;
};

/// "I/N".
std::string shard_label(int index, int count);

/// `batch` (commands/batch.cpp): grades the submissions in args.in (its shard of them) in
/// parallel: each student's reports and record in args.out/students/<id>/, then the class files
/// (scores.csv, ...) and batch.json (what was graded, for --resume and merge). Exit status 1 when a
/// submission could not be graded.
int batch(const GradeConfig& config, const CaseBook& book, const BatchArgs& args,
          const GradeOptions& options);

/// `merge` (commands/merge.cpp): joins the --out folders of a sharded batch into `out` (which may
/// be one of them): every student's folder, then the class files from all the records, the same
/// bytes one unsharded batch writes. Throws std::runtime_error naming the part when the parts are
/// not one class graded one way (missing shard, a student in two parts, another fingerprint).
int merge(const GradeConfig& config, const CaseBook& book, const std::vector<std::string>& parts,
          const std::filesystem::path& out);

/// The assignment a batch's --out folder was graded for (its batch.json).
std::string batch_assignment(const std::filesystem::path& part);

/// `similarity` (commands/similarity.cpp): every subfolder of `dir` is one student's submission;
/// writes similarity.html and similarity.json into `out` (grader/src/similarity.hpp) and prints
/// how many pairs reach `threshold` percent. 0 whatever it finds: the report is evidence for a
/// person, not a failure.
int similarity_command(const GradeConfig& config, const std::string& dir, const std::string& out,
                       double threshold);
/// The submissions to compare: those that can be graded, one per folder (a Gradescope group's
/// members share theirs).
std::vector<SimilarityInput> similarity_inputs(const std::vector<Submission>& subs);
/// The same for a list of submissions (batch's, or another discovery's).
int similarity(const GradeConfig& config, const std::vector<SimilarityInput>& inputs,
               const std::string& out, double threshold);

/// Shell lines (setup.sh, run_autograder, a PrairieLearn image) that create the unprivileged user
/// of the "user" sandbox and make the grader's secrets under `source` readable by root only.
std::string sandbox_setup_lines(const std::string& source);

/// `gradescope-zip` (commands/gradescope_zip.cpp): builds the Gradescope autograder zip (setup.sh
/// and run_autograder from grader/templates/, the framework without solutions/ but with the
/// hidden data).
int gradescope_zip(const GradeConfig& config, const std::string& zip_path);

/// Records, in the build tree, that `zip` was built from the selected assignment's manifest as it
/// is now (commands/zip_record.cpp).
void record_gradescope_zip(const GradeConfig& config, const std::filesystem::path& zip);
/// One line for standard error when the selected assignment's manifest has changed since the last
/// Gradescope zip built in this build tree (what the change needs: a new zip, a new release);
/// "" when it has not, or when no zip was built here.
std::string stale_gradescope_zip_notice(const GradeConfig& config);

/// One mutant (assignments/<id>/grader/mutants/NAME.toml): a realistic mistake applied to a copy of
/// the reference.
struct MutantSpec {
  std::string name, task, file, description;
  bool public_catches = false;  ///< the handout says the self-check catches it
  std::vector<std::tuple<std::string, std::string, int>> replacements;  ///< find, with, nth
  std::filesystem::path dir;  ///< its submission folder (made by make_mutant_folders)
};

/// Reads every *.toml of `specs_dir` (sorted by name) and writes each mutant's submission folder,
/// `root`/NAME/submission: the reference's task files with its replacements applied. Throws
/// std::runtime_error naming the file when a spec is incomplete or no longer applies.
std::vector<MutantSpec> make_mutant_folders(const GradeConfig& config,
                                            const std::filesystem::path& specs_dir,
                                            const std::filesystem::path& root);

/// What `jelly-grade hints` is asked to do (commands/hints.cpp).
struct HintsArgs {
  std::string out;       ///< --out FILE ("": assignments/<id>/grader/hints.json)
  bool check = false;    ///< --check: regenerate, compare with the file, prove the hints work
  bool digest = false;   ///< --check-digest: only whether the file was made from today's sources
  std::string controls;  ///< --controls DIR: honest mistakes (mutant files) that must get no hint
  std::string work;      ///< --work DIR: where the submissions are graded
};

/// `hints` (commands/hints.cpp): grades the reference, the stubs and every mutant on the public
/// cases and writes each mutant's signature (its outputs on the public cases it fails) to
/// hints.json (hints.hpp). Returns 0, or 1 when a check fails.
int hints(const GradeConfig& config, const CaseBook& book, const HintsArgs& args, int jobs,
          const GradeOptions& options);

/// A submission graded for the hints: the reference, the stubs, a mutant or a control.
struct GradedSubmission {
  std::string name, task, description;
  std::filesystem::path dir;
  GradeReport report;
  std::string error;  ///< the grader's error, when it could not be graded
};

/// `mutants --check-hints` (commands/hints.cpp): `hints --check` on the submissions the mutation
/// self-test has just graded (the reference, the stubs, then the mutants in file-name order, as
/// `hints` grades them), so that they are not graded twice. They were graded with the hidden
/// tests too; the hints look at public cases only, so their signatures and hints are the same.
/// The controls of args.controls are graded here, on the public cases. Returns as `hints`.
int check_hints_of_graded(const GradeConfig& config, const CaseBook& book, const HintsArgs& args,
                          std::vector<GradedSubmission> graded, int jobs,
                          const GradeOptions& options);

/// `mutants` (commands/mutants.cpp): applies every assignments/<id>/grader/mutants/*.toml to a copy
/// of solutions/<id>/,
/// grades each, checks that the reference scores full marks, the stubs zero, and every mutant
/// loses points in its own task only. Writes the table (Markdown) to `table_path` when given.
/// With `hints_check` (--check-hints), also checks hints.json on the same gradings
/// (check_hints_of_graded). Returns 0 when every check holds.
int mutants(const GradeConfig& config, const CaseBook& book, const std::string& table_path,
            const std::string& work, int jobs, const GradeOptions& options,
            const HintsArgs* hints_check = nullptr);

}  // namespace jelly::grade
