#pragma once
// A deterministic replay of real-time segmentation (issue 12): the segmentation of frame s is
// used from frame s + lag on, carried there by chained flow, and the next segmentation starts
// on that frame, exactly as AsyncSegmenter behaves when its worker needs `lag` frames per call.
// It makes the accuracy cost of late masks measurable without threads or timing noise
// (`perception.emulated_lag_frames`); the first frame is segmented in time, as in real time.
#include <memory>
#include <optional>

#include "perception/mask_carrier.hpp"

namespace dynanav {

class LaggedSegmenter final : public Segmenter {
 public:
  LaggedSegmenter(std::unique_ptr<Segmenter> inner, int lag_frames, const PerceptionConfig& config);
  Instances segment(const RgbdFrame& frame) override;
  [[nodiscard]] std::string name() const override;
  [[nodiscard]] std::map<std::string, double> lastTiming() const override { return timing_; }

 private:
  struct InFlight {
    RgbdFrame frame;  // shallow: the carrier only reads its index and, rarely, its image
    Instances instances;
    int ready_at = 0;  // the frame index from which the result is used
  };

  std::unique_ptr<Segmenter> inner_;
  int lag_frames_;
  MaskCarrier carrier_;
  std::optional<InFlight> in_flight_;
  bool started_ = false;
  std::map<std::string, double> timing_;
};

}  // namespace dynanav
