#pragma once
// Instance memory: a person or a pushed box does not vanish for one frame, but a segmenter's
// output can (a missed detection, an empty mask, a dropped ground-truth mask). When an instance of
// the last frame has no counterpart now (same class, overlapping box), its mask is carried into
// this frame by DIS flow (MaskPropagator, depth-corrected) for up to `mask_memory_frames` frames,
// filling only pixels no fresh instance claims. Without it the lost object's keypoints reach the
// initial pose in that frame (issue 7: pushed box with 20 % of the masks dropped).
#include <map>
#include <memory>

#include "perception/propagation.hpp"
#include "perception/segmenter.hpp"

namespace dynanav {

class RememberingSegmenter final : public Segmenter {
 public:
  RememberingSegmenter(std::unique_ptr<Segmenter> inner, int memory_frames,
                       const PerceptionConfig& config);
  Instances segment(const RgbdFrame& frame) override;
  [[nodiscard]] std::string name() const override { return inner_->name(); }
  /// The wrapped segmenter's steps plus "memory" (ms spent carrying lost instances).
  [[nodiscard]] std::map<std::string, double> lastTiming() const override { return timing_; }
  /// Instances carried into the last frame (counted over the run).
  [[nodiscard]] long carriedCount() const { return carried_total_; }

 private:
  std::unique_ptr<Segmenter> inner_;
  int memory_frames_;
  MaskPropagator propagator_;
  std::vector<Instance> last_items_;
  std::map<uint16_t, int> carried_frames_;  ///< id in the last output → frames it has been carried
  std::map<std::string, double> timing_;
  long carried_total_ = 0;
};

/// Whether `fresh` holds an instance of `old`'s class whose box overlaps old's box by at least
/// `min_iou` (the same object, seen again).
bool hasCounterpart(const Instance& old, const Instances& fresh, double min_iou);

}  // namespace dynanav
