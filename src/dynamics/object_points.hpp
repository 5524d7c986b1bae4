#pragma once
// The points an object is tracked by: a regular grid inside its mask (people: the trunk between
// shoulders and hips when the keypoint model ran, the part of a walker that moves rigidly),
// carried to the next frame by the shared dense flow (PreparedFrame::flow_half, half-size
// pixels) and lifted to 3D with that frame's depth.
#include <opencv2/core.hpp>
#include <optional>
#include <vector>

#include "core/camera.hpp"
#include "core/se3.hpp"
#include "perception/instances.hpp"

namespace dynanav {

struct SampleOptions {
  int step_px = 5;
  int max_points = 400;       ///< the grid is thinned evenly to at most this many
  int trunk_min_points = 20;  ///< fewer inside the trunk: the whole mask
  /// A person's full height in pixels at its depth (0: unknown): places the trunk band of a
  /// person whose head or feet are out of view.
  double person_height_px = 0.0;
};

/// Grid pixels (every step_px) with label `id`; for people, those of the trunk when that gives
/// trunk_min_points: inside the box spanned by both shoulders and both hips when keypoints were
/// found, else the band 20-50 % of the person's height below the top of the head: the height is
/// the box's when the box is wholly in view, else options.person_height_px measured from the end
/// of the box that is in view (the head, or the feet).
struct ObjectSample {
  std::vector<cv::Point2f> pixels;
  bool trunk = false;  ///< a person's trunk (else the whole mask: its centre is not the trunk's)
};
ObjectSample sampleObjectPixels(const cv::Mat& labels, const Instance& instance,
                                const SampleOptions& options);

/// A surface of another label nearer than a point, within the dense flow's reach of it: the flow's
/// patches there carry that surface's motion along.
struct NearerSurface {
  bool found = false;
  uint16_t label = 0;  ///< its label (0: no instance, the static scene)
};

/// For each of `pixels` (depths `z_m`, 0: none), a pixel within `reach_px` of it of another label
/// (not `id`) whose depth is nearer by more than `margin_m`, probed on two rings, reach/2 and
/// reach, in eight directions; of several, the nearest in depth (what occludes the point most).
/// Pixels without depth never have one.
std::vector<NearerSurface> besideNearerSurface(const std::vector<cv::Point2f>& pixels,
                                               const std::vector<float>& z_m, const cv::Mat& labels,
                                               uint16_t id, const cv::Mat& depth_m, int reach_px,
                                               double margin_m);

/// -1 when the instance touches the image's left edge, +1 the right edge, 0 neither (or both):
/// an object cut by the image's side shows only part of itself.
int instanceCutSide(const Instance& instance, int image_cols);

/// Which of the depths `z_m` (0 or less: none) lie within band_m of the median of those with
/// depth: a mask that spills over its outline sees the background behind, not the object.
std::vector<uint8_t> withinDepthBand(const std::vector<float>& z_m, double band_m);

/// Median depth (m) of the pixels labelled `label` inside `box`, every `step`-th pixel and row,
/// those with depth only; 0 when none (or without depth of the labels' size).
double medianLabelDepthM(const cv::Mat& labels, uint16_t label, cv::Rect box,
                         const cv::Mat& depth_m, int step);

/// Where `pixel` (full size) of the previous frame is in this one, by the half-size flow field;
/// false when it leaves the image.
bool carryByFlow(const cv::Mat& flow_half, cv::Size image_size, cv::Point2f& pixel);

/// Depth (m) at the pixel nearest `pixel`; 0 when invalid or outside.
float depthAt(const cv::Mat& depth_m, const cv::Point2f& pixel);

/// Robust centre of an object seen as `p_camera` points: the per-axis median of the points
/// within depth_band_m of their median depth, pushed behind_m further along its viewing ray
/// (visible points lie on the surface facing the camera). Empty when no point is given.
std::optional<Vec3> objectCentre(const std::vector<Vec3>& p_camera, double depth_band_m,
                                 double behind_m);

/// Horizontal extent (m) of the points: the 10th to 90th percentile of camera x.
double objectWidth(const std::vector<Vec3>& p_camera);

}  // namespace dynanav
