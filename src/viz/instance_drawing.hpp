#pragma once
// Instances drawn over their image (moved here from perception/, issue 15): the segment
// command's overlay video and contact sheets, and the base layer of the annotated run video.
#include <opencv2/core.hpp>
#include <string>
#include <vector>

#include "perception/instances.hpp"

namespace dynanav {

/// What the run decided about an instance (from the pipeline's verdicts), for its label.
struct InstanceStatus {
  uint16_t id = 0;
  std::string verdict;  ///< "moving", "prior", "static", "" (not judged)
};

/// Colours the labels over the image (for overlays and contact sheets): one colour per id,
/// boxes, class names and, when present, shoulders and hips. With `statuses`, each box's label
/// adds the instance's verdict and dynamic instances get a thicker outline.
cv::Mat drawInstances(const cv::Mat& bgr, const Instances& instances,
                      const std::vector<InstanceStatus>& statuses = {});

/// Tiles overlay thumbnails, 8 x 6 per sheet, each stamped with its frame index, into
/// DIR/sheet_NNNN.png (NNNN = first frame of the sheet).
class ContactSheets {
 public:
  explicit ContactSheets(std::string dir);
  ~ContactSheets();
  ContactSheets(const ContactSheets&) = delete;
  ContactSheets& operator=(const ContactSheets&) = delete;
  void add(const cv::Mat& overlay, int frame_index);
  void flush();

 private:
  static constexpr int kCols = 8, kRows = 6;
  std::string dir_;
  cv::Mat sheet_;
  int count_ = 0, first_ = 0;
};

}  // namespace dynanav
