#include "jelly/movie/mp4.hpp"

#include <cstdio>
#include <vector>

#include "run_program.hpp"

namespace jelly::movie {

#ifdef _WIN32
const char* const kFfmpegInstallHint =
    "install ffmpeg (https://ffmpeg.org/download.html) and put the folder of ffmpeg.exe on PATH";
#else
const char* const kFfmpegInstallHint =
    "install ffmpeg: apt-get install ffmpeg on Debian/Ubuntu, or tools/install-deps.sh --ffmpeg";
#endif

Mp4Result encode_mp4(const std::filesystem::path& frames_dir, double fps,
                     const std::filesystem::path& out) {
  Mp4Result r;
  const auto ffmpeg = find_on_path("ffmpeg");
  if (!ffmpeg) {
    r.status = Mp4Result::Status::NoFfmpeg;
    return r;
  }
  char rate[32];
  std::snprintf(rate, sizeof rate, "%g", fps);
  // ffmpeg -loglevel error -y -framerate FPS -i DIR/frame_%05d.png
  //        -vf pad=ceil(iw/2)*2:ceil(ih/2)*2 -pix_fmt yuv420p -c:v libx264 OUT
  // The frames' numbering is the render command's and the app's. libx264 wants even sizes, hence
  // the padding; yuv420p is what every player decodes.
  const std::vector<std::string> args = {"-loglevel",
                                         "error",
                                         "-y",
                                         "-framerate",
                                         rate,
                                         "-i",
                                         (frames_dir / "frame_%05d.png").string(),
                                         "-vf",
                                         "pad=ceil(iw/2)*2:ceil(ih/2)*2",
                                         "-pix_fmt",
                                         "yuv420p",
                                         "-c:v",
                                         "libx264",
                                         out.string()};
  const ProgramResult run = run_program(*ffmpeg, args);
  if (run.started && run.exit_code == 0 && run.error.empty()) {
    r.status = Mp4Result::Status::Written;
    return r;
  }
  r.status = Mp4Result::Status::Failed;
  r.detail =
      !run.error.empty() ? run.error : "ffmpeg exited with code " + std::to_string(run.exit_code);
  return r;
}

}  // namespace jelly::movie
