#include "dynamics/scene_flow.hpp"

#include <algorithm>
#include <cmath>
#include <map>

#include <opencv2/imgproc.hpp>

#include "core/frame.hpp"
#include "core/median.hpp"
#include "dynamics/depth_tolerance.hpp"

namespace dynanav {
double sceneFlowPointThreshold(double z_prev_m, double z_cur_m, const DynamicsConfig& config) {
  const double sigma_prev = config.depth_noise_per_z2 * z_prev_m * z_prev_m;
  const double sigma_cur = config.depth_noise_per_z2 * z_cur_m * z_cur_m;
  const double noise_m = config.scene_flow_point_sigmas * std::hypot(sigma_prev, sigma_cur);
  return std::max(config.scene_flow_point_m, noise_m);
}

SceneFlowVerdict sceneFlowVerdict(const std::vector<Vec3>& p_prev_camera,
                                  const std::vector<Vec3>& p_cur_camera, const SE3& T_cur_prev,
                                  const DynamicsConfig& config,
                                  const BackgroundMotion& background) {
  SceneFlowVerdict v;
  const size_t n = std::min(p_prev_camera.size(), p_cur_camera.size());
  double sum = 0.0;
  Vec3 sum_vector = Vec3::Zero();
  for (size_t i = 0; i < n; ++i) {
    // Where the point would be now had it not moved, vs. where it is.
    const Vec3 flow = p_cur_camera[i] - T_cur_prev * p_prev_camera[i] - background.displacement_m;
    const double flow_m = flow.norm();
    sum += flow_m;
    sum_vector += flow;
    ++v.points;
    const double threshold_m =
        std::max(sceneFlowPointThreshold(p_prev_camera[i].z(), p_cur_camera[i].z(), config),
                 config.scene_flow_point_sigmas * background.sigma_m);
    v.moving += flow_m > threshold_m ? 1 : 0;
  }
  v.mean_flow_m = v.points ? sum / v.points : 0.0;
  v.decided = v.points >= config.scene_flow_min_points;
  v.mean_vector_m = v.points ? sum_vector.norm() / v.points : 0.0;
  // Depth noise alone (sigma ~1.5 cm at 3 m on a Kinect) moves many single points past 2 cm but
  // averages out over the object; a real motion does not. So the object's mean displacement
  // must pass the point threshold too (scene_flow_mean_check).
  const bool mean_moves =
      !config.scene_flow_mean_check || v.mean_vector_m > config.scene_flow_point_m;
  v.dynamic =
      v.decided && mean_moves && double(v.moving) > config.scene_flow_share * double(v.points);
  // The noise-grown point threshold keeps depth noise from making things move, but at a few
  // metres it exceeds a walker's displacement per frame (11 cm at 4 m): failing it is no evidence
  // of standing still. The mean vector, where the noise averages out, is.
  v.still = v.decided && !v.dynamic && v.mean_vector_m <= config.scene_flow_point_m;
  return v;
}

BackgroundMotion backgroundMotion(const std::vector<Vec3>& p_prev_camera,
                                  const std::vector<Vec3>& p_cur_camera, const SE3& T_cur_prev,
                                  const DynamicsConfig& config) {
  BackgroundMotion motion;
  const size_t n = std::min(p_prev_camera.size(), p_cur_camera.size());
  if (n == 0 || int(n) < config.scene_flow_min_points) return motion;
  std::vector<Vec3> flows(n);
  for (size_t i = 0; i < n; ++i) flows[i] = p_cur_camera[i] - T_cur_prev * p_prev_camera[i];
  std::vector<double> values(n);
  for (int a = 0; a < 3; ++a) {
    for (size_t i = 0; i < n; ++i) values[i] = flows[i][a];
    motion.displacement_m[a] = medianInPlace(values);
  }
  // The median length of the residuals is 1.538 sigma for a 3D Gaussian of sigma per axis: a
  // scale that ignores the few background points a walker's flow drags along.
  for (size_t i = 0; i < n; ++i) values[i] = (flows[i] - motion.displacement_m).norm();
  motion.sigma_m = medianInPlace(values) / 1.538;
  return motion;
}

std::vector<cv::Point> sampleRingPixels(const cv::Mat& object_mask, const cv::Mat& labels,
                                        int inner_px, int outer_px, int step) {
  CV_Assert(object_mask.type() == CV_8UC1 && labels.type() == CV_16UC1 &&
            object_mask.size() == labels.size() && step > 0 && inner_px >= 0);
  std::vector<cv::Point> pixels;
  if (outer_px <= inner_px) return pixels;
  // On the sampling grid, one cell per sample (step x step px, the sample at its centre): a cell
  // holds the object if any of its pixels does. Dilating the grid instead of the image costs
  // step^3 times less (a full-size 193 px dilation per object doubled the stage's time), and
  // only the cells within the outer edge of the object's box are looked at.
  const int cols = object_mask.cols / step, rows = object_mask.rows / step;
  const cv::Rect box = cv::boundingRect(object_mask);
  if (cols == 0 || rows == 0 || box.empty()) return pixels;
  const int reach = outer_px / step;
  const cv::Rect cells_box = cv::Rect(cv::Point(box.x / step - reach, box.y / step - reach),
                                      cv::Point((box.br().x - 1) / step + reach + 1,
                                                (box.br().y - 1) / step + reach + 1)) &
                             cv::Rect(0, 0, cols, rows);
  if (cells_box.empty()) return pixels;
  cv::Mat cells;
  cv::resize(object_mask(cv::Rect(cells_box.tl() * step, cells_box.size() * step)), cells,
             cells_box.size(), 0, 0, cv::INTER_AREA);
  cells = cells > 0;
  const auto grow = [&](int radius_cells) {
    cv::Mat out;
    cv::dilate(cells, out,
               cv::getStructuringElement(cv::MORPH_RECT,
                                         cv::Size(2 * radius_cells + 1, 2 * radius_cells + 1)));
    return out;
  };
  // Beyond the inner gap (rounded up) and within the outer edge (rounded down), in cells.
  cv::Mat ring = grow(reach);
  ring.setTo(0, grow((inner_px + step - 1) / step));
  for (int r = 0; r < cells_box.height; ++r) {
    const uchar* row = ring.ptr<uchar>(r);
    for (int c = 0; c < cells_box.width; ++c) {
      const cv::Point p((cells_box.x + c) * step + step / 2, (cells_box.y + r) * step + step / 2);
      if (row[c] && labels.at<uint16_t>(p) == 0) pixels.push_back(p);
    }
  }
  return pixels;
}

std::vector<cv::Point> sampleMaskPixels(const cv::Mat& mask, int step) {
  CV_Assert(mask.type() == CV_8UC1 && step > 0);
  std::vector<cv::Point> pixels;
  for (int v = step / 2; v < mask.rows; v += step) {
    const uchar* row = mask.ptr<uchar>(v);
    for (int u = step / 2; u < mask.cols; u += step)
      if (row[u]) pixels.emplace_back(u, v);
  }
  return pixels;
}

namespace {
/// Depth at a sub-pixel position by nearest pixel (bilinear would blend across depth edges).
float depthAt(const cv::Mat& depth_m, float u, float v) {
  const int x = int(std::lround(u)), y = int(std::lround(v));
  if (x < 0 || y < 0 || x >= depth_m.cols || y >= depth_m.rows) return 0.f;
  return depth_m.at<float>(y, x);
}
/// The depth at a flow's end as FlowEndDepth describes.
float endDepth(const cv::Mat& cur_depth_m, const cv::Point2f& end, const Vec3& p_prev_camera,
               const FlowEndDepth& end_depth, double focal_px) {
  const float own_m = depthAt(cur_depth_m, end.x, end.y);
  if (end_depth.radius_px <= 0) return own_m;
  const double expected_m = (end_depth.T_cur_prev * p_prev_camera).z();
  const int radius_px = flowEndSearchRadiusPx(end_depth, expected_m, focal_px);
  const DepthRange range = depthRangeAround(cur_depth_m, end, radius_px, expected_m);
  const double jump_m = 2.0 * sceneFlowPointThreshold(expected_m, expected_m, *end_depth.config);
  if (!(range.min_m > 0.f) || double(range.max_m - range.min_m) <= jump_m) return own_m;
  return range.nearest_m;
}
}  // namespace

int flowEndSearchRadiusPx(const FlowEndDepth& end_depth, double expected_z_m, double focal_px) {
  if (end_depth.radius_px <= 0) return 0;
  CV_Assert(end_depth.config != nullptr);
  double radius_px = end_depth.radius_px;
  if (end_depth.parallax && expected_z_m > 0.0)
    radius_px += focal_px * end_depth.T_cur_prev.translation().norm() / expected_z_m;
  return int(std::lround(std::min(radius_px, double(end_depth.config->depth_test_max_radius_px))));
}

void liftFlowCorrespondences(const std::vector<cv::Point>& prev_pixels, const cv::Mat& flow,
                             const cv::Mat& prev_depth_m, const cv::Mat& cur_depth_m,
                             const PinholeCamera& camera, std::vector<Vec3>& p_prev_camera,
                             std::vector<Vec3>& p_cur_camera, std::vector<size_t>* kept,
                             const FlowEndDepth& end_depth) {
  CV_Assert(flow.type() == CV_32FC2);
  p_prev_camera.clear();
  p_cur_camera.clear();
  if (kept) kept->clear();
  // Both ends in the lens's pixels (the flow's and the registered depth's), lifted along the
  // undistorted pixels' rays: the lens shifts a point by an amount that changes as it moves in
  // the image (up to 18 px at fr1's corners, 10 px 50 px further in), so the two ends' shifts
  // differ and a still point read as moving by the difference (at fr1's corner pixel, 2 m away,
  // 9.5 mm for a camera step of 3.6 cm).
  std::vector<size_t> index;
  std::vector<cv::Point2f> starts, ends;
  std::vector<float> z_start;
  for (size_t i = 0; i < prev_pixels.size(); ++i) {
    const cv::Point& p = prev_pixels[i];
    if (p.x < 0 || p.y < 0 || p.x >= flow.cols || p.y >= flow.rows) continue;
    const cv::Vec2f f = flow.at<cv::Vec2f>(p);
    const float u1 = float(p.x) + f[0], v1 = float(p.y) + f[1];
    if (!camera.inImage(u1, v1)) continue;
    const float z0 = prev_depth_m.at<float>(p);
    if (!validDepth(z0)) continue;
    index.push_back(i);
    starts.emplace_back(float(p.x), float(p.y));
    ends.emplace_back(u1, v1);
    z_start.push_back(z0);
  }
  const std::vector<cv::Point2f> ray_starts = camera.undistortPixels(starts);
  const std::vector<cv::Point2f> ray_ends = camera.undistortPixels(ends);
  for (size_t k = 0; k < index.size(); ++k) {
    const Vec3 p_prev = camera.backproject(ray_starts[k].x, ray_starts[k].y, z_start[k]);
    const float z1 = endDepth(cur_depth_m, ends[k], p_prev, end_depth, camera.fx);
    if (!validDepth(z1)) continue;
    p_prev_camera.push_back(p_prev);
    p_cur_camera.push_back(camera.backproject(ray_ends[k].x, ray_ends[k].y, z1));
    if (kept) kept->push_back(index[k]);
  }
}

uint16_t labelAlongFlow(const cv::Mat& labels, const std::vector<cv::Point>& old_pixels,
                        const cv::Mat& flow) {
  CV_Assert(labels.type() == CV_16UC1 && (flow.empty() || flow.type() == CV_32FC2));
  std::map<uint16_t, int> counts;
  int total = 0;
  for (const cv::Point& p : old_pixels) {
    const cv::Vec2f f = flow.empty() ? cv::Vec2f(0.f, 0.f) : flow.at<cv::Vec2f>(p);
    const int x = int(std::lround(float(p.x) + f[0])), y = int(std::lround(float(p.y) + f[1]));
    if (x < 0 || y < 0 || x >= labels.cols || y >= labels.rows) continue;
    ++total;
    if (const uint16_t l = labels.at<uint16_t>(y, x)) ++counts[l];
  }
  uint16_t best = 0;
  int best_count = 0;
  for (const auto& [id, count] : counts)
    if (count > best_count) best = id, best_count = count;
  return total > 0 && best_count * 3 >= total ? best : 0;
}

}  // namespace dynanav
