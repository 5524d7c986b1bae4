#include "perception/frame_prep.hpp"

#include <cmath>
#include <opencv2/imgproc.hpp>

namespace dynanav {
namespace {

/// Grey image of `frame` (BGR or already grey) and, when `with_half`, its half-size copy.
PreparedFrame prepareFrame(const RgbdFrame& frame, bool with_half) {
  PreparedFrame out;
  if (frame.bgr.channels() == 3)
    cv::cvtColor(frame.bgr, out.grey, cv::COLOR_BGR2GRAY);
  else
    out.grey = frame.bgr;
  if (with_half) cv::resize(out.grey, out.grey_half, cv::Size(), 0.5, 0.5, cv::INTER_AREA);
  return out;
}

}  // namespace

int disPatchFootprintPx(int patch_px, int finest_scale, double image_scale) {
  return int(std::lround(patch_px * (1 << finest_scale) / image_scale));
}

PreparedFrame FramePrep::prepare(const RgbdFrame& frame) {
  PreparedFrame out = prepareFrame(frame, needs_.half || needs_.flow);
  if (!needs_.flow) return out;
  if (!previous_half_.empty() && previous_half_.size() == out.grey_half.size()) {
    if (!dis_) {
      dis_ = cv::DISOpticalFlow::create(cv::DISOpticalFlow::PRESET_ULTRAFAST);
      dis_->setPatchSize(kSharedFlowPatchPx);
      dis_->setFinestScale(needs_.flow_finest_scale);
      dis_->setVariationalRefinementIterations(needs_.flow_refinement_iterations);
    }
    dis_->calc(previous_half_, out.grey_half, out.flow_half);
  }
  previous_half_ = out.grey_half;
  return out;
}

}  // namespace dynanav
