#pragma once
// What every segmenter returns (DESIGN.md §1, perception): one label image plus a record per
// instance. Labels are CV_16U, 0 = background, k = the instance with id k.
#include <array>
#include <cstdint>
#include <opencv2/core.hpp>
#include <optional>
#include <string>
#include <vector>

namespace dynanav {

/// COCO body keypoints as MoveNet orders them (17 points).
enum class BodyPart : int {
  kNose = 0,
  kLeftShoulder = 5,
  kRightShoulder = 6,
  kLeftHip = 11,
  kRightHip = 12,
};
inline constexpr int kBodyKeypointCount = 17;

struct Keypoint {
  cv::Point2f pixel{0.f, 0.f};  ///< image pixel (x right, y down)
  float score = 0.f;            ///< MoveNet heatmap value, 0..1
};

struct BodyKeypoints {
  std::array<Keypoint, kBodyKeypointCount> points{};
  [[nodiscard]] const Keypoint& at(BodyPart part) const { return points[size_t(part)]; }
};

struct Instance {
  uint16_t id = 0;          ///< label value in Instances::labels
  std::string class_name;   ///< COCO name ("person", "chair", ...)
  float score = 1.f;        ///< detector confidence (1 for ground-truth masks)
  cv::Rect box;             ///< detector box clipped to the image (or the mask's bounds)
  std::string mask_source;  ///< how the mask was made: "selfie", "depth", "file", "flow"
  std::optional<BodyKeypoints> keypoints;  ///< persons only, when the keypoint model ran
};

struct Instances {
  cv::Mat labels;               ///< CV_16U, 0 = background
  std::vector<Instance> items;  ///< ordered by id
  /// The frame this segmentation was made on (< 0: not recorded); masks carried by flow keep
  /// it, so a late segmentation shows how late it is.
  int segmented_index = -1;

  [[nodiscard]] bool empty() const { return items.empty(); }
  [[nodiscard]] const Instance* find(uint16_t id) const;
  /// CV_8U 255 where labels == id.
  [[nodiscard]] cv::Mat mask(uint16_t id) const;
  /// Pixels labelled id.
  [[nodiscard]] int area(uint16_t id) const;
  /// Instances whose class is `class_name`.
  [[nodiscard]] int count(const std::string& class_name) const;
  /// Empty (all background) instances for an image size.
  static Instances none(cv::Size size);
};

/// Recomputes each box from its labelled pixels and drops instances with no pixel left.
void tightenToLabels(Instances& instances);

}  // namespace dynanav
