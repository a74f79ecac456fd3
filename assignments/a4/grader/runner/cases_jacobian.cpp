// A4.T2 cases: ik_jacobian on forward kinematics recorded from the reference when the data was
// generated (so a wrong FK costs nothing here), for chains of the course's skeleton and postures
// and of random trees: bones without some channels (zero columns), the root's three, the arm
// p − s_i. J is compared column by column.
#include <algorithm>
#include <cstdint>
#include <cstdio>
#include <string>
#include <vector>

#include "cases.hpp"

namespace jelly::grade {

namespace {

// The chains of the case: params.pairs = [{ start, end }] (bone names or indices), and with
// params.random.pairs that many random ones (each end a random bone, the start up to 5 bones up).
std::vector<std::vector<int>> case_chains(const TaskTable& t, const skeleton::Skeleton& s,
                                          const Params& params) {
  std::vector<std::vector<int>> out;
  const SkeletonTasks& k = skeleton_tasks(t);
  if (params.has("pairs"))
    for (const Params& p : params.list("pairs"))
      out.push_back(k.ik_chain(s, bone_index(s, p.text("start"), "params.pairs.start"),
                               bone_index(s, p.text("end"), "params.pairs.end")));
  if (params.has("random") && params.table("random").has("pairs")) {
    const Params r = params.table("random");
    Sequence q(static_cast<std::uint64_t>(r.integer("seed")) + 2000);
    const double n = static_cast<double>(s.bones.size());
    for (long i = 0; i < r.integer("pairs"); ++i) {
      const int end =
          std::min(static_cast<int>((q.next() + 1.0) * 0.5 * n), static_cast<int>(n) - 1);
      int start = end;
      for (int up = static_cast<int>((q.next() + 1.0) * 3.0); up > 0 && s.bones[start].parent >= 0;
           --up)
        start = s.bones[start].parent;
      out.push_back(k.ik_chain(s, start, end));
    }
  }
  return out;
}

// At generate-reference time: the skeleton, and with the reference's tasks every posture's
// forward kinematics and every chain.
void prepare_jacobian(const TaskTable& t, const Params& params, Json& input) {
  prepare_skeleton_input(params, input, kLimitsInInput);
  const SkeletonInput in = skeleton_input(params, input);
  input["fk"] = Json::array();
  for (const skeleton::Posture& p : in.motion.frames) {
    skeleton::BoneFrames f;
    skeleton_tasks(t).forward_kinematics(in.skeleton, p, f);
    input["fk"].push_back(frames_json(f));
  }
  input["chains"] = case_chains(t, in.skeleton, params);
}

void run_jacobian(const TaskTable& t, const Params& params, const Json& input, Outputs& out) {
  const SkeletonInput in = skeleton_input(params, input);
  const std::vector<std::vector<int>> chains =
      input.at("chains").get<std::vector<std::vector<int>>>();
  std::size_t p = 0;
  for (const Json& fk : input.at("fk")) {
    const skeleton::BoneFrames frames = json_frames(fk);
    for (std::size_t c = 0; c < chains.size(); ++c) {
      skeleton::Matrix3X J;
      skeleton_tasks(t).ik_jacobian(in.skeleton, frames, chains[c], J);
      char name[48];
      std::snprintf(name, sizeof name, "p%02zu_c%02zu", p, c);
      out.array(name, J,
                "J (3 × 3m, column 3b + k for chain entry b and axis k) of the chain " +
                    chain_text(in.skeleton, chains[c]) + " at posture " + std::to_string(p) +
                    " of " + in.words + ", from the recorded forward kinematics");
    }
    ++p;
  }
}

}  // namespace

// ik_jacobian: params.course = { asf, amc, from, to } or params.random = { seed, bones, frames,
// pairs }, with params.pairs; outputs pNN_cMM, J of chain MM at posture NN.
void register_jacobian_cases(Registry& r) {
  r.add({"ik_jacobian",
         "ik_jacobian of chains (params.pairs, params.random.pairs) at recorded forward kinematics "
         "of the course's postures (params.course) or of random ones (params.random)",
         prepare_jacobian, run_jacobian});
}

}  // namespace jelly::grade
