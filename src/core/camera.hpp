#pragma once
// Pinhole camera with the Brown–Conrady distortion model (k1, k2, p1, p2, k3) as OpenCV and the
// TUM/Bonn calibrations use it. TUM fr1/fr2 and Bonn images are NOT undistorted; fr3 is.
#include <array>
#include <opencv2/core.hpp>
#include <string>
#include <vector>

#include "core/se3.hpp"

namespace dynanav {

struct PinholeCamera {
  std::string name = "custom";  ///< where the calibration came from (for logs and stats)
  int width = 640;
  int height = 480;
  double fx = 525.0, fy = 525.0, cx = 319.5, cy = 239.5;
  std::array<double, 5> distortion{0, 0, 0, 0, 0};  ///< k1, k2, p1, p2, k3
  double depth_factor = 5000.0;                     ///< raw 16-bit depth value per metre
  /// Virtual stereo baseline (m) for the RGB-D "right coordinate" u_r = u - fx*b/z (ORB-SLAM2's
  /// bf). Points deeper than `close_depth_baselines` baselines only constrain rotation well.
  double baseline_m = 0.08;
  double close_depth_baselines = 40.0;
  /// Rolling-shutter readout time of the colour camera (s): the delay between its first and last
  /// row. 0 = global shutter (or not known). Tracking re-times keypoints with it
  /// (slam/rolling_shutter).
  double readout_s = 0.0;
  /// Exposure time of the colour camera (s); 0 = not known. A corner blurred over the exposure is
  /// found anywhere along its streak, so its pixel may miss the depth sample it is compared with
  /// (dynamics/depth_tolerance).
  double exposure_s = 0.0;

  [[nodiscard]] bool isDistorted() const;
  [[nodiscard]] double bf() const { return fx * baseline_m; }
  [[nodiscard]] double closeDepthThreshold() const { return baseline_m * close_depth_baselines; }
  [[nodiscard]] cv::Mat K() const;           ///< 3x3 CV_64F
  [[nodiscard]] cv::Mat distCoeffs() const;  ///< 1x5 CV_64F

  /// Pixel of a point in the camera frame (undistorted pinhole model). z must be > 0.
  [[nodiscard]] Eigen::Vector2d project(const Vec3& p_camera) const {
    return {fx * p_camera.x() / p_camera.z() + cx, fy * p_camera.y() / p_camera.z() + cy};
  }
  /// Point in the camera frame from an undistorted pixel and its depth (m).
  [[nodiscard]] Vec3 backproject(double u, double v, double z) const {
    return {(u - cx) * z / fx, (v - cy) * z / fy, z};
  }
  [[nodiscard]] bool inImage(double u, double v, double border = 0.0) const {
    return u >= border && v >= border && u < width - border && v < height - border;
  }

  /// Undistorted pixel positions of distorted ones (identity when not distorted).
  [[nodiscard]] std::vector<cv::Point2f> undistortPixels(
      const std::vector<cv::Point2f>& pixels) const;
  /// Pixel distortion of an undistorted pixel (for rendering/simulation).
  [[nodiscard]] cv::Point2d distortPixel(const cv::Point2d& undistorted) const;
  /// Bounds of the undistorted image (ORB-SLAM's mnMinX..mnMaxY), from the corners.
  [[nodiscard]] cv::Rect2d undistortedBounds() const;

  /// Calibrations from ../shared/data/SOURCES.md.
  static PinholeCamera tumFreiburg1();
  static PinholeCamera tumFreiburg2();
  static PinholeCamera tumFreiburg3();
  static PinholeCamera bonn();
  /// Calibration for a sequence folder name containing freiburg1|2|3 or bonn; false if none.
  static bool fromSequenceName(const std::string& folder_name, PinholeCamera& camera);
};

}  // namespace dynanav
