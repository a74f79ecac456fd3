// A4.T4 cases: ik_iterate through scripted collaborators (ik_script.cpp). Recorded: the answers of
// the reference's own FK, Jacobian, solve and clamp along its solve of the course's hw3-ik (73
// updates, 105 with limits: kinematics contract §8) and of random chains; a correct iteration
// hands back the same postures call after call. Toy: errors the case chooses, to check the
// stopping rule |e| < ε and max_iterations. Unreachable targets are graded by what the contract
// fixes (every update made, the error finite and ≥ ε, nothing outside the chain moved), not by
// the path.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

#include "cases.hpp"

namespace jelly::grade {

namespace {

// The case's target: params.target = [x, y, z], or with params.target_frame = f the end of the
// chain's end bone at posture f of the case (the reference's FK, so a reachable one).
Vec3 case_target(const TaskTable& t, const Params& params, const SkeletonInput& in,
                 const std::vector<int>& chain) {
  if (params.has("target")) return params.vec("target");
  skeleton::BoneFrames f;
  const long frame = params.integer("target_frame");
  skeleton_tasks(t).forward_kinematics(in.skeleton, in.motion.frames.at(frame), f);
  return f.end[static_cast<std::size_t>(chain.front())];
}

// params.toy = { errors = [...] }: end_effector's k-th answer target − (errors[k], 0, 0), and
// each solve's answer x_j = (−1)^j·0.01·(j + 1) radians, on every column (those of channels a
// bone lacks included: they must not be used).
IkScript toy_script(const Params& toy, const Vec3& target, std::size_t chain_size) {
  IkScript s;
  for (double e : toy.numbers("errors")) s.effector.push_back(target - Vec3(e, 0.0, 0.0));
  const Eigen::Index n = 3 * static_cast<Eigen::Index>(chain_size);
  s.J.emplace_back(skeleton::Matrix3X::Zero(3, n));
  skeleton::VectorX x(n);
  for (Eigen::Index j = 0; j < n; ++j)
    x(j) = (j % 2 == 0 ? 0.01 : -0.01) * static_cast<double>(j + 1);
  s.x.push_back(x);
  return s;
}

// At generate-reference time: the skeleton, the chain, the target and the script (recorded from
// the reference's own solve, or the toy).
void prepare_iterate(const TaskTable& t, const Params& params, Json& input) {
  prepare_skeleton_input(params, input, kLimitsInInput);
  const SkeletonInput in = skeleton_input(params, input);
  const SkeletonTasks& k = skeleton_tasks(t);
  const std::vector<int> chain =
      k.ik_chain(in.skeleton, bone_index(in.skeleton, params.text("start"), "params.start"),
                 bone_index(in.skeleton, params.text("end"), "params.end"));
  const Vec3 target = case_target(t, params, in, chain);
  input["chain"] = chain;
  input["target"] = vec_json(target);
  if (params.has("toy")) {
    input["script"] = script_json(toy_script(params.table("toy"), target, chain.size()));
    return;
  }
  IkScript script;
  skeleton::Posture posture = in.motion.frames.front();
  k.ik_iterate(in.skeleton, chain, target, settings_of(params),
               recording_ops(t, in.skeleton, chain, script), posture);
  input["script"] = script_json(script);
}

// The angles of the bones outside the chain, and the chain's own, of a posture.
Vec3Array others(const skeleton::Posture& p, const std::vector<int>& chain) {
  std::vector<int> rest;
  for (int i = 0; i < static_cast<int>(p.angles.size()); ++i)
    if (std::find(chain.begin(), chain.end(), i) == chain.end()) rest.push_back(i);
  return chain_angles(p, rest);
}

// The chain's angles at each posture of a list, one after the other.
Vec3Array chain_path(const std::vector<skeleton::Posture>& list, const std::vector<int>& chain) {
  Vec3Array a(3, static_cast<Eigen::Index>(list.size() * chain.size()));
  for (std::size_t c = 0; c < list.size(); ++c)
    a.middleCols(static_cast<Eigen::Index>(c * chain.size()),
                 static_cast<Eigen::Index>(chain.size())) = chain_angles(list[c], chain);
  return a;
}

Vec3Array vectors(const std::vector<Vec3>& list) {
  Vec3Array a(3, static_cast<Eigen::Index>(list.size()));
  for (std::size_t c = 0; c < list.size(); ++c) a.col(static_cast<Eigen::Index>(c)) = list[c];
  return a;
}

void run_iterate(const TaskTable& t, const Params& params, const Json& input, Outputs& out) {
  const SkeletonInput in = skeleton_input(params, input);
  const std::vector<int> chain = input.at("chain").get<std::vector<int>>();
  const Vec3 target = json_vec(input.at("target"));
  const skeleton::IkSettings settings = settings_of(params);
  const IkScript script = json_script(input.at("script"), in.skeleton.bones.size());
  IkLog log;
  const skeleton::IkOps ops = scripted_ops(script, log);
  skeleton::Posture posture = in.motion.frames.front();
  const skeleton::IkResult r =
      skeleton_tasks(t).ik_iterate(in.skeleton, chain, target, settings, ops, posture);
  const std::string what =
      "the iteration on the chain " + chain_text(in.skeleton, chain) + " of " + in.words;
  out.value("updates", r.updates, "the updates made by " + what);
  out.value("error", r.error, "|target − p| after the last forward kinematics of " + what);
  out.values("calls",
             {static_cast<double>(log.effector.size()), static_cast<double>(log.jacobian_calls),
              static_cast<double>(log.e.size()), static_cast<double>(log.clamp.size())},
             "the calls of ops.end_effector, ops.jacobian, ops.solve and ops.clamp (after each "
             "update when limits are on, never on the input posture) by " +
                 what);
  out.array("path", chain_path(log.effector, chain),
            "the chain's angles (rx, ry, rz) [degrees] handed to ops.end_effector, call after "
            "call (the input posture, then the posture after each update), by " +
                what);
  out.array("solve_e", vectors(log.e), "the e = target − p handed to ops.solve by " + what);
  out.array(
      "clamped", chain_path(log.clamp, chain),
      "the chain's angles handed to ops.clamp (the posture just after each update) by " + what);
  out.array("final", chain_angles(posture, chain),
            "the chain's angles (rx, ry, rz) [degrees] at the end of " + what);
  out.array("others", others(posture, chain),
            "the angles of every bone outside the chain at the end of " + what +
                " (unchanged: only the chain moves)");
  out.vec("root_translation", posture.root_translation,
          "the root's translation at the end of " + what + " (never changed)");
}

}  // namespace

// ik_iterate: params.course = { asf, amc, from, to } or params.random, params.start, params.end,
// params.target or params.target_frame, params.settings, and params.toy = { errors } for a toy
// script; outputs updates, error, calls, path, solve_e, clamped, final, others,
// root_translation.
void register_iterate_cases(Registry& r) {
  r.add({"ik_iterate",
         "ik_iterate through answers recorded from the reference's solve (or a toy, params.toy) "
         "on the course's skeleton (params.course) or a random one (params.random)",
         prepare_iterate, run_iterate});
}

}  // namespace jelly::grade
