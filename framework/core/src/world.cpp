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
#include "jelly/terrain_physics.hpp"

namespace jelly {

World::World(TaskTable tasks)
    : tasks_(tasks),
      spring_pass_(tasks.make_spring_group_pass ? tasks.make_spring_group_pass() : nullptr),
      physics_(std::make_unique<TerrainPhysics>(*this)) {}

World::~World() = default;

// Every member, in declaration order (a member added to World is added here too).
World::World(World&& other)
    : JacobianSystem(),
      tasks_(other.tasks_),
      spring_pass_(std::move(other.spring_pass_)),
      state_(std::move(other.state_)),
      mass_(std::move(other.mass_)),
      inv_mass_(std::move(other.inv_mass_)),
      groups_(std::move(other.groups_)),
      terrains_(std::move(other.terrains_)),
      gravity_(std::move(other.gravity_)),
      counters_(std::move(other.counters_)),
      force_(std::move(other.force_)),
      lowest_initial_height_(other.lowest_initial_height_),
      threads_(other.threads_),
      pairs_(std::move(other.pairs_)),
      pair_of_spring_(std::move(other.pair_of_spring_)),
      physics_(std::move(other.physics_)) {
  physics_->world_ = this;
  other.physics_ = std::make_unique<TerrainPhysics>(other);
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
  // Particles already there keep their inverse mass (a body kind's physics may have set it to 0).
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
  if (const char* why = physics_->refuses_terrain()) throw std::logic_error(why);
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
  if (physics_) physics_->reset_counters();
}

void World::acceleration(const State& s, Vec3Array& a) { physics_->acceleration(s, a); }

void World::apply_collisions(State& s) { physics_->apply_collisions(s); }

void World::begin_step(long step, double h) { physics_->begin_step(step, h); }

void World::end_step(double h) { physics_->end_step(h); }

bool World::is_fixed(Eigen::Index i) const { return physics_->is_fixed(i); }

void World::set_physics(std::unique_ptr<BodyPhysics> physics) {
  if (!physics || !physics->made_for(*this))
    throw std::logic_error("set_physics: expected a BodyPhysics made for this world");
  physics_ = std::move(physics);
}

void World::add_spring_forces(const State& s, Vec3Array& f) {
  for (const SpringGroup& g : groups_) {
    ++counters_.spring_group_evaluations[static_cast<std::size_t>(g.type)];
    counters_.springs_evaluated += static_cast<std::int64_t>(g.springs.size());
  }
  if (spring_pass_) {
    spring_pass_->accumulate(groups_.data(), groups_.size(), s, f);
  } else {
    for (const SpringGroup& g : groups_)
      accumulate_spring_forces(g, s, f, tasks_.spring_force, tasks_.damper_force);
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

// ----- the World's parts a BodyPhysics works on -----
Vec3Array& BodyPhysics::force_scratch(World& world) { return world.force_; }
EffectCounters& BodyPhysics::counters(World& world) { return world.counters_; }
Eigen::VectorXd& BodyPhysics::inverse_masses(World& world) { return world.inv_mass_; }
std::vector<SpringGroup>& BodyPhysics::spring_groups(World& world) { return world.groups_; }
void BodyPhysics::springs_changed(World& world) {
  if (world.spring_pass_) world.spring_pass_->springs_changed();
}
void BodyPhysics::add_spring_forces(World& world, const State& s, Vec3Array& f) {
  world.add_spring_forces(s, f);
}

}  // namespace jelly
