#include "core/camera.hpp"

#include <algorithm>
#include <opencv2/calib3d.hpp>

namespace dynanav {

bool PinholeCamera::isDistorted() const {
  return std::any_of(distortion.begin(), distortion.end(), [](double d) { return d != 0.0; });
}

cv::Mat PinholeCamera::K() const {
  return (cv::Mat_<double>(3, 3) << fx, 0, cx, 0, fy, cy, 0, 0, 1);
}

cv::Mat PinholeCamera::distCoeffs() const {
  return (cv::Mat_<double>(1, 5) << distortion[0], distortion[1], distortion[2], distortion[3],
          distortion[4]);
}

std::vector<cv::Point2f> PinholeCamera::undistortPixels(
    const std::vector<cv::Point2f>& pixels) const {
  if (!isDistorted() || pixels.empty()) return pixels;
  std::vector<cv::Point2f> out;
  // P = K maps the normalised undistorted coordinates back to pixels.
  cv::undistortPoints(pixels, out, K(), distCoeffs(), cv::noArray(), K());
  return out;
}

cv::Point2d PinholeCamera::distortPixel(const cv::Point2d& undistorted) const {
  const double x = (undistorted.x - cx) / fx;
  const double y = (undistorted.y - cy) / fy;
  const auto [k1, k2, p1, p2, k3] = distortion;
  const double r2 = x * x + y * y;
  const double radial = 1.0 + r2 * (k1 + r2 * (k2 + r2 * k3));
  const double xd = x * radial + 2.0 * p1 * x * y + p2 * (r2 + 2.0 * x * x);
  const double yd = y * radial + p1 * (r2 + 2.0 * y * y) + 2.0 * p2 * x * y;
  return {xd * fx + cx, yd * fy + cy};
}

cv::Rect2d PinholeCamera::undistortedBounds() const {
  const std::vector<cv::Point2f> corners = {
      {0.f, 0.f}, {float(width), 0.f}, {0.f, float(height)}, {float(width), float(height)}};
  const auto u = undistortPixels(corners);
  const double min_x = std::min(u[0].x, u[2].x), max_x = std::max(u[1].x, u[3].x);
  const double min_y = std::min(u[0].y, u[1].y), max_y = std::max(u[2].y, u[3].y);
  return {min_x, min_y, max_x - min_x, max_y - min_y};
}

PinholeCamera PinholeCamera::tumFreiburg1() {
  PinholeCamera c;
  c.name = "tum_freiburg1";
  c.fx = 517.306408;
  c.fy = 516.469215;
  c.cx = 318.643040;
  c.cy = 255.313989;
  c.distortion = {0.262383, -0.953104, -0.005358, 0.002628, 1.163314};
  // Kinect v1 colour camera, rolling shutter. Not published with the dataset: chosen from the
  // readout sweep on the first half of fr1_xyz (docs/slam.md, "Rolling shutter"); 25 ms of the
  // 33 ms frame period.
  c.readout_s = 0.025;
  return c;
}

PinholeCamera PinholeCamera::tumFreiburg2() {
  // TUM's published fr2 calibration (ORB-SLAM2 TUM2.yaml agrees).
  PinholeCamera c;
  c.name = "tum_freiburg2";
  c.fx = 520.908620;
  c.fy = 521.007327;
  c.cx = 325.141442;
  c.cy = 249.701764;
  c.distortion = {0.231222, -0.784899, -0.003257, -0.000105, 0.917205};
  return c;
}

PinholeCamera PinholeCamera::tumFreiburg3() {
  PinholeCamera c;
  c.name = "tum_freiburg3";
  c.fx = 535.4;
  c.fy = 539.2;
  c.cx = 320.1;
  c.cy = 247.6;
  c.distortion = {0, 0, 0, 0, 0};  // fr3 images are already undistorted
  return c;
}

PinholeCamera PinholeCamera::bonn() {
  PinholeCamera c;
  c.name = "bonn";
  c.fx = 542.822841;
  c.fy = 542.576870;
  c.cx = 315.593520;
  c.cy = 237.756098;
  c.distortion = {0.039903, -0.099343, -0.000730, -0.000144, 0.0};
  // The Xtion's rolling-shutter readout is not published. The readout estimated from the tracking
  // residuals of the Bonn crowd window (slam/readout_estimate) is unbiased only at the true value
  // and reads low below it: 16 ms at 0, 28 ms when re-timed with 25 ms, 30 ms with 30 ms. The
  // fixed point is about 30 ms of the 33 ms frame (docs/slam.md, "The readout from the residuals").
  c.readout_s = 0.030;
  return c;
}

bool PinholeCamera::fromSequenceName(const std::string& folder_name, PinholeCamera& camera) {
  const auto has = [&](const char* s) { return folder_name.find(s) != std::string::npos; };
  if (has("freiburg1") || has("fr1")) {
    camera = tumFreiburg1();
    return true;
  }
  if (has("freiburg2") || has("fr2")) {
    camera = tumFreiburg2();
    return true;
  }
  if (has("freiburg3") || has("fr3")) {
    camera = tumFreiburg3();
    return true;
  }
  if (has("bonn")) {
    camera = bonn();
    return true;
  }
  return false;
}

}  // namespace dynanav
