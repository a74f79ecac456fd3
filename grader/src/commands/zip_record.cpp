// What the last Gradescope zip of an assignment was built from, so that every later command can
// say when the manifest (the rubric) has changed since: the grader reads the manifest at once,
// but Gradescope grades with the zip that was uploaded, and students self-check with the release
// they were given.
#include <fstream>
#include <string>

#include "commands/commands.hpp"
#include "inputs/files.hpp"

namespace jelly::grade {

namespace {

constexpr const char* kZipLine = "# jelly-grade gradescope-zip wrote ";

/// BUILD/grader/gradescope-zips/<id>.toml: a first line naming the zip, then the manifest's bytes.
fs::path zip_record(const GradeConfig& config) {
  return config.binary_dir / "grader" / "gradescope-zips" / (config.assignment().id + ".toml");
}

fs::path manifest_path(const GradeConfig& config) {
  return config.assignment().dir / "assignment.toml";
}

}  // namespace

void record_gradescope_zip(const GradeConfig& config, const fs::path& zip) {
  const fs::path record = zip_record(config);
  fs::create_directories(record.parent_path());
  std::ofstream(record, std::ios::binary) << kZipLine << zip.string() << "\n"
                                          << read_file(manifest_path(config));
}

std::string stale_gradescope_zip_notice(const GradeConfig& config) {
  const std::string record = read_file(zip_record(config));
  const std::string prefix = kZipLine;
  const auto eol = record.find('\n');
  if (record.compare(0, prefix.size(), prefix) != 0 || eol == std::string::npos) return "";
  if (record.substr(eol + 1) == read_file(manifest_path(config))) return "";
  const std::string zip = record.substr(prefix.size(), eol - prefix.size());
  const std::string id = config.assignment().id;
  return "jelly-grade: " + manifest_path(config).string() + " changed after the Gradescope zip " +
         zip + " was built: this grader uses the new manifest now, but Gradescope grades with " +
         "the zip you uploaded (build and upload a new one: jelly-grade gradescope-zip OUT.zip " +
         "--assignment " + id + ") and students self-check with the release they have (publish " +
         "a new one: tools/make-student-release)";
}

}  // namespace jelly::grade
