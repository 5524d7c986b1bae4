#pragma once
// What the dynamics steps decided for one frame: returned to the pipeline, carried in the
// FrameResult, summed up by the stats writer (stats.json "dynamics").
#include <algorithm>
#include <cstdint>
#include <vector>

namespace dynanav {

struct FrameDynamics {
  int keypoints = 0;          ///< extracted (already outside prior-dynamic masks)
  int dynamic_keypoints = 0;  ///< made unusable: depth test / instance vote / residual movers
  int static_keypoints = 0;   ///< usable after the test
  int prior_instances = 0;    ///< people etc. in this frame (cut out of extraction)
  int moving_instances =
      0;                  ///< non-prior instances voted moving (depth vote, or moving last frame)
  int prior_moving = 0;   ///< prior instances whose scene flow says moving
  int prior_static = 0;   ///< prior instances whose scene flow says static
  int culled_points = 0;  ///< map points removed: on a moving object, or vanished
  int residual_regions = 0;          ///< regions of young points moving against the static map
  double masked_share = 0.0;         ///< image share cut out of extraction
  std::vector<uint16_t> moving_ids;  ///< this frame's instance ids found moving (ascending)
  std::vector<uint16_t> static_ids;  ///< this frame's prior instance ids scene flow found static

  [[nodiscard]] bool foundMoving(uint16_t id) const {
    return std::binary_search(moving_ids.begin(), moving_ids.end(), id);
  }
  [[nodiscard]] bool foundStatic(uint16_t id) const {
    return std::binary_search(static_ids.begin(), static_ids.end(), id);
  }
};

}  // namespace dynanav
