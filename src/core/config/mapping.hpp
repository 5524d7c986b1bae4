#pragma once
// Config section `mapping` (see core/config.hpp for how sections are loaded and echoed).
// To add a tunable: the member with its default, and one v("key", member, "doc", valid) line in
// visit(); `valid` (core/config/range.hpp) is the documented range the loader enforces.
// Defaults follow ORB-SLAM2's local mapping for RGB-D input.
#include "core/config/range.hpp"

#include <string>
#include <vector>

namespace dynanav {

/// Local mapping.
struct MappingConfig {
  int covisibility_min_weight = 15;
  int triangulation_neighbours = 10;
  int fuse_neighbours = 10;
  double recent_point_min_found_ratio = 0.25;
  int recent_point_min_observations = 3;
  int ba_iterations_first = 5;
  int ba_iterations_second = 10;
  std::string ba_linear_solver = "sparse_schur";
  double redundant_keyframe_ratio = 0.9;
  int redundant_min_observers = 3;
  int queue_capacity = 3;
  int final_ba_iterations = 10;
  template <class V>
  void visit(V&& v) {
    v("covisibility_min_weight", covisibility_min_weight,
      "shared map points for two keyframes to count as covisible", Range{1, 100000});
    v("triangulation_neighbours", triangulation_neighbours,
      "best covisible keyframes searched for new triangulated points", Range{1, 1000});
    v("fuse_neighbours", fuse_neighbours, "best covisible keyframes whose points are fused",
      Range{1, 1000});
    v("recent_point_min_found_ratio", recent_point_min_found_ratio,
      "a new point found in fewer than this share of frames where it was visible is culled",
      Range{0, 1});
    v("recent_point_min_observations", recent_point_min_observations,
      "a new point with at most this many observations (one with depth counts 2) two keyframes "
      "after its creation is culled",
      Range{0, 1000});
    v("ba_iterations_first", ba_iterations_first, "local BA iterations before outlier removal",
      Range{0, 1000});
    v("ba_iterations_second", ba_iterations_second, "local BA iterations after outlier removal",
      Range{0, 1000});
    v("ba_linear_solver", ba_linear_solver, "Ceres linear solver: sparse_schur | dense_schur",
      OneOf{"sparse_schur", "dense_schur"});
    v("redundant_keyframe_ratio", redundant_keyframe_ratio,
      "a keyframe whose close points are this share seen by enough others is culled", Range{0, 1});
    v("redundant_min_observers", redundant_min_observers,
      "other keyframes that must see a point at the same or finer scale for redundancy",
      Range{1, 1000});
    v("queue_capacity", queue_capacity, "keyframes waiting for local mapping (threaded mode)",
      Range{1, 1000});
    v("final_ba_iterations", final_ba_iterations,
      "iterations per pass of the whole-map bundle adjustment at the end of a run (0 = none)",
      Range{0, 1000});
  }
};

}  // namespace dynanav
