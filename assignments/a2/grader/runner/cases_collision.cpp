// A2.T6–T7 cases: collide_particle_sphere and collide_spheres on hand-made pairs (each case mixes
// pairs that must respond and pairs that must not: separating, out of reach, no normal at the
// centre, both bodies of inverse mass 0) and on random ones. Every output names its pair in the
// student's terms; a pinned particle (w = 0) or a kinematic sphere that moved, and a position
// that changed, are counted apart so that the message names the body.
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <functional>
#include <string>
#include <vector>

#include "cases.hpp"

namespace jelly::grade {

namespace {

std::string vec_text(const Vec3& v) {
  char buf[96];
  std::snprintf(buf, sizeof buf, "(%.6g, %.6g, %.6g)", v.x(), v.y(), v.z());
  return buf;
}

bool same_bits(const Vec3& a, const Vec3& b) {
  return a.x() == b.x() && a.y() == b.y() && a.z() == b.z() &&
         std::signbit(a.x()) == std::signbit(b.x()) && std::signbit(a.y()) == std::signbit(b.y()) &&
         std::signbit(a.z()) == std::signbit(b.z());
}

ImpulseSettings settings_from(const Params& params) {
  ImpulseSettings s;
  const Params t = params.table("settings");
  s.restitution = t.number("restitution");
  s.tolerance = t.number("tolerance");
  return s;
}

// Names the first few bodies of a kind that did something they must not ("pair 'x': v (0,0,0) →
// (0,1,0)").
class Offenders {
 public:
  void add(const std::string& text) {
    if (count_ < 2) text_ += (count_ > 0 ? "; " : "") + text;
    ++count_;
  }
  int count() const { return count_; }
  std::string text() const {
    return count_ <= 2 ? text_ : text_ + " and " + std::to_string(count_ - 2) + " more";
  }

 private:
  std::string text_;
  int count_ = 0;
};

// Outputs kept back and emitted later (Later::emit), so that a case can report the bodies that
// must not move before its per-pair values: the first failure a student sees names them.
class Later {
 public:
  void vec(const std::string& name, const Vec3& v, const std::string& note) {
    items_.push_back([=](Outputs& o) { o.vec(name, v, note); });
  }
  void value(const std::string& name, double v, const std::string& note) {
    items_.push_back([=](Outputs& o) { o.value(name, v, note); });
  }
  void emit(Outputs& out) const {
    for (const auto& f : items_) f(out);
  }

