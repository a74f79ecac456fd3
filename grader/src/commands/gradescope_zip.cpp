#include "commands/commands.hpp"

#include <fstream>
#include <iostream>
#include <stdexcept>

#include "commands/templates.hpp"

namespace jelly::grade {

std::string sandbox_setup_lines(const std::string& source) {
  // One sandbox user per core: each concurrent compile or test runs as a user of its own, so that
  // killing what one run left behind never touches another (isolation.hpp). The secrets: the
  // hidden data (grader/data/<id>/hidden) and the case files, which list the hidden cases, of
  // every assignment the tree holds (a shell pattern: the zip holds one).
  const std::string user = std::string(kSandboxUser) + "-$i";
  const std::string secrets = source + "/grader/data " + source + "/assignments/*/grader/cases";
  return std::string("for i in $(seq 0 $(( $(nproc) - 1 ))); do id -u ") + user +
         " >/dev/null 2>&1 || useradd --system --no-create-home --user-group --shell " +
         "/usr/sbin/nologin " + user + "; done\n" + "chown root:root " + secrets + "\n" +
         "chmod 0700 " + secrets + "\n" + "if [ -d " + source +
         "/build/grader/object-cache ]; then chmod 0700 " + source +
         "/build/grader/object-cache; fi\n";
}

namespace {

/// Copies the header folder INCLUDE_DIR/SUBDIR (which must hold FILE) into the zip's
/// source/third_party/NAME/include/SUBDIR with the first licence that exists; says what is
/// missing and returns false when the headers are not there.
bool bundle_headers(const fs::path& stage, const std::string& name, const fs::path& include_dir,
                    const std::string& subdir, const std::string& file,
                    const std::vector<fs::path>& licences, const std::string& package) {
  const fs::path headers = include_dir / subdir;
  const fs::path bundle = stage / "source" / "third_party" / name;
  if (!fs::exists(headers / file)) {
    std::cerr << "jelly-grade: gradescope-zip: " << name << " headers not found at "
              << headers.string() << " (expected " << file << " there; install " << package
              << ")\n";
    return false;
  }
  fs::create_directories(bundle / "include");
  fs::copy(headers, bundle / "include" / subdir, fs::copy_options::recursive);
  for (const fs::path& licence : licences)
    if (fs::exists(licence)) {
      fs::copy_file(licence, bundle / "LICENSE", fs::copy_options::overwrite_existing);
      break;
    }
  return true;
}

/// `text` with its placeholder line "@SANDBOX_SETUP_LINES@" replaced by `lines` and every
/// "@ASSIGNMENT@" by the assignment's id (the scripts grade that one assignment). A template
/// without either is a grader bug (grader/templates/ edited by hand): said so, and nothing is
/// written.
std::string with_sandbox_setup(std::string_view text, const std::string& lines,
                               const std::string& assignment, const char* template_name) {
  const std::string placeholder = "@SANDBOX_SETUP_LINES@\n";
  std::string out(text);
  const auto at = out.find(placeholder);
  if (at == std::string::npos)
    throw std::logic_error(std::string("grader/templates/") + template_name + " has no line " +
                           placeholder.substr(0, placeholder.size() - 1));
  out.replace(at, placeholder.size(), lines);
  const std::string id_placeholder = "@ASSIGNMENT@";
  if (out.find(id_placeholder) == std::string::npos)
    throw std::logic_error(std::string("grader/templates/") + template_name + " never names " +
                           id_placeholder + " (the assignment it grades)");
  for (auto pos = out.find(id_placeholder); pos != std::string::npos;
       pos = out.find(id_placeholder, pos + assignment.size()))
    out.replace(pos, id_placeholder.size(), assignment);
  return out;
}

/// The framework as a student release has it (scenes included), with ONE assignment (the selected
/// one: its folder with its manifest, cases, runner and public data) plus its hidden data; never
/// solutions/. Everything, setup.sh and run_autograder included, sits at the zip's top level:
/// Gradescope extracts the zip into /autograder/source, where both scripts expect the framework's
/// CMakeLists.txt (and copies run_autograder to /autograder/run_autograder).
void stage_source(const GradeConfig& config, const fs::path& stage) {
  const AssignmentConfig& assignment = config.assignment();
  // scenes/: the assignment's default scene is compiled into the programs (the report's frames).
  for (const char* item : {"CMakeLists.txt", "cmake", "framework", "grader", "scenes"}) {
    const fs::path from = config.source_dir / item;
    if (!fs::exists(from)) continue;
    fs::copy(from, stage / "source" / item, fs::copy_options::recursive);
  }
  const fs::path assignments = stage / "source" / "assignments";
  fs::create_directories(assignments);
  fs::copy(assignment.dir, assignments / assignment.id, fs::copy_options::recursive);
  // The manifest's keys as tools/jelly_manifest.py wrote them for this build: the zip has no tools/
  // and Gradescope's image may have no Python 3.11, so its CMake reads them from this file.
  fs::path keys_name = assignment.dir.filename();
  keys_name += ".cmake";
  const fs::path keys = config.binary_dir / "jelly-manifests" / keys_name;
  if (fs::exists(keys))
    fs::copy_file(keys, assignments / assignment.id / "assignment.keys.cmake",
                  fs::copy_options::overwrite_existing);
  // Not needed to grade: the grader's own tests, the other assignments' hidden data; and never
  // anything derived from a reference: solutions/, every assignment's mutants (they quote it).
  fs::remove_all(stage / "source" / "grader" / "tests");
  const fs::path data = stage / "source" / "grader" / "data";
  if (fs::is_directory(data))
    for (const fs::directory_entry& e : fs::directory_iterator(data))
      if (e.path().filename() != assignment.id) fs::remove_all(e.path());
  fs::remove_all(stage / "source" / "solutions");
  for (const fs::directory_entry& e : fs::directory_iterator(assignments))
    fs::remove_all(e.path() / "grader" / "mutants");
}

/// toml++'s and CLI11's headers, for an image without libtomlplusplus-dev or libcli11-dev
/// (Gradescope's Ubuntu): the build then uses them header-only (cmake/JellyDeps.cmake). Taken from
/// this machine, with their licences. False (said) when they are not here.
bool bundle_third_party(const fs::path& stage) {
  return bundle_headers(stage, "tomlplusplus", JELLY_TOMLPLUSPLUS_INCLUDE_DIR, "toml++", "toml.h",
                        {"/usr/share/doc/libtomlplusplus-dev/copyright",
                         JELLY_TOMLPLUSPLUS_INCLUDE_DIR "/../LICENSE"},
                        "libtomlplusplus-dev") &&
         bundle_headers(
             stage, "cli11", JELLY_CLI11_INCLUDE_DIR, "CLI", "CLI.hpp",
             {"/usr/share/doc/libcli11-dev/copyright", JELLY_CLI11_INCLUDE_DIR "/../LICENSE"},
             "libcli11-dev");
}

/// setup.sh and run_autograder at the top of the zip. setup.sh's compiler check sits between its
/// "# BEGIN compiler check" and "# END compiler check" lines
/// (tests/grader/commands/setup_compiler_check.sh runs the block alone with stand-in compilers):
/// the framework needs GCC 11 or newer (floating-point std::to_chars) and CMake 3.16 or newer.
/// Gradescope's Ubuntu 22.04 base image has GCC 11.4 and CMake 3.22; on an older image the block
/// installs g++-11 where the archive has it, else it stops naming what to choose. The compiler it
/// settles on is exported as CXX for CMake.
void write_scripts(const fs::path& stage, const std::string& assignment) {
  const std::string sandbox = sandbox_setup_lines("/autograder/source");
  const std::string setup =
      with_sandbox_setup(gradescope_setup_template(), sandbox, assignment, "setup.sh.in");
  const std::string run = with_sandbox_setup(gradescope_run_autograder_template(), sandbox,
                                             assignment, "run_autograder.in");
  std::ofstream(stage / "source" / "setup.sh", std::ios::binary) << setup;
  std::ofstream(stage / "source" / "run_autograder", std::ios::binary) << run;
  fs::permissions(stage / "source" / "setup.sh",
                  fs::perms::owner_all | fs::perms::group_read | fs::perms::others_read);
  fs::permissions(stage / "source" / "run_autograder",
                  fs::perms::owner_all | fs::perms::group_read | fs::perms::others_read);
}

}  // namespace

int gradescope_zip(const GradeConfig& config, const std::string& zip_path) {
  const fs::path stage = config.binary_dir / "grader" / "gradescope-zip";
  fs::remove_all(stage);
  // The staging folder holds the hidden data and cases: it goes as soon as the zip is written (or
  // failed), whatever happens.
  struct RemoveStage {
    fs::path dir;
    ~RemoveStage() {
      std::error_code ec;
      fs::remove_all(dir, ec);
    }
  } remove_stage{stage};
  fs::create_directories(stage / "source");
  const AssignmentConfig& assignment = config.assignment();
  stage_source(config, stage);
  if (!bundle_third_party(stage)) return 2;
  write_scripts(stage, assignment.id);
  const fs::path zip = fs::absolute(zip_path);
  fs::remove(zip);
  const Limits lim = trusted_tool_limits(300.0);
  const ChildResult c =
      run_child({"/usr/bin/zip", "-q", "-r", zip.string(), "."}, lim, stage / "source");
  if (c.exit_code != 0) {
    std::cerr << "jelly-grade: zip failed: " << c.err << "\n";
    return 2;
  }
  record_gradescope_zip(config, zip);
  std::cout << "jelly-grade: wrote " << zip.string() << " for assignment " << assignment.id
            << " (setup.sh, run_autograder and the framework without solutions/, all at the top: "
               "Gradescope extracts it into /autograder/source)\n";
  return 0;
}

}  // namespace jelly::grade
