// The skeletons and postures of the cases of the skeleton's slots (skeleton_case_inputs.hpp): the
// course's files (data/mocap/, read by the reference when the data is generated and stored as the
// case's input, so that grading reads no file) and random ones (random trees whose parents may
// come after their children in file order, random axes, directions, lengths, dof orders, limits
// and postures).
#include "skeleton_case_inputs.hpp"

#include <algorithm>
#include <cstdint>
#include <optional>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

#include "jelly/skeleton/rotation.hpp"
#include "jelly/skeleton/skeleton_files.hpp"

#ifndef JELLY_GRADE_SOURCE_DIR
#define JELLY_GRADE_SOURCE_DIR "."
#endif

namespace jelly::grade {

namespace {

using skeleton::Bone;
using skeleton::Channel;
using skeleton::Motion;
using skeleton::Posture;
using skeleton::Skeleton;

// A bone's keys in this order (the recorded inputs' bytes): name, limits (when recorded), parent,
// children, channels, direction, length, axis.
Json bone_json(const Bone& b, LimitsInInput limits) {
  Json channels = Json::array();
  for (Channel c : b.channels) channels.push_back(static_cast<int>(c));
  Json out = {{"name", b.name}};
  if (limits == LimitsInInput::Recorded) {
    out["limits"] = Json::array();
    for (const skeleton::Limit& l : b.limits) out["limits"].push_back({l.lo, l.hi});
  }
  out["parent"] = b.parent;
  out["children"] = b.children;
  out["channels"] = channels;
  out["direction"] = vec_json(b.direction);
  out["length"] = b.length;
  out["axis"] = vec_json(b.axis);
  return out;
}

Json skeleton_json(const Skeleton& s, LimitsInInput limits) {
  Json bones = Json::array();
  for (const Bone& b : s.bones) bones.push_back(bone_json(b, limits));
  return {{"scale", s.scale}, {"bones", bones}};
}

Skeleton json_skeleton(const Json& j) {
  Skeleton s;
  s.scale = j.at("scale").get<double>();
  for (const Json& e : j.at("bones")) {
    Bone b;
    b.name = e.at("name").get<std::string>();
    b.parent = e.at("parent").get<int>();
    b.children = e.at("children").get<std::vector<int>>();
    for (const Json& c : e.at("channels")) b.channels.push_back(static_cast<Channel>(c.get<int>()));
    if (e.contains("limits"))
      for (const Json& l : e.at("limits"))
        b.limits.push_back({l.at(0).get<double>(), l.at(1).get<double>()});
    b.direction = json_vec(e.at("direction"));
    b.length = e.at("length").get<double>();
    b.axis = json_vec(e.at("axis"));
    s.bones.push_back(std::move(b));
  }
  skeleton::derive_bone_data(s);
  return s;
}

// A motion's frames [from, to) as [[tx, ty, tz, rx0, ry0, rz0, rx1, …], …].
Json motion_json(const Motion& m, long from, long to, const std::string& file) {
  if (from < 0 || to > static_cast<long>(m.frames.size()) || from >= to)
    throw std::runtime_error("params.course: frames [" + std::to_string(from) + ", " +
                             std::to_string(to) + ") are not in " + file + " (" +
                             std::to_string(m.frames.size()) + " frames)");
  Json frames = Json::array();
  for (long f = from; f < to; ++f) frames.push_back(posture_json(m.frames[f]));
  return frames;
}

Motion json_motion(const Json& j, std::size_t bones) {
  Motion m;
  for (const Json& row : j) m.frames.push_back(json_posture(row, bones));
  return m;
}

std::string mocap(const std::string& name) {
  return std::string(JELLY_GRADE_SOURCE_DIR) + "/data/mocap/" + name;
}

// ----- random skeletons and motions -----

long below(Sequence& r, long n) {  // uniform in 0 … n−1
  const long k = static_cast<long>((r.next() + 1.0) * 0.5 * static_cast<double>(n));
  return std::min(std::max(k, 0L), n - 1);
}

// A random permutation of 0 … n−1.
std::vector<int> shuffled(Sequence& r, int n) {
  std::vector<int> v(static_cast<std::size_t>(n));
  for (int i = 0; i < n; ++i) v[i] = i;
  for (int i = n - 1; i > 0; --i) std::swap(v[i], v[below(r, i + 1)]);
  return v;
}

// Bone 0 the root (six channels in a random order); the others hung one by one, in a random
// order, under a bone already hung, so a parent's index may be above its child's; with `limits`
// 1 or 2, random limits on about two bones in three (2: the root's too).
Skeleton random_skeleton(Sequence& r, int bones, double scale, long limits) {
  Skeleton s;
  s.scale = scale;
  s.bones.resize(static_cast<std::size_t>(bones));
  s.bones[0].name = "root";
  for (int k : shuffled(r, 6)) s.bones[0].channels.push_back(static_cast<Channel>(k));
  if (limits == 2)  // a root with limits, which no clamp may use
    for (int c = 0; c < 6; ++c) s.bones[0].limits.push_back({-1.0, 1.0});
  std::vector<int> hung{0};
  std::vector<int> order = shuffled(r, bones - 1);
  for (int k : order) {
    const int i = k + 1;
    Bone& b = s.bones[i];
    b.name = "bone" + std::to_string(i);
    b.parent = hung[below(r, static_cast<long>(hung.size()))];
    s.bones[b.parent].children.push_back(i);
    hung.push_back(i);
    Vec3 d = r.next3();
    if (d.norm() < 1e-2) d = Vec3(0.0, 1.0, 0.0);
    b.direction = d.normalized();
    b.length = below(r, 8) == 0 ? 0.0 : (11.0 + 5.0 * r.next()) / 2.0;  // 0 or in [3, 8)
    b.axis = 180.0 * r.next3();
    const long dofs = below(r, 5);  // 0 … 3 channels, 3 twice as often
    for (int c : shuffled(r, 3))
      if (static_cast<long>(b.channels.size()) < std::min(dofs, 3L))
        b.channels.push_back(static_cast<Channel>(3 + c));
    // Limits on about two bones in three, one (lo, hi) per channel in the dof order.
    if (limits != 0 && below(r, 3) != 0)
      for (std::size_t c = 0; c < b.channels.size(); ++c) {
        const double lo = -90.0 * (r.next() + 1.0) * 0.5, hi = 90.0 * (r.next() + 1.0) * 0.5;
        b.limits.push_back({lo, hi});
      }
  }
  skeleton::derive_bone_data(s);
  return s;
}

// Angles on the channels a bone has (zero on the others), up to `angle` degrees.
Posture random_posture(Sequence& r, const Skeleton& s, double angle, double translation) {
  Posture p = Posture::zero(s.bones.size());
  p.root_translation = translation * r.next3();
  for (std::size_t b = 0; b < s.bones.size(); ++b) {
    const Vec3 draw = angle * r.next3();
    for (int k = 0; k < 3; ++k)
      if (s.bones[b].has_rotation(k)) p.angles[b][k] = draw[k];
  }
  return p;
}

Motion random_motion(Sequence& r, const Skeleton& s, long frames, const Params& p) {
  Motion m;
  const double angle = p.number("angle", 180.0), translation = p.number("translation", 10.0);
  const double near = p.number("near", 0.0);
  for (long f = 0; f < frames; ++f) {
    if (near > 0.0 && f > 0) {
      Posture q = m.frames.back();  // a step of `near` degrees on every channel it has
      for (std::size_t b = 0; b < s.bones.size(); ++b)
        for (int k = 0; k < 3; ++k)
          if (s.bones[b].has_rotation(k)) q.angles[b][k] += near * r.next();
      m.frames.push_back(q);
    } else {
      m.frames.push_back(random_posture(r, s, angle, translation));
    }
  }
  // gimbal = 1: every ry at ±90° exactly (gimbal lock, kinematics contract §11.9), + on even
  // frames.
  if (p.integer("gimbal", 0) != 0)
    for (std::size_t f = 0; f < m.frames.size(); ++f)
      for (std::size_t b = 0; b < s.bones.size(); ++b)
        if (s.bones[b].has_rotation(1)) m.frames[f].angles[b].y() = f % 2 == 0 ? 90.0 : -90.0;
  return m;
}

}  // namespace

void prepare_skeleton_input(const Params& params, Json& input, LimitsInInput limits) {
  if (!params.has("course")) return;
  const Params c = params.table("course");
  const double scale = params.number("scale", 0.2);
  const std::string asf = c.text("asf", "skeleton.asf");
  const skeleton::SkeletonResult sr = skeleton::read_asf(mocap(asf), scale);
  if (!sr) throw std::runtime_error("params.course.asf: " + sr.error->text());
  input["skeleton"] = skeleton_json(*sr.skeleton, limits);
  input["frames"] = Json::array();
  if (!c.has("amc")) return;
  const std::string amc = c.text("amc");
  const skeleton::MotionResult a = skeleton::read_amc(mocap(amc), *sr.skeleton);
  if (!a) throw std::runtime_error("params.course.amc: " + a.error->text());
  input["frames"] = motion_json(*a.motion, c.integer("from"), c.integer("to"), amc);
  if (!c.has("amc_b")) return;
  const std::string amc_b = c.text("amc_b");
  const skeleton::MotionResult b = skeleton::read_amc(mocap(amc_b), *sr.skeleton);
  if (!b) throw std::runtime_error("params.course.amc_b: " + b.error->text());
  input["frames_b"] = motion_json(*b.motion, c.integer("from_b"), c.integer("to_b"), amc_b);
}

SkeletonInput skeleton_input(const Params& params, const Json& input) {
  SkeletonInput in;
  if (params.has("course")) {
    const Params c = params.table("course");
    in.skeleton = json_skeleton(input.at("skeleton"));
    in.motion = json_motion(input.at("frames"), in.skeleton.bones.size());
    if (input.contains("frames_b"))
      in.motion_b = json_motion(input.at("frames_b"), in.skeleton.bones.size());
    in.words = "the course's " + c.text("asf", "skeleton.asf");
    if (c.has("amc"))
      in.words += " with " + c.text("amc") + " frames " + std::to_string(c.integer("from")) +
                  " to " + std::to_string(c.integer("to") - 1);
    in.words += " (scale " + std::to_string(in.skeleton.scale).substr(0, 4) + ")";
    return in;
  }
  const Params p = params.table("random");
  Sequence r(static_cast<std::uint64_t>(p.integer("seed")));
  const long bones = p.integer("bones");
  if (bones < 1) throw std::runtime_error("params.random.bones: expected at least 1");
  in.skeleton =
      random_skeleton(r, static_cast<int>(bones), p.number("scale", 0.2), p.integer("limits", 0));
  in.motion = random_motion(r, in.skeleton, p.integer("frames", 1), p);
  if (p.has("frames_b")) in.motion_b = random_motion(r, in.skeleton, p.integer("frames_b"), p);
  in.words = "a random skeleton of " + std::to_string(bones) + " bones (seed " +
             std::to_string(p.integer("seed")) + ")";
  return in;
}

int bone_index(const skeleton::Skeleton& s, const std::string& name, const std::string& key) {
  if (const std::optional<int> i = s.find(name)) return *i;
  if (!name.empty() && name.find_first_not_of("0123456789") == std::string::npos) {
    const int i = std::stoi(name);
    if (i < static_cast<int>(s.bones.size())) return i;
  }
  throw std::runtime_error(key + ": no bone \"" + name + "\"");
}

Json vec_json(const Vec3& v) { return Json::array({v.x(), v.y(), v.z()}); }

Vec3 json_vec(const Json& j) {
  return Vec3(j.at(0).get<double>(), j.at(1).get<double>(), j.at(2).get<double>());
}

Json posture_json(const Posture& p) {
  std::vector<double> row{p.root_translation.x(), p.root_translation.y(), p.root_translation.z()};
  for (const Vec3& a : p.angles) row.insert(row.end(), {a.x(), a.y(), a.z()});
  return row;
}

Posture json_posture(const Json& j, std::size_t bones) {
  const std::vector<double> v = j.get<std::vector<double>>();
  if (v.size() != 3 + 3 * bones) throw std::runtime_error("input: a posture of the wrong size");
  Posture p = Posture::zero(bones);
  p.root_translation = Vec3(v[0], v[1], v[2]);
  for (std::size_t b = 0; b < bones; ++b)
    p.angles[b] = Vec3(v[3 + 3 * b], v[4 + 3 * b], v[5 + 3 * b]);
  return p;
}

Json frames_json(const skeleton::BoneFrames& f) {
  Json rotation = Json::array(), start = Json::array(), end = Json::array();
  for (const skeleton::Mat3& m : f.rotation)
    rotation.push_back(std::vector<double>(m.data(), m.data() + 9));
  for (const Vec3& v : f.start) start.push_back(vec_json(v));
  for (const Vec3& v : f.end) end.push_back(vec_json(v));
  return {{"rotation", rotation}, {"start", start}, {"end", end}};
}

skeleton::BoneFrames json_frames(const Json& j) {
  skeleton::BoneFrames f;
  for (const Json& m : j.at("rotation")) {
    const std::vector<double> v = m.get<std::vector<double>>();
    if (v.size() != 9) throw std::runtime_error("input: a rotation of the wrong size");
    f.rotation.push_back(Eigen::Map<const skeleton::Mat3>(v.data()));
  }
  for (const Json& v : j.at("start")) f.start.push_back(json_vec(v));
  for (const Json& v : j.at("end")) f.end.push_back(json_vec(v));
  return f;
}

Vec3Array posture_angles(const Posture& p) {
  Vec3Array a(3, static_cast<Eigen::Index>(p.angles.size()));
  for (std::size_t b = 0; b < p.angles.size(); ++b)
    a.col(static_cast<Eigen::Index>(b)) = p.angles[b];
  return a;
}

std::vector<skeleton::Mat3> posture_rotations(const std::vector<Vec3>& angles) {
  std::vector<skeleton::Mat3> out;
  for (const Vec3& a : angles) out.push_back(skeleton::euler_matrix(a));
  return out;
}

void emit_rotations(Outputs& out, const std::string& prefix,
                    const std::vector<skeleton::Mat3>& rotations, const std::string& what) {
  static const char* names[] = {"x", "y", "z"};
  for (int c = 0; c < 3; ++c) {
    Vec3Array column(3, static_cast<Eigen::Index>(rotations.size()));
    for (std::size_t i = 0; i < rotations.size(); ++i)
      column.col(static_cast<Eigen::Index>(i)) = rotations[i].col(c);
    out.array(prefix + "_axis_" + names[c], column,
              std::string("every bone's ") + names[c] + " axis turned by " + what + " (column " +
                  std::to_string(c) + " of the rotation)");
  }
}

std::string bone_list(const skeleton::Skeleton& s) {
  std::string out;
  for (std::size_t i = 0; i < s.bones.size() && i < 40; ++i)
    out += (i ? ", " : "") + std::to_string(i) + " " + s.bones[i].name;
  return out;
}

}  // namespace jelly::grade
