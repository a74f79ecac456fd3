// The one MP4 step of Jelly Lab: numbered PNG frames to an H.264 video through ffmpeg, for
// `jelly render` and for jelly-lab's recordings. ffmpeg is optional (Debian package `ffmpeg`,
// `tools/install-deps.sh --ffmpeg`); without it the frames stay PNG.
#pragma once

#include <filesystem>
#include <string>

namespace jelly::movie {

/// What encode_mp4 did.
struct Mp4Result {
  enum class Status {
    Written,   ///< `out` was written
    NoFfmpeg,  ///< no ffmpeg on PATH: nothing was run
    Failed,    ///< ffmpeg could not be started or did not exit 0
  };
  Status status = Status::NoFfmpeg;
  std::string detail;  ///< Failed: how (ffmpeg's exit code, or why it could not start)
};

/// How to get ffmpeg, for the "no ffmpeg" messages: "install ffmpeg: apt-get install ffmpeg …".
extern const char* const kFfmpegInstallHint;

/// Encodes `frames_dir`/frame_00000.png, frame_00001.png, … (every frame up to the first gap)
/// into `out`: H.264 (libx264), yuv420p, `fps` frames per second, the size padded up to even.
/// Runs ffmpeg from PATH with an argument vector (no shell, so no quoting of the paths); its
/// errors go to this process's stderr, it reads nothing from stdin. Overwrites `out`.
Mp4Result encode_mp4(const std::filesystem::path& frames_dir, double fps,
                     const std::filesystem::path& out);

}  // namespace jelly::movie
