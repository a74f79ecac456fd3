// The reference's fast spring engine: the spring pass over all of a world's spring groups in one
// call (jelly/spring_group_pass.hpp), for the viewer, the CLI and the grader's reference data.
// Framework machinery of the reference, not a task; it computes the answer of the shared spring
// and damper force tasks, so it lives with the reference and is never shipped to students.
// Speed: docs/performance.md.
//
// Part of the task module mass_spring (solutions/tasks/mass_spring/): compiled once for each
// assignment whose manifest lists the module in `task_modules`, in that assignment's namespace
// (the build defines JELLY_TASKS_NAMESPACE), with that assignment's spring_force and damper_force.
#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <map>
#include <memory>
#include <utility>
#include <vector>

#ifdef _OPENMP
#include <omp.h>
#endif

#include "jelly/spring_group_pass.hpp"
#include "jelly/task_table.hpp"
#include "jelly/types.hpp"

#ifndef JELLY_TASKS_NAMESPACE
#error "a task module is compiled for an assignment: the build defines JELLY_TASKS_NAMESPACE"
#endif

namespace jelly::JELLY_TASKS_NAMESPACE {

// The module's tasks, as the assignment declares them (same signatures, same contract section:
// physics contract §2); the assignment's reference defines them.
Vec3 spring_force(const Vec3& xa, const Vec3& xb, double ks, double rest_length,
                  double degenerate_length);
Vec3 damper_force(const Vec3& xa, const Vec3& xb, const Vec3& va, const Vec3& vb, double kd,
                  double degenerate_length);

}  // namespace jelly::JELLY_TASKS_NAMESPACE

// The hot loops below are compiled twice, for the baseline x86-64 vector width (SSE2) and for
// AVX2, and the loader picks the one the processor supports, so that the default build runs the
// wide loops without -march=native. Neither clone uses FMA (-ffp-contract=off is on anyway), so
// both give the same bits (tests/determinism builds with JELLY_NO_VECTOR_CLONES to test each
// width on its own).
#if defined(__x86_64__) && defined(__ELF__) && defined(__GNUC__) && !defined(JELLY_NO_VECTOR_CLONES)
#define JELLY_VECTOR_CLONES __attribute__((target_clones("avx2", "default")))
#else
#define JELLY_VECTOR_CLONES
#endif

