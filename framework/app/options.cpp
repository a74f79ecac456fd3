// jelly-lab's command line (CLI11 through jelly::cli::Command, as every Jelly Lab program).
#include <cstdio>
#include <sstream>

#include "app.hpp"
#include "jelly/cli_common/command_line.hpp"
#include "jelly/render/body_view.hpp"

namespace jelly::app {

namespace {

/// The usage; each body kind with a view adds its panel to --open's list and its line of keys.
std::string usage_text() {
  std::string panels, keys;
  for (const render::BodyView* view : render::body_views()) {
    if (!view->panel_id().empty()) panels += std::string(view->panel_id()) + ",";
    if (!view->keys_help().empty()) keys += std::string(view->keys_help()) + "\n";
  }
  return "usage: jelly-lab [SCENE] [--scenes DIR] [--integrator NAME] [--dt H] [--compare "
         "a,b[,c[,d]]]\n"
         "                 [--slot-set K:key=value ...] (run K of --compare gets its own "
         "parameter)\n"
         "                 [--size WxH] [--backend window|auto] [--factor F] [--particles] "
         "[--springs]\n"
         "                 [--smoke-test] [--screenshot FILE] [--shot-at T] [--benchmark N] "
         "[--samples 0|2|4]\n"
         "                 [--open scene,simulation," +
         panels +
         "comparison,parameters,draw,plots,recording]\n"
         "       jelly-lab --headless SCENE --frames DIR ...   (same as `jelly render`, no "
         "display)\n"
         "keys: space play/pause, N single step, R reset, C reset camera, P screenshot, Esc "
         "quit\n" +
         keys +
         "mouse: left-drag orbit, wheel zoom\n"
         "exit codes: 0 closed normally; 1 no window could be opened, a screenshot could not be "
         "written or\n"
         "the smoke test failed; 2 bad command line or scene input.\n";
}

/// An integrator's name, e.g. for --integrator and each of --compare a,b.
CLI::Validator integrator_name() {
  return CLI::Validator(
      [](std::string& name) {
        return integrator_from_string(name)
                   ? std::string()
                   : "unknown integrator '" + name +
                         "' (explicit_euler, implicit_euler, midpoint, rk4, "
                         "symplectic_euler, backward_euler)";
      },
      "");
}

}  // namespace

std::optional<int> parse_options(int argc, char** argv, AppOptions& o) {
  using namespace jelly::cli;
  const std::string usage = usage_text();
  Command cmd("jelly-lab", usage, usage);
  std::string scenes_dir, screenshot, size, open;
  std::vector<std::string> slot_sets;
  cmd.add_option("SCENE", o.scene);
  cmd.add_option("--scenes", scenes_dir)->type_name("DIR");
  cmd.add_option("--integrator", o.integrator)->type_name("NAME")->check(integrator_name());
  cmd.add_option("--dt", o.dt)->type_name("H")->check(positive_number(true));
  cmd.add_option("--shot-at", o.shot_at)->type_name("T")->check(positive_number(true));
  cmd.add_option("--factor", o.factor)->type_name("F")->check(positive_number(true));
  cmd.add_option("--benchmark", o.benchmark)->type_name("N")->check(whole_number(0));
  cmd.add_option("--samples", o.samples)->type_name("0|2|4")->check(whole_number(0));
  cmd.add_option("--compare", o.compare)
      ->type_name("A,B[,C[,D]]")
      ->delimiter(',')
      ->check(integrator_name())
      ->multi_option_policy(CLI::MultiOptionPolicy::TakeAll);
  cmd.repeated("--slot-set", slot_sets, "K:KEY=VALUE");
  cmd.add_option("--size", size)->type_name("WxH");
  cmd.add_option("--backend", o.backend)->type_name("window|auto");
  cmd.add_option("--open", open)->type_name("PANELS");
  cmd.add_flag("--smoke-test", o.smoke_test);
  cmd.add_option("--screenshot", screenshot)->type_name("FILE");
  cmd.add_flag("--particles", o.particles);
  cmd.add_flag("--springs", o.springs);
  if (const auto code = cmd.parse_args(argc, argv, 1)) return code;

  if (o.backend != "window" && o.backend != "auto")
    return cmd.error(
        "--backend for the app is window or auto (use --headless for offscreen), got '" +
        o.backend + "'");
  if (!scenes_dir.empty()) o.scenes_dir = scenes_dir;
  if (!screenshot.empty()) o.screenshot = screenshot;
  if (!o.compare.empty() && (o.compare.size() < 2 || o.compare.size() > 4))
    return cmd.error("--compare takes 2 to 4 integrators");
  for (const std::string& v : slot_sets) {
    const std::size_t colon = v.find(':');
    int k = 0;
    if (colon == std::string::npos || std::sscanf(v.substr(0, colon).c_str(), "%d", &k) != 1 ||
        k < 1 || k > 4 || v.find('=', colon) == std::string::npos)
      return cmd.error("--slot-set needs K:key=value with K from 1 to 4, got '" + v + "'");
    o.slot_sets.emplace_back(k, v.substr(colon + 1));
  }
  if (!size.empty() && (std::sscanf(size.c_str(), "%dx%d", &o.width, &o.height) != 2 ||
                        o.width < 320 || o.height < 240))
    return cmd.error("--size needs WxH (at least 320x240), got '" + size + "'");
  std::stringstream panels(open);
  for (std::string item; std::getline(panels, item, ',');) o.open_panels.push_back(item);
  return std::nullopt;
}

}  // namespace jelly::app
