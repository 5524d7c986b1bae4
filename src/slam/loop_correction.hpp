#pragma once
// Closing a verified loop (ORB-SLAM2 LoopClosing::CorrectLoop, T-RO 2015 §VII-C/D, RGB-D: SE(3)):
// 1. the current keyframe and its covisible window move with the loop's correction, their points
//    with them; 2. the current keyframe's duplicated points are replaced by the loop's, and the
//    loop's points are fused into the window; 3. the essential graph (spanning tree, strong
//    covisibility edges, loop edges and the new loop links) is optimised and every point follows
//    its reference keyframe. Call with the map locked.
#include <map>
#include <set>

#include "core/config/loop.hpp"
#include "slam/loop_verification.hpp"
#include "slam/map.hpp"

namespace dynanav {

struct LoopCorrectionSummary {
  int window_keyframes = 0;
  int points_fused = 0;
  int graph_edges = 0;
  double graph_initial_cost = 0.0;
  double graph_final_cost = 0.0;
};

LoopCorrectionSummary correctLoop(Map& map, KeyFrame& current, const VerifiedLoop& loop,
                                  const LoopConfig& config, int covisibility_min_weight);

using KeyFramePoses = std::map<KeyFrame*, SE3>;  ///< keyed by address; T_world_camera
using LoopLinks = std::map<KeyFrame*, std::set<KeyFrame*>>;

struct EssentialGraphResult {
  int edges = 0;
  double initial_cost = 0.0;
  double final_cost = 0.0;
};

/// Optimises every keyframe pose over the essential graph, `fixed` held still. Edges measure the
/// relative poses before the correction (`uncorrected`, for keyframes the correction moved; the
/// current pose for the others); `loop_links` (new links across the loop) measure the corrected
/// poses. Points move with their first observer. Exposed for tests.
EssentialGraphResult optimizeEssentialGraph(Map& map, const KeyFrame& fixed,
                                            const KeyFramePoses& uncorrected,
                                            const LoopLinks& loop_links, const LoopConfig& config);

}  // namespace dynanav