namespace jelly::JELLY_TASKS_NAMESPACE {
namespace {

#ifdef _OPENMP
// Below this many particles the pass runs on one thread whatever set_threads asked (fork and
// join would cost more than they save).
constexpr int kParallelThreshold = 512;
#endif

// ---- The reference's fast spring pass --------------------------------------------------------
//
// Springs are grouped by their index offset b − a (after ordering each pair so that a < b). In a
// cube every spring direction is one offset, so each group is a dense run a = first … first+count
// with b = a + offset: a loop over a that the compiler vectorises without gathers, on the state in
// structure-of-arrays form. Springs that fit no dense run (duplicates, sparse offsets) take a
// scalar path. The sums are done per particle in a fixed order (offset by offset: + from the spring
// it owns, − from the spring that ends at it, then the leftovers in list order), so the bits depend
// neither on the vector width nor on how the particles are split among threads. Each spring's force
// is the same arithmetic as spring_force(...) + damper_force(...).

struct OffsetRun {
  int offset = 0;               // b − a > 0
  int first = 0;                // smallest a
  int count = 0;                // dense length: a ∈ [first, first + count)
  std::vector<double> rest;     // rest length per a − first
  std::vector<double> present;  // 1 where a spring (a, a + offset) exists, else 0
};

struct Plan {
  std::vector<OffsetRun> runs;    // ascending offset
  std::vector<Spring> leftovers;  // scalar path, in list order
};

std::unique_ptr<Plan> make_plan(const std::vector<Spring>& springs) {
  auto plan = std::make_unique<Plan>();
  std::map<int, std::vector<std::pair<int, double>>> by_offset;  // offset → (a, rest)
  for (const Spring& sp : springs) {
    const int a = std::min(sp.a, sp.b), b = std::max(sp.a, sp.b);
    if (a == b) {
      plan->leftovers.push_back(sp);
      continue;
    }
    by_offset[b - a].emplace_back(a, sp.rest_length);
  }
  for (auto& [offset, list] : by_offset) {
    int lo = list.front().first, hi = lo;
    for (const auto& e : list) lo = std::min(lo, e.first), hi = std::max(hi, e.first);
    OffsetRun run;
    run.offset = offset;
    run.first = lo;
    run.count = hi - lo + 1;
    const bool dense = 4 * list.size() >= static_cast<std::size_t>(run.count);
    if (dense) {
      run.rest.assign(static_cast<std::size_t>(run.count), 0.0);
      run.present.assign(static_cast<std::size_t>(run.count), 0.0);
    }
    for (const auto& [a, rest] : list) {
      const auto k = static_cast<std::size_t>(a - lo);
      if (dense && run.present[k] == 0.0) {
        run.present[k] = 1.0;
        run.rest[k] = rest;
      } else {
        plan->leftovers.push_back(Spring{a, a + offset, rest});  // sparse offset or a duplicate
      }
    }
    if (dense) plan->runs.push_back(std::move(run));
  }
  return plan;
}

// The state in structure-of-arrays form, shared by the threads of one pass. Kept by the engine
// between calls, so that a step allocates nothing once warmed up.
struct Scratch {
  std::vector<double> x, y, z, vx, vy, vz;
  std::vector<double> sums;        // per group: its force sums fx, fy, fz (3 n each), from zero
  std::vector<const Plan*> plans;  // per group: its layout (nullptr: no springs)
};

// Forces on the owners a = 0 … count−1 of springs (a, a + off), with positions and velocities given
// from the first owner on: one lane per spring, no branch, so that the loop vectorises. An absent
// or degenerate spring gets u = 0 and so a zero force.
JELLY_VECTOR_CLONES
void spring_lane(int count, int off, const double* __restrict x, const double* __restrict y,
                 const double* __restrict z, const double* __restrict vx,
                 const double* __restrict vy, const double* __restrict vz,
                 const double* __restrict rest, const double* __restrict present, double ks,
                 double kd, double degenerate, double* __restrict tx, double* __restrict ty,
                 double* __restrict tz) {
  for (int a = 0; a < count; ++a) {
    const int b = a + off;
    const double d0 = x[a] - x[b], d1 = y[a] - y[b], d2 = z[a] - z[b];
    const double length = std::sqrt(d0 * d0 + d1 * d1 + d2 * d2);
    const bool live = (present[a] != 0.0) & !(length < degenerate) & (length != 0.0);
    const double inverse = live ? 1.0 / length : 0.0;
    const double u0 = d0 * inverse, u1 = d1 * inverse, u2 = d2 * inverse;
    const double along = (vx[a] - vx[b]) * u0 + (vy[a] - vy[b]) * u1 + (vz[a] - vz[b]) * u2;
    const double cs = -ks * (length - rest[a]);
    const double cd = -kd * along;
    tx[a] = cs * u0 + cd * u0;
    ty[a] = cs * u1 + cd * u1;
    tz[a] = cs * u2 + cd * u2;
  }
}

// Particles [j0, j1) of a 3×N column-major array into three arrays, in one pass.
JELLY_VECTOR_CLONES
void to_components(int j0, int j1, const double* __restrict in, double* __restrict c0,
                   double* __restrict c1, double* __restrict c2) {
  for (int i = j0; i < j1; ++i) {
    c0[i] = in[3 * i];
    c1[i] = in[3 * i + 1];
    c2[i] = in[3 * i + 2];
  }
}

// out[3i + d] += c_d[i] for the particles [j0, j1), in one pass.
JELLY_VECTOR_CLONES
void add_components(int j0, int j1, const double* __restrict c0, const double* __restrict c1,
                    const double* __restrict c2, double* __restrict out) {
  for (int i = j0; i < j1; ++i) {
    out[3 * i] += c0[i];
    out[3 * i + 1] += c1[i];
    out[3 * i + 2] += c2[i];
  }
}

// Lanes per chunk: the chunk's forces (12 KB) stay in L1 between the lane and the two scatter
// loops. Measured: 128 lanes cost n = 30 about 40 % (the backward jumps from chunk to chunk
// defeat the hardware prefetcher once the state no longer fits in L2), 512 and 2048 cost the same.
constexpr int kChunk = 512;

// Adds the forces of every dense run to F[j] for the particles j ∈ [j0, j1). Per particle the
// order is fixed: run by run (ascending offset), + from the spring it owns, then − from the spring
// ending at it. The chunks of a run go from the last to the first, so the chunk holding a spring
// that ends at j (owner j − off) is never handled before the chunk holding j's own spring.
JELLY_VECTOR_CLONES
void pass_over_block(const Plan& plan, double ks, double kd, double degenerate, const Scratch& s,
                     double* __restrict fx, double* __restrict fy, double* __restrict fz, int j0,
                     int j1) {
  alignas(64) double tx[kChunk], ty[kChunk], tz[kChunk];
  const double* __restrict x = s.x.data();
  const double* __restrict y = s.y.data();
  const double* __restrict z = s.z.data();
  const double* __restrict vx = s.vx.data();
  const double* __restrict vy = s.vy.data();
  const double* __restrict vz = s.vz.data();
  for (const OffsetRun& run : plan.runs) {
    const int off = run.offset;
    // Springs needed: those owned by a particle of the block (a ∈ [j0, j1)) and those ending in it
    // (a + off ∈ [j0, j1)).
    const int lo = std::max(run.first, j0 - off);
    const int hi = std::min(run.first + run.count, j1);
    for (int c1 = hi; c1 > lo; c1 -= kChunk) {
      const int c0 = std::max(lo, c1 - kChunk);
      const double* __restrict rest = run.rest.data() + (c0 - run.first);
      const double* __restrict present = run.present.data() + (c0 - run.first);
      spring_lane(c1 - c0, off, x + c0, y + c0, z + c0, vx + c0, vy + c0, vz + c0, rest, present,
                  ks, kd, degenerate, tx, ty, tz);
      for (int a = std::max(c0, j0); a < c1; ++a) {  // + on the owner a
        fx[a] += tx[a - c0];
        fy[a] += ty[a - c0];
        fz[a] += tz[a - c0];
      }
      const int end = std::min(c1, j1 - off);
      for (int a = c0; a < end; ++a) {  // − on the other end b = a + off
        fx[a + off] -= tx[a - c0];
        fy[a + off] -= ty[a - c0];
        fz[a + off] -= tz[a - c0];
      }
    }
  }
}

// Adds the scalar leftovers of a group (list order) to f.
void add_leftovers(const Plan& plan, const SpringGroup& group, const State& s, Vec3Array& f) {
  for (const Spring& sp : plan.leftovers) {
    const Vec3 xa = s.x.col(sp.a), xb = s.x.col(sp.b);
    const Vec3 fa =
        spring_force(xa, xb, group.ks, sp.rest_length, group.degenerate_length) +
        damper_force(xa, xb, s.v.col(sp.a), s.v.col(sp.b), group.kd, group.degenerate_length);
    f.col(sp.a) += fa;
    f.col(sp.b) -= fa;
  }
}

}  // namespace

// The engine: a plan per group position, rebuilt when the group's spring list is another one
// (moved, resized) or springs_changed() was called, and the scratch of the pass.
class SpringEngine final : public SpringGroupPass {
 public:
  void accumulate(const SpringGroup* groups, std::size_t count, const State& s,
                  Vec3Array& f) override;
  void set_threads(int threads) override { threads_ = std::max(1, threads); }
  void springs_changed() override { plans_.clear(); }

