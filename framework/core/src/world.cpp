#include "jelly/world.hpp"

#include <cstdint>

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>
#include <stdexcept>
#include <string>

#include "jelly/spring_pass.hpp"
#include "jelly/terrain_geometry.hpp"

namespace jelly {

namespace {

// Grid coordinates of a particle of a cube.
struct GridCoord {
  int i, j, k;
};
GridCoord grid_coord(const CubeLattice& c, int index) {
  const int r = index - c.first_index();
  const int n = c.n();
  return {r / (n * n), (r / n) % n, r % n};
}

// A body diagonal joins particles whose grid coordinates differ in all three axes.
bool is_body_diagonal(const CubeLattice& c, const Spring& s) {
  const GridCoord a = grid_coord(c, s.a);
  const GridCoord b = grid_coord(c, s.b);
  return a.i != b.i && a.j != b.j && a.k != b.k;
}

// The sphere obstacle seen from particle x: its tangent plane there (the student's plane functions
// then do the rest). Returns false when x is at the centre (no direction).
bool tangent_plane(const Sphere& s, const Vec3& x, Plane& out) {
  const Vec3 d = x - s.center;
  const double len = d.norm();
  if (!(len > 0.0)) return false;
  out.normal = d / len;
  out.point = s.center + s.radius * out.normal;
  out.has_hole = false;
  out.surface = s.surface;
  return true;
}

// The per-shape loop of collision and contact, written once: calls on_plane(plane, i) or
// on_bowl(bowl, i) for every particle i of x, for a sphere on_plane(its tangent plane at x_i, i)
// (no call at its centre), and returns how many calls returned true. The shape is chosen once per
// pass, not per particle.
template <typename OnPlane, typename OnBowl>
std::int64_t count_per_particle(const Terrain& terrain, const Vec3Array& x, OnPlane on_plane,
                                OnBowl on_bowl) {
  const Eigen::Index n = x.cols();
  std::int64_t hits = 0;
  if (const auto* plane = std::get_if<Plane>(&terrain.shape)) {
    for (Eigen::Index i = 0; i < n; ++i)
      if (on_plane(*plane, i)) ++hits;
  } else if (const auto* bowl = std::get_if<Bowl>(&terrain.shape)) {
    for (Eigen::Index i = 0; i < n; ++i)
      if (on_bowl(*bowl, i)) ++hits;
  } else {
    const auto& sphere = std::get<Sphere>(terrain.shape);
    Plane tangent;
    for (Eigen::Index i = 0; i < n; ++i)
      if (tangent_plane(sphere, x.col(i), tangent) && on_plane(tangent, i)) ++hits;
  }
  return hits;
}

// Lower and upper corners of the particles' bounding box: four particles (12 doubles) at a time
// into 12 running minima and maxima held in vector registers (Eigen's rowwise min and max would
// make six strided passes).
void bounding_box(const Vec3Array& x, Vec3& lo, Vec3& hi) {
  const Eigen::Index n = x.cols();
  if (n == 0) {
    lo = hi = Vec3::Zero();
    return;
  }
  const double* p = x.data();
  using Block = Eigen::Array<double, 12, 1>;  // four particles: x y z x y z x y z x y z
  Block l, h;
  for (int k = 0; k < 12; ++k) l[k] = h[k] = p[k % 3];
  const Eigen::Index blocks = n / 4;
  for (Eigen::Index j = 0; j < blocks; ++j) {
    const Eigen::Map<const Block> q(p + 12 * j);
    l = l.min(q);
    h = h.max(q);
  }
  for (Eigen::Index i = 4 * blocks; i < n; ++i)
    for (int d = 0; d < 3; ++d) {
      l[d] = std::min(l[d], p[3 * i + d]);
      h[d] = std::max(h[d], p[3 * i + d]);
    }
  for (int d = 0; d < 3; ++d) {  // slot k holds coordinate k % 3
    for (int k = d + 3; k < 12; k += 3) {
      l[d] = std::min(l[d], l[k]);
      h[d] = std::max(h[d], h[k]);
    }
  }
  lo = Vec3(l[0], l[1], l[2]);
  hi = Vec3(h[0], h[1], h[2]);
}

}  // namespace

World::World(TaskTable tasks)
    : tasks_(tasks),
      spring_pass_(tasks.make_spring_group_pass ? tasks.make_spring_group_pass() : nullptr) {}

int World::add_cube(const CubeSpec& spec) {
  const auto first = static_cast<int>(state_.size());
  cubes_.emplace_back(spec, first);
  const CubeLattice& lattice = cubes_.back();
  Vec3Array velocities(3, lattice.particle_count());
  velocities.colwise() = spec.velocity;
  add_particles(lattice.initial_positions(), velocities, spec.mass);
  return static_cast<int>(cubes_.size()) - 1;
}

int World::add_particles(const Vec3Array& positions, const Vec3Array& velocities, double mass) {
  const Eigen::Index first = state_.size();
  const Eigen::Index count = positions.cols();
  State grown;
  grown.resize(first + count);
  grown.x.leftCols(first) = state_.x;
  grown.v.leftCols(first) = state_.v;
  grown.x.rightCols(count) = positions;
  grown.v.rightCols(count) = velocities;
  state_ = std::move(grown);
  Eigen::VectorXd m(first + count);
  m.head(first) = mass_;
  m.tail(count).setConstant(mass);
  mass_ = std::move(m);
  // Particles already there keep their inverse mass (a pinned cloth particle's is 0).
  Eigen::VectorXd w(first + count);
  w.head(first) = inv_mass_;
  w.tail(count) = mass_.tail(count).cwiseInverse();
  inv_mass_ = std::move(w);
  for (Eigen::Index i = 0; i < count; ++i)
    lowest_initial_height_ = (first == 0 && i == 0)
                                 ? positions(1, i)
                                 : std::min(lowest_initial_height_, positions(1, i));
  force_.resize(3, state_.size());
  pairs_.clear();
  return static_cast<int>(first);
}

void World::build_cube_springs(int cube, SpringType type, double ks, double kd) {
  const CubeLattice& lattice = cubes_.at(static_cast<std::size_t>(cube));
  SpringGroup group;
  group.type = type;
  group.ks = ks;
  group.kd = kd;
  group.degenerate_length = degenerate_length_for(lattice.spacing());
  const char* builder = "";
  switch (type) {
    case SpringType::Structural:
      builder = "add_structural_springs";
      tasks_.add_structural_springs(lattice, group.springs);
      break;
    case SpringType::Bending:
      builder = "add_bending_springs";
      tasks_.add_bending_springs(lattice, group.springs);
      break;
    case SpringType::Shear:
    case SpringType::ShearBody: {
      builder = "add_shear_springs";
      tasks_.add_shear_springs(lattice, group.springs);
      if (type == SpringType::ShearBody) {
        // Keep the body diagonals here and take them out of the cube's face-shear group.
        auto& springs = group.springs;
        springs.erase(
            std::remove_if(springs.begin(), springs.end(),
                           [&](const Spring& s) { return !is_body_diagonal(lattice, s); }),
            springs.end());
        for (SpringGroup& g : groups_) {
          if (g.type != SpringType::Shear || g.springs.empty()) continue;
          const int a = g.springs.front().a;
          if (a < lattice.first_index() || a >= lattice.first_index() + lattice.particle_count())
            continue;
          g.springs.erase(
              std::remove_if(g.springs.begin(), g.springs.end(),
                             [&](const Spring& s) { return is_body_diagonal(lattice, s); }),
              g.springs.end());
          if (spring_pass_) spring_pass_->springs_changed();
        }
      }
      break;
    }
  }
  // The framework never trusts a builder's output blindly: a bad index would crash the force pass.
  const int lo = lattice.first_index();
  const int hi = lo + lattice.particle_count();
  for (std::size_t k = 0; k < group.springs.size(); ++k) {
    const Spring& s = group.springs[k];
    if (s.a < lo || s.a >= hi || s.b < lo || s.b >= hi || s.a == s.b ||
        !std::isfinite(s.rest_length) || s.rest_length < 0.0) {
      throw std::runtime_error(
          std::string(builder) + " produced spring #" + std::to_string(k) + " joining particles " +
          std::to_string(s.a) + " and " + std::to_string(s.b) + " with rest length " +
          std::to_string(s.rest_length) + "; expected two different particles in " +
          std::to_string(lo) + ".." + std::to_string(hi - 1) + " and a finite rest length ≥ 0");
    }
  }
  add_spring_group(std::move(group));
}

void World::add_spring_group(SpringGroup group) {
  groups_.push_back(std::move(group));
  pairs_.clear();
}

void World::set_gravity(std::optional<Vec3> g) { gravity_ = g; }

void World::set_force_threads(int threads) {
  threads_ = std::max(1, threads);
  if (spring_pass_) spring_pass_->set_threads(threads_);
}

void World::add_terrain(Terrain terrain) {
  if (inverse_mass_form_)
    throw std::logic_error("a cloth world has no terrain (cloth contract §6)");
  terrains_.push_back(std::move(terrain));
  const std::size_t n = terrains_.size();
  counters_.collision_queries.resize(n, 0);
  counters_.contact_queries.resize(n, 0);
  counters_.collisions.resize(n, 0);
  counters_.contacts.resize(n, 0);
  counters_.broadphase_skips.resize(n, 0);
}

std::size_t World::spring_count() const {
  std::size_t n = 0;
  for (const SpringGroup& g : groups_) n += g.springs.size();
  return n;
}

void World::reset_counters() {
  const std::size_t n = terrains_.size();
  counters_ = EffectCounters{};
  counters_.collision_queries.assign(n, 0);
  counters_.contact_queries.assign(n, 0);
  counters_.collisions.assign(n, 0);
  counters_.contacts.assign(n, 0);
  counters_.broadphase_skips.assign(n, 0);
}

void World::acceleration(const State& s, Vec3Array& a) {
  if (inverse_mass_form_) {
    cloth_acceleration(s, a);
    return;
  }
  ++counters_.acceleration_evaluations;
  const Eigen::Index n = s.size();
  force_.resize(3, n);
  // 1. Gravity (only when the scene has it).
  double* f = force_.data();
  const double* m = mass_.data();
  if (gravity_) {
    ++counters_.gravity_applications;
    const double g0 = gravity_->x(), g1 = gravity_->y(), g2 = gravity_->z();
    for (Eigen::Index i = 0; i < n; ++i) {  // column i: m_i g
      f[3 * i] = g0 * m[i];
      f[3 * i + 1] = g1 * m[i];
      f[3 * i + 2] = g2 * m[i];
    }
  } else {
    force_.setZero();
  }
  // 2. Springs and dampers of every group the scene built: in one call when the task library
  //    offers a spring engine, else group by group.
  for (const SpringGroup& g : groups_) {
    ++counters_.spring_group_evaluations[static_cast<std::size_t>(g.type)];
    counters_.springs_evaluated += static_cast<std::int64_t>(g.springs.size());
  }
  if (spring_pass_) {
    spring_pass_->accumulate(groups_.data(), groups_.size(), s, force_);
  } else {
    for (const SpringGroup& g : groups_)
      accumulate_spring_forces(g, s, force_, tasks_.spring_force, tasks_.damper_force);
  }
  // 3. Contact forces, terrain by terrain in scene order (contract §5).
  contact_pass(s, force_);
  // 4. Divide by the mass.
  a.resize(3, n);
  double* out = a.data();
  for (Eigen::Index i = 0; i < n; ++i) {
    out[3 * i] = f[3 * i] / m[i];
    out[3 * i + 1] = f[3 * i + 1] / m[i];
    out[3 * i + 2] = f[3 * i + 2] / m[i];
  }
}

void World::contact_pass(const State& s, Vec3Array& f) {
  if (terrains_.empty()) return;
  bool box_ready = false;
  Vec3 lo, hi;
  const Eigen::Index n = s.size();
  for (std::size_t t = 0; t < terrains_.size(); ++t) {
    const Terrain& terrain = terrains_[t];
    if (!terrain.contact) continue;
    if (!box_ready) {
      bounding_box(s.x, lo, hi);
      box_ready = true;
    }
    // Exact broad phase: contact needs φ < ε somewhere in the box.
    if (!(min_signed_distance(terrain, lo, hi) < terrain.surface().epsilon) ||
        box_outside_extent(terrain, lo, hi)) {
      ++counters_.broadphase_skips[t];
      continue;
    }
    counters_.contact_queries[t] += static_cast<std::int64_t>(n);
    // A particle's force changes only where the student's function says it made contact.
    const auto contact = [&](auto task) {
      return [&, task](const auto& surface, Eigen::Index i) {
        Vec3 fi = f.col(i);
        if (!task(surface, s.x.col(i), s.v.col(i), fi)) return false;
        f.col(i) = fi;
        return true;
      };
    };
    counters_.contacts[t] += count_per_particle(terrain, s.x, contact(tasks_.contact_plane),
                                                contact(tasks_.contact_bowl));
  }
}

void World::apply_collisions(State& s) {
  if (inverse_mass_form_) {
    apply_cloth_collisions(s);
    return;
  }
  if (terrains_.empty()) return;
  ++counters_.collision_passes;
  const Eigen::Index n = s.size();
  for (std::size_t t = 0; t < terrains_.size(); ++t) {
    const Terrain& terrain = terrains_[t];
    if (!terrain.collision && !terrain.project) continue;
    // The box is recomputed per terrain: an earlier terrain's projection may have moved particles.
    Vec3 lo, hi;
    bounding_box(s.x, lo, hi);
    const bool may_touch = min_signed_distance(terrain, lo, hi) < terrain.surface().epsilon &&
                           !box_outside_extent(terrain, lo, hi);
    if (!may_touch) {
      ++counters_.broadphase_skips[t];
      continue;
    }
    if (terrain.collision) {
      counters_.collision_queries[t] += static_cast<std::int64_t>(n);
      // A particle's velocity changes only where the student's function says it collided.
      const auto collide = [&](auto task) {
        return [&, task](const auto& surface, Eigen::Index i) {
          Vec3 vi = s.v.col(i);
          if (!task(surface, s.x.col(i), vi)) return false;
          s.v.col(i) = vi;
          return true;
        };
      };
      counters_.collisions[t] += count_per_particle(terrain, s.x, collide(tasks_.collide_plane),
                                                    collide(tasks_.collide_bowl));
    }
    if (terrain.project) {
      // Optional effect (contract §5): particles behind the surface, inside the extent, are moved
      // onto it along the normal.
      for (Eigen::Index i = 0; i < n; ++i) {
        const Vec3 x = s.x.col(i);
        if (!in_extent(terrain, x)) continue;
        const double phi = signed_distance(terrain, x);
        if (phi < 0.0) s.x.col(i) = x - phi * surface_normal(terrain, x);
      }
    }
  }
}

double World::reference_height() const {
  double ref = lowest_initial_height_;
  for (const Terrain& t : terrains_)
    if (const auto low = lowest_point(t)) ref = std::min(ref, *low);
  return ref;
}

Energy World::energy(const State& s) const {
  Energy e;
  const Eigen::Index n = s.size();
  for (Eigen::Index i = 0; i < n; ++i) e.kinetic += 0.5 * mass_[i] * s.v.col(i).squaredNorm();
  if (gravity_) {
    const double ref = reference_height();
    // Height along y, the axis every course scene's gravity acts along; a gravity vector with other
    // components contributes its work through −m g·x.
    for (Eigen::Index i = 0; i < n; ++i) {
      Vec3 rel = s.x.col(i);
      rel.y() -= ref;
      e.gravitational -= mass_[i] * gravity_->dot(rel);
    }
  }
  for (const SpringGroup& g : groups_) {
    for (const Spring& sp : g.springs) {
      const double stretch = (s.x.col(sp.a) - s.x.col(sp.b)).norm() - sp.rest_length;
      e.spring += 0.5 * g.ks * stretch * stretch;
    }
  }
  return e;
}

std::vector<std::pair<int, int>> World::jacobian_pattern() const {
  pattern_cache();
  return pairs_;
}

void World::pattern_cache() const {
  if (!pairs_.empty() || groups_.empty()) return;
  std::map<std::pair<int, int>, int> index;
  pair_of_spring_.assign(groups_.size(), {});
  for (std::size_t g = 0; g < groups_.size(); ++g) {
    auto& of = pair_of_spring_[g];
    of.reserve(groups_[g].springs.size());
    for (const Spring& s : groups_[g].springs) {
      const std::pair<int, int> key{std::min(s.a, s.b), std::max(s.a, s.b)};
      auto [it, inserted] = index.emplace(key, static_cast<int>(pairs_.size()));
      if (inserted) pairs_.push_back(key);
      of.push_back(it->second);
    }
  }
}

void World::force_jacobians(const State& s, ForceJacobians& jac) {
  pattern_cache();
  jac.set_zero();
  for (std::size_t g = 0; g < groups_.size(); ++g)
    add_spring_jacobians(groups_[g], s, pair_of_spring_[g], jac);
}

}  // namespace jelly
