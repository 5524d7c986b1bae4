#pragma once
// Step 7 of the per-frame story (DESIGN.md §1): scene flow of every instance from a few frames
// back to this one (objects sampled in the old frame, followed by dense flow, lifted with both
// depths, the camera's own motion removed) says whether it moved. Holds the recent frames it
// needs and the mask of non-prior objects found moving, which the next frame cuts out of ORB
// extraction (cutOutMovingObjects).
#include <deque>
#include <opencv2/core.hpp>
#include <opencv2/video/tracking.hpp>
#include <vector>

#include "core/camera.hpp"
#include "core/config/dynamics.hpp"
#include "core/se3.hpp"
#include "perception/instances.hpp"

namespace dynanav {

struct PriorVerdicts {
  int prior_moving = 0;              ///< prior instances scene flow found moving
  int prior_static = 0;              ///< prior instances scene flow found static
  std::vector<uint16_t> moving_ids;  ///< this frame's ids of instances found moving
  std::vector<uint16_t> static_ids;  ///< this frame's ids of prior instances found static
};

/// What one frame gives the verifier.
struct VerifierInput {
  const cv::Mat& grey_half;  ///< grey image at half size (FramePrep)
  const cv::Mat& depth_m;    ///< CV_32F
  const Instances& instances;
  const SE3& T_camera_world;
  bool tracked = false;
  const PinholeCamera& camera;
};

class PriorVerifier {
 public:
  explicit PriorVerifier(const DynamicsConfig& config);
  /// Scene flow of the oldest kept frame's instances into this frame; `depth_voted` are this
  /// frame's non-prior instances the depth test found moving (kept cut out next frame).
  PriorVerdicts verify(const VerifierInput& input, const std::vector<uint16_t>& depth_voted);
  /// CV_8U: non-prior instances found moving in the last verified frame (empty before).
  [[nodiscard]] const cv::Mat& movingMask() const { return moving_mask_; }
  /// How far (px, full size) the dense flow at a pixel draws on the image around it: one DIS
  /// patch at its finest level (64 px with the ultrafast preset on half-size images).
  [[nodiscard]] int flowFootprintPx() const;

 private:
  struct Snapshot {
    cv::Mat grey_half;
    cv::Mat depth_m;
    Instances instances;
    SE3 T_camera_world = SE3::Identity();
    bool tracked = false;
  };
  /// Keeps the correspondences whose old depth lies within scene_flow_prior_depth_band_m of
  /// their median (withinDepthBand), in order.
  void keepWithinDepthBand(std::vector<Vec3>& p_old, std::vector<Vec3>& p_cur) const;
  DynamicsConfig config_;
  std::deque<Snapshot> frames_;  // oldest first, at most scene_flow_gap_frames
  cv::Mat moving_mask_;
  cv::Ptr<cv::DISOpticalFlow> dis_ =
      cv::DISOpticalFlow::create(cv::DISOpticalFlow::PRESET_ULTRAFAST);
};

/// Step 3's second half: non-prior instances that cover the last frame's moving mask by half or
/// more are cut out of `allowed` (created when empty) before their keypoints reach the pose.
/// Returns their ids (ascending, as instances are ordered).
std::vector<uint16_t> cutOutMovingObjects(cv::Mat& allowed, const Instances& instances,
                                          const cv::Mat& moving_mask, const DynamicsConfig& config);

}  // namespace dynanav
