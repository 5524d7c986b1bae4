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

/// The grey image DIS flow runs on: `bgr` in grey, scaled by `scale` (≥ 1: full size).
cv::Mat flowGrey(const cv::Mat& bgr, double scale);

/// Scratch images reused across frames: fresh multi-MB buffers cost page faults per frame.
struct WarpBuffers {
  cv::Mat flow;  ///< flow at full size
  cv::Mat map;   ///< remap coordinates
};

/// `reference`'s labels pulled into `frame` along `flow_small` (where each pixel of `frame` came
/// from in the reference, at a reduced scale), each instance then cut to the pixels near its
/// depth mode in `frame`. `grow_px` > 0: each instance may also take the pixels up to that far
/// from its carried mask that lie in its depth band (the part of a moving body the flow left
/// behind). Fills timing.warp_ms and timing.depth_ms.
Instances warpInstances(const Instances& reference, const cv::Mat& flow_small,
                        const RgbdFrame& frame, const PerceptionConfig& config,
                        WarpBuffers& buffers, PropagationTiming& timing, int grow_px = 0);

/// Instance `id` in `labels` cut to its depth band and grown by up to `grow_px` into unlabelled
/// pixels of that band (depth mode of the instance's own pixels, `bin_m` histogram bins).
void growWithinDepth(cv::Mat& labels, const cv::Mat& depth_m, uint16_t id, int grow_px,
                     double bin_m, double band_m);

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
  PerceptionConfig config_;
  cv::Ptr<cv::DISOpticalFlow> dis_;
  cv::Mat reference_grey_;  // at config_.flow_scale
  cv::Mat flow_small_;
  WarpBuffers buffers_;
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
