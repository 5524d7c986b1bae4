#pragma once
// Prior-dynamic objects (people) confirmed by 3D scene flow (Ou et al. 2022, §3.2): sample points
// inside the object's mask, follow them to the next frame with optical flow, lift both ends with
// depth, remove the camera's own motion, and call a point moving if it moved more than
// scene_flow_point_m (0.02 m; more where depth noise is larger: sceneFlowPointThreshold); the
// object is dynamic when more than scene_flow_share (30 %) of its
// points move. A sitting person is then static: their points may help tracking but never become
// map points.
#include <opencv2/core.hpp>
#include <vector>

#include "core/camera.hpp"
#include "core/config/dynamics.hpp"
#include "core/se3.hpp"

namespace dynanav {

struct SceneFlowVerdict {
  int points = 0;            ///< points with valid depth at both ends
  int moving = 0;            ///< of them, moving more than the threshold
  double mean_flow_m = 0;    ///< mean 3D displacement length after ego-motion compensation
  double mean_vector_m = 0;  ///< length of the mean 3D displacement vector (noise cancels)
  bool decided = false;      ///< enough points for a verdict
  bool dynamic = false;
  /// Decided, not dynamic, and the mean displacement vector within scene_flow_point_m: confidently
  /// standing still. A verdict between the two (the mean moved, too few points past their noise
  /// threshold: a far walker) is neither.
  bool still = false;
};

/// Displacement (m) above which one point counts as moving: scene_flow_point_m, or
/// scene_flow_point_sigmas sigmas of the depth noise at its two ends (depth_noise_per_z2 · z²)
/// where that is larger (at 3 m: 3 × 2.0 cm = 6.1 cm with the defaults), so depth noise alone does
/// not make far points move.
double sceneFlowPointThreshold(double z_prev_m, double z_cur_m, const DynamicsConfig& config);

/// How the static background around an object moved between the two frames after ego-motion
/// (current camera frame): what a dense flow dragged along, a pose slightly off or depth noise
/// gives a point that did not move.
struct BackgroundMotion {
  Vec3 displacement_m = Vec3::Zero();  ///< per-axis median displacement
  double sigma_m = 0.0;                ///< robust per-axis sigma of the displacements about it
};

/// Verdict from corresponding 3D points of one object in the previous and current camera frames.
/// T_cur_prev maps previous-camera coordinates into the current camera (the ego-motion).
/// `background` (backgroundMotion of the object's surroundings; default: none) is taken off every
/// point, and a point moves only if it moved scene_flow_point_sigmas of the background's sigma
/// too: an error the object shares with its surroundings moves neither.
SceneFlowVerdict sceneFlowVerdict(const std::vector<Vec3>& p_prev_camera,
                                  const std::vector<Vec3>& p_cur_camera, const SE3& T_cur_prev,
                                  const DynamicsConfig& config,
                                  const BackgroundMotion& background = {});

/// The background's motion from its corresponding points (as sceneFlowVerdict's); none (zero)
/// with fewer than scene_flow_min_points points: then the object is judged against the camera's
/// motion alone.
BackgroundMotion backgroundMotion(const std::vector<Vec3>& p_prev_camera,
                                  const std::vector<Vec3>& p_cur_camera, const SE3& T_cur_prev,
                                  const DynamicsConfig& config);

/// Grid pixels (every `step` px, on sampleMaskPixels' grid) of the background more than
/// `inner_px` and at most `outer_px` (chessboard distance) from an object's mask (CV_8U, non-zero
/// = the object): its surroundings, with every instance of `labels` (CV_16U, 0 = background) left
/// out. Distances are to the grid's resolution: the inner gap rounded up, the outer edge down,
/// counted in step x step cells. The inner gap keeps out what a patch-based dense flow fills in
/// from the object itself.
std::vector<cv::Point> sampleRingPixels(const cv::Mat& object_mask, const cv::Mat& labels,
                                        int inner_px, int outer_px, int step);

/// Pixels on a regular grid (every `step` px) inside `mask` (CV_8U, non-zero = inside).
std::vector<cv::Point> sampleMaskPixels(const cv::Mat& mask, int step);

/// How liftFlowCorrespondences reads the depth at a flow's end. A dense flow is a pixel or two
/// off where depth jumps, and on a thin or see-through object (a chair's back, its legs) that
/// pixel swaps the object's depth for the wall's behind it: a static point would move by the
/// gap. So where the depths within radius_px of the end span two surfaces (they spread more than
/// twice sceneFlowPointThreshold at the expected depth), the one nearest to the depth the point
/// would have now had it stood still (T_cur_prev applied to its previous position) is taken. On
/// one surface the end pixel's own depth is kept: the nearest of many noisy depths would shrink
/// every displacement by the noise (a far walker's approach would read as standing).
/// The radius grows (`parallax`) by the parallax the camera's translation gives the point
/// (flowEndSearchRadiusPx): the dense flow blends patches of both surfaces, whose image motions
/// differ by their parallax, so the flow at an edge is off by up to that much.
struct FlowEndDepth {
  SE3 T_cur_prev = SE3::Identity();
  int radius_px = 0;                       ///< 0: the end pixel's own depth
  bool parallax = false;                   ///< widen radius_px by the point's parallax
  const DynamicsConfig* config = nullptr;  ///< thresholds and the cap; required when radius_px > 0
};

/// Search radius (px) around a flow's end for a point expected at `expected_z_m` now: radius_px,
/// plus (parallax) focal_px · |translation of T_cur_prev| / z — the point's image motion from the
/// camera's translation, which bounds how much its flow differs from that of any surface behind
/// it (a point on the far surface, the wall seen through a chair, gets the smaller radius of its
/// own depth) — at most config->depth_test_max_radius_px. 0 when radius_px is 0.
int flowEndSearchRadiusPx(const FlowEndDepth& end_depth, double expected_z_m, double focal_px);

/// Follows sampled pixels of the previous frame through a dense flow field (CV_32FC2, previous →
/// current, e.g. DIS) and lifts both ends with depth. Pixels that leave the image or lack depth
/// at either end are dropped; `kept` (optional) receives the indices of the pixels kept.
/// Pixels are the lens's (distorted, as the flow and the registered depth are); each end is
/// lifted along its undistorted pixel's ray.
void liftFlowCorrespondences(const std::vector<cv::Point>& prev_pixels, const cv::Mat& flow,
                             const cv::Mat& prev_depth_m, const cv::Mat& cur_depth_m,
                             const PinholeCamera& camera, std::vector<Vec3>& p_prev_camera,
                             std::vector<Vec3>& p_cur_camera, std::vector<size_t>* kept = nullptr,
                             const FlowEndDepth& end_depth = {});

/// The current instance an old object's sampled pixels land on when followed along the flow
/// (old frame → current); 0 if no instance gets a third of them. Following the flow matters for
/// small, fast objects: a walker 4 m away crossing the view moves half its width in 3 frames,
/// so its old mask barely overlaps its new one. An empty `flow` looks the pixels up where they
/// were (the instance now covering the old mask).
uint16_t labelAlongFlow(const cv::Mat& labels, const std::vector<cv::Point>& old_pixels,
                        const cv::Mat& flow);

}  // namespace dynanav
