#include "perception/frame_prep.hpp"

#include <opencv2/imgproc.hpp>

namespace dynanav {

PreparedFrame prepareFrame(const RgbdFrame& frame, bool with_half) {
  PreparedFrame out;
  if (frame.bgr.channels() == 3)
    cv::cvtColor(frame.bgr, out.grey, cv::COLOR_BGR2GRAY);
  else
    out.grey = frame.bgr;
  if (with_half) cv::resize(out.grey, out.grey_half, cv::Size(), 0.5, 0.5, cv::INTER_AREA);
  return out;
}

}  // namespace dynanav
