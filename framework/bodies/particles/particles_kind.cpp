// The particles body kind: particles given one by one, with explicit springs (A1's two-particle
// spring and particle clouds): its [body] keys and checks, and how such a scene becomes a World.
// Registered by body.cmake.
#include <algorithm>
#include <cmath>
#include <limits>

#include "jelly/body_kind.hpp"
#include "jelly/particles_scene.hpp"
#include "jelly/world.hpp"
#include "param_rows.hpp"

namespace jelly::bodies {

namespace {

using namespace params_detail;

// The messages of checks made in two places (a key's value as it is set, and the scene as a whole).
std::string velocity_count_message(Eigen::Index positions, Eigen::Index given) {
  return "must give one velocity per position (" + std::to_string(positions) + "), got " +
         std::to_string(given);
}
std::string spring_index_message(std::size_t i, long long a, long long b, Eigen::Index n) {
  return "spring " + std::to_string(i) + " joins particles " + std::to_string(a) + " and " +
         std::to_string(b) + "; expected two different indices in 0.." + std::to_string(n - 1);
}

std::optional<std::string> check_rest_length_count(const Decl&, const SceneSpec& s, const Ctx&,
                                                   const Value& v) {
  const std::size_t given = std::get<std::vector<double>>(v).size();
  if (given != particles_scene(s).springs.size())
    return "must give one rest length per spring (" +
           std::to_string(particles_scene(s).springs.size()) + "), got " + std::to_string(given);
  return std::nullopt;
}

std::optional<std::string> check_spring_indices(const Decl&, const SceneSpec& s, const Ctx&,
                                                const Value& v) {
  // Checked here, before the indices are narrowed to int by the setter.
  const Eigen::Index n = particles_scene(s).positions.cols();
  const auto& pairs = std::get<std::vector<IndexPair>>(v);
  for (std::size_t i = 0; i < pairs.size(); ++i)
    if (pairs[i][0] >= n || pairs[i][1] >= n)
      return spring_index_message(i, pairs[i][0], pairs[i][1], n);
  return std::nullopt;
}

std::optional<std::string> check_velocity_count(const Decl&, const SceneSpec& s, const Ctx&,
                                                const Value& v) {
  const auto given = static_cast<Eigen::Index>(std::get<std::vector<Vec3>>(v).size());
  if (given != particles_scene(s).positions.cols())
    return velocity_count_message(particles_scene(s).positions.cols(), given);
  return std::nullopt;
}

class ParticlesKind final : public BodyKindModule {
 public:
  std::string_view name() const override { return "particles"; }
  std::string_view description() const override { return "particles given one by one"; }
  std::string_view body_phrase() const override { return "particles"; }

  std::vector<Decl> rows() const override {
    return body_section(
        name(),
        {
            make(
                "body.mass", Scope::Body, ValueKind::Real, "kg", Default::Yes, kPositive,
                "Mass of every particle",
                [](const SceneSpec& s, const Ctx&) -> Value { return particles_scene(s).mass; },
                [](SceneSpec& s, const Ctx&, const Value& v) {
                  particles_scene(s).mass = real(v);
                }),
            make(
                "body.positions", Scope::Body, ValueKind::Vec3List, "m", Default::None, kAny,
                "Initial positions, at least one; text form \"x,y,z; x,y,z\"",
                [](const SceneSpec& s, const Ctx&) -> Value {
                  return columns(particles_scene(s).positions);
                },
                [](SceneSpec& s, const Ctx&, const Value& v) {
                  particles_scene(s).positions = matrix(std::get<std::vector<Vec3>>(v));
                  // A different count makes the old velocities meaningless: start at rest.
                  if (particles_scene(s).velocities.cols() != particles_scene(s).positions.cols())
                    particles_scene(s).velocities =
                        Vec3Array::Zero(3, particles_scene(s).positions.cols());
                }),
            checked(make(
                        "body.velocities", Scope::Body, ValueKind::Vec3List, "m/s", Default::None,
                        kAny, "Initial velocities, one per position (optional: zero)",
                        [](const SceneSpec& s, const Ctx&) -> Value {
                          return columns(particles_scene(s).velocities);
                        },
                        [](SceneSpec& s, const Ctx&, const Value& v) {
                          particles_scene(s).velocities = matrix(std::get<std::vector<Vec3>>(v));
                        }),
                    check_velocity_count),
            checked(
                make(
                    "body.springs", Scope::Body, ValueKind::IndexPairList, "", Default::None, kAny,
                    "Springs as pairs of particle indices (0-based, a ≠ b); text form \"a,b; a,b\"",
                    [](const SceneSpec& s, const Ctx&) -> Value {
                      std::vector<IndexPair> out;
                      for (const Spring& sp : particles_scene(s).springs)
                        out.push_back({sp.a, sp.b});
                      return out;
                    },
                    [](SceneSpec& s, const Ctx&, const Value& v) {
                      // A spring that is unchanged (same pair at the same place in the list) keeps
                      // its rest length; a new one rests at the distance between the current
                      // positions.
                      const Vec3Array& x = particles_scene(s).positions;
                      const std::vector<Spring>& old = particles_scene(s).springs;
                      std::vector<Spring> springs;
                      for (const IndexPair& p : std::get<std::vector<IndexPair>>(v)) {
                        Spring sp{static_cast<int>(p[0]), static_cast<int>(p[1]),
                                  std::numeric_limits<double>::quiet_NaN()};
                        const std::size_t k = springs.size();
                        if (k < old.size() && old[k].a == sp.a && old[k].b == sp.b)
                          sp.rest_length = old[k].rest_length;
                        else if (p[0] >= 0 && p[1] >= 0 && p[0] < x.cols() && p[1] < x.cols())
                          sp.rest_length = (x.col(sp.a) - x.col(sp.b)).norm();
                        springs.push_back(sp);
                      }
                      particles_scene(s).springs = std::move(springs);
                    }),
                check_spring_indices),
            checked(
                make(
                    "body.rest_lengths", Scope::Body, ValueKind::RealList, "m", Default::None,
                    kPositive,
                    "Rest length of each spring, one per spring (optional: the initial distance)",
                    [](const SceneSpec& s, const Ctx&) -> Value {
                      std::vector<double> out;
                      for (const Spring& sp : particles_scene(s).springs)
                        out.push_back(sp.rest_length);
                      return out;
                    },
                    [](SceneSpec& s, const Ctx&, const Value& v) {
                      const auto& r = std::get<std::vector<double>>(v);
                      for (std::size_t i = 0; i < r.size() && i < particles_scene(s).springs.size();
                           ++i)
                        particles_scene(s).springs[i].rest_length = r[i];
                    }),
                check_rest_length_count),
            make(
                "body.spring_type", Scope::Body, ValueKind::Choice, "", Default::Yes, kAny,
                "Whose coefficients the springs use; that [springs.<type>] table must be present",
                [](const SceneSpec& s, const Ctx&) -> Value {
                  return std::string(to_string(particles_scene(s).spring_type));
                },
                [](SceneSpec& s, const Ctx&, const Value& v) {
                  particles_scene(s).spring_type = *spring_type_from_string(text(v));
                },
                {"structural", "shear", "shear_body", "bending"}),
        });
  }

