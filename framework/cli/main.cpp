// `jelly`: the headless command line of Jelly Lab.
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <string>

#include "commands.hpp"
#include "jelly/session/scene_catalog.hpp"

#ifdef JELLY_HAVE_RENDER
#include "jelly/movie/render_command.hpp"
#endif
#ifdef JELLY_HAVE_STUDY
#include "study_command.hpp"
#endif

namespace {

constexpr const char* kHelp = R"(usage: jelly COMMAND [options]

commands:
  run SCENE      run a scene headless; write the trajectory and a summary as CSV
  check SCENE    validate a scene; print what it builds and each integrator's stable step size
  params SCENE   list every declared parameter of a scene (key, value, unit, range, meaning)
  probe          list which student tasks of each assignment look implemented in this build
  render SCENE   draw frames (or --replay a recorded run) to PNG without a display (OSMesa)   [when built with the viewer]
  study ...      accuracy against cost; what a parameter does (effects)   [numerics study]

SCENE is a .toml file or the name of one in the scenes folder, for every command.
`jelly COMMAND --help` tells more; the scene format is in docs/scenes.md.
)";

/// The help, its examples computed from the scenes this build finds (a release ships only the
/// scenes its assignments run).
std::string help_text() {
  namespace session = jelly::session;
  const std::filesystem::path dir = session::default_scenes_dir();
  const std::string example = session::example_scene(dir);
  std::string text = kHelp;
  if (!example.empty()) text += "For example: jelly run " + example + "\n";
  return text + session::scenes_line(dir) + "\n";
}

}  // namespace

int main(int argc, char** argv) {
  using namespace jelly::cli;
  if (argc < 2 || !std::strcmp(argv[1], "--help") || !std::strcmp(argv[1], "-h") ||
      !std::strcmp(argv[1], "help")) {
    std::fputs(help_text().c_str(), argc < 2 ? stderr : stdout);
    return argc < 2 ? kExitUsage : kExitOk;
  }
  const std::string command = argv[1];
  try {
    if (command == "run") return run_command(argc, argv);
    if (command == "check") return check_command(argc, argv);
    if (command == "params") return params_command(argc, argv);
    if (command == "probe") return probe_command(argc, argv);
#ifdef JELLY_HAVE_RENDER
    if (command == "render") return jelly::movie::render_command(argc - 1, argv + 1);
#endif
#ifdef JELLY_HAVE_STUDY
    if (command == "study") return study_command(argc, argv);
#endif
  } catch (const std::exception& e) {
    std::fprintf(stderr, "jelly %s: unexpected error: %s\n", command.c_str(), e.what());
    return kExitInternal;
  }
  if (command == "render" || command == "study") {
    std::fprintf(stderr,
                 "jelly: '%s' is not part of this build (configure with the viewer/study on)\n",
                 command.c_str());
    return kExitUsage;
  }
  std::fprintf(stderr, "jelly: unknown command '%s'\n%s", command.c_str(), help_text().c_str());
  return kExitUsage;
}
