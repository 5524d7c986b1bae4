#include "mapping/render_cloud.hpp"

#include <algorithm>
#include <cmath>

#include "core/error.hpp"

namespace dynanav {

cv::Mat renderCloud(const ColouredCloud& cloud, const FloorPlane& floor, const CloudView& view) {
  if (view.kind != "top" && view.kind != "oblique")
    throw InputError("--view", "expected top or oblique, got '" + view.kind + "'");
  const Vec3 up = floor.found ? floor.up : Vec3(0, -1, 0);
  const Vec3 right = projectOntoPlane(Vec3::UnitX(), up).normalized();
  const Vec3 forward = up.cross(right).normalized();
  // Points in floor coordinates (right, forward, height), the ceiling cut.
  std::vector<Vec3> q;
  std::vector<cv::Vec3b> colour;
  for (size_t i = 0; i < cloud.size(); ++i) {
    const Vec3 p = cloud.p_world[i].cast<double>();
    const double h = floor.found ? floor.height(p) : up.dot(p);
    if (floor.found && h > view.max_height_m) continue;
    q.emplace_back(right.dot(p), forward.dot(p), h);
    colour.push_back(cloud.bgr[i]);
  }
  cv::Mat image(view.size, CV_8UC3, cv::Scalar(40, 40, 40));
  if (q.empty()) return image;
  // Robust extent (1st-99th percentile), so a few stray far points do not shrink the scene.
  auto range = [&](int axis) {
    std::vector<double> v;
    for (const Vec3& p : q) v.push_back(p[axis]);
    std::sort(v.begin(), v.end());
    return std::make_pair(v[v.size() / 100], v[v.size() - 1 - v.size() / 100]);
  };
  const auto [r0, r1] = range(0);
  const auto [f0, f1] = range(1);
  const auto [h0, h1] = range(2);
  const Vec3 centre((r0 + r1) / 2, (f0 + f1) / 2, (h0 + h1) / 2);
  const double extent = std::max({r1 - r0, f1 - f0, 0.5});
  // View frame: a = image right, b = image down, c = depth (larger = farther).
  Eigen::Matrix3d R;
  double focal_px;
  Vec3 eye;
  const bool top = view.kind == "top";
  if (top) {
    R << 1, 0, 0, 0, -1, 0, 0, 0, -1;  // image right = right, image down = -forward, depth = -h
    focal_px =
        0.95 * std::min(view.size.width / (r1 - r0 + 1e-3), view.size.height / (f1 - f0 + 1e-3));
    eye = centre;
  } else {
    const double el = view.elevation_deg * M_PI / 180, az = view.azimuth_deg * M_PI / 180;
    const Vec3 look(std::sin(az) * std::cos(el), std::cos(az) * std::cos(el), -std::sin(el));
    const Vec3 a = look.cross(Vec3::UnitZ()).normalized();
    const Vec3 b = look.cross(a).normalized();
    R.row(0) = a.transpose();
    R.row(1) = b.transpose();
    R.row(2) = look.transpose();
    const double distance = 1.3 * extent;
    eye = centre - look * distance;
    focal_px = view.size.width / (2 * std::tan(0.5 * 60 * M_PI / 180));
  }
  cv::Mat depth(view.size, CV_32F, cv::Scalar(1e9));
  const int s = std::max(1, view.splat_px);
  for (size_t i = 0; i < q.size(); ++i) {
    const Vec3 v = R * (q[i] - eye);
    double u, w, z;
    if (top) {
      u = view.size.width / 2.0 + focal_px * v.x();
      w = view.size.height / 2.0 + focal_px * v.y();
      z = v.z();
    } else {
      if (v.z() < 0.1) continue;
      u = view.size.width / 2.0 + focal_px * v.x() / v.z();
      w = view.size.height / 2.0 + focal_px * v.y() / v.z();
      z = v.z();
    }
    const int x0 = int(u) - s / 2, y0 = int(w) - s / 2;
    for (int y = std::max(0, y0); y < std::min(view.size.height, y0 + s); ++y)
      for (int x = std::max(0, x0); x < std::min(view.size.width, x0 + s); ++x) {
        float& d = depth.at<float>(y, x);
        if (z < d) {
          d = float(z);
          image.at<cv::Vec3b>(y, x) = colour[i];
        }
      }
  }
  return image;
}

}  // namespace dynanav
