// jelly-lab: the windowed viewer, or `jelly-lab --headless ...` = `jelly render ...`.
#include <cstring>
#include <string>
#include <vector>

#include "app.hpp"
#include "jelly/movie/render_command.hpp"

int main(int argc, char** argv) {
  if (argc >= 2 &&
      (std::strcmp(argv[1], "--headless") == 0 || std::strcmp(argv[1], "render") == 0)) {
    // Same path as `jelly render`: argv[0] becomes the command name.
    return jelly::movie::render_command(argc - 1, argv + 1);
  }
  jelly::app::AppOptions options;
  if (const auto code = jelly::app::parse_options(argc, argv, options)) return *code;
  return jelly::app::run_app(options);
}
