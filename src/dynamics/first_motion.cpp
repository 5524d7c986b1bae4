#include "dynamics/first_motion.hpp"

#include <cmath>

#include "dynamics/object_points.hpp"

namespace dynanav {

std::optional<FirstMotion> firstFrameMotion(const FirstMotionInput& input,
                                            const ObjectMotionOptions& options) {
  const PreviousDepthFrame& previous = input.previous;
  const double dt = input.stamp_s - previous.stamp_s;
  if (previous.depth_m.empty() || input.flow_half.empty() || !(dt > 0.0) ||
      previous.depth_m.size() != input.depth_m.size() ||
      input.labels.size() != input.depth_m.size())
    return std::nullopt;
  const cv::Size size = input.depth_m.size();
  const int margin = int(std::lround(input.search_margin_px));
  const cv::Rect region =
      cv::Rect(input.instance.box.x - margin, input.instance.box.y - margin,
               input.instance.box.width + 2 * margin, input.instance.box.height + 2 * margin) &
      cv::Rect(0, 0, size.width, size.height);
  // Previous-frame grid points the flow carries onto the new mask, with depth at both ends.
  std::vector<cv::Point2f> from;
  std::vector<cv::Point2f> to;
  std::vector<float> z_from;
  std::vector<float> z_to;
  const int step = std::max(1, input.step_px);
  for (int y = region.y; y < region.y + region.height; y += step)
    for (int x = region.x; x < region.x + region.width; x += step) {
      const float z0 = previous.depth_m.at<float>(y, x);
      if (!(std::isfinite(z0) && z0 > 0.f)) continue;
      cv::Point2f px{float(x), float(y)};
      if (!carryByFlow(input.flow_half, size, px)) continue;
      const int u = int(std::lround(px.x)), v = int(std::lround(px.y));
      if (u < 0 || v < 0 || u >= size.width || v >= size.height) continue;
      if (input.labels.at<uint16_t>(v, u) != input.instance.id) continue;
      const float z1 = depthAt(input.depth_m, px);
      if (!(z1 > 0.f)) continue;
      from.emplace_back(float(x), float(y));
      to.emplace_back(px.x, px.y);
      z_from.push_back(z0);
      z_to.push_back(z1);
    }
  if (int(from.size()) < options.min_points) return std::nullopt;
  // Only points within the band of the object's median depth are the object's, as for the
  // tracker's own points.
  const std::vector<uint8_t> keep = withinDepthBand(z_to, input.depth_band_m);
  std::vector<Vec3> p_prev_world;
  std::vector<Eigen::Vector2d> pixels;
  std::vector<double> depth_now;
  // Rays are the undistorted pixels' (the depth stays the lens pixel's, as registered).
  const std::vector<cv::Point2f> ray_from = input.camera.undistortPixels(from);
  const std::vector<cv::Point2f> ray_to = input.camera.undistortPixels(to);
  for (size_t i = 0; i < from.size(); ++i) {
    if (!keep[i]) continue;
    p_prev_world.push_back(previous.T_world_camera *
                           input.camera.backproject(ray_from[i].x, ray_from[i].y, z_from[i]));
    pixels.emplace_back(ray_to[i].x, ray_to[i].y);
    depth_now.push_back(z_to[i]);
  }
  if (int(pixels.size()) < options.min_points) return std::nullopt;
  const ObjectMotion motion =
      estimateObjectMotion(p_prev_world, pixels, input.T_world_camera.inverse(), input.camera,
                           SE3::Identity(), options, depth_now);
  if (!motion.ok) return std::nullopt;
  return FirstMotion{inlierCentroidVelocity(motion, p_prev_world, dt), motion.H_world,
                     motion.inliers};
}

}  // namespace dynanav
