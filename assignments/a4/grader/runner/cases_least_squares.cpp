// A4.T3 cases: least_squares on hand-made and random J and e: full rank, rank-deficient (repeated,
// parallel and zero columns), J = 0, and at tiny and huge scales. The answer must be the
// minimum-norm one (kinematics contract §6.3) and finite. x is compared scaled by ‖J‖/|e|
// (Frobenius norm; 1 when either is 0), so that one tolerance fits every scale.
#include <algorithm>
#include <cstdint>
#include <cstdio>
#include <string>
#include <vector>

#include "cases.hpp"

namespace jelly::grade {

namespace {

struct Problem {
  skeleton::Matrix3X J;
  Vec3 e = Vec3::Zero();
  std::string words;
};

// params.matrices = [{ columns = [[x, y, z], …], e = [x, y, z], scale?, e_scale? }]: J's columns
// and e, each multiplied by its scale.
Problem hand_made(const Params& m) {
  Problem p;
  const Json& columns = m.json().at("columns");
  p.J = skeleton::Matrix3X::Zero(3, static_cast<Eigen::Index>(columns.size()));
  const double scale = m.number("scale", 1.0);
  for (std::size_t c = 0; c < columns.size(); ++c)
    p.J.col(static_cast<Eigen::Index>(c)) = scale * json_vec(columns.at(c));
  p.e = m.number("e_scale", 1.0) * m.vec("e");
  p.words = m.text("what");
  return p;
}

// params.random = { seed, count, bones, rank?, zero?, scale? }: J of 3 × 3m (m = 1 … bones), of
// rank `rank` (0: full) as a product of random factors, with about a third of its columns zero when
// zero = 1.
std::vector<Problem> random_problems(const Params& r) {
  std::vector<Problem> out;
  Sequence q(static_cast<std::uint64_t>(r.integer("seed")));
  const long bones = r.integer("bones"), rank = r.integer("rank", 0);
  const double scale = r.number("scale", 1.0);
  for (long i = 0; i < r.integer("count"); ++i) {
    const Eigen::Index m =
        1 + static_cast<Eigen::Index>((q.next() + 1.0) * 0.5 * static_cast<double>(bones));
    const Eigen::Index n = 3 * std::min<Eigen::Index>(m, bones);
    Problem p;
    p.J = skeleton::Matrix3X::Zero(3, n);
    if (rank > 0) {
      Eigen::MatrixXd a(3, rank), b(rank, n);
      for (Eigen::Index k = 0; k < a.size(); ++k) a.data()[k] = q.next();
      for (Eigen::Index k = 0; k < b.size(); ++k) b.data()[k] = q.next();
      p.J = a * b;
    } else {
      for (Eigen::Index c = 0; c < n; ++c) p.J.col(c) = q.next3();
    }
    if (r.integer("zero", 0) != 0)
      for (Eigen::Index c = 0; c < n; ++c)
        if (q.next() < -1.0 / 3.0) p.J.col(c).setZero();
    p.J *= scale;
    p.e = q.next3();
    p.words = "a random J of 3 × " + std::to_string(n) +
              (rank > 0 ? " and rank " + std::to_string(rank) : std::string(" (full rank)")) +
              (r.integer("zero", 0) != 0 ? " with zero columns" : "");
    out.push_back(p);
  }
  return out;
}

std::vector<Problem> problems(const Params& params) {
  std::vector<Problem> out;
  if (params.has("matrices"))
    for (const Params& m : params.list("matrices")) out.push_back(hand_made(m));
  if (params.has("random"))
    for (Problem& p : random_problems(params.table("random"))) out.push_back(std::move(p));
  return out;
}

void run_least_squares(const TaskTable& t, const Params& params, Outputs& out) {
  const std::vector<Problem> in = problems(params);
  for (std::size_t i = 0; i < in.size(); ++i) {
    skeleton::VectorX x;
    skeleton_tasks(t).least_squares(in[i].J, in[i].e, x);
    const double nj = in[i].J.norm(), ne = in[i].e.norm();
    const double scale = nj > 0.0 && ne > 0.0 ? nj / ne : 1.0;
    char name[32];
    std::snprintf(name, sizeof name, "x%02zu", i);
    out.values(name, std::vector<double>(x.data(), x.data() + x.size()),
               "x, the minimum-norm least-squares solution of J x = e (finite: no NaN or "
               "infinity) for " +
                   in[i].words);
    std::vector<double> scaled(static_cast<std::size_t>(x.size()));
    for (Eigen::Index k = 0; k < x.size(); ++k) scaled[static_cast<std::size_t>(k)] = x(k) * scale;
    out.values(std::string(name) + "_scaled", scaled,
               "x·‖J‖/|e| (x scaled to the problem's size), x the minimum-norm least-squares "
               "solution of J x = e for " +
                   in[i].words);
  }
}

}  // namespace

// least_squares: params.matrices (hand-made) and/or params.random; outputs xNN (x as computed,
// checked finite) and xNN_scaled (x·‖J‖/|e|, compared).
void register_least_squares_cases(Registry& r) {
  r.add({"least_squares",
         "least_squares on hand-made (params.matrices) or random (params.random) J and e", nullptr,
         [](const TaskTable& t, const Params& p, const Json&, Outputs& o) {
           run_least_squares(t, p, o);
         }});
}

}  // namespace jelly::grade
