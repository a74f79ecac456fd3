// A4.T5 cases (the bonus). clamp_to_limits on the course's skeleton and on random ones (random dof
// orders, so the limits' order is the dof line's; bones without limits; with limits = 2 a root
// with limits, which must stay untouched) at postures pushed past the limits. ik_solve through a
// scripted ops.iterate that moves the posture and reports the outcome the case chooses: stable
// only when error < ε, the input posture put back bit for bit when not stable and restore is
// on, and the error the one iterate measured (before the restore, §11.14).
#include <cstdint>
#include <cstdio>
#include <string>
#include <vector>

#include "cases.hpp"

namespace jelly::grade {

namespace {

// Each posture of the case with every angle moved by up to params.push degrees (default 200), so
// that many pass their limits.
std::vector<skeleton::Posture> pushed(const SkeletonInput& in, const Params& params) {
  Sequence q(static_cast<std::uint64_t>(params.integer("push_seed", 1)));
  const double push = params.number("push", 200.0);
  std::vector<skeleton::Posture> out;
  for (skeleton::Posture p : in.motion.frames) {
    for (Vec3& a : p.angles) a += push * q.next3();
    out.push_back(p);
  }
  return out;
}

// The chains of params.pairs = [{ start, end }], prepared with the reference's ik_chain.
void prepare_chains(const TaskTable& t, const Params& params, Json& input) {
  prepare_skeleton_input(params, input, kLimitsInInput);
  const SkeletonInput in = skeleton_input(params, input);
  input["chains"] = Json::array();
  for (const Params& p : params.list("pairs"))
    input["chains"].push_back(skeleton_tasks(t).ik_chain(
        in.skeleton, bone_index(in.skeleton, p.text("start"), "params.pairs.start"),
        bone_index(in.skeleton, p.text("end"), "params.pairs.end")));
}

void run_clamp(const TaskTable& t, const Params& params, const Json& input, Outputs& out) {
  const SkeletonInput in = skeleton_input(params, input);
  const std::vector<std::vector<int>> chains =
      input.at("chains").get<std::vector<std::vector<int>>>();
  const std::vector<skeleton::Posture> postures = pushed(in, params);
  for (std::size_t p = 0; p < postures.size(); ++p)
    for (std::size_t c = 0; c < chains.size(); ++c) {
      skeleton::Posture posture = postures[p];
      skeleton_tasks(t).clamp_to_limits(in.skeleton, chains[c], posture);
      char name[48];
      std::snprintf(name, sizeof name, "p%02zu_c%02zu", p, c);
      out.array(name, posture_angles(posture),
                "every bone's angles (rx, ry, rz) [degrees] after clamping the chain " +
                    chain_text(in.skeleton, chains[c]) + " at a pushed posture " +
                    std::to_string(p) + " of " + in.words + " (bones " + bone_list(in.skeleton) +
                    ")");
      out.vec(std::string(name) + "_root", posture.root_translation,
              "the root's translation after the clamp (never changed)");
    }
}

// The posture ops.iterate leaves: every angle moved by an amount no sum of two doubles undoes.
skeleton::Posture iterated(const skeleton::Posture& p, std::uint64_t seed) {
  Sequence q(seed);
  skeleton::Posture out = p;
  for (Vec3& a : out.angles) a += 37.1234567891 * q.next3() + Vec3::Constant(1e-9);
  return out;
}

void run_solve(const TaskTable& t, const Params& params, const Json& input, Outputs& out) {
  const SkeletonInput in = skeleton_input(params, input);
  const skeleton::Posture start = in.motion.frames.front();
  std::size_t o = 0;
  for (const Params& outcome : params.list("outcomes")) {
    skeleton::IkSettings settings = settings_of(params);
    settings.restore = outcome.integer("restore", 1) != 0;
    skeleton::IkResult said;
    said.updates = static_cast<int>(outcome.integer("updates"));
    said.error = outcome.number("error");
    int calls = 0;
    skeleton::IkOps ops;
    ops.iterate = [&](skeleton::Posture& p) {
      ++calls;
      p = iterated(p, 100 + o);
      return said;
    };
    skeleton::Posture posture = start;
    const skeleton::IkResult r = skeleton_tasks(t).ik_solve(settings, ops, posture);
    char name[32];
    std::snprintf(name, sizeof name, "s%02zu", o);
    const std::string what = std::string("ik_solve when ops.iterate reports ") +
                             std::to_string(said.updates) + " updates and error " +
                             outcome.text("error_text") +
                             " (ε = " + std::to_string(settings.epsilon) + ", restore " +
                             (settings.restore ? "on" : "off") + ")";
    out.value(std::string(name) + "_stable", r.stable ? 1.0 : 0.0,
              "stable (1) or not (0): error < ε, from " + what);
    out.value(std::string(name) + "_updates", r.updates, "the updates returned by " + what);
    out.value(std::string(name) + "_error", r.error,
              "the error returned by " + what + " (iterate's, measured before any restore)");
    out.value(std::string(name) + "_iterate_calls", calls, "ops.iterate calls made by " + what);
    out.array(std::string(name) + "_posture", posture_angles(posture),
              "every bone's angles after " + what +
                  " (restored: the input posture bit for bit; kept: iterate's)");
    out.vec(std::string(name) + "_root", posture.root_translation,
            "the root's translation after " + what);
    ++o;
  }
}

}  // namespace

// clamp_to_limits: params.course or params.random (limits = 1 or 2), params.pairs, params.push;
// outputs pNN_cMM (every bone's angles) and pNN_cMM_root.
// ik_solve: params.course or params.random, params.settings, params.outcomes = [{ updates, error,
// error_text, restore }]; outputs sNN_stable, _updates, _error, _iterate_calls, _posture, _root.
void register_limits_cases(Registry& r) {
  r.add({"clamp_to_limits",
         "clamp_to_limits of chains (params.pairs) at postures pushed past the limits",
         prepare_chains, run_clamp});
  r.add({"ik_solve",
         "ik_solve around a scripted ops.iterate reporting the outcomes of params.outcomes",
         [](const TaskTable&, const Params& p, Json& input) {
           prepare_skeleton_input(p, input, kLimitsInInput);
         },
         run_solve});
}

}  // namespace jelly::grade
