#include "dynamics/height_range.hpp"

#include <Eigen/Dense>
#include <algorithm>
#include <cmath>
#include <vector>

#include "core/median.hpp"

namespace dynanav {
namespace {

bool otherInstance(uint16_t label, uint16_t id) {
  return label != 0 && label != id;
}

/// A ranged centre's error new in each frame: along_m along its viewing ray; across it
/// across_sigma_m (the body axis against the torso centre) and a mask edge's worth of pixels.
Mat3 frameCovariance(const Vec3& p_camera, double along_m, double across_sigma_m,
                     double edge_sigma_px, const PinholeCamera& camera) {
  const double range_m = p_camera.norm();
  const double across_m = std::hypot(across_sigma_m, range_m * edge_sigma_px / camera.fx);
  const Vec3 n = p_camera / range_m;
  const Mat3 along = n * n.transpose();
  return along_m * along_m * along + across_m * across_m * (Mat3::Identity() - along);
}

/// The viewing ray (z = 1) through the body axis's column at image row v.
Vec3 axisRay(const PersonExtent& extent, double v, const PinholeCamera& camera) {
  return Vec3((extent.column_px - camera.cx) / camera.fx, (v - camera.cy) / camera.fy, 1.0);
}

}  // namespace

std::optional<PersonExtent> personExtent(const cv::Mat& labels, const Instance& instance,
                                         int edge_margin_px) {
  const cv::Rect box = instance.box & cv::Rect(0, 0, labels.cols, labels.rows);
  // The mask's own bounds (a detector's box may be looser than its mask).
  int top = -1, bottom = -1, left = labels.cols, right = -1;
  for (int y = box.y; y < box.y + box.height; ++y) {
    const uint16_t* row = labels.ptr<uint16_t>(y);
    for (int x = box.x; x < box.x + box.width; ++x) {
      if (row[x] != instance.id) continue;
      if (top < 0) top = y;
      bottom = y;
      left = std::min(left, x);
      right = std::max(right, x);
    }
  }
  if (top < 0) return std::nullopt;
  if (top <= edge_margin_px || left <= edge_margin_px ||
      bottom >= labels.rows - 1 - edge_margin_px || right >= labels.cols - 1 - edge_margin_px)
    return std::nullopt;
  // Another instance right above the crown or below the soles: the silhouette ends at the
  // occluder, not at the person's head or feet.
  const uint16_t* above = labels.ptr<uint16_t>(top - 1);
  const uint16_t* below = labels.ptr<uint16_t>(bottom + 1);
  const uint16_t* first = labels.ptr<uint16_t>(top);
  const uint16_t* last = labels.ptr<uint16_t>(bottom);
  for (int x = left; x <= right; ++x) {
    if (first[x] == instance.id && otherInstance(above[x], instance.id)) return std::nullopt;
    if (last[x] == instance.id && otherInstance(below[x], instance.id)) return std::nullopt;
  }
  // Body axis: the median column of the torso band (swinging arms and striding legs pull the
  // whole mask's centre to and fro).
  const int height = bottom - top + 1;
  const int band_top = top + int(std::lround(0.2 * height));
  const int band_bottom = std::max(band_top, top + int(std::lround(0.5 * height)));
  std::vector<int> columns;
  for (int y = band_top; y <= band_bottom; ++y) {
    const uint16_t* row = labels.ptr<uint16_t>(y);
    for (int x = left; x <= right; ++x)
      if (row[x] == instance.id) columns.push_back(x);
  }
  if (columns.empty()) return std::nullopt;
  const int median_column = medianInPlace(columns);
  PersonExtent extent;
  extent.top_px = top - 0.5;
  extent.bottom_px = bottom + 0.5;
  extent.column_px = median_column;
  return extent;
}

double nearerOutlineShare(const cv::Mat& labels, const cv::Mat& depth_m, uint16_t id,
                          const cv::Rect& box, double nearer_than_m) {
  const cv::Rect area =
      (box + cv::Size(2, 2) - cv::Point(1, 1)) & cv::Rect(0, 0, labels.cols, labels.rows);
  const auto inMask = [&](int x, int y) {
    return x >= 0 && y >= 0 && x < labels.cols && y < labels.rows &&
           labels.at<uint16_t>(y, x) == id;
  };
  int outline = 0, nearer = 0;
  for (int y = area.y; y < area.y + area.height; ++y)
    for (int x = area.x; x < area.x + area.width; ++x) {
      if (inMask(x, y)) continue;
      if (!inMask(x - 1, y) && !inMask(x + 1, y) && !inMask(x, y - 1) && !inMask(x, y + 1))
        continue;
      ++outline;
      const float z = depth_m.at<float>(y, x);
      if (std::isfinite(z) && z > 0.f && z < nearer_than_m) ++nearer;
    }
  return outline > 0 ? double(nearer) / outline : 0.0;
}

Eigen::Matrix<double, 6, 6> statureCovariance(const Vec3& p_world, const Vec3& v_world_mps,
                                              const Vec3& camera_world, double scale_sigma) {
  Eigen::Matrix<double, 6, 1> J;
  J << p_world - camera_world, v_world_mps;
  return scale_sigma * scale_sigma * J * J.transpose();
}

std::optional<HeightRange> rangeFromHeight(const PersonExtent& extent, const PinholeCamera& camera,
                                           const Vec3& up_camera,
                                           const HeightRangeOptions& options) {
  const double height_px = extent.heightPx();
  if (!(height_px > 0.0) || !(options.stature.mean_m > 0.0) || up_camera.norm() < 1e-9)
    return std::nullopt;
  const Vec3 r_top = axisRay(extent, extent.top_px, camera);
  const Vec3 r_bottom = axisRay(extent, extent.bottom_px, camera);
  // a·r_top − b·r_bottom = H·up, in least squares (exact for a camera whose x axis is level).
  Eigen::Matrix<double, 3, 2> A;
  A.col(0) = r_top;
  A.col(1) = -r_bottom;
  const Vec3 rhs = options.stature.mean_m * up_camera.normalized();
  const Eigen::Vector2d ab = A.colPivHouseholderQr().solve(rhs);
  if (!(ab(0) > 0.0) || !(ab(1) > 0.0)) return std::nullopt;
  const Vec3 crown = ab(0) * r_top, soles = ab(1) * r_bottom;
  HeightRange out;
  out.p_camera = crown + kTorsoCentreBelowTop * (soles - crown);
  out.range_m = out.p_camera.norm();
  // Both the stature's and the pixel height's errors scale the solution about the camera centre:
  // the centre moves along its viewing ray.
  const double stature_rel = options.stature.sigma_m / options.stature.mean_m;
  const double pixels_rel = std::sqrt(2.0) * options.edge_sigma_px / height_px;
  out.scale_sigma = stature_rel;
  out.sigma_range_m = out.range_m * std::hypot(stature_rel, pixels_rel);
  if (!(out.sigma_range_m <= options.max_relative_sigma * out.range_m)) return std::nullopt;
  out.cov_frame_camera = frameCovariance(out.p_camera, out.range_m * pixels_rel,
                                         options.across_sigma_m, options.edge_sigma_px, camera);
  return out;
}

namespace {

/// The torso centre over the feet whose nearest outline point is at row bottom_px on the plane
/// (n, offset); none if the rays do not meet the floor ahead of the camera or the centre falls
/// below it.
std::optional<Vec3> torsoOverSoles(const PersonExtent& extent, double bottom_px,
                                   const PinholeCamera& camera, const Vec3& n, double offset_m,
                                   double foot_lead_m, double outline_height_m) {
  const Vec3 r_soles = axisRay(extent, bottom_px, camera);
  const double along = n.dot(r_soles);
  const double outline_offset_m = offset_m + outline_height_m;  // the plane the outline is in
  if (!(outline_offset_m < 0.0) || !(along < 0.0)) return std::nullopt;
  const Vec3 front = (outline_offset_m / along) * r_soles;
  const Vec3 level = (r_soles - along * n).normalized();  // away from the camera, along the floor
  const Vec3 soles = front + foot_lead_m * level - outline_height_m * n;  // the axis, on the floor
  const Vec3 r_torso =
      axisRay(extent, extent.top_px + kTorsoCentreBelowTop * (bottom_px - extent.top_px), camera);
  // c·r_torso = soles + h·n in least squares: the torso on the vertical through the soles.
  Eigen::Matrix<double, 3, 2> A;
  A.col(0) = r_torso;
  A.col(1) = -n;
  const Eigen::Vector2d ch = A.colPivHouseholderQr().solve(soles);
  if (!(ch(0) > 0.0) || !(ch(1) > 0.0)) return std::nullopt;
  return 0.5 * (ch(0) * r_torso + soles + ch(1) * n);
}

}  // namespace

double footLeadM(const FloorContactOptions& options, std::optional<double> abs_cos) {
  // The mean of |cos| over headings uniform in angle is 2 / pi.
  const double c = abs_cos ? std::clamp(*abs_cos, 0.0, 1.0) : 2.0 / M_PI;
  return options.foot_lead_side_m + (options.foot_lead_along_m - options.foot_lead_side_m) * c;
}

std::optional<HeightRange> rangeFromFloorContact(const PersonExtent& extent,
                                                 const PinholeCamera& camera,
                                                 const CameraFloor& floor,
                                                 std::optional<double> heading_abs_cos,
                                                 const FloorContactOptions& options) {
  const Vec3 n = floor.normal_camera.normalized();
  const double lead = footLeadM(options, heading_abs_cos), e = options.foot_outline_height_m;
  const auto centre = torsoOverSoles(extent, extent.bottom_px, camera, n, floor.offset_m, lead, e);
  if (!centre) return std::nullopt;
  HeightRange out;
  out.p_camera = *centre;
  out.range_m = centre->norm();
  // Relative range errors by finite differences: the soles' row (new each frame) and the
  // floor's height and tilt toward the camera (persistent: the scale).
  const auto relativeShift = [&](double bottom_px, const Vec3& normal, double offset_m) {
    const auto moved =
        torsoOverSoles(extent, bottom_px, camera, normal.normalized(), offset_m, lead, e);
    return moved ? std::abs(moved->norm() - out.range_m) / out.range_m : 1.0;
  };
  const double pixels_rel =
      relativeShift(extent.bottom_px + options.edge_sigma_px, n, floor.offset_m);
  const double offset_rel =
      relativeShift(extent.bottom_px, n, floor.offset_m + options.offset_sigma_m);
  // Tilt toward the camera: the normal turned about the camera's x axis.
  const double tilt = options.tilt_sigma_deg * M_PI / 180.0;
  const Vec3 tilted = Eigen::AngleAxisd(tilt, Vec3::UnitX()) * n;
  const double tilt_rel = relativeShift(extent.bottom_px, tilted, floor.offset_m);
  // The floor is fitted afresh every frame: its errors are partly new each frame (the fit's
  // jitter) and partly the same (the sensor's bias); both are counted in both parts.
  out.scale_sigma = std::hypot(offset_rel, tilt_rel);
  const double frame_rel = std::hypot(pixels_rel, out.scale_sigma);
  out.sigma_range_m = out.range_m * std::hypot(out.scale_sigma, frame_rel);
  out.cov_frame_camera = frameCovariance(out.p_camera, out.range_m * frame_rel,
                                         options.across_sigma_m, options.edge_sigma_px, camera);
  return out;
}

}  // namespace dynanav
