#pragma once
// Movers the segmenter missed, found by geometry (issue 18): a person nobody masked (an arm
// reaching in at the image border, someone the detector lost) is mapped at the next keyframe like
// the background, from that keyframe's depth. While it moves sideways its points pass the depth
// test (their depth hardly changes) and pull the pose along. Against a pose refitted to the
// established map points (slam/established_residuals.hpp) they show a residual, and — unlike
// noise — the same residual for all of them. So young matched points are grouped into regions
// (near in the image and in depth), and a region whose mean normalised residual is both
// significant (chi-square of the mean over its points) and large (pixels), beyond the common
// offset of the other young points (their keyframe's pose error), is a mover: its keypoints are
// dropped for this frame. Its points are not culled: a false region then costs one frame's
// keypoints, not the map, and a mover's young points that no later keyframe confirms leave the
// map by local mapping's culling of recent points.
//
// One frame's decision, but one that pools many points; a single point's residual decides
// nothing. Established points are not judged here: the refitted pose rests on them.
#include <vector>

#include "core/config/dynamics.hpp"
#include "perception/instances.hpp"
#include "slam/established_residuals.hpp"
#include "slam/frame.hpp"

namespace dynanav {

struct ResidualMovers {
  std::vector<int> keypoints;  ///< keypoints of moving regions, ascending
  int regions = 0;             ///< regions found moving
};

/// Groups the young keypoints of `frame` with a valid residual (`residuals`, per keypoint) and
/// depth into regions: linked when within residual_region_radius_px in the image and
/// residual_region_depth_band_m in depth. A region of at least residual_region_min_points moves
/// when, with each r/σ less the median r/σ of the young keypoints outside it (when at least
/// residual_region_min_points), n·|mean|² > residual_region_chi2 and |mean| ≥
/// residual_region_min_px.
ResidualMovers findResidualMovers(const Frame& frame, const std::vector<MapResidual>& residuals,
                                  const DynamicsConfig& config);

/// A non-prior instance moving sideways (a box pushed across the view) keeps its depth, so the
/// depth vote passes it, while its established map points (it stood still while mapped) pull
/// the frame's pose along until scene flow, measured against that pose, finds it (the simulated
/// pushed box dragged the camera 17 cm in 5 frames). Against the background's own pose
/// (slam/established_residuals.hpp, residualsToBackground) its matches show the motion.
struct ResidualInstances {
  std::vector<uint16_t> ids;   ///< instances found moving, ascending
  std::vector<int> keypoints;  ///< all their keypoints, ascending
};

/// For every instance of `instances` outside dynamics.prior_dynamic_classes with at least
/// residual_region_min_points matches valid in `background_residuals`: it moves when the
/// median r/σ of its matches (robust to the false matches among them: its variance is π/2 the
/// mean's) passes n·(2/π)·|median|² > residual_region_chi2 and |median| ≥ residual_region_min_px.
ResidualInstances findResidualInstances(const Frame& frame,
                                        const std::vector<MapResidual>& background_residuals,
                                        const Instances& instances, const DynamicsConfig& config);

}  // namespace dynanav