  std::optional<CrossError> check(const SceneSpec& s) const override {
    const ParticleBodySpec& p = particles_scene(s);
    const Eigen::Index n = p.positions.cols();
    if (n < 1)
      return CrossError{"body.positions", "a particles body needs at least one position, got none"};
    if (p.velocities.cols() != n)
      return CrossError{"body.velocities", velocity_count_message(n, p.velocities.cols())};
    for (std::size_t i = 0; i < p.springs.size(); ++i) {
      const Spring& sp = p.springs[i];
      if (sp.a < 0 || sp.b < 0 || sp.a >= n || sp.b >= n || sp.a == sp.b)
        return CrossError{"body.springs", spring_index_message(i, sp.a, sp.b, n)};
      if (!(std::isfinite(sp.rest_length) && sp.rest_length > 0.0))
        return CrossError{"body.rest_lengths",
                          "spring " + std::to_string(i) + " has rest length " +
                              format_double(sp.rest_length) +
                              "; must be > 0 m (particles that start at the same place need an "
                              "explicit rest length)"};
    }
    if (!p.springs.empty() && !spring_settings(s, p.spring_type).enabled) {
      const std::string type(to_string(p.spring_type));
      return CrossError{"body.spring_type", "the particles' springs use the [springs." + type +
                                                "] coefficients, but the scene has no [springs." +
                                                type + "] table"};
    }
    return std::nullopt;
  }

  /// "particles: N, m = M kg" (the %.3g of a rendered caption).
  std::string caption_body(const SceneSpec& scene) const override {
    const ParticleBodySpec& p = particles_scene(scene);
    return "\nparticles: " + std::to_string(p.positions.cols()) +
           text_printf(", m = %.3g kg", p.mass) + "\n";
  }

  std::string_view stability_reason() const override { return "since contact stiffens the cube"; }

  void build(const SceneSpec& scene, World& world) const override {
    const ParticleBodySpec& p = particles_scene(scene);
    Vec3Array velocities = p.velocities.cols() == p.positions.cols()
                               ? p.velocities
                               : Vec3Array::Zero(3, p.positions.cols());
    world.add_particles(p.positions, velocities, p.mass);
    if (!p.springs.empty()) {
      const SpringSettings* settings = &scene.structural;
      if (p.spring_type == SpringType::Shear) settings = &scene.shear;
      if (p.spring_type == SpringType::ShearBody) settings = &scene.shear_body;
      if (p.spring_type == SpringType::Bending) settings = &scene.bending;
      if (settings->enabled) {
        SpringGroup g;
        g.type = p.spring_type;
        g.ks = settings->ks;
        g.kd = settings->kd;
        double shortest = p.springs.front().rest_length;
        for (const Spring& s : p.springs) shortest = std::min(shortest, s.rest_length);
        g.degenerate_length = degenerate_length_for(shortest);
        g.springs = p.springs;
        world.add_spring_group(std::move(g));
      }
    }
    world.set_gravity(scene.gravity);
    for (const Terrain& t : scene.terrains) world.add_terrain(t);
  }
};

}  // namespace

const BodyKindModule& particles_kind() {
  static const ParticlesKind kind;
  return kind;
}

}  // namespace jelly::bodies
