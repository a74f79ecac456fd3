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

#include "jelly/cli_common/command_line.hpp"
#include "jelly/scene.hpp"
#include "jelly/session/assignments.hpp"
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

}  // namespace

int main(int argc, char** argv) {
  using namespace jelly;
  using namespace jelly::cli;
  Command cmd("skeleton_study", kHelp, "(see skeleton_study --help)\n");
  std::string scene_path, prefix;
  std::vector<std::string> sets;
  int repeats = 5;
  cmd.add_option("SCENE", scene_path)->required();
  cmd.repeated("--set", sets, "KEY=VALUE");
  cmd.add_option("--out", prefix)->type_name("PREFIX");
  cmd.add_option("--repeats", repeats)->type_name("R")->check(CLI::Range(1, 1000));
  if (const auto code = cmd.parse_args(argc, argv, 1)) return *code;
  SceneResult loaded = load_scene(scene_path);
  if (!loaded) return cmd.error(loaded.error->text());
  SceneSpec scene = *loaded.scene;
  for (const std::string& set : sets)
    if (const auto error = set_assignment(scene, set)) return cmd.error(error->text());
  if (prefix.empty()) prefix = "study-" + scene.name;
  try {
    std::fputs(
        bodies::study_skeleton_scene(scene, session::tasks_for(scene), prefix, repeats).c_str(),
        stdout);
  } catch (const std::system_error& e) {
    std::fprintf(stderr, "skeleton_study: %s\n", e.what());
    return kExitInternal;
  } catch (const std::exception& e) {
    return cmd.error(e.what());
  }
  return kExitOk;
}