 private:
  // The layout of the group at one position, and which spring list it was made from.
  struct CachedPlan {
    const Spring* springs = nullptr;
    std::size_t size = 0;
    std::unique_ptr<Plan> plan;
  };
  const Plan* plan_of(std::size_t position, const SpringGroup& group);

  std::vector<CachedPlan> plans_;
  Scratch scratch_;
  int threads_ = 1;
};

const Plan* SpringEngine::plan_of(std::size_t position, const SpringGroup& group) {
  if (group.springs.empty()) return nullptr;
  CachedPlan& c = plans_[position];
  if (!c.plan || c.springs != group.springs.data() || c.size != group.springs.size()) {
    c.plan = make_plan(group.springs);
    c.springs = group.springs.data();
    c.size = group.springs.size();
  }
  return c.plan.get();
}

// The whole pass for `count` groups, in the order f ← ((f + S₁) + L₁) + S₂ + L₂ …, where S_g is
// group g's dense sum (from zero, per particle in offset order) and L_g its scalar leftovers:
// with the state turned into structure-of-arrays once, and (with threads) one parallel region in
// which each thread owns a block of particles from the copy to the write-back.
void SpringEngine::accumulate(const SpringGroup* groups, std::size_t count, const State& s,
                              Vec3Array& f) {
  if (count == 0) return;
  const int n = static_cast<int>(s.size());
  const auto un = static_cast<std::size_t>(n);
  if (plans_.size() < count) plans_.resize(count);
  Scratch& w = scratch_;
  for (auto* v : {&w.x, &w.y, &w.z, &w.vx, &w.vy, &w.vz}) v->resize(un);
  w.sums.resize(3 * un * count);
  bool leftovers = false;
  w.plans.resize(count);  // kept between calls: no allocation once warmed up
  const Plan** plans = w.plans.data();
  for (std::size_t g = 0; g < count; ++g) {
    plans[g] = plan_of(g, groups[g]);
    if (plans[g] && !plans[g]->leftovers.empty()) leftovers = true;
  }
  const double* xs = s.x.data();
  const double* vs = s.v.data();
  double* out = f.data();
  double* sums = w.sums.data();
  int threads = 1;
#ifdef _OPENMP
  threads = n >= kParallelThreshold ? threads_ : 1;
#endif
  const int block = (n + threads - 1) / threads;
  // One block of particles per thread: the result is the same for any number of threads.
  auto body = [&](int t, auto barrier) {
    const int j0 = std::min(n, t * block), j1 = std::min(n, (t + 1) * block);
    to_components(j0, j1, xs, w.x.data(), w.y.data(), w.z.data());
    to_components(j0, j1, vs, w.vx.data(), w.vy.data(), w.vz.data());
    barrier();  // a block's springs read the neighbours of other blocks
    for (std::size_t g = 0; g < count; ++g) {
      if (!plans[g]) continue;
      double* fx = sums + 3 * un * g;
      std::fill(fx + j0, fx + j1, 0.0);
      std::fill(fx + un + j0, fx + un + j1, 0.0);
      std::fill(fx + 2 * un + j0, fx + 2 * un + j1, 0.0);
      pass_over_block(*plans[g], groups[g].ks, groups[g].kd, groups[g].degenerate_length, w, fx,
                      fx + un, fx + 2 * un, j0, j1);
      if (!leftovers) add_components(j0, j1, fx, fx + un, fx + 2 * un, out);
    }
  };
#ifdef _OPENMP
  if (threads > 1) {
#pragma omp parallel num_threads(threads)
    body(omp_get_thread_num(), [] {
#pragma omp barrier
    });
  } else {
    body(0, [] {});
  }
#else
  body(0, [] {});
#endif
  if (!leftovers) return;
  for (std::size_t g = 0; g < count; ++g) {  // rare: sparse offsets or duplicate springs
    if (!plans[g]) continue;
    const double* fx = sums + 3 * un * g;
    add_components(0, n, fx, fx + un, fx + 2 * un, out);
    add_leftovers(*plans[g], groups[g], s, f);
  }
}

std::unique_ptr<SpringGroupPass> make_spring_group_pass() {
  return std::make_unique<SpringEngine>();
}

// What the module's reference adds to the assignment's task table beyond its tasks (the build's
// generated task_table_slots.cpp calls it for the reference library only).
void add_mass_spring_slots(TaskTable& t) { t.make_spring_group_pass = &make_spring_group_pass; }

}  // namespace jelly::JELLY_TASKS_NAMESPACE
