// A2.T12 (bonus) cases: friction_impulse right after a given normal impulse, on hand-made
// entries (sliding inside and outside Coulomb's cone, a pinned body, no normal impulse, no
// tangential velocity) and on random ones. Besides the velocities, the case counts entries whose
// sliding your function reversed (the cone never reverses it) and pinned bodies that moved.
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <string>
#include <vector>

#include "cases.hpp"

namespace jelly::grade {

namespace {

struct FrictionInput {
  std::string label;
  Impulse normal;
  double mu = 0.0, w_a = 0.0, w_b = 0.0;
  Vec3 v_a, v_b;
};

std::string vec_text(const Vec3& v) {
  char buf[96];
  std::snprintf(buf, sizeof buf, "(%.6g, %.6g, %.6g)", v.x(), v.y(), v.z());
  return buf;
}

std::vector<FrictionInput> friction_inputs(const Params& params) {
  std::vector<FrictionInput> out;
  if (params.has("random")) {
    // random = { seed, count, speed, j, mu }: normal N = U normalised, j·(1 + U)/2, μ mu·(1 + U)/2,
    // w_a, w_b in (0.5, 1], velocities speed·U with their normal approach removed (as after a
    // normal impulse of e = 0). U uniform in [−1, 1).
    const Params r = params.table("random");
    Sequence s(static_cast<std::uint64_t>(r.integer("seed")));
    const long count = r.integer("count");
    const double speed = r.number("speed"), j = r.number("j"), mu = r.number("mu");
    for (long i = 0; i < count; ++i) {
      FrictionInput f;
      Vec3 n = s.next3();
      if (n.norm() < 1e-3) n = Vec3(0.0, 1.0, 0.0);
      f.normal = Impulse{true, n.normalized(), j * (1.0 + s.next()) / 2.0};
      f.mu = mu * (1.0 + s.next()) / 2.0;
      f.w_a = 0.75 + 0.25 * s.next();
      f.w_b = 0.75 + 0.25 * s.next();
      f.v_a = speed * s.next3();
      f.v_b = speed * s.next3();
      const double approach = f.normal.normal.dot(f.v_a - f.v_b);
      if (approach < 0.0) f.v_a -= approach * f.normal.normal;
      char buf[64];
      std::snprintf(buf, sizeof buf, "random entry #%ld", i);
      f.label = buf;
      out.push_back(f);
    }
    return out;
  }
  for (const Params& e : params.list("entries")) {
    FrictionInput f;
    f.label = e.text("label");
    f.normal.applied = e.integer("applied") != 0;
    f.normal.normal = e.vec("normal");
    f.normal.j = e.number("j");
    f.mu = e.number("mu");
    f.w_a = e.number("wa");
    f.w_b = e.number("wb");
    f.v_a = e.vec("va");
    f.v_b = e.vec("vb");
    out.push_back(f);
  }
  return out;
}

std::string words(const FrictionInput& f) {
  char buf[420];
  std::snprintf(buf, sizeof buf,
                "entry '%s' (normal impulse %s, N=%s, j=%g; μ=%g; w_a=%g w_b=%g; v_a=%s v_b=%s)",
                f.label.c_str(), f.normal.applied ? "applied" : "NOT applied",
                vec_text(f.normal.normal).c_str(), f.normal.j, f.mu, f.w_a, f.w_b,
                vec_text(f.v_a).c_str(), vec_text(f.v_b).c_str());
  return buf;
}

void run_friction(const TaskTable& t, const Params& params, Outputs& out) {
  const std::vector<FrictionInput> in = friction_inputs(params);
  int reversed = 0, pinned = 0;
  std::string reversed_text, pinned_text;
  std::vector<Vec3> after_a, after_b;
  for (const FrictionInput& f : in) {
    Vec3 v_a = f.v_a, v_b = f.v_b;
    cloth_tasks(t).friction_impulse(f.normal, f.mu, f.w_a, f.w_b, v_a, v_b);
    after_a.push_back(v_a);
    after_b.push_back(v_b);
    // The relative tangential velocity before and after: friction may slow it, stop it, never
    // turn it round.
    const Vec3& N = f.normal.normal;
    const Vec3 before = (f.v_a - f.v_b) - N.dot(f.v_a - f.v_b) * N;
    const Vec3 after = (v_a - v_b) - N.dot(v_a - v_b) * N;
    if (before.dot(after) < -1e-12 * before.squaredNorm() && reversed++ == 0)
      reversed_text = "yours: on '" + f.label + "' the sliding " + vec_text(before) + " became " +
                      vec_text(after);
    const bool moved = (f.w_a == 0.0 && v_a != f.v_a) || (f.w_b == 0.0 && v_b != f.v_b);
    if (moved && pinned++ == 0)
      pinned_text = "yours: on '" + f.label + "' a body of inverse mass 0 (pinned) moved";
  }
  // The two rules first (the first failure a student sees names the entry), then the values.
  out.value("reversed", reversed,
            "entries whose relative sliding velocity your friction turned round (Coulomb's "
            "cone stops sliding at most: j_T ≤ |v_rel,T| / (w_a + w_b))");
  out.detail("reversed", "",
             reversed > 1 ? reversed_text + " (and " + std::to_string(reversed - 1) + " more)"
                          : reversed_text);
  out.value("pinned_moved", pinned,
            "entries where a body of inverse mass 0 (a pin) changed velocity (must be 0)");
  out.detail("pinned_moved", "", pinned_text);
  for (std::size_t i = 0; i < in.size(); ++i) {
    char name[32];
    std::snprintf(name, sizeof name, "f%02zu", i);
    const std::string w = words(in[i]);
    out.vec(std::string(name) + "_va", after_a[i], "v_a after friction on " + w + " [m/s]");
    out.vec(std::string(name) + "_vb", after_b[i], "v_b after friction on " + w + " [m/s]");
  }
}

}  // namespace

// friction: params.entries = [{ label, applied, normal, j, mu, wa, wb, va, vb }] or params.random;
// outputs reversed and pinned_moved, then fNN_va, fNN_vb per entry.
void register_friction_cases(Registry& r) {
  r.add({"friction",
         "friction_impulse after a given normal impulse, on hand-made (params.entries) or random "
         "(params.random) entries",
         nullptr, [](const TaskTable& t, const Params& p, const Json&, Outputs& o) {
           run_friction(t, p, o);
         }});
}

}  // namespace jelly::grade
