#include "slam/orb_extractor.hpp"

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstring>
#include <stdexcept>

#include <opencv2/imgproc.hpp>

#include "slam/orb_orientation.hpp"
#include "slam/orb_quadtree.hpp"

namespace dynanav {
namespace {

constexpr int kPatchSize = 31;        // rBRIEF patch; the orientation disc has its half width
constexpr int kEdgeThreshold = 19;    // keypoints stay this far from each level's border
constexpr int kFastBorder = 3;        // FAST's circle radius
constexpr int kCellSize = 30;         // ORB-SLAM2's grid cell for the per-cell thresholds

}  // namespace

OrbExtractor::OrbExtractor(const OrbConfig& config) : config_(config) {
  if (config.n_levels < 1 || config.scale_factor <= 1.0 || config.n_features < 1)
    throw std::invalid_argument("OrbConfig: need n_levels >= 1, scale_factor > 1, n_features >= 1");
  const int n = config.n_levels;
  scale_.resize(n);
  inv_scale_.resize(n);
  sigma2_.resize(n);
  inv_sigma2_.resize(n);
  for (int i = 0; i < n; ++i) {
    scale_[i] = static_cast<float>(std::pow(config.scale_factor, i));
    inv_scale_[i] = 1.0f / scale_[i];
    sigma2_[i] = scale_[i] * scale_[i];
    inv_sigma2_[i] = 1.0f / sigma2_[i];
  }
  // Features per level in proportion to the level's linear size (ORB-SLAM2): a geometric series
  // with ratio 1/scale whose sum is n_features; the last level takes what rounding left over.
  const double ratio = 1.0 / config.scale_factor;
  double share = config.n_features * (1.0 - ratio) / (1.0 - std::pow(ratio, n));
  n_per_level_.resize(n);
  int assigned = 0;
  for (int i = 0; i + 1 < n; ++i) {
    n_per_level_[i] = static_cast<int>(std::lround(share));
    assigned += n_per_level_[i];
    share *= ratio;
  }
  n_per_level_[n - 1] = std::max(config.n_features - assigned, 0);

  umax_ = orientationDisc(kPatchSize / 2);
  pyramid_.resize(n);
  // OpenCV's ORB is used only to compute rBRIEF with its learned test pattern on our keypoints
  // (positions, octaves and angles are ours); its pyramid uses the same sizes and interpolation.
  descriptor_ = cv::ORB::create(config.n_features, static_cast<float>(config.scale_factor), n,
                                kEdgeThreshold - kFastBorder, 0, 2, cv::ORB::FAST_SCORE,
                                kPatchSize, config.fast_threshold_initial);
}

void OrbExtractor::buildPyramid(const cv::Mat& gray) {
  pyramid_[0] = gray;
  for (int i = 1; i < levels(); ++i) {
    const cv::Size size(static_cast<int>(std::lround(gray.cols * inv_scale_[i])),
                        static_cast<int>(std::lround(gray.rows * inv_scale_[i])));
    // From the previous level, as ORB-SLAM2 does: cheaper, and bilinear over 1.2x is fine.
    cv::resize(pyramid_[i - 1], pyramid_[i], size, 0, 0, cv::INTER_LINEAR);
  }
}

void OrbExtractor::detectLevel(int level, std::vector<cv::KeyPoint>& out) {
  const cv::Mat& image = pyramid_[level];
  // Region where FAST may fire so that corners end kEdgeThreshold px inside the level image.
  const int border = kEdgeThreshold - kFastBorder;
  const cv::Rect region(border, border, image.cols - 2 * border, image.rows - 2 * border);
  out.clear();
  if (region.width <= 2 * kFastBorder || region.height <= 2 * kFastBorder) return;
  const cv::Mat roi = image(region);

  // ORB-SLAM2 runs FAST with the initial threshold in each 30 px cell and falls back to the low
  // threshold in cells that gave nothing, so textureless areas still contribute. One pass over
  // the whole region with the initial threshold finds the same corners (FAST is local) at a
  // fraction of the cost; only empty cells are searched again.
  // With a mask, corners on masked pixels are dropped before the distribution, so the whole
  // budget goes to the allowed part of the image.
  const cv::Mat* mask = has_mask_ ? &mask_pyramid_[level] : nullptr;
  const auto allowed = [&](const cv::KeyPoint& kp) {
    return !mask || mask->at<uchar>(static_cast<int>(kp.pt.y) + border, static_cast<int>(kp.pt.x) + border) != 0;
  };
  std::vector<cv::KeyPoint> found;
  cv::FAST(roi, found, config_.fast_threshold_initial, true);
  if (mask) std::erase_if(found, [&](const cv::KeyPoint& kp) { return !allowed(kp); });
  const int n_cols = std::max(1, region.width / kCellSize);
  const int n_rows = std::max(1, region.height / kCellSize);
  const int cell_w = (region.width + n_cols - 1) / n_cols;
  const int cell_h = (region.height + n_rows - 1) / n_rows;
  std::vector<unsigned char> occupied(static_cast<size_t>(n_cols) * n_rows, 0);
  for (const auto& kp : found) {
    const int cx = std::min(n_cols - 1, static_cast<int>(kp.pt.x) / cell_w);
    const int cy = std::min(n_rows - 1, static_cast<int>(kp.pt.y) / cell_h);
    occupied[cy * n_cols + cx] = 1;
  }
  for (int cy = 0; cy < n_rows; ++cy) {
    for (int cx = 0; cx < n_cols; ++cx) {
      if (occupied[cy * n_cols + cx]) continue;
      // The cell grown by FAST's radius, so the low-threshold pass reports corners in the cell.
      const cv::Rect cell(cx * cell_w - kFastBorder, cy * cell_h - kFastBorder,
                          cell_w + 2 * kFastBorder, cell_h + 2 * kFastBorder);
      const cv::Rect window = cell & cv::Rect(0, 0, region.width, region.height);
      if (window.width <= 2 * kFastBorder || window.height <= 2 * kFastBorder) continue;
      if (mask && cv::countNonZero((*mask)(window + region.tl())) == 0) continue;
      cv::FAST(roi(window), cell_scratch_, config_.fast_threshold_min, true);
      for (auto kp : cell_scratch_) {
        kp.pt.x += static_cast<float>(window.x);
        kp.pt.y += static_cast<float>(window.y);
        if (allowed(kp)) found.push_back(kp);
      }
    }
  }

  out = distributeQuadtree(found, 0.0f, static_cast<float>(region.width), 0.0f,
                           static_cast<float>(region.height), n_per_level_[level]);
  const float scale = scale_[level];
  for (auto& kp : out) {
    kp.pt.x += static_cast<float>(border);
    kp.pt.y += static_cast<float>(border);
    kp.angle = intensityCentroidAngle(
        image, cv::Point(static_cast<int>(kp.pt.x), static_cast<int>(kp.pt.y)), umax_);
    kp.octave = level;
    kp.size = kPatchSize * scale;
    kp.pt *= scale;  // level-0 pixel coordinates
  }
}

void OrbExtractor::extract(const cv::Mat& gray, std::vector<cv::KeyPoint>& keypoints,
                           cv::Mat& descriptors) {
  extract(gray, cv::Mat(), keypoints, descriptors);
}

void OrbExtractor::extract(const cv::Mat& gray, const cv::Mat& mask,
                           std::vector<cv::KeyPoint>& keypoints, cv::Mat& descriptors) {
  cv::Mat input = gray;
  if (gray.type() == CV_8UC3) cv::cvtColor(gray, input, cv::COLOR_BGR2GRAY);
  if (input.type() != CV_8UC1 || input.empty())
    throw std::invalid_argument("OrbExtractor::extract: need a non-empty CV_8UC1 image");
  has_mask_ = !mask.empty();
  if (has_mask_ && (mask.type() != CV_8UC1 || mask.size() != input.size()))
    throw std::invalid_argument("OrbExtractor::extract: the mask must be CV_8UC1 of the image size");
  buildPyramid(input);
  if (has_mask_) {
    mask_pyramid_.resize(levels());
    mask_pyramid_[0] = mask;
    // Each level straight from level 0 (nearest neighbour), so masks do not erode level by level.
    for (int i = 1; i < levels(); ++i)
      cv::resize(mask, mask_pyramid_[i], pyramid_[i].size(), 0, 0, cv::INTER_NEAREST);
  }
  keypoints.clear();
  keypoints.reserve(config_.n_features + levels() * 4);
  std::vector<cv::KeyPoint> level_kps;
  for (int level = 0; level < levels(); ++level) {
    detectLevel(level, level_kps);
    keypoints.insert(keypoints.end(), level_kps.begin(), level_kps.end());
  }
  const size_t n_detected = keypoints.size();
  if (keypoints.empty()) {
    descriptors.create(0, 32, CV_8U);
    return;
  }
  descriptor_->compute(input, keypoints, descriptors);
  if (keypoints.size() != n_detected || descriptors.rows != static_cast<int>(n_detected))
    throw std::logic_error("OrbExtractor: descriptor stage dropped keypoints");
}

int descriptorDistance(const cv::Mat& a, const cv::Mat& b) {
  const uchar* pa = a.ptr<uchar>();
  const uchar* pb = b.ptr<uchar>();
  int distance = 0;
  for (int i = 0; i < 32; i += 8) {
    uint64_t wa, wb;  // memcpy: rows need not be 8-byte aligned
    std::memcpy(&wa, pa + i, 8);
    std::memcpy(&wb, pb + i, 8);
    distance += std::popcount(wa ^ wb);
  }
  return distance;
}

}  // namespace dynanav
