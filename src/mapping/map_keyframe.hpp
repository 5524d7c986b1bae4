#pragma once
// What the static map keeps of a keyframe until the end of the run, when its optimised pose is
// known (issue 15): colour and depth at reduced resolution, with every dynamic pixel's depth
// already removed, so nothing that moved can reach the map.
#include <cstdint>
#include <opencv2/core.hpp>
#include <vector>

#include "core/camera.hpp"
#include "core/se3.hpp"

namespace dynanav {

struct MapKeyframe {
  double stamp_s = 0.0;
  cv::Mat bgr;      ///< CV_8UC3 at 1/downscale of the input
  cv::Mat depth_m;  ///< CV_32F, same size; 0 = invalid, too far, or dynamic
};

/// A kept keyframe with its final pose (world = first camera frame, y down).
struct PosedKeyframe {
  const MapKeyframe* keyframe = nullptr;
  SE3 T_world_camera = SE3::Identity();
};

/// CV_8U mask, 255 = static: every pixel of the instances in `dynamic_ids` removed, grown by
/// `dilation_px` (mask edges trail a moving body by a few pixels).
cv::Mat staticMask(const cv::Mat& labels_u16, const std::vector<uint16_t>& dynamic_ids,
                   int dilation_px);

/// Keeps a keyframe at 1/downscale resolution (area-averaged colour, nearest depth, so no depth
/// is invented across edges); depth is zeroed outside `static_mask` and beyond `max_depth_m`.
MapKeyframe keepKeyframe(double stamp_s, const cv::Mat& bgr, const cv::Mat& depth_m,
                         const cv::Mat& static_mask, int downscale, double max_depth_m);

/// Normalised ray (x/z, y/z) of every pixel of a 1/downscale image (CV_32FC2), with the
/// camera's lens distortion removed, so back-projection is p_camera = z * (rx, ry, 1).
cv::Mat rayTable(const PinholeCamera& camera, int downscale);

}  // namespace dynanav
