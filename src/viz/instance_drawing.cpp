#include "viz/instance_drawing.hpp"

#include <filesystem>
#include <opencv2/imgcodecs.hpp>
#include <opencv2/imgproc.hpp>

#include "viz/colours.hpp"

namespace dynanav {

cv::Mat drawInstances(const cv::Mat& bgr, const Instances& instances,
                      const std::vector<InstanceStatus>& statuses) {
  cv::Mat out = bgr.clone();
  for (const auto& item : instances.items) {
    const cv::Scalar colour = colourOfId(item.id);
    // Blend inside the mask's bounds only: a full-image blend per instance was most of the
    // video's drawing time.
    const cv::Mat mask = instances.mask(item.id);
    const cv::Rect roi = cv::boundingRect(mask);
    if (roi.area() > 0) {
      const cv::Mat m = mask(roi);
      cv::Mat blended;
      cv::addWeighted(out(roi), 0.45, cv::Mat(roi.size(), CV_8UC3, colour), 0.55, 0.0, blended);
      blended.copyTo(out(roi), m);
    }
    std::string verdict;
    for (const InstanceStatus& s : statuses)
      if (s.id == item.id) verdict = s.verdict;
    const bool dynamic = verdict == "moving" || verdict == "prior";
    cv::rectangle(out, item.box, dynamic ? cv::Scalar(0, 0, 255) : colour, dynamic ? 3 : 2);
    std::string text = item.class_name + " " + std::to_string(item.id) + " " +
                       cv::format("%.2f", item.score) + " " + item.mask_source;
    if (!verdict.empty()) text += " " + verdict;
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

namespace {
const cv::Size kThumb{200, 150};
}

ContactSheets::ContactSheets(std::string dir) : dir_(std::move(dir)) {
  std::filesystem::create_directories(dir_);
}

ContactSheets::~ContactSheets() {
  flush();
}

void ContactSheets::add(const cv::Mat& overlay, int frame_index) {
  if (sheet_.empty())
    sheet_ = cv::Mat(kRows * kThumb.height, kCols * kThumb.width, CV_8UC3, cv::Scalar::all(0));
  if (count_ == 0) first_ = frame_index;
  const cv::Rect cell((count_ % kCols) * kThumb.width, (count_ / kCols) * kThumb.height,
                      kThumb.width, kThumb.height);
  cv::resize(overlay, sheet_(cell), kThumb, 0, 0, cv::INTER_AREA);
  cv::putText(sheet_(cell), std::to_string(frame_index), {4, 18}, cv::FONT_HERSHEY_SIMPLEX, 0.6,
              cv::Scalar(0, 255, 0), 2);
  if (++count_ == kCols * kRows) flush();
}

void ContactSheets::flush() {
  if (count_ == 0) return;
  cv::imwrite((std::filesystem::path(dir_) / cv::format("sheet_%04d.png", first_)).string(),
              sheet_);
  sheet_.setTo(cv::Scalar::all(0));
  count_ = 0;
}

}  // namespace dynanav
