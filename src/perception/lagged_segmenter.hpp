#pragma once
// A deterministic replay of real-time segmentation (issue 12): the segmentation of frame s is
// used from frame s + lag on, carried there by chained flow, and the next segmentation starts
// on that frame, exactly as AsyncSegmenter behaves when its worker needs `lag` frames per call.
// It makes the accuracy cost of late masks measurable without threads or timing noise
// (`perception.emulated_lag_frames`); the first frame is segmented in time, as in real time.
// With a schedule (`perception.replay_arrivals`: a real-time run's stats.json) it replays that
// run's own arrivals instead: which frames were segmented and on which frame each result came.
#include <map>
#include <memory>
#include <optional>
#include <vector>

#include "perception/mask_carrier.hpp"

namespace dynanav {

class LaggedSegmenter final : public Segmenter {
 public:
  LaggedSegmenter(std::unique_ptr<Segmenter> inner, int lag_frames, const PerceptionConfig& config);
  /// Replays `arrivals`: segmented frame index → the frame index its result arrived on.
  LaggedSegmenter(std::unique_ptr<Segmenter> inner, std::map<int, int> arrivals,
                  const PerceptionConfig& config);
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
  std::vector<InFlight> in_flight_;  // started, not yet due (in start order)
  std::map<int, int> arrivals_;      // replay: segmented index → arrival index (empty: fixed lag)
  bool started_ = false;
  std::map<std::string, double> timing_;
};

}  // namespace dynanav
