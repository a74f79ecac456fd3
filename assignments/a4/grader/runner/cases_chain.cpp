// A4.T1 cases: ik_chain on the course's skeleton (lowerback → rfingers, 9 bones; a start that is
// no ancestor of the end, so up to the root; start = end; the root) and on random trees, where
// siblings and cousins must stay out of the chain. Chains are compared exactly, bone by bone.
#include <cstdint>
#include <cstdio>
#include <string>
#include <utility>
#include <vector>

#include "cases.hpp"

namespace jelly::grade {

namespace {

long below(Sequence& r, long n) {  // uniform in 0 … n−1
  const long k = static_cast<long>((r.next() + 1.0) * 0.5 * static_cast<double>(n));
  return k < 0 ? 0 : (k > n - 1 ? n - 1 : k);
}

// params.pairs = [{ start, end }] (bone names or indices) and/or params.random.pairs random
// pairs: every other one's start an ancestor of its end (or the end itself), the others' any bone.
std::vector<std::pair<int, int>> chain_pairs(const skeleton::Skeleton& s, const Params& params) {
  std::vector<std::pair<int, int>> out;
  if (params.has("pairs"))
    for (const Params& p : params.list("pairs"))
      out.emplace_back(bone_index(s, p.text("start"), "params.pairs.start"),
                       bone_index(s, p.text("end"), "params.pairs.end"));
  if (params.has("random") && params.table("random").has("pairs")) {
    const Params r = params.table("random");
    Sequence q(static_cast<std::uint64_t>(r.integer("seed")) + 64);
    const long n = static_cast<long>(s.bones.size());
    for (long i = 0; i < r.integer("pairs"); ++i) {
      const int end = static_cast<int>(below(q, n));
      int start = static_cast<int>(below(q, n));
      if (i % 2 == 0) {  // an ancestor: up a random number of steps
        start = end;
        for (long up = below(q, 6); up > 0 && s.bones[start].parent >= 0; --up)
          start = s.bones[start].parent;
      }
      out.emplace_back(start, end);
    }
  }
  return out;
}

void run_chain(const TaskTable& t, const Params& params, const Json& input, Outputs& out) {
  const SkeletonInput in = skeleton_input(params, input);
  const std::vector<std::pair<int, int>> pairs = chain_pairs(in.skeleton, params);
  for (std::size_t i = 0; i < pairs.size(); ++i) {
    const auto [start, end] = pairs[i];
    const std::vector<int> chain = skeleton_tasks(t).ik_chain(in.skeleton, start, end);
    char name[32];
    std::snprintf(name, sizeof name, "c%02zu", i);
    out.values(name, std::vector<double>(chain.begin(), chain.end()),
               "the chain (bone indices, end bone first) from start bone " + std::to_string(start) +
                   " " + in.skeleton.bones[start].name + " to end bone " + std::to_string(end) +
                   " " + in.skeleton.bones[end].name + " of " + in.words +
                   (i == 0 ? " (bones " + bone_list(in.skeleton) + ")" : std::string()));
  }
}

}  // namespace

// ik_chain: params.course = { asf } (prepared) with params.pairs, or params.random = { seed,
// bones, pairs } (and params.pairs by index); outputs cNN, each chain's bone indices.
void register_chain_cases(Registry& r) {
  r.add({"ik_chain",
         "ik_chain between named (params.pairs) or random (params.random.pairs) bones of the "
         "course's skeleton (params.course) or of a random tree (params.random)",
         [](const TaskTable&, const Params& p, Json& input) {
           prepare_skeleton_input(p, input, kLimitsInInput);
         },
         [](const TaskTable& t, const Params& p, const Json& input, Outputs& o) {
           run_chain(t, p, input, o);
         }});
}

}  // namespace jelly::grade
