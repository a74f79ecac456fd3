// A jelly-grade built without yaml-cpp and libzip: a student's self-check
// (JELLY_GRADER_SECCOMP=OFF, Windows, macOS), which grades the student's own folder and never a
// class's export. Reading a Gradescope export or a zip of a class says which build can.
#include <stdexcept>

#include "inputs/class_archives.hpp"
#include "inputs/submissions.hpp"

namespace jelly::grade {

namespace {
[[noreturn]] void instructor_only(const std::string& what, const std::string& package) {
  throw std::runtime_error(what + ": this jelly-grade was built without " + package +
                           " (a student's self-check build): reading a class's export is the "
                           "instructor's grader's job (Linux with its sandbox; sudo "
                           "tools/install-deps.sh installs what it needs)");
}
}  // namespace

std::vector<std::string> zip_entry_names(const std::filesystem::path&, const std::string& shown) {
  instructor_only(shown, "libzip");
}

std::vector<GradescopeEntry> read_gradescope_metadata(const std::string&, const std::string& file) {
  instructor_only(file, "yaml-cpp");
}

}  // namespace jelly::grade
