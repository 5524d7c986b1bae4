#pragma once
// Pose-graph optimisation over the essential graph (ORB-SLAM2 Optimizer::OptimizeEssentialGraph,
// T-RO 2017 §V-D / Strasdat et al. 2010), in Ceres. RGB-D fixes the scale, so the graph is over
// SE(3) rather than Sim(3). Plain data in and out: nodes with an initial pose, edges with a
// measured relative pose; the map-facing side (which edges, which poses) is in loop_correction.
#include <cstdint>
#include <vector>

#include "core/se3.hpp"

namespace dynanav {

struct PoseGraphNode {
  uint64_t id = 0;
  SE3 T_world_camera = SE3::Identity();
  bool fixed = false;
};

/// Measured T_a_b = T_world_a^-1 * T_world_b. Residual: the 6-vector
/// (translation of, 2 * vector part of the quaternion of) T_a_b_measured^-1 * T_a_b_estimated.
struct PoseGraphEdge {
  int a = 0;  ///< node index
  int b = 0;
  SE3 T_a_b = SE3::Identity();
  double weight = 1.0;
};

struct PoseGraph {
  std::vector<PoseGraphNode> nodes;
  std::vector<PoseGraphEdge> edges;
};

struct PoseGraphSummary {
  double initial_cost = 0.0;
  double final_cost = 0.0;
  int iterations = 0;
};

/// Optimises the non-fixed nodes in place (Levenberg-Marquardt, sparse normal Cholesky).
PoseGraphSummary optimizePoseGraph(PoseGraph& graph, int max_iterations = 20);

}  // namespace dynanav
