// The collaborators of A4's iteration and solve in the grader (kinematics contract §6.4, §6.5):
// scripted answers, recorded from the reference's own solve when the data is generated, or made
// from a case's toy. The iteration is graded on what it does with the answers it is given (the
// postures it hands back, the e it solves for, the calls it makes), never on your own FK, Jacobian
// or solve, and a submission's runner never holds the reference.
#include <algorithm>
#include <cstddef>
#include <stdexcept>
#include <vector>

#include "cases.hpp"

namespace jelly::grade {

namespace {

// The k-th answer of a list, the last one past its end.
template <class T>
const T& answer(const std::vector<T>& list, std::size_t k) {
  return list[std::min(k, list.size() - 1)];
}

Json matrix_json(const Eigen::MatrixXd& m) {
  return {{"rows", m.rows()},
          {"cols", m.cols()},
          {"data", std::vector<double>(m.data(), m.data() + m.size())}};
}

Eigen::MatrixXd json_matrix(const Json& j) {
  const std::vector<double> v = j.at("data").get<std::vector<double>>();
  const Eigen::Index rows = j.at("rows").get<Eigen::Index>(),
                     cols = j.at("cols").get<Eigen::Index>();
  if (static_cast<Eigen::Index>(v.size()) != rows * cols)
    throw std::runtime_error("input: a matrix of the wrong size");
  return Eigen::Map<const Eigen::MatrixXd>(v.data(), rows, cols);
}

}  // namespace

Json script_json(const IkScript& s) {
  Json j = {{"effector", Json::array()},
            {"J", Json::array()},
            {"x", Json::array()},
            {"clamp", Json::array()}};
  for (const Vec3& p : s.effector) j["effector"].push_back(vec_json(p));
  for (const skeleton::Matrix3X& m : s.J) j["J"].push_back(matrix_json(m));
  for (const skeleton::VectorX& x : s.x) j["x"].push_back(matrix_json(x));
  for (const skeleton::Posture& p : s.clamp) j["clamp"].push_back(posture_json(p));
  return j;
}

IkScript json_script(const Json& j, std::size_t bones) {
  IkScript s;
  for (const Json& p : j.at("effector")) s.effector.push_back(json_vec(p));
  for (const Json& m : j.at("J")) s.J.emplace_back(json_matrix(m));
  for (const Json& x : j.at("x")) s.x.emplace_back(json_matrix(x));
  for (const Json& p : j.at("clamp")) s.clamp.push_back(json_posture(p, bones));
  return s;
}

skeleton::IkOps scripted_ops(const IkScript& script, IkLog& log) {
  skeleton::IkOps ops;
  ops.end_effector = [&script, &log](const skeleton::Posture& p) {
    log.effector.push_back(p);
    return script.effector.empty() ? Vec3(Vec3::Zero())
                                   : answer(script.effector, log.effector.size() - 1);
  };
  ops.jacobian = [&script, &log](const skeleton::Posture&, skeleton::Matrix3X& J) {
    ++log.jacobian_calls;
    J = script.J.empty() ? skeleton::Matrix3X(3, 0)
                         : answer(script.J, static_cast<std::size_t>(log.jacobian_calls - 1));
  };
  ops.solve = [&script, &log](const skeleton::Matrix3X& J, const Vec3& e, skeleton::VectorX& x) {
    log.e.push_back(e);
    x = script.x.empty() ? skeleton::VectorX(skeleton::VectorX::Zero(J.cols()))
                         : answer(script.x, log.e.size() - 1);
  };
  ops.clamp = [&script, &log](skeleton::Posture& p) {
    log.clamp.push_back(p);
    if (!script.clamp.empty()) p = answer(script.clamp, log.clamp.size() - 1);
  };
  return ops;
}

skeleton::IkOps recording_ops(const TaskTable& t, const skeleton::Skeleton& s,
                              const std::vector<int>& chain, IkScript& script) {
  const SkeletonTasks& k = skeleton_tasks(t);
  skeleton::IkOps ops;
  ops.end_effector = [&k, &s, &chain, &script](const skeleton::Posture& p) {
    skeleton::BoneFrames f;
    k.forward_kinematics(s, p, f);
    script.effector.push_back(f.end[static_cast<std::size_t>(chain.front())]);
    return script.effector.back();
  };
  ops.jacobian = [&k, &s, &chain, &script](const skeleton::Posture& p, skeleton::Matrix3X& J) {
    skeleton::BoneFrames f;
    k.forward_kinematics(s, p, f);
    k.ik_jacobian(s, f, chain, J);
    script.J.push_back(J);
  };
  ops.solve = [&k, &script](const skeleton::Matrix3X& J, const Vec3& e, skeleton::VectorX& x) {
    k.least_squares(J, e, x);
    script.x.push_back(x);
  };
  ops.clamp = [&k, &s, &chain, &script](skeleton::Posture& p) {
    k.clamp_to_limits(s, chain, p);
    script.clamp.push_back(p);
  };
  return ops;
}

skeleton::IkSettings settings_of(const Params& params) {
  skeleton::IkSettings s;
  if (!params.has("settings")) return s;
  const Params p = params.table("settings");
  s.step = p.number("step", s.step);
  s.epsilon = p.number("epsilon", s.epsilon);
  s.max_iterations = static_cast<int>(p.integer("max_iterations", s.max_iterations));
  s.limits = p.integer("limits", 0) != 0;
  s.restore = p.integer("restore", 1) != 0;
  return s;
}

}  // namespace jelly::grade
