// Reference solution of A1.T4–A1.T5 (spring and damper forces). Not shipped to students.
#include <algorithm>
#include <cmath>
#include <cstddef>
#include <map>
#include <memory>
#include <utility>
#include <vector>

#ifdef _OPENMP
#include <omp.h>
#endif

#include "jelly/tasks/forces.hpp"

namespace jelly::tasks {

#ifdef _OPENMP
// Below this many particles the pass runs on one thread whatever group.threads asks (fork and
// join would cost more than they save).
constexpr int kParallelThreshold = 512;
#endif

Vec3 spring_force(const Vec3& xa, const Vec3& xb, double ks, double rest_length,
                  double degenerate_length) {
  const Vec3 d = xa - xb;
  const double length = d.norm();
  if (length < degenerate_length || length == 0.0) return Vec3::Zero();
  const Vec3 u = d * (1.0 / length);  // one division instead of three
  return (-ks * (length - rest_length)) * u;
}

Vec3 damper_force(const Vec3& xa, const Vec3& xb, const Vec3& va, const Vec3& vb, double kd,
                  double degenerate_length) {
  const Vec3 d = xa - xb;
  const double length = d.norm();
  if (length < degenerate_length || length == 0.0) return Vec3::Zero();
  const Vec3 u = d * (1.0 / length);
  return (-kd * (va - vb).dot(u)) * u;
}

namespace {

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
  std::vector<OffsetRun> runs;   // ascending offset
  std::vector<Spring> leftovers;  // scalar path, in list order
};

std::shared_ptr<const Plan> make_plan(const std::vector<Spring>& springs) {
  auto plan = std::make_shared<Plan>();
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

// Scratch kept per thread between calls, so that a step allocates nothing once warmed up.
struct Scratch {
  std::vector<double> x, y, z, vx, vy, vz, fx, fy, fz;
};
Scratch& scratch() {
  thread_local Scratch s;
  return s;
}
struct Lane {
  std::vector<double> tx, ty, tz;
};
Lane& lane() {
  thread_local Lane l;
  return l;
}

// Forces on the owners a = 0 … count−1 of springs (a, a + off), with positions and velocities given
// from the first owner on: one lane per spring, no branch, so that the loop vectorises. An absent or
// degenerate spring gets u = 0 and so a zero force.
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

// out[i] = in[3i + d]: one coordinate of a 3×N column-major array.
void gather_component(int n, const double* __restrict in, int d, double* __restrict out) {
  for (int i = 0; i < n; ++i) out[i] = in[3 * i + d];
}

// out[3i + d] += in[i].
void add_component(int n, const double* __restrict in, int d, double* __restrict out) {
  for (int i = 0; i < n; ++i) out[3 * i + d] += in[i];
}

// Adds the forces of every dense run to F[j] for the particles j ∈ [j0, j1).
void pass_over_block(const Plan& plan, double ks, double kd, double degenerate, const Scratch& s,
                     double* __restrict fx, double* __restrict fy, double* __restrict fz, int j0,
                     int j1) {
  Lane& t = lane();
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
    if (lo >= hi) continue;
    const auto n = static_cast<std::size_t>(hi - lo);
    if (t.tx.size() < n) t.tx.resize(n), t.ty.resize(n), t.tz.resize(n);
    double* __restrict tx = t.tx.data();
    double* __restrict ty = t.ty.data();
    double* __restrict tz = t.tz.data();
    const double* __restrict rest = run.rest.data() + (lo - run.first);
    const double* __restrict present = run.present.data() + (lo - run.first);
    spring_lane(hi - lo, off, x + lo, y + lo, z + lo, vx + lo, vy + lo, vz + lo, rest, present, ks, kd,
                degenerate, tx, ty, tz);
    for (int a = std::max(lo, j0); a < hi; ++a) {  // + on the owner a
      fx[a] += tx[a - lo];
      fy[a] += ty[a - lo];
      fz[a] += tz[a - lo];
    }
    const int end = std::min(hi, j1 - off);
    for (int a = lo; a < end; ++a) {  // − on the other end b = a + off
      fx[a + off] -= tx[a - lo];
      fy[a + off] -= ty[a - lo];
      fz[a + off] -= tz[a - lo];
    }
  }
}

}  // namespace

void accumulate_spring_forces(const SpringGroup& group, const State& s, Vec3Array& f) {
  if (group.springs.empty()) return;
  if (!group.task_cache) group.task_cache = make_plan(group.springs);
  const Plan& plan = *static_cast<const Plan*>(group.task_cache.get());
  const int n = static_cast<int>(s.size());
  Scratch& w = scratch();
  for (auto* v : {&w.x, &w.y, &w.z, &w.vx, &w.vy, &w.vz}) v->resize(static_cast<std::size_t>(n));
  for (auto* v : {&w.fx, &w.fy, &w.fz}) v->assign(static_cast<std::size_t>(n), 0.0);
  const double* xs = s.x.data();
  const double* vs = s.v.data();
  gather_component(n, xs, 0, w.x.data());  // to structure-of-arrays, one stream at a time
  gather_component(n, xs, 1, w.y.data());
  gather_component(n, xs, 2, w.z.data());
  gather_component(n, vs, 0, w.vx.data());
  gather_component(n, vs, 1, w.vy.data());
  gather_component(n, vs, 2, w.vz.data());
  const double ks = group.ks, kd = group.kd, degenerate = group.degenerate_length;
#ifdef _OPENMP
  // Blocks of particles; the result is the same for any number of blocks or threads.
  const int threads = n >= kParallelThreshold ? std::max(1, group.threads) : 1;
  const int block = (n + threads - 1) / threads;
#pragma omp parallel for schedule(static) num_threads(threads) if (threads > 1)
  for (int t = 0; t < threads; ++t)
    pass_over_block(plan, ks, kd, degenerate, w, w.fx.data(), w.fy.data(), w.fz.data(), t * block,
                    std::min(n, (t + 1) * block));
#else
  pass_over_block(plan, ks, kd, degenerate, w, w.fx.data(), w.fy.data(), w.fz.data(), 0, n);
#endif
  add_component(n, w.fx.data(), 0, f.data());
  add_component(n, w.fy.data(), 1, f.data());
  add_component(n, w.fz.data(), 2, f.data());
  for (const Spring& sp : plan.leftovers) {
    const Vec3 xa = s.x.col(sp.a), xb = s.x.col(sp.b);
    const Vec3 fa =
        spring_force(xa, xb, ks, sp.rest_length, degenerate) +
        damper_force(xa, xb, s.v.col(sp.a), s.v.col(sp.b), kd, degenerate);
    f.col(sp.a) += fa;
    f.col(sp.b) -= fa;
  }
}

}  // namespace jelly::tasks