 private:
  std::vector<std::function<void(Outputs&)>> items_;
};

// What every impulse case reports about the Impulse a pair returned: applied (0/1), and its
// normal and size only when applied (a pair that does not collide returns Impulse{}).
void impulse_outputs(const std::string& p, const Impulse& imp, const std::string& pair,
                     Later& out) {
  out.value(p + "_applied", imp.applied ? 1.0 : 0.0,
            "1 when your function says it applied an impulse to " + pair + ", else 0");
  out.vec(p + "_normal", imp.applied ? imp.normal : Vec3::Zero(),
          "the unit normal N (from B towards A) your function returned for " + pair);
  out.value(p + "_j", imp.applied ? imp.j : 0.0,
            "the size j of the normal impulse your function returned for " + pair + " [N·s]");
}

// ----- cloth–sphere -----

struct ParticleSpherePair {
  std::string label;
  PointBody particle;
  SphereBody sphere;
};

std::vector<ParticleSpherePair> particle_sphere_pairs(const Params& params) {
  std::vector<ParticleSpherePair> out;
  if (params.has("random")) {
    // random = { seed, count, radius, gap, speed, pinned_every, kinematic_every }: a sphere of
    // radius radius·(1.5 + U)/2 at centre U, a particle at distance r + gap·U from it in a random
    // direction, velocities speed·U; every pinned_every-th particle pinned (w = 0), every
    // kinematic_every-th sphere kinematic (inverse mass 0). U uniform in [−1, 1).
    const Params r = params.table("random");
    Sequence s(static_cast<std::uint64_t>(r.integer("seed")));
    const long count = r.integer("count"), pin_every = r.integer("pinned_every"),
               kin_every = r.integer("kinematic_every");
    const double radius = r.number("radius"), gap = r.number("gap"), speed = r.number("speed");
    for (long i = 0; i < count; ++i) {
      ParticleSpherePair p;
      p.sphere.center = s.next3();
      p.sphere.radius = radius * (1.5 + s.next()) / 2.0;
      Vec3 dir = s.next3();
      if (dir.norm() < 1e-3) dir = Vec3(0.0, 1.0, 0.0);
      dir.normalize();
      p.particle.position = p.sphere.center + (p.sphere.radius + gap * s.next()) * dir;
      p.particle.velocity = speed * s.next3();
      p.sphere.velocity = speed * s.next3();
      p.particle.inverse_mass = (pin_every > 0 && i % pin_every == pin_every - 1)
                                    ? 0.0
                                    : 1.0 / (1.0 + 0.5 * (1.0 + s.next()));
      p.sphere.inverse_mass = (kin_every > 0 && i % kin_every == kin_every - 1)
                                  ? 0.0
                                  : 1.0 / (100.0 * (1.0 + 0.5 * (1.0 + s.next())));
      char buf[64];
      std::snprintf(buf, sizeof buf, "random pair #%ld", i);
      p.label = buf;
      out.push_back(p);
    }
    return out;
  }
  for (const Params& e : params.list("pairs")) {
    ParticleSpherePair p;
    p.label = e.text("label");
    p.particle.position = e.vec("x");
    p.particle.velocity = e.vec("v");
    p.particle.inverse_mass = e.number("w");
    p.sphere.center = e.vec("c");
    p.sphere.velocity = e.vec("u");
    p.sphere.radius = e.number("r");
    p.sphere.inverse_mass = e.number("w_sphere");
    out.push_back(p);
  }
  return out;
}

std::string particle_words(const ParticleSpherePair& p) {
  char buf[512];
  std::snprintf(buf, sizeof buf, "pair '%s' (particle x=%s v=%s w=%g; sphere c=%s u=%s r=%g w=%g)",
                p.label.c_str(), vec_text(p.particle.position).c_str(),
                vec_text(p.particle.velocity).c_str(), p.particle.inverse_mass,
                vec_text(p.sphere.center).c_str(), vec_text(p.sphere.velocity).c_str(),
                p.sphere.radius, p.sphere.inverse_mass);
  return buf;
}

void run_particle_sphere(const TaskTable& t, const Params& params, Outputs& out) {
  const ImpulseSettings settings = settings_from(params);
  Offenders pinned, kinematic, moved;
  const std::vector<ParticleSpherePair> pairs = particle_sphere_pairs(params);
  // Every pair is run first, so that the bodies that must not move are reported before the
  // values: the first failure a student sees names the pinned particle that moved.
  Later per_pair;
  for (std::size_t i = 0; i < pairs.size(); ++i) {
    ParticleSpherePair p = pairs[i];
    const std::string words = particle_words(pairs[i]);
    const Impulse imp = cloth_tasks(t).collide_particle_sphere(p.particle, p.sphere, settings);
    char name[32];
    std::snprintf(name, sizeof name, "p%02zu", i);
    per_pair.vec(std::string(name) + "_v", p.particle.velocity,
                 "the particle's velocity after " + words + " [m/s]");
    per_pair.vec(std::string(name) + "_u", p.sphere.velocity,
                 "the sphere's velocity after " + words + " [m/s]");
    impulse_outputs(name, imp, "pair '" + pairs[i].label + "'", per_pair);
    if (pairs[i].particle.inverse_mass == 0.0 &&
        !same_bits(p.particle.velocity, pairs[i].particle.velocity))
      pinned.add("the pinned particle of pair '" + pairs[i].label + "' (w = 0) moved: v " +
                 vec_text(pairs[i].particle.velocity) + " → " + vec_text(p.particle.velocity));
    if (pairs[i].sphere.inverse_mass == 0.0 &&
        !same_bits(p.sphere.velocity, pairs[i].sphere.velocity))
      kinematic.add("the kinematic sphere of pair '" + pairs[i].label +
                    "' (inverse mass 0) changed velocity: u " + vec_text(pairs[i].sphere.velocity) +
                    " → " + vec_text(p.sphere.velocity));
    if (!same_bits(p.particle.position, pairs[i].particle.position) ||
        !same_bits(p.sphere.center, pairs[i].sphere.center) ||
        p.sphere.radius != pairs[i].sphere.radius ||
        p.particle.inverse_mass != pairs[i].particle.inverse_mass ||
        p.sphere.inverse_mass != pairs[i].sphere.inverse_mass)
      moved.add("pair '" + pairs[i].label + "'");
  }
  out.value("pinned_moved", pinned.count(),
            "pinned particles (inverse mass w = 0) whose velocity your function changed (must "
            "be 0: no impulse moves a pin)");
  out.detail("pinned_moved", "", pinned.text());
  out.value("kinematic_changed", kinematic.count(),
            "kinematic spheres (inverse mass 0) whose velocity your function changed (must be 0)");
  out.detail("kinematic_changed", "", kinematic.text());
  out.value("positions_changed", moved.count(),
            "pairs whose positions, radius or inverse masses your function changed (it may change "
            "velocities only)");
  out.detail("positions_changed", "", moved.count() ? "yours: " + moved.text() : "");
  per_pair.emit(out);
}

// ----- sphere–sphere -----

struct SpherePair {
  std::string label;
  SphereBody a, b;
};

std::vector<SpherePair> sphere_pairs(const Params& params) {
  std::vector<SpherePair> out;
  if (params.has("random")) {
    // random = { seed, count, radius, gap, speed, kinematic_every }: sphere b at U with radius
    // radius·(1.5 + U)/2, sphere a at distance r_a + r_b + gap·U in a random direction,
    // velocities speed·U, masses default_sphere_mass(r)·(1.5 + U/2); every kinematic_every-th pair
    // has a kinematic a (and every 2·kinematic_every-th a kinematic b as well).
    const Params r = params.table("random");
    Sequence s(static_cast<std::uint64_t>(r.integer("seed")));
    const long count = r.integer("count"), kin_every = r.integer("kinematic_every");
    const double radius = r.number("radius"), gap = r.number("gap"), speed = r.number("speed");
    for (long i = 0; i < count; ++i) {
      SpherePair p;
      p.b.center = s.next3();
      p.b.radius = radius * (1.5 + s.next()) / 2.0;
      p.a.radius = radius * (1.5 + s.next()) / 2.0;
      Vec3 dir = s.next3();
      if (dir.norm() < 1e-3) dir = Vec3(1.0, 0.0, 0.0);
      dir.normalize();
      p.a.center = p.b.center + (p.a.radius + p.b.radius + gap * s.next()) * dir;
      p.a.velocity = speed * s.next3();
      p.b.velocity = speed * s.next3();
      p.a.inverse_mass = 1.0 / (default_sphere_mass(p.a.radius) * (1.0 + 0.5 * (1.0 + s.next())));
      p.b.inverse_mass = 1.0 / (default_sphere_mass(p.b.radius) * (1.0 + 0.5 * (1.0 + s.next())));
      if (kin_every > 0 && i % kin_every == kin_every - 1) p.a.inverse_mass = 0.0;
      if (kin_every > 0 && i % (2 * kin_every) == 2 * kin_every - 1) p.b.inverse_mass = 0.0;
      char buf[64];
      std::snprintf(buf, sizeof buf, "random pair #%ld", i);
      p.label = buf;
      out.push_back(p);
    }
    return out;
  }
  for (const Params& e : params.list("pairs")) {
    SpherePair p;
    p.label = e.text("label");
    p.a.center = e.vec("ca");
    p.a.velocity = e.vec("ua");
    p.a.radius = e.number("ra");
    p.a.inverse_mass = e.number("wa");
    p.b.center = e.vec("cb");
    p.b.velocity = e.vec("ub");
    p.b.radius = e.number("rb");
    p.b.inverse_mass = e.number("wb");
    out.push_back(p);
  }
  return out;
}

std::string sphere_words(const SpherePair& p) {
  char buf[512];
  std::snprintf(buf, sizeof buf,
                "pair '%s' (sphere a c=%s u=%s r=%g w=%g; sphere b c=%s u=%s r=%g w=%g)",
                p.label.c_str(), vec_text(p.a.center).c_str(), vec_text(p.a.velocity).c_str(),
                p.a.radius, p.a.inverse_mass, vec_text(p.b.center).c_str(),
                vec_text(p.b.velocity).c_str(), p.b.radius, p.b.inverse_mass);
  return buf;
}

void run_sphere_pairs(const TaskTable& t, const Params& params, Outputs& out) {
  const ImpulseSettings settings = settings_from(params);
  Offenders kinematic, moved;
  const std::vector<SpherePair> pairs = sphere_pairs(params);
  Later per_pair;  // reported after the bodies that must not move
  for (std::size_t i = 0; i < pairs.size(); ++i) {
    SpherePair p = pairs[i];
    const std::string words = sphere_words(pairs[i]);
    const Impulse imp = cloth_tasks(t).collide_spheres(p.a, p.b, settings);
    char name[32];
    std::snprintf(name, sizeof name, "p%02zu", i);
    per_pair.vec(std::string(name) + "_ua", p.a.velocity,
                 "sphere a's velocity after " + words + " [m/s]");
    per_pair.vec(std::string(name) + "_ub", p.b.velocity,
                 "sphere b's velocity after " + words + " [m/s]");
    impulse_outputs(name, imp, "pair '" + pairs[i].label + "'", per_pair);
    const SphereBody* before[2] = {&pairs[i].a, &pairs[i].b};
    const SphereBody* after[2] = {&p.a, &p.b};
    for (int k = 0; k < 2; ++k) {
      if (before[k]->inverse_mass == 0.0 && !same_bits(after[k]->velocity, before[k]->velocity))
        kinematic.add(std::string("the kinematic sphere ") + (k == 0 ? "a" : "b") + " of pair '" +
                      pairs[i].label + "' (inverse mass 0) changed velocity: u " +
                      vec_text(before[k]->velocity) + " → " + vec_text(after[k]->velocity));
      if (!same_bits(after[k]->center, before[k]->center) ||
          after[k]->radius != before[k]->radius ||
          after[k]->inverse_mass != before[k]->inverse_mass) {
        moved.add("pair '" + pairs[i].label + "'");
        break;
      }
    }
  }
  out.value("kinematic_changed", kinematic.count(),
            "kinematic spheres (inverse mass 0) whose velocity your function changed (must be 0)");
  out.detail("kinematic_changed", "", kinematic.text());
  out.value("positions_changed", moved.count(),
            "pairs whose centres, radii or inverse masses your function changed (it may change "
            "velocities only)");
  out.detail("positions_changed", "", moved.count() ? "yours: " + moved.text() : "");
  per_pair.emit(out);
}

}  // namespace

// particle_sphere: params.settings = { restitution, tolerance } and params.pairs = [{ label, x, v,
// w, c, u, r, w_sphere }] or params.random (particle_sphere_pairs). sphere_pairs: params.settings
// and params.pairs = [{ label, ca, ua, ra, wa, cb, ub, rb, wb }] or params.random. Outputs per
// pair NN: the velocities after, pNN_applied, pNN_normal, pNN_j; then the bodies that must not
// have moved.
void register_collision_cases(Registry& r) {
  r.add({"particle_sphere",
         "collide_particle_sphere on hand-made (params.pairs) or random (params.random) pairs",
         nullptr, [](const TaskTable& t, const Params& p, const Json&, Outputs& o) {
           run_particle_sphere(t, p, o);
         }});
  r.add({"sphere_pairs",
         "collide_spheres on hand-made (params.pairs) or random (params.random) pairs", nullptr,
         [](const TaskTable& t, const Params& p, const Json&, Outputs& o) {
           run_sphere_pairs(t, p, o);
         }});
}

}  // namespace jelly::grade
