#pragma once
// Test scenes' segmentations: an instance whose mask is a rectangle.
#include <string>

#include "perception/instances.hpp"

namespace dynanav::test {

/// Labels `box` (clipped to the label image) as instance `id` of `class_name` and records it,
/// its box the clipped one; returns the record (for keypoints and the like).
inline Instance& addBoxInstance(Instances& instances, uint16_t id, const std::string& class_name,
                                const cv::Rect& box) {
  const cv::Rect clipped = box & cv::Rect(0, 0, instances.labels.cols, instances.labels.rows);
  instances.labels(clipped).setTo(id);
  Instance instance;
  instance.id = id;
  instance.class_name = class_name;
  instance.box = clipped;
  instances.items.push_back(instance);
  return instances.items.back();
}

}  // namespace dynanav::test
