#pragma once
// Mask propagation between segmented frames (issue 6, --segment-every k): labels are pulled
// from the previous frame along dense DIS optical flow (Kroeger et al., ECCV 2016; OpenCV's
// fast preset) computed from the new frame back to the previous one, then each instance keeps
// only the pixels near its depth mode in the new frame (flow bleeds over depth edges).
#include <opencv2/core.hpp>
#include <opencv2/video/tracking.hpp>

#include "core/config/perception.hpp"
#include "core/frame.hpp"
#include "perception/instances.hpp"
#include "perception/segmenter.hpp"

namespace dynanav {

struct PropagationTiming {
  double flow_ms = 0.0;   ///< grey conversion, downscale, DIS
  double warp_ms = 0.0;   ///< flow upscaling and label remap
  double depth_ms = 0.0;  ///< depth correction and boxes
};

class MaskPropagator {
 public:
  explicit MaskPropagator(const PerceptionConfig& config);
  /// The frame and instances to propagate from (a segmented frame, or the last propagated one).
  void setReference(const RgbdFrame& frame, const Instances& instances);
  [[nodiscard]] bool hasReference() const { return !reference_grey_.empty(); }
  /// The reference's instances carried to `frame`; the new frame becomes the reference.
  Instances propagate(const RgbdFrame& frame);
  [[nodiscard]] const PropagationTiming& lastTiming() const { return timing_; }

 private:
  cv::Mat smallGrey(const cv::Mat& bgr) const;

  PerceptionConfig config_;
  cv::Ptr<cv::DISOpticalFlow> dis_;
  cv::Mat reference_grey_;  // at config_.flow_scale
  cv::Mat flow_small_, flow_, map_;  // reused: fresh multi-MB buffers cost page faults per frame
  Instances reference_;
  PropagationTiming timing_;
};

/// Runs a segmenter on every k-th frame and propagates its instances in between.
class PropagatingSegmenter final : public Segmenter {
 public:
  PropagatingSegmenter(std::unique_ptr<Segmenter> inner, int every, const PerceptionConfig& config);
  Instances segment(const RgbdFrame& frame) override;
  [[nodiscard]] std::string name() const override;
  [[nodiscard]] std::map<std::string, double> lastTiming() const override { return timing_; }

 private:
  std::unique_ptr<Segmenter> inner_;
  int every_;
  long calls_ = 0;
  MaskPropagator propagator_;
  std::map<std::string, double> timing_;
};

}  // namespace dynanav
