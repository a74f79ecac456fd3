// The skeleton's accuracy study (kinematics contract §10, docs/skeleton-studies.md): slerp against
// the linear interpolation of Euler angles on a skeleton warp scene, through the task table this
// program links (JELLY_TASKS), as `jelly run` would play it. The study itself is the skeleton
// module's (framework/bodies/skeleton/skeleton_study.cpp); this is its command line.
//
//   skeleton_study SCENE [--set KEY=VALUE]... [--out PREFIX] [--repeats R]
#include <cstdio>
#include <exception>
#include <string>
#include <system_error>
#include <vector>

#include <CLI/CLI.hpp>

#include "jelly/a3/task_table.hpp"
#include "jelly/scene.hpp"
#include "skeleton_study.hpp"

namespace {

constexpr const char* kHelp = R"(usage: skeleton_study SCENE [options]

Compares, on every output frame of a skeleton warp scene (body.mode = "warp"), the warped posture
of the linked tasks (slerp, kinematics contract §5) with the linear interpolation of the Euler
angles: per bone the largest and the mean angle between the two rotations [degrees], the worst
output frame, and the time per frame of each and of forward kinematics (median of --repeats runs).
Writes PREFIX-bones.csv (one row per bone with channels) and PREFIX-frames.csv (one row per output
frame: its input time and the largest angle over the bones).

options:
  --set KEY=VALUE   change a scene parameter (repeatable), as for `jelly run`
  --out PREFIX      output files (default study-SCENENAME)
  --repeats R       timing runs, 1 to 1000 (default 5)

exit codes: 0 done; 2 bad command line, scene, file or slot; 1 a file could not be written.
)";

/// A command-line, scene or file error: the message and exit code 2.
int usage_error(const std::string& message) {
  std::fprintf(stderr, "skeleton_study: %s\n(see skeleton_study --help)\n", message.c_str());
  return 2;
}

}  // namespace

int main(int argc, char** argv) {
  using namespace jelly;
  CLI::App cmd("", "skeleton_study");
  cmd.set_help_flag("-h,--help");
  cmd.allow_windows_style_options(false);
  std::string scene_path, prefix;
  std::vector<std::string> sets;
  int repeats = 5;
  cmd.add_option("SCENE", scene_path)->required();
  cmd.add_option("--set", sets)
      ->allow_extra_args(false)
      ->multi_option_policy(CLI::MultiOptionPolicy::TakeAll);
  cmd.add_option("--out", prefix);
  cmd.add_option("--repeats", repeats)->check(CLI::Range(1, 1000));
  try {
    cmd.parse(argc, argv);
  } catch (const CLI::CallForHelp&) {
    std::fputs(kHelp, stdout);
    return 0;
  } catch (const CLI::ParseError& e) {
    return usage_error(e.what());
  }
  SceneResult loaded = load_scene(scene_path);
  if (!loaded) return usage_error(loaded.error->text());
  SceneSpec scene = *loaded.scene;
  for (const std::string& set : sets)
    if (const auto error = set_assignment(scene, set)) return usage_error(error->text());
  if (prefix.empty()) prefix = "study-" + scene.name;
  try {
    // The assignment's task table as the build links it (JELLY_TASKS: the students' or the
    // reference's), the table `jelly run` plays the scene with.
    std::fputs(bodies::study_skeleton_scene(scene, a3::task_table(), prefix, repeats).c_str(),
               stdout);
  } catch (const std::system_error& e) {
    std::fprintf(stderr, "skeleton_study: %s\n", e.what());
    return 1;
  } catch (const std::exception& e) {
    return usage_error(e.what());
  }
  return 0;
}
