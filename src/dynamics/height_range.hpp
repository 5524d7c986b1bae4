#pragma once
// Monocular range to a person from the pixel height of the mask and a prior on adult stature:
// beyond the depth sensor's range (4.5 m in the simulator, 4-5 m for structured light and
// time-of-flight RGB-D cameras) a walker has a mask but no depth, and the tracker would have no
// position for it. A person standing upright whose head and feet are both in view spans a
// known-ish height H; the rays through the top of the head and the soles then fix the distance
// up to the ratio of the person's true stature to the prior's. Used only when depth is missing
// (ObjectTracker, docs/tracking.md step 6); its covariance says how little it knows along the
// viewing ray.
#include <opencv2/core.hpp>
#include <optional>

#include "core/camera.hpp"
#include "core/se3.hpp"
#include "dynamics/floor_plane.hpp"
#include "perception/instances.hpp"

namespace dynanav {

/// Stature of an adult of either sex (m). Mean and spread of a pooled adult population: adult
/// men average about 1.75-1.80 m and women 1.61-1.66 m in the USA and Europe (e.g. the CDC's
/// NHANES 2015-2018 anthropometric reference data, Fryar et al. 2021: 1.75 / 1.61 m; within each
/// sex the standard deviation is about 0.07 m); pooling both sexes gives a mean of 1.68-1.72 m
/// and a spread of 0.09-0.10 m. Rounded, not fitted to any sequence; a walking person's silhouette
/// is a few centimetres lower than the standing stature, which is well inside the spread.
struct StaturePrior {
  double mean_m = 1.70;
  double sigma_m = 0.09;
};

/// A person's silhouette in the image (full-size pixel coordinates, pixel centres at integers):
/// the top edge of its topmost row, the bottom edge of its lowest row, and the column of its body
/// axis (median column of the mask's torso band).
struct PersonExtent {
  double top_px = 0.0;
  double bottom_px = 0.0;
  double column_px = 0.0;
  [[nodiscard]] double heightPx() const { return bottom_px - top_px; }
};

/// Fraction of a person's height from the top of the head down to the torso centre (the
/// middle of the band 20-50 % below the head that the tracker samples as the trunk,
/// object_points.hpp; shoulders at about 18 % and hips at about 47-50 % of stature below the
/// crown, Drillis and Contini's segment proportions). The simulator's truth and the depth-based
/// centre are both the torso's.
inline constexpr double kTorsoCentreBelowTop = 0.35;

/// The extent of `instance`'s mask in `labels` when head and feet are both in view: none when
/// the mask comes within `edge_margin_px` of any image edge (a cut silhouette is not the
/// person's height, and one cut at the side may lack the head), or when another instance lies
/// directly above its top row or below its bottom row (an occluder hides the head or the feet).
/// An occluder the segmenter does not report (a desk) is not seen here.
std::optional<PersonExtent> personExtent(const cv::Mat& labels, const Instance& instance,
                                         int edge_margin_px = 1);

/// Share of the pixels just outside the mask of instance `id` (4-neighbours of its pixels, inside
/// the image) whose depth is valid and nearer than `nearer_than_m` (camera z): where something
/// nearer than the person borders its silhouette, it may hide part of it (a cabinet in front of
/// a walker's side, a desk in front of its legs), and the silhouette's height is not the
/// person's. A free silhouette borders only what is behind it or beyond the sensor's range.
double nearerOutlineShare(const cv::Mat& labels, const cv::Mat& depth_m, uint16_t id,
                          const cv::Rect& box, double nearer_than_m);

struct HeightRangeOptions {
  StaturePrior stature;
  /// Standard deviation (px) of each end of the mask: a segmenter's boundary is uncertain by a
  /// pixel or two; the two ends are independent.
  double edge_sigma_px = 1.5;
  /// Standard deviation (m) across the viewing ray: the mask's median column and the torso
  /// fraction vs. the true torso centre (arms, posture).
  double across_sigma_m = 0.05;
  /// A range known to worse than this share of itself (one sigma) is no range: the stature
  /// alone leaves 5 %, the mask's ends add 2.1 px / height px, so this keeps silhouettes taller
  /// than about 9 px. A shorter one is a sliver (a few rows of a walker at the image's side)
  /// that would place a person hundreds of metres away: in the simulated office such slivers
  /// stood 252-1010 m away (docs/tracking.md "Session 35").
  double max_relative_sigma = 0.25;
};

struct HeightRange {
  Vec3 p_camera = Vec3::Zero();  ///< torso centre (m)
  /// Covariance (m^2) of the errors that are new in every frame: the mask's ends (along the
  /// viewing ray, in proportion) and the body axis across it.
  Mat3 cov_frame_camera = Mat3::Identity();
  /// Relative standard deviation of the stature (σ_H / H): an error of the person, the same in
  /// every frame, that scales p_camera about the camera centre (δp = −ε·p).
  double scale_sigma = 0.0;
  double range_m = 0.0;        ///< distance of the torso centre from the camera
  double sigma_range_m = 0.0;  ///< standard deviation along the viewing ray, both parts
  /// Both parts: what a single frame's range is known to.
  [[nodiscard]] Mat3 covCamera() const {
    return cov_frame_camera + scale_sigma * scale_sigma * p_camera * p_camera.transpose();
  }
};

/// The torso centre of an upright person of the prior's stature whose crown and soles appear at
/// extent.top_px and extent.bottom_px in column extent.column_px: the crown point a·r_top and the
/// sole point b·r_bottom (r: the pixels' rays, z = 1) are H apart along `up_camera` (the world's
/// up in this camera frame), solved for a, b in least squares. Scaling the stature scales the
/// solution, so the relative range error is the stature's relative spread (one per person) and
/// that of the pixel height (σ_edge·√2 / height_px, new in each frame); both lie along the
/// viewing ray. Across the ray:
/// across_sigma_m and a pixel's worth of the column. None when the geometry is degenerate (the
/// solution lies behind the camera) or the range is known to worse than max_relative_sigma.
std::optional<HeightRange> rangeFromHeight(const PersonExtent& extent, const PinholeCamera& camera,
                                           const Vec3& up_camera,
                                           const HeightRangeOptions& options = {});

struct FloorContactOptions {
  /// Where the lowest row of a silhouette is: the front of the nearest shoe's outline, not the
  /// point under the body's axis. How far that lies in front of the axis, toward the camera, for a
  /// person of the stature prior's 1.70 m (Drillis and Contini's segment proportions: foot length
  /// 0.152 H = 0.26 m, the ankle, under the axis of a standing body, a quarter of it from the
  /// heel): facing the camera its toe tips, 0.19 m; walking away about as much, its trailing
  /// heel (0.065 m) being half a stride back; side on half a shoe's width, 0.05 m. In between,
  /// in proportion to |cos| of the angle between its heading and the viewing direction
  /// (footLeadM).
  double foot_lead_along_m = 0.19;
  double foot_lead_side_m = 0.05;
  /// Height above the floor of that outline's lowest point seen from afar: a shoe's front is
  /// rounded, so the ray grazing it meets the floor a little beyond it.
  double foot_outline_height_m = 0.02;
  /// Standard deviation (px) of the mask's lowest row (the soles), as HeightRangeOptions.
  double edge_sigma_px = 1.5;
  /// Standard deviation (m) across the viewing ray, as HeightRangeOptions.
  double across_sigma_m = 0.05;
  /// Errors of the fitted floor that persist from frame to frame (the depth sensor's own bias,
  /// a floor that is not quite flat): its height below the camera and its tilt toward the
  /// camera. Each moves the soles' range in proportion, like a stature's error: at 11 m the
  /// soles' ray dips 8° below the horizon, so 0.1° of tilt is 1.2 % of range and 2 cm of
  /// height 1.2 %. (The simulated approach read +0.7-0.9 % +- 0.8 % over 63-77 frames, a
  /// scratch comparison, docs/tracking.md "Session 18".)
  double offset_sigma_m = 0.02;
  double tilt_sigma_deg = 0.1;
};

/// How far the nearest point of a person's feet lies in front of its body axis, toward the camera
/// (FloorContactOptions): `abs_cos` is |cos| of the angle between the level direction it walks
/// and the level viewing direction; none (standing, or its velocity not known yet): the mean over
/// all headings.
double footLeadM(const FloorContactOptions& options, std::optional<double> abs_cos);

/// The torso centre of a person standing on `floor` whose soles appear at extent.bottom_px in
/// column extent.column_px: the soles' ray meets the front of the nearest shoe (its outline's
/// height above the floor), the body's axis stands the feet's lead (footLeadM, from
/// `heading_abs_cos`) beyond it along the level viewing direction, and the torso centre lies on
/// that axis, where it meets the ray through the torso's row (the share kTorsoCentreBelowTop of the
/// silhouette below its top). No stature is assumed. The floor's errors (options) scale the
/// solution about the camera centre: scale_sigma; the soles' row and the body axis are new each
/// frame: cov_frame_camera. None when the soles' ray does not meet the floor ahead of the camera.
std::optional<HeightRange> rangeFromFloorContact(const PersonExtent& extent,
                                                 const PinholeCamera& camera,
                                                 const CameraFloor& floor,
                                                 std::optional<double> heading_abs_cos,
                                                 const FloorContactOptions& options = {});

/// Covariance (world, [p, v]) that a common scale error of relative sigma `scale_sigma` gives a
/// track every centre of which came from the height range: a stature off the prior by ε scales
/// all of them about the camera centre, the position by −ε·(p − c) and the velocity by −ε·v (the
/// wearer's own velocity neglected: ε is ~5 %).
Eigen::Matrix<double, 6, 6> statureCovariance(const Vec3& p_world, const Vec3& v_world_mps,
                                              const Vec3& camera_world, double scale_sigma);

}  // namespace dynanav
