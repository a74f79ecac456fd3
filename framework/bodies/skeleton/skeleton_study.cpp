// The accuracy study of a skeleton warp scene: slerp against the linear interpolation of Euler
// angles on the scene's own warp (kinematics contract §10; docs/skeleton-studies.md).
#include "skeleton_study.hpp"

#include <algorithm>
#include <cmath>
#include <ctime>
#include <functional>
#include <memory>
#include <stdexcept>
#include <system_error>

#include "jelly/portable_math.hpp"
#include "jelly/recorder.hpp"
#include "jelly/skeleton/rotation.hpp"
#include "jelly/skeleton_scene.hpp"

namespace jelly::bodies {

namespace {

using skeleton::Motion;
using skeleton::Posture;

constexpr double kDegreesPerRadian = 180.0 / 3.14159265358979323846;

/// The input time of every output frame, checked.
std::vector<double> input_times(const skeleton::TimeWarp& warp, const SkeletonTasks& tasks) {
  std::vector<double> s(static_cast<std::size_t>(warp.output_frames));
  for (int i = 0; i < warp.output_frames; ++i) {
    s[i] = tasks.time_map(i, warp);
    if (!(s[i] >= 0.0 && s[i] <= warp.input_frames - 1))
      throw std::runtime_error("task time_map, output frame " + std::to_string(i) +
                               ": returned s outside 0 ≤ s ≤ N − 1");
  }
  return s;
}

/// Median processor time [µs] of `repeats` runs of `body`, divided by `frames` (std::clock: the
/// time this process ran, so that other programs sharing the machine count less than in wall time).
double median_us_per_frame(int repeats, int frames, const std::function<void()>& body) {
  std::vector<double> us;
  for (int r = 0; r < std::max(1, repeats); ++r) {
    const std::clock_t start = std::clock();
    body();
    const std::clock_t stop = std::clock();
    us.push_back(1e6 * static_cast<double>(stop - start) / CLOCKS_PER_SEC);
  }
  std::nth_element(us.begin(), us.begin() + us.size() / 2, us.end());
  return us[us.size() / 2] / frames;
}

/// The errors of every bone with channels over the frames (no timing).
void measure_errors(const SkeletonInputs& in, const std::vector<double>& times,
                    const SkeletonTasks& tasks, InterpolationStudy& out) {
  const skeleton::Skeleton& sk = in.skeleton;
  for (std::size_t b = 0; b < sk.bones.size(); ++b)
    if (!sk.bones[b].channels.empty())
      out.bones.push_back(
          {static_cast<int>(b), sk.bones[b].name, static_cast<int>(sk.bones[b].channels.size())});
  Posture slerped, lerped;
  double sum = 0.0;
  for (int i = 0; i < out.output_frames; ++i) {
    slerped = Posture::zero(sk.bones.size());
    tasks.warped_posture(sk, in.motion, times[i], slerped);
    euler_lerp_posture(in.motion, times[i], lerped);
    double frame_max = 0.0;
    for (BoneInterpolationError& e : out.bones) {
      const double a = rotation_angle_degrees(slerped.angles.at(e.bone), lerped.angles[e.bone]);
      e.mean_degrees += a;
      sum += a;
      frame_max = std::max(frame_max, a);
      if (a > e.max_degrees) {
        e.max_degrees = a;
        e.worst_frame = i;
        e.worst_s = times[i];
      }
      if (a > out.max_degrees) {
        out.max_degrees = a;
        out.worst_bone = e.bone;
        out.worst_frame = i;
      }
    }
    out.frame_max_degrees.push_back(frame_max);
  }
  for (BoneInterpolationError& e : out.bones) e.mean_degrees /= out.output_frames;
  out.mean_degrees = sum / (static_cast<double>(out.output_frames) * out.bones.size());
}

/// The time per frame of slerp, of the Euler lerp and of forward kinematics.
void measure_costs(const SkeletonInputs& in, const std::vector<double>& times,
                   const SkeletonTasks& tasks, int repeats, InterpolationStudy& out) {
  const skeleton::Skeleton& sk = in.skeleton;
  const int m = out.output_frames;
  std::vector<Posture> postures(m, Posture::zero(sk.bones.size()));
  out.slerp_us_per_frame = median_us_per_frame(repeats, m, [&] {
    for (int i = 0; i < m; ++i) tasks.warped_posture(sk, in.motion, times[i], postures[i]);
  });
  Posture lerped;
  double sink = 0.0;  // keeps the lerp from being optimised away
  out.lerp_us_per_frame = median_us_per_frame(repeats, m, [&] {
    for (int i = 0; i < m; ++i) {
      euler_lerp_posture(in.motion, times[i], lerped);
      sink += lerped.angles.back().x();
    }
  });
  skeleton::BoneFrames frames;
  out.fk_us_per_frame = median_us_per_frame(repeats, m, [&] {
    for (int i = 0; i < m; ++i) tasks.forward_kinematics(sk, postures[i], frames);
  });
  if (!std::isfinite(sink)) out.lerp_us_per_frame = std::nan("");
}

}  // namespace

double rotation_angle_degrees(const Vec3& a, const Vec3& b) {
  const skeleton::Quaternion qa = skeleton::euler_to_quaternion(a);
  const skeleton::Quaternion qb = skeleton::euler_to_quaternion(b);
  const skeleton::Quaternion rel = skeleton::multiply(qa.conjugate(), qb);
  return 2.0 * portable::atan2(rel.vec().norm(), std::fabs(rel.w())) * kDegreesPerRadian;
}

void euler_lerp_posture(const Motion& input, double s, Posture& out) {
  const int last = static_cast<int>(input.frames.size()) - 1;
  const int l = std::min(static_cast<int>(std::floor(s)), last);
  const int r = std::min(l + 1, last);
  const double t = s - l;
  const Posture& left = input.frames[l];
  const Posture& right = input.frames[r];
  out.angles.resize(left.angles.size());
  out.root_translation = (1.0 - t) * left.root_translation + t * right.root_translation;
  for (std::size_t b = 0; b < left.angles.size(); ++b)
    out.angles[b] = (1.0 - t) * left.angles[b] + t * right.angles[b];
}

InterpolationStudy study_interpolation(const SkeletonInputs& in, const skeleton::TimeWarp& warp,
                                       const SkeletonTasks& tasks, int repeats) {
  const auto require = [](bool filled, const char* name) {
    if (!filled)
      throw std::runtime_error(std::string("the interpolation study needs the task ") + name +
                               ", and this program's tasks do not fill it");
  };
  require(tasks.time_map != nullptr, "time_map");
  require(tasks.warped_posture != nullptr, "warped_posture");
  require(tasks.forward_kinematics != nullptr, "forward_kinematics");
  InterpolationStudy out;
  out.input_frames = warp.input_frames;
  out.output_frames = warp.output_frames;
  out.frame_s = input_times(warp, tasks);
  measure_errors(in, out.frame_s, tasks, out);
  measure_costs(in, out.frame_s, tasks, repeats, out);
  return out;
}

namespace {

/// An output file of the study; a file that cannot be opened is an output error.
std::unique_ptr<CsvWriter> open_output(const std::string& path, const char* header) {
  try {
    return std::make_unique<CsvWriter>(path, header);
  } catch (const std::runtime_error& e) {
    throw std::system_error(std::make_error_code(std::errc::io_error), e.what());
  }
}

void write_bones(const std::string& path, const InterpolationStudy& st) {
  const auto out = open_output(
      path, "bone,name,channels,max_degrees,mean_degrees,worst_output_frame,worst_input_time");
  for (const BoneInterpolationError& e : st.bones)
    out->write_cells({static_cast<double>(e.bone), e.name, static_cast<double>(e.channels),
                      e.max_degrees, e.mean_degrees, static_cast<double>(e.worst_frame),
                      e.worst_s});
  out->flush();
}

void write_frames(const std::string& path, const InterpolationStudy& st) {
  const auto out = open_output(path, "output_frame,input_time,max_degrees");
  for (int i = 0; i < st.output_frames; ++i)
    out->write_row({static_cast<double>(i), st.frame_s[i], st.frame_max_degrees[i]});
  out->flush();
}

/// The warp a scene asks for; throws when the scene plays no warp.
skeleton::TimeWarp scene_warp(const SceneSpec& scene, const SkeletonInputs& in) {
  const SkeletonSceneSpec& k = skeleton_scene(scene);
  if (k.mode != SkeletonMode::Warp)
    throw std::runtime_error(
        "the skeleton's accuracy study compares slerp with Euler lerp on a "
        "warp: " +
        scene.name + " has body.mode = \"" + std::string(skeleton_mode_name(k.mode)) +
        "\" (give a scene with body.mode = \"warp\")");
  skeleton::TimeWarp warp;
  warp.input_frames = static_cast<int>(in.motion.frames.size());
  warp.output_frames = skeleton_output_frames(scene, in);
  warp.keyframe_in = static_cast<int>(k.keyframe_in);
  warp.keyframe_out = static_cast<int>(k.keyframe_out);
  return warp;
}

std::string report(const SceneSpec& scene, const SkeletonInputs& in, const InterpolationStudy& st) {
  const BoneInterpolationError& worst =
      *std::max_element(st.bones.begin(), st.bones.end(),
                        [](const auto& a, const auto& b) { return a.max_degrees < b.max_degrees; });
  return text_printf(
      "%s: slerp against Euler lerp on a warp of %s, %d -> %d frames, %zu bones with channels\n"
      "  angle between them: max %.6g deg (bone %s, output frame %d, s = %.6g), mean %.6g deg\n"
      "  time per frame: slerp (warped_posture) %.4g us, Euler lerp %.4g us, forward kinematics "
      "%.4g us\n",
      scene.name.c_str(), in.amc_file.c_str(), st.input_frames, st.output_frames, st.bones.size(),
      st.max_degrees, worst.name.c_str(), worst.worst_frame, worst.worst_s, st.mean_degrees,
      st.slerp_us_per_frame, st.lerp_us_per_frame, st.fk_us_per_frame);
}

}  // namespace

std::string study_skeleton_scene(const SceneSpec& scene, const TaskTable& tasks,
                                 const std::string& prefix, int repeats) {
  const SkeletonInputs in = read_skeleton_inputs(scene);
  const skeleton::TimeWarp warp = scene_warp(scene, in);
  const InterpolationStudy st = study_interpolation(in, warp, skeleton_tasks(tasks), repeats);
  const std::string bones = prefix + "-bones.csv", frames = prefix + "-frames.csv";
  write_bones(bones, st);
  write_frames(frames, st);
  return report(scene, in, st) + "  wrote " + bones + " and " + frames + "\n";
}

}  // namespace jelly::bodies
