// What a frame of the viewer costs A3's player while a warp slider moves (issue 31: "the viewer
// plays at 120 Hz with the warp recomputed while a slider moves", 8.33 ms a frame). Google
// Benchmark, the CPU side only: drawing is the renderer's ("Rendering" in docs/performance.md).
// Results: docs/performance.md ("A3 in the viewer").
//   BM_SliderFrame       one frame with K_in moved by one: SkeletonPlayer::set_warp (every output
//       frame warped through A3's reference time_map and warped_posture, as the viewer does), then
//       the shown frame's and its original's forward kinematics (what the drawable asks), ms
//   BM_SliderFrameHeightPlot   the same, and the warped series of the panel's plot of a bone's
//       end height (forward kinematics of every output frame: bone_series; the original's series
//       is kept while a slider moves), ms
//   BM_PlayFrame         a frame of playback without a slider: one frame further, its forward
//       kinematics and its original's, µs
// The scene is hw2-warp-2022 (punch_kick.amc, 450 → 450 frames, K_in 160 → K_out 150).
#include <benchmark/benchmark.h>

#include <stdexcept>
#include <string>

#include "jelly/a3/task_table.hpp"
#include "jelly/scene.hpp"
#include "jelly/skeleton_player.hpp"
#include "jelly/skeleton_tasks.hpp"

namespace jelly {
namespace {

SceneSpec warp_scene() {
  const SceneResult r = load_scene(std::string(JELLY_SOURCE_DIR) + "/scenes/hw2-warp-2022.toml");
  if (!r) throw std::runtime_error(r.error->text());
  return *r.scene;
}

/// The player of the 2022 warp with A3's reference tasks; stops the benchmark on a problem.
struct Viewer {
  TaskTable table = a3::task_table();
  SkeletonPlayer player{warp_scene(), skeleton_tasks(table)};
};

/// The shown frame's bone frames and its original's, as the drawable asks them.
double shown(const SkeletonPlayer& p, int frame) {
  const skeleton::BoneFrames* out = p.output_frames(frame);
  const skeleton::BoneFrames* in = p.input_frames(frame);
  if (!out || !in) throw std::runtime_error("no bone frames: " + p.problem());
  return out->end.back().y() + in->end.back().y();
}

void slider_frames(benchmark::State& state, bool plot) {
  Viewer v;
  skeleton::TimeWarp w = v.player.warp();
  const int frame = 200, bone = 20;
  int moves = 0;
  for (auto _ : state) {
    w.keyframe_in = 160 + (moves++ & 1);  // the slider moves by one each frame
    if (std::string e = v.player.set_warp(w); !e.empty()) {
      state.SkipWithError(e.c_str());
      break;
    }
    v.player.seek(frame);
    double y = shown(v.player, frame);
    if (plot) y += bone_series(v.player, bone, BoneQuantity::Height, false).back();
    benchmark::DoNotOptimize(y);
  }
  state.counters["frames"] = v.player.frame_count();
}

void BM_SliderFrame(benchmark::State& s) { slider_frames(s, false); }
void BM_SliderFrameHeightPlot(benchmark::State& s) { slider_frames(s, true); }

void BM_PlayFrame(benchmark::State& state) {
  Viewer v;
  int frame = 0;
  for (auto _ : state) {
    frame = (frame + 1) % v.player.frame_count();
    v.player.seek(frame);
    benchmark::DoNotOptimize(shown(v.player, frame));
  }
}

BENCHMARK(BM_SliderFrame)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_SliderFrameHeightPlot)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_PlayFrame)->Unit(benchmark::kMicrosecond);

}  // namespace
}  // namespace jelly

BENCHMARK_MAIN();
