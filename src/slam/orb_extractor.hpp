#pragma once
// ORB features distributed as ORB-SLAM2 does it (Mur-Artal & Tardós, T-RO 2017, §III-A; Rublee et
// al., ICCV 2011): an image pyramid, FAST corners per grid cell with a fallback threshold, a
// quadtree that spreads the budget over the image, orientation by intensity centroid and rBRIEF
// descriptors on the blurred level image.
#include <opencv2/core.hpp>
#include <opencv2/features2d.hpp>
#include <vector>

#include "core/config/orb.hpp"

namespace dynanav {

class OrbExtractor {
 public:
  explicit OrbExtractor(const OrbConfig& config);

  /// Keypoints in level-0 pixel coordinates of the (distorted) input image, with octave, angle
  /// (degrees, [0, 360)), size (31 px patch times the level scale) and FAST response set, ordered
  /// by level; descriptors N x 32 CV_8U, row i for keypoint i. `gray` is CV_8UC1 (BGR is
  /// converted). Deterministic: the same image always gives the same output.
  void extract(const cv::Mat& gray, std::vector<cv::KeyPoint>& keypoints, cv::Mat& descriptors);
  /// Same, with features only where `mask` (CV_8UC1, image size) is non-zero; an empty mask allows
  /// everything. The feature budget is spread over the allowed part, so masking out a person does
  /// not cost static features (for the dynamic-scene pipeline).
  void extract(const cv::Mat& gray, const cv::Mat& mask, std::vector<cv::KeyPoint>& keypoints,
               cv::Mat& descriptors);

  [[nodiscard]] int levels() const { return static_cast<int>(scale_.size()); }
  /// Per level: scale relative to level 0 (1.0 at level 0), its inverse, and the squares, which
  /// ORB-SLAM2 uses as the variance of a keypoint's position at that level.
  [[nodiscard]] const std::vector<float>& scaleFactors() const { return scale_; }
  [[nodiscard]] const std::vector<float>& invScaleFactors() const { return inv_scale_; }
  [[nodiscard]] const std::vector<float>& levelSigma2() const { return sigma2_; }
  [[nodiscard]] const std::vector<float>& invLevelSigma2() const { return inv_sigma2_; }
  /// Feature budget per level (geometric: level i gets (1/scale)^i times level 0's share).
  [[nodiscard]] const std::vector<int>& featuresPerLevel() const { return n_per_level_; }
  /// The pyramid of the last extract() call (level 0 is the input image).
  [[nodiscard]] const std::vector<cv::Mat>& pyramid() const { return pyramid_; }

 private:
  void buildPyramid(const cv::Mat& gray);
  /// FAST corners of one level inside its border, in level coordinates, distributed.
  void detectLevel(int level, std::vector<cv::KeyPoint>& out);

  OrbConfig config_;
  std::vector<float> scale_, inv_scale_, sigma2_, inv_sigma2_;
  std::vector<int> n_per_level_;
  std::vector<int> umax_;  // half-width of the orientation disc per row offset
  std::vector<cv::Mat> pyramid_;
  std::vector<cv::Mat> mask_pyramid_;
  bool has_mask_ = false;
  std::vector<cv::KeyPoint> cell_scratch_;
  cv::Ptr<cv::ORB> descriptor_;  // only for rBRIEF with OpenCV's learned test pattern
};

/// Hamming distance of two 1x32 CV_8U descriptor rows (popcount on 64-bit words).
int descriptorDistance(const cv::Mat& a, const cv::Mat& b);

}  // namespace dynanav
