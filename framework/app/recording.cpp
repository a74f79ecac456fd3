// jelly-lab's recording (PNG frames, then an MP4 through jelly::movie's ffmpeg step) and
// screenshots.
#include <cstdio>
#include <ctime>

#include "app_loop.hpp"
#include "jelly/movie/mp4.hpp"

namespace jelly::app {

namespace fs = std::filesystem;
using namespace jelly::render;

namespace {

std::string timestamp() {
  const std::time_t t = std::time(nullptr);
  char buf[32];
  std::strftime(buf, sizeof buf, "%Y%m%d-%H%M%S", std::localtime(&t));
  return buf;
}

}  // namespace

void finish_recording(AppState& s) {
  s.recording = false;
  std::string msg = std::to_string(s.record_frame) + " frames in " + s.record_dir.string();
  if (s.record_frame > 0) {
    // Recorded frames advance 1/30 s x factor each (stepping.cpp): the video plays at 30 fps.
    const fs::path mp4 = s.record_dir / "video.mp4";
    const movie::Mp4Result video = movie::encode_mp4(s.record_dir, 30.0, mp4);
    switch (video.status) {
      case movie::Mp4Result::Status::Written: msg += ", " + mp4.filename().string(); break;
      case movie::Mp4Result::Status::Failed: msg += " (ffmpeg failed: " + video.detail + ")"; break;
      case movie::Mp4Result::Status::NoFfmpeg:
        msg +=
            " (no ffmpeg: PNG only; for video.mp4, " + std::string(movie::kFfmpegInstallHint) + ")";
        break;
    }
  }
  s.record_message = msg;
}

/// Recording control used by the panel.
void toggle_recording(AppState& s) {
  if (s.recording) {
    finish_recording(s);
    return;
  }
  s.record_dir = fs::path("recordings") / timestamp();
  s.record_frame = 0;
  s.recording = true;
  s.record_message = "recording to " + s.record_dir.string();
}

void record_frame(AppState& s, const WindowBackend& window) {
  if (!s.recording) return;
  char name[32];
  std::snprintf(name, sizeof name, "frame_%05d.png", s.record_frame++);
  // Recorded frames show the scene and its printed parameters, not the panels.
  const Image shot = window.read_pixels();
  const std::string err =
      write_png(s.record_dir / name,
                crop(shot, s.frame.left_margin, 0, shot.width - s.frame.left_margin, shot.height));
  if (!err.empty()) {
    s.record_message = err;
    s.recording = false;
  }
}

bool save_screenshot(AppState& s, const fs::path& requested, const WindowBackend& window) {
  const fs::path file =
      !requested.empty() ? requested : fs::path("jelly-lab-" + timestamp() + ".png");
  const std::string err = write_png(file, window.read_pixels());
  s.screenshot_message = err.empty() ? "saved " + file.string() : err;
  std::printf("%s\n", s.screenshot_message.c_str());
  s.screenshot_requested = false;
  return err.empty();
}

}  // namespace jelly::app
