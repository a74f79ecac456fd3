// The slot-level cases of the skeleton's forward kinematics (kinematics_cases.hpp): local_rotation
// on hand-made and random angles (gimbal lock included), and forward_kinematics on the course's
// skeleton and postures and on random skeletons (random trees, axes, directions, lengths, dof
// orders) and postures. Each assignment that has these tasks registers them and runs them with its
// own case files.
#include "kinematics_cases.hpp"

#include <cstdint>
#include <cstdio>
#include <string>
#include <vector>

namespace jelly::grade {

namespace {

std::string angles_text(const Vec3& a) {
  char buf[96];
  std::snprintf(buf, sizeof buf, "(rx, ry, rz) = (%.9g, %.9g, %.9g)°", a.x(), a.y(), a.z());
  return buf;
}

// params.angles = [[rx, ry, rz], …] or params.random = { seed, count, range } (each angle in
// ±range degrees) or both.
std::vector<Vec3> rotation_inputs(const Params& params) {
  std::vector<Vec3> out;
  if (params.has("angles"))
    for (const Params& e : params.list("angles")) out.push_back(e.vec("degrees"));
  if (params.has("random")) {
    const Params r = params.table("random");
    Sequence s(static_cast<std::uint64_t>(r.integer("seed")));
    for (long i = 0; i < r.integer("count"); ++i) out.push_back(r.number("range") * s.next3());
  }
  return out;
}

void run_local_rotation(const TaskTable& t, const Params& params, Outputs& out) {
  const std::vector<Vec3> in = rotation_inputs(params);
  for (std::size_t i = 0; i < in.size(); ++i) {
    char name[32];
    std::snprintf(name, sizeof name, "e%02zu", i);
    const skeleton::Mat3 e = skeleton_tasks(t).local_rotation(in[i]);
    static const char* axes[] = {"x", "y", "z"};
    for (int c = 0; c < 3; ++c)
      out.vec(std::string(name) + "_" + axes[c], e.col(c),
              std::string("column ") + std::to_string(c) + " of E(θ) = R_z(rz)·R_y(ry)·R_x(rx) " +
                  "(the " + axes[c] + " axis turned by it) for " + angles_text(in[i]));
  }
}

// One posture's forward kinematics: every bone's start, end and rotation.
void emit_frames(const std::string& prefix, const skeleton::BoneFrames& f, const std::string& what,
                 const std::string& bones, Outputs& out) {
  Vec3Array start(3, static_cast<Eigen::Index>(f.start.size()));
  Vec3Array end(3, static_cast<Eigen::Index>(f.end.size()));
  for (std::size_t i = 0; i < f.start.size(); ++i)
    start.col(static_cast<Eigen::Index>(i)) = f.start[i];
  for (std::size_t i = 0; i < f.end.size(); ++i) end.col(static_cast<Eigen::Index>(i)) = f.end[i];
  out.array(prefix + "_end", end,
            "every bone's end e_i of " + what +
                (bones.empty() ? std::string() : " (bones " + bones + ")"));
  out.array(prefix + "_start", start, "every bone's start s_i of " + what);
  emit_rotations(out, prefix, f.rotation, "its global rotation R_i in " + what);
}

void run_forward_kinematics(const TaskTable& t, const Params& params, const Json& input,
                            Outputs& out) {
  const SkeletonInput in = skeleton_input(params, input);
  const std::string bones = bone_list(in.skeleton);
  for (std::size_t p = 0; p < in.motion.frames.size(); ++p) {
    skeleton::BoneFrames f;
    skeleton_tasks(t).forward_kinematics(in.skeleton, in.motion.frames[p], f);
    char prefix[32];
    std::snprintf(prefix, sizeof prefix, "p%02zu", p);
    emit_frames(prefix, f, "posture " + std::to_string(p) + " of " + in.words,
                p == 0 ? bones : std::string(), out);
  }
}

}  // namespace

void register_kinematics_cases(Registry& r, LimitsInInput limits) {
  r.add({"local_rotation",
         "local_rotation on hand-made (params.angles) or random (params.random) Euler angles",
         nullptr, [](const TaskTable& t, const Params& p, const Json&, Outputs& o) {
           run_local_rotation(t, p, o);
         }});
  r.add({"forward_kinematics",
         "forward_kinematics of every posture of the course's files (params.course) or of a random "
         "skeleton and motion (params.random)",
         [limits](const TaskTable&, const Params& p, Json& input) {
           prepare_skeleton_input(p, input, limits);
         },
         [](const TaskTable& t, const Params& p, const Json& input, Outputs& o) {
           run_forward_kinematics(t, p, input, o);
         }});
}

}  // namespace jelly::grade
