#include "slam/depth_surface.hpp"

#include <cmath>

#include "core/frame.hpp"

namespace dynanav {
namespace {

/// Neighbours this many surface pixels away give the normal: one pixel apart, the depth's
/// quantisation (a disparity step is 1-2 cm at 3 m) would tilt it by tens of degrees.
constexpr int kNormalSpanPx = 2;

/// A plane may be steep to the ray, but a neighbour further along the ray than this share of the
/// depth per pixel of span lies across a depth edge (another surface), not on the plane.
constexpr double kMaxDepthStepPerPx = 0.05;

Vec3 backproject(const DepthSurface& s, int x, int y, float z) {
  return {(x - s.cx) * z / s.fx, (y - s.cy) * z / s.fy, double(z)};
}

}  // namespace

DepthSurfaceMaker::DepthSurfaceMaker(const PinholeCamera& camera, double depth_max_m)
    : full_size_(camera.width, camera.height),
      half_size_(camera.width / 2, camera.height / 2),
      depth_max_m_(depth_max_m) {
  // A surface pixel x covers full-size pixels 2x and 2x+1, centred on u = 2x + 0.5.
  intrinsics_.fx = camera.fx / 2.0;
  intrinsics_.fy = camera.fy / 2.0;
  intrinsics_.cx = (camera.cx - 0.5) / 2.0;
  intrinsics_.cy = (camera.cy - 0.5) / 2.0;
  source_.assign(size_t(half_size_.area()), -1);
  const bool distorted = camera.isDistorted();
  for (int y = 0; y < half_size_.height; ++y)
    for (int x = 0; x < half_size_.width; ++x) {
      cv::Point2d full(2.0 * x + 0.5, 2.0 * y + 0.5);
      if (distorted) full = camera.distortPixel(full);
      const int u = int(std::lround(full.x)), v = int(std::lround(full.y));
      if (u < 0 || v < 0 || u >= full_size_.width || v >= full_size_.height) continue;
      source_[size_t(y * half_size_.width + x)] = v * full_size_.width + u;
    }
}

DepthSurface DepthSurfaceMaker::make(const cv::Mat& depth_m, const cv::Mat& allowed) const {
  DepthSurface surface = intrinsics_;
  if (depth_m.size() != full_size_ || depth_m.type() != CV_32F) return surface;
  const bool masked = !allowed.empty() && allowed.size() == full_size_;
  const cv::Mat depth = depth_m.isContinuous() ? depth_m : depth_m.clone();
  const cv::Mat mask = masked && !allowed.isContinuous() ? allowed.clone() : allowed;
  surface.depth_m = cv::Mat(half_size_, CV_32F);
  const float* z_full = depth.ptr<float>();
  float* z_half = surface.depth_m.ptr<float>();
  for (size_t i = 0; i < source_.size(); ++i) {
    const int s = source_[i];
    float z = 0.f;
    if (s >= 0 && (!masked || mask.ptr<uint8_t>()[s] != 0)) {
      z = z_full[s];
      if (!validDepth(z) || z > depth_max_m_) z = 0.f;
    }
    z_half[i] = z;
  }
  return surface;
}

std::optional<SurfacePoint> surfaceAt(const DepthSurface& s, const Vec3& p_camera,
                                      double max_distance_m) {
  if (s.empty() || p_camera.z() <= 0.0) return std::nullopt;
  const int x = int(std::lround(s.fx * p_camera.x() / p_camera.z() + s.cx));
  const int y = int(std::lround(s.fy * p_camera.y() / p_camera.z() + s.cy));
  const int d = kNormalSpanPx;
  if (x < d || y < d || x >= s.depth_m.cols - d || y >= s.depth_m.rows - d) return std::nullopt;
  const float z = s.depth_m.at<float>(y, x);
  const float zl = s.depth_m.at<float>(y, x - d), zr = s.depth_m.at<float>(y, x + d);
  const float zu = s.depth_m.at<float>(y - d, x), zd = s.depth_m.at<float>(y + d, x);
  if (!(z > 0.f && zl > 0.f && zr > 0.f && zu > 0.f && zd > 0.f)) return std::nullopt;
  const float max_step = float(kMaxDepthStepPerPx * d) * z;
  for (const float zn : {zl, zr, zu, zd})
    if (std::abs(zn - z) > max_step) return std::nullopt;
  SurfacePoint out;
  out.p_camera = backproject(s, x, y, z);
  const Vec3 across = backproject(s, x + d, y, zr) - backproject(s, x - d, y, zl);
  const Vec3 down = backproject(s, x, y + d, zd) - backproject(s, x, y - d, zu);
  Vec3 n = across.cross(down);
  const double norm = n.norm();
  if (!(norm > 0.0)) return std::nullopt;
  n /= norm;
  if (n.dot(out.p_camera) > 0.0) n = -n;  // toward the camera
  out.normal_camera = n;
  if (std::abs(n.dot(p_camera - out.p_camera)) > max_distance_m) return std::nullopt;
  return out;
}

std::vector<Vec3> surfaceSamples(const DepthSurface& s, int step_px) {
  std::vector<Vec3> out;
  if (s.empty()) return out;
  const int step = std::max(1, step_px);
  for (int y = step / 2; y < s.depth_m.rows; y += step) {
    const float* row = s.depth_m.ptr<float>(y);
    for (int x = step / 2; x < s.depth_m.cols; x += step)
      if (row[x] > 0.f) out.push_back(backproject(s, x, y, row[x]));
  }
  return out;
}

}  // namespace dynanav
