// `jelly render` (and `jelly-lab --headless`): draws a scene's frames with no display, through the
// same renderer as the window (a backend switch, not a second renderer), and makes the movie
// (jelly/movie/mp4.hpp). The library jelly::movie, which the `jelly` CLI and jelly-lab both link.
#pragma once

namespace jelly::movie {

/// argv[0] is the command name ("render"); then
///   SCENE --frames DIR [--width W] [--height H] [--fps F] [--duration T] [--integrator NAME]
///   [--dt H] [--set key=value ...] [--compare a,b,c] [--backend offscreen|window|null]
///   [--camera YAW,PITCH,DISTANCE] [--particles] [--springs] [--no-caption] [--no-video]
///   [--benchmark N] [--samples 0|2|4]
/// Writes DIR/frame_00000.png …, and DIR/video.mp4 when ffmpeg is on PATH (encode_mp4, mp4.hpp).
/// With `--replay FILE.csv` [--label TEXT] it simulates nothing: it draws the recorded positions of
/// each frame of FILE (replay.hpp) into DIR/frame_00000.png … in file order, the scene giving
/// the terrains and the body.
/// Returns the exit code (0 ok, 1 run error or instability, 2 usage or input error).
int render_command(int argc, char** argv);

}  // namespace jelly::movie
