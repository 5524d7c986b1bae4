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

int Instances::area(uint16_t id) const { return cv::countNonZero(mask(id)); }

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

namespace {

cv::Scalar colourOf(uint16_t id) {
  // Well-separated hues from the golden ratio, so neighbouring ids differ.
  const double hue = std::fmod(double(id) * 0.618033988749895, 1.0) * 180.0;
  cv::Mat hsv(1, 1, CV_8UC3, cv::Scalar(hue, 220, 255)), bgr;
  cv::cvtColor(hsv, bgr, cv::COLOR_HSV2BGR);
  const auto c = bgr.at<cv::Vec3b>(0, 0);
  return {double(c[0]), double(c[1]), double(c[2])};
}

}  // namespace

cv::Mat drawInstances(const cv::Mat& bgr, const Instances& instances) {
  cv::Mat out = bgr.clone();
  for (const auto& item : instances.items) {
    const cv::Scalar colour = colourOf(item.id);
    const cv::Mat m = instances.mask(item.id);
    cv::Mat tint(out.size(), CV_8UC3, colour);
    cv::Mat blended;
    cv::addWeighted(out, 0.45, tint, 0.55, 0.0, blended);
    blended.copyTo(out, m);
    cv::rectangle(out, item.box, colour, 2);
    const std::string text = item.class_name + " " + std::to_string(item.id) + " " +
                             cv::format("%.2f", item.score) + " " + item.mask_source;
    cv::putText(out, text, item.box.tl() + cv::Point(2, 14), cv::FONT_HERSHEY_SIMPLEX, 0.45,
                cv::Scalar(255, 255, 255), 1, cv::LINE_AA);
    if (item.keypoints) {
      const BodyPart parts[] = {BodyPart::kLeftShoulder, BodyPart::kRightShoulder,
                                BodyPart::kLeftHip, BodyPart::kRightHip};
      for (BodyPart part : parts) {
        const Keypoint& k = item.keypoints->at(part);
        if (k.score < 0.2f) continue;
        const bool shoulder = part == BodyPart::kLeftShoulder || part == BodyPart::kRightShoulder;
        cv::circle(out, k.pixel, 5, shoulder ? cv::Scalar(0, 255, 255) : cv::Scalar(255, 0, 255),
                   cv::FILLED, cv::LINE_AA);
      }
    }
  }
  return out;
}

}  // namespace dynanav
