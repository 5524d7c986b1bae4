#include "dynamics/object_points.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <opencv2/imgproc.hpp>

#include "core/median.hpp"

namespace dynanav {
namespace {

/// The box spanned by shoulders and hips, when all four were found.
std::optional<cv::Rect> trunkBox(const Instance& instance) {
  if (!instance.keypoints) return std::nullopt;
  constexpr float kMinScore = 0.3f;
  std::vector<cv::Point2f> corners;
  for (const BodyPart part : {BodyPart::kLeftShoulder, BodyPart::kRightShoulder, BodyPart::kLeftHip,
                              BodyPart::kRightHip}) {
    const Keypoint& k = instance.keypoints->at(part);
    if (k.score < kMinScore) return std::nullopt;
    corners.push_back(k.pixel);
  }
  return cv::boundingRect(corners);
}

/// Without keypoints: the trunk is about the band from 20 % to 50 % of a person's height below
/// the top of the head (shoulders to hips of an adult). The height is the box's when the whole
/// person is in view, else the expected height at its depth, counted from the top of the head
/// or, with the head out of view, up from the feet.
std::optional<cv::Rect> trunkBand(const Instance& instance, int image_rows, double height_px) {
  if (instance.class_name != "person") return std::nullopt;
  const cv::Rect& b = instance.box;
  const bool top_in_view = b.y > 1, bottom_in_view = b.y + b.height < image_rows - 1;
  double top = b.y, height = b.height;
  if (!(top_in_view && bottom_in_view)) {
    if (height_px <= 0.0 || (!top_in_view && !bottom_in_view)) return std::nullopt;
    height = std::max(height_px, double(b.height));
    if (!top_in_view) top = b.y + b.height - height;
  }
  return cv::Rect(b.x, int(std::lround(top + 0.2 * height)), b.width,
                  int(std::lround(0.3 * height)));
}

std::vector<cv::Point2f> gridIn(const cv::Mat& labels, uint16_t id, cv::Rect area, int step) {
  std::vector<cv::Point2f> out;
  area &= cv::Rect(0, 0, labels.cols, labels.rows);
  // The grid is anchored at the image origin, so a mask sampled twice gives the same pixels.
  const int x0 = (area.x + step - 1) / step * step;
  const int y0 = (area.y + step - 1) / step * step;
  for (int y = y0; y < area.y + area.height; y += step) {
    const uint16_t* row = labels.ptr<uint16_t>(y);
    for (int x = x0; x < area.x + area.width; x += step)
      if (row[x] == id) out.emplace_back(float(x), float(y));
  }
  return out;
}

}  // namespace

ObjectSample sampleObjectPixels(const cv::Mat& labels, const Instance& instance,
                                const SampleOptions& options) {
  const int step = std::max(1, options.step_px);
  std::vector<cv::Point2f> points;
  if (const auto trunk = trunkBox(instance)) {
    points = gridIn(labels, instance.id, *trunk, step);
  } else if (const auto band = trunkBand(instance, labels.rows, options.person_height_px)) {
    points = gridIn(labels, instance.id, *band, step);
  }
  const bool trunk = int(points.size()) >= options.trunk_min_points;
  if (!trunk) points = gridIn(labels, instance.id, instance.box, step);
  if (options.max_points > 0 && int(points.size()) > options.max_points) {
    std::vector<cv::Point2f> thinned;
    thinned.reserve(size_t(options.max_points));
    const double stride = double(points.size()) / options.max_points;
    for (int k = 0; k < options.max_points; ++k) thinned.push_back(points[size_t(k * stride)]);
    points = std::move(thinned);
  }
  return {std::move(points), trunk};
}

std::vector<uint8_t> withinDepthBand(const std::vector<float>& z_m, double band_m) {
  std::vector<float> valid;
  for (float z : z_m)
    if (z > 0.f) valid.push_back(z);
  std::vector<uint8_t> keep(z_m.size(), 0);
  if (valid.empty()) return keep;
  const float z_median = medianInPlace(valid);
  for (size_t i = 0; i < z_m.size(); ++i)
    keep[i] = z_m[i] > 0.f && std::abs(z_m[i] - z_median) <= float(band_m);
  return keep;
}

std::vector<NearerSurface> besideNearerSurface(const std::vector<cv::Point2f>& pixels,
                                               const std::vector<float>& z_m, const cv::Mat& labels,
                                               uint16_t id, const cv::Mat& depth_m, int reach_px,
                                               double margin_m) {
  std::vector<NearerSurface> beside(pixels.size());
  if (reach_px <= 0 || labels.empty() || labels.size() != depth_m.size()) return beside;
  // Two rings, half the reach and the reach, eight directions each.
  std::array<cv::Point2f, 16> probes;
  for (int k = 0; k < 16; ++k) {
    const double angle = (k % 8) * CV_PI / 4.0, r = (k < 8 ? 0.5 : 1.0) * reach_px;
    probes[size_t(k)] = cv::Point2f(float(r * std::cos(angle)), float(r * std::sin(angle)));
  }
  for (size_t i = 0; i < pixels.size(); ++i) {
    if (!(z_m[i] > 0.f)) continue;
    float nearest_z = z_m[i] - float(margin_m);
    for (const cv::Point2f& d : probes) {
      const cv::Point2f q = pixels[i] + d;
      const int x = int(std::lround(q.x)), y = int(std::lround(q.y));
      if (x < 0 || y < 0 || x >= labels.cols || y >= labels.rows) continue;
      const uint16_t label = labels.at<uint16_t>(y, x);
      const float z = depthAt(depth_m, q);
      if (label == id || !(z > 0.f) || !(z < nearest_z)) continue;
      nearest_z = z;
      beside[i] = {true, label};
    }
  }
  return beside;
}

int instanceCutSide(const Instance& instance, int image_cols) {
  const bool left = instance.box.x <= 1;
  const bool right = instance.box.x + instance.box.width >= image_cols - 1;
  return left == right ? 0 : (left ? -1 : 1);
}

double medianLabelDepthM(const cv::Mat& labels, uint16_t label, cv::Rect box,
                         const cv::Mat& depth_m, int step) {
  if (depth_m.size() != labels.size()) return 0.0;
  std::vector<float> z;
  box &= cv::Rect(0, 0, labels.cols, labels.rows);
  for (int y = box.y; y < box.y + box.height; y += step)
    for (int x = box.x; x < box.x + box.width; x += step)
      if (labels.at<uint16_t>(y, x) == label) {
        const float d = depth_m.at<float>(y, x);
        if (std::isfinite(d) && d > 0.f) z.push_back(d);
      }
  if (z.empty()) return 0.0;
  return medianInPlace(z);
}

bool carryByFlow(const cv::Mat& flow_half, cv::Size image_size, cv::Point2f& pixel) {
  if (!flow_half.empty()) {
    // Half-size pixel centres: (u + 0.5) / 2 - 0.5.
    const int xh = int(std::lround((pixel.x + 0.5f) * 0.5f - 0.5f));
    const int yh = int(std::lround((pixel.y + 0.5f) * 0.5f - 0.5f));
    if (xh < 0 || yh < 0 || xh >= flow_half.cols || yh >= flow_half.rows) return false;
    const cv::Point2f d = flow_half.at<cv::Point2f>(yh, xh);
    pixel += 2.0f * d;
  }
  return pixel.x >= 0.f && pixel.y >= 0.f && pixel.x <= float(image_size.width - 1) &&
         pixel.y <= float(image_size.height - 1);
}

float depthAt(const cv::Mat& depth_m, const cv::Point2f& pixel) {
  const int x = int(std::lround(pixel.x)), y = int(std::lround(pixel.y));
  if (x < 0 || y < 0 || x >= depth_m.cols || y >= depth_m.rows) return 0.f;
  const float z = depth_m.at<float>(y, x);
  return std::isfinite(z) && z > 0.f ? z : 0.f;
}

std::optional<Vec3> objectCentre(const std::vector<Vec3>& p_camera, double depth_band_m,
                                 double behind_m) {
  if (p_camera.empty()) return std::nullopt;
  std::vector<double> z;
  z.reserve(p_camera.size());
  for (const Vec3& p : p_camera) z.push_back(p.z());
  const double z_median = medianInPlace(z);
  std::vector<double> xs, ys, zs;
  for (const Vec3& p : p_camera) {
    if (std::abs(p.z() - z_median) > depth_band_m) continue;
    xs.push_back(p.x());
    ys.push_back(p.y());
    zs.push_back(p.z());
  }
  if (xs.empty()) return std::nullopt;
  const Vec3 surface(medianInPlace(xs), medianInPlace(ys), medianInPlace(zs));
  return surface + behind_m * surface.normalized();
}

double objectWidth(const std::vector<Vec3>& p_camera) {
  if (p_camera.size() < 2) return 0.0;
  std::vector<double> x;
  for (const Vec3& p : p_camera) x.push_back(p.x());
  std::sort(x.begin(), x.end());
  return x[x.size() * 9 / 10] - x[x.size() / 10];
}

}  // namespace dynanav
