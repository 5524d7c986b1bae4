#pragma once
// Carrying a late segmentation to the current frame (real-time mode, issue 12). The segmenter
// finishes frame j while the pipeline is already at frame i > j. One DIS flow straight from i
// back to j fails where it matters most: a person close to the camera moves tens of pixels in
// the 3–4 frames of lag, more than the fast preset follows, and the carried mask slides off
// the body, whose keypoints then reach the pose. The carrier keeps the flow between each pair
// of consecutive processed frames (it computes one per frame anyway, to carry the masks from
// frame to frame) and chains them, so j's labels reach i through the same small steps.
#include <deque>
#include <opencv2/video/tracking.hpp>

#include "perception/propagation.hpp"

namespace dynanav {

class MaskCarrier {
 public:
  /// `history_frames`: how many frame-to-frame flows are kept; a segmentation older than that
  /// is carried by one direct flow.
  explicit MaskCarrier(const PerceptionConfig& config, int history_frames = 12);

  /// `frame` was segmented in time: it becomes the reference, the flow history restarts.
  void reset(const RgbdFrame& frame, const Instances& instances);
  /// The newest instances carried to `frame` (frames in sequence order). `arrived`: a
  /// segmentation of the earlier frame `arrived_frame` that finished since the last call.
  Instances carry(const RgbdFrame& frame, const Instances* arrived = nullptr,
                  const RgbdFrame* arrived_frame = nullptr);
  [[nodiscard]] bool hasReference() const { return !grey_.empty(); }
  [[nodiscard]] const PropagationTiming& lastTiming() const { return timing_; }
  /// Arrivals carried by chained flows / by one direct flow (history too short), over the run.
  [[nodiscard]] long chainedArrivals() const { return chained_; }
  [[nodiscard]] long directArrivals() const { return direct_; }

 private:
  struct Step {
    int index = 0;           ///< the frame this flow starts from
    int previous_index = 0;  ///< the processed frame it points back to
    cv::Mat flow;            ///< at flow scale: where each pixel of `index` was in `previous`
  };
  /// Flow from the newest step's frame back to frame `index`, chained through the history;
  /// empty when the history does not reach back to it.
  cv::Mat chainedFlowTo(int index) const;

  PerceptionConfig config_;
  int history_frames_;
  cv::Ptr<cv::DISOpticalFlow> dis_;
  std::deque<Step> steps_;  // oldest first
  cv::Mat grey_;            // the last processed frame, at flow scale
  Instances reference_;     // its instances
  WarpBuffers buffers_;
  PropagationTiming timing_;
  long chained_ = 0;
  long direct_ = 0;
};

}  // namespace dynanav
