#pragma once
// Where frames come from (DESIGN.md §1, FrameSource): a TUM/Bonn folder, the simulator's output
// (the same layout), an OpenNI2 camera or .oni recording (device_source.hpp). A source yields
// frames in order; frames it cannot read are skipped, logged and counted, never fatal.
#include <algorithm>
#include <filesystem>
#include <future>
#include <memory>
#include <optional>
#include <string>
#include <utility>

#include "core/camera.hpp"
#include "core/config.hpp"
#include "core/frame.hpp"
#include "io/sequence.hpp"

namespace dynanav {

class FrameSource {
 public:
  virtual ~FrameSource() = default;
  /// The next readable frame in order, or nullopt at the end.
  virtual std::optional<RgbdFrame> next() = 0;
  /// Frames the source expects to deliver (0 = unknown, e.g. a live camera).
  [[nodiscard]] virtual size_t expected() const = 0;
  /// Frames skipped so far because they could not be read.
  [[nodiscard]] virtual int skipped() const = 0;
  [[nodiscard]] virtual const PinholeCamera& camera() const = 0;
  /// For logs and errors: where the frames come from.
  [[nodiscard]] virtual std::string describe() const = 0;
  /// For the log: where the intrinsics came from ("camera.yaml", "device field of view", ...).
  [[nodiscard]] virtual std::string cameraSource() const { return "the source"; }
  /// Why the frames stopped before their end ("" = they did not; a signal is not a failure).
  [[nodiscard]] virtual std::string failure() const { return {}; }
};

struct SequenceSourceOptions {
  std::filesystem::path dir;
  IoConfig io;
  std::optional<PinholeCamera> fallback_camera;  ///< used when the folder says nothing
  std::optional<std::pair<int, int>> blackout;   ///< inclusive 0-based frame range made black
  int max_frames = 0;                            ///< 0 = all (per pass)
  int passes = 1;  ///< > 1: play the sequence again and again (a long-run test); time keeps running
};

/// A TUM-layout folder (TUM, Bonn, `dynanav simulate` output). Decoding the next frame's images
/// overlaps with processing this one (a pure function of the files: deterministic). A blackout
/// range is replaced by black images with invalid depth (a tracking-loss drill).
class SequenceSource final : public FrameSource {
 public:
  /// Throws InputError for a missing folder, bad lists or no camera.
  explicit SequenceSource(const SequenceSourceOptions& options);
  std::optional<RgbdFrame> next() override;
  [[nodiscard]] size_t expected() const override {
    return total_ * size_t(std::max(1, options_.passes));
  }
  [[nodiscard]] int skipped() const override { return skipped_; }
  [[nodiscard]] const PinholeCamera& camera() const override { return sequence_.camera(); }
  [[nodiscard]] std::string describe() const override;
  [[nodiscard]] std::string cameraSource() const override { return sequence_.cameraSource(); }
  [[nodiscard]] const TumSequence& sequence() const { return sequence_; }

 private:
  void prefetch();

  SequenceSourceOptions options_;
  TumSequence sequence_;
  size_t total_ = 0;     // frames per pass
  size_t position_ = 0;  // index (within the pass) of the frame being prefetched
  int pass_ = 0;
  double pass_span_s_ = 0.0;  // a pass's duration plus one frame interval
  int skipped_ = 0;
  std::future<RgbdFrame> next_;
};

}  // namespace dynanav
