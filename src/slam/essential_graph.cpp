#include "slam/essential_graph.hpp"

#include <ceres/ceres.h>

#include <memory>

namespace dynanav {
namespace {

// Relative-pose error of Ceres' pose_graph_3d example: the rotation and translation of
// T_ab_measured^-1 * (T_wa^-1 * T_wb), small-angle rotation as twice the quaternion vector part.
struct RelativePoseError {
  RelativePoseError(const SE3& T_a_b, double weight)
      : q_ab(Quat(T_a_b.linear()).normalized()),
        t_ab(T_a_b.translation()),
        sqrt_weight(std::sqrt(weight)) {}

  template <typename T>
  bool operator()(const T* q_a_ptr, const T* t_a_ptr, const T* q_b_ptr, const T* t_b_ptr,
                  T* residual) const {
    Eigen::Map<const Eigen::Quaternion<T>> q_a(q_a_ptr), q_b(q_b_ptr);
    Eigen::Map<const Eigen::Matrix<T, 3, 1>> t_a(t_a_ptr), t_b(t_b_ptr);
    const Eigen::Quaternion<T> q_a_inv = q_a.conjugate();
    const Eigen::Quaternion<T> q_ab_est = q_a_inv * q_b;
    const Eigen::Matrix<T, 3, 1> t_ab_est = q_a_inv * (t_b - t_a);
    const Eigen::Quaternion<T> q_err = q_ab.template cast<T>().conjugate() * q_ab_est;
    const Eigen::Matrix<T, 3, 1> t_err =
        q_ab.template cast<T>().conjugate() * (t_ab_est - t_ab.template cast<T>());
    Eigen::Map<Eigen::Matrix<T, 6, 1>> r(residual);
    r.template head<3>() = t_err * T(sqrt_weight);
    r.template tail<3>() = T(2.0 * sqrt_weight) * q_err.vec();
    return true;
  }

  Quat q_ab;
  Vec3 t_ab;
  double sqrt_weight;
};

}  // namespace

PoseGraphSummary optimizePoseGraph(PoseGraph& graph, int max_iterations) {
  PoseGraphSummary summary;
  const size_t n = graph.nodes.size();
  std::vector<Eigen::Vector4d> q(n);  // x, y, z, w (Eigen's storage order)
  std::vector<Vec3> t(n);
  for (size_t i = 0; i < n; ++i) {
    const Quat qi(graph.nodes[i].T_world_camera.linear());
    q[i] = qi.normalized().coeffs();
    t[i] = graph.nodes[i].T_world_camera.translation();
  }
  ceres::Problem problem;
  for (const auto& e : graph.edges) {
    if (e.a == e.b) continue;
    auto* cost = new ceres::AutoDiffCostFunction<RelativePoseError, 6, 4, 3, 4, 3>(
        new RelativePoseError(e.T_a_b, e.weight));
    problem.AddResidualBlock(cost, nullptr, q[e.a].data(), t[e.a].data(), q[e.b].data(),
                             t[e.b].data());
  }
  for (size_t i = 0; i < n; ++i) {
    if (!problem.HasParameterBlock(q[i].data())) continue;
    problem.SetManifold(q[i].data(), new ceres::EigenQuaternionManifold);
    if (graph.nodes[i].fixed) {
      problem.SetParameterBlockConstant(q[i].data());
      problem.SetParameterBlockConstant(t[i].data());
    }
  }
  if (problem.NumResidualBlocks() == 0) return summary;
  ceres::Solver::Options options;
  options.linear_solver_type = ceres::SPARSE_NORMAL_CHOLESKY;
  options.max_num_iterations = max_iterations;
  options.num_threads = 1;  // deterministic
  ceres::Solver::Summary result;
  ceres::Solve(options, &problem, &result);
  summary.initial_cost = result.initial_cost;
  summary.final_cost = result.final_cost;
  summary.iterations = static_cast<int>(result.iterations.size());
  for (size_t i = 0; i < n; ++i) {
    if (graph.nodes[i].fixed) continue;
    graph.nodes[i].T_world_camera = makeSE3(Quat(q[i][3], q[i][0], q[i][1], q[i][2]), t[i]);
  }
  return summary;
}

}  // namespace dynanav
