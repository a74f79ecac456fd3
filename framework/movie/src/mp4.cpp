#include "jelly/movie/mp4.hpp"

#include <cstdio>
#include <vector>

#include "jelly/process/process.hpp"

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
  const auto ffmpeg = process::find_on_path("ffmpeg");
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
  const std::vector<std::string> argv = {ffmpeg->u8string(),
                                         "-loglevel",
                                         "error",
                                         "-y",
                                         "-framerate",
                                         rate,
                                         "-i",
                                         (frames_dir / "frame_%05d.png").u8string(),
                                         "-vf",
                                         "pad=ceil(iw/2)*2:ceil(ih/2)*2",
                                         "-pix_fmt",
                                         "yuv420p",
                                         "-c:v",
                                         "libx264",
                                         out.u8string()};
  // An hour at most: a movie of a long run at full resolution takes minutes.
  const process::ChildResult run = process::run_child(argv, process::trusted_tool_limits(3600.0));
  if (run.started && !run.timed_out && run.exit_code == 0) {
    r.status = Mp4Result::Status::Written;
    return r;
  }
  r.status = Mp4Result::Status::Failed;
  if (!run.started)
    r.detail = "cannot start " + ffmpeg->string() + ": " + run.start_error;
  else if (run.timed_out)
    r.detail = "ffmpeg took longer than an hour and was stopped";
  else if (run.signal != 0)
    r.detail = "ffmpeg was killed by " + process::describe_signal(run.signal);
  else
    r.detail = "ffmpeg exited with code " + std::to_string(run.exit_code);
  if (!run.err.empty()) r.detail += ": " + run.err;
  return r;
}

}  // namespace jelly::movie
