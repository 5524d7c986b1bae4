#include "perception/instances.hpp"

#include <algorithm>
#include <cmath>
#include <map>
#include <opencv2/imgproc.hpp>

namespace dynanav {

const Instance* Instances::find(uint16_t id) const {
  for (const auto& item : items)
    if (item.id == id) return &item;
  return nullptr;
}

cv::Mat Instances::mask(uint16_t id) const {
  cv::Mat m;
  cv::compare(labels, cv::Scalar(id), m, cv::CMP_EQ);
  return m;
}

int Instances::area(uint16_t id) const {
  return cv::countNonZero(mask(id));
}

int Instances::count(const std::string& class_name) const {
  return int(std::count_if(items.begin(), items.end(),
                           [&](const Instance& i) { return i.class_name == class_name; }));
}

Instances Instances::none(cv::Size size) {
  Instances out;
  out.labels = cv::Mat::zeros(size, CV_16U);
  return out;
}

void tightenToLabels(Instances& instances) {
  // One pass over the label image collects every id's bounds (cheaper than a mask per id).
  std::map<uint16_t, cv::Rect> bounds;
  const cv::Mat& labels = instances.labels;
  for (int y = 0; y < labels.rows; ++y) {
    const auto* row = labels.ptr<uint16_t>(y);
    for (int x = 0; x < labels.cols; ++x) {
      if (!row[x]) continue;
      auto [it, inserted] = bounds.try_emplace(row[x], x, y, 1, 1);
      if (!inserted) it->second |= cv::Rect(x, y, 1, 1);
    }
  }
  std::vector<Instance> kept;
  for (auto& item : instances.items) {
    const auto it = bounds.find(item.id);
    if (it == bounds.end()) continue;
    item.box = it->second;
    kept.push_back(std::move(item));
  }
  instances.items = std::move(kept);
}

}  // namespace dynanav
