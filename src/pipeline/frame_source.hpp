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
  /// > 1: play the sequence again and again (a long-run test), alternately forward and backward
  /// (passStep), time running on (passStamp).
  int passes = 1;
};

/// Where the frame delivered in place `delivered` (0-based over all passes) comes from when a
/// sequence of `per_pass` frames is played in passes. Passes alternate direction (forward,
/// backward, forward, ...) so that the camera path stays continuous: replaying from the start
/// would teleport the camera from the last pose to the first between two frames, which no camera
/// does and which a tracker may follow as a small move, mapping the same images again elsewhere.
/// A backward pass starts with the frame the forward pass ended on: the camera holds still for
/// one frame interval, then retraces its path.
struct PassStep {
  int pass = 0;
  size_t index = 0;  ///< 0-based frame of the sequence
  bool backward = false;
};
PassStep passStep(size_t delivered, size_t per_pass);

/// The stamp (s) that a sequence stamp `stamp_s` gets in pass `pass` of a sequence spanning
/// `first_s`..`last_s`: each pass starts `span_s` after the one before (the sequence's duration
/// plus one frame interval); a backward pass mirrors the stamps, so intervals between frames are
/// the recorded ones, in reverse, and stamps keep increasing.
double passStamp(double stamp_s, const PassStep& step, double first_s, double last_s,
                 double span_s);

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
  size_t total_ = 0;                     // frames per pass
  size_t delivered_ = 0;                 // place (over all passes) of the frame being prefetched
  double first_s_ = 0.0, last_s_ = 0.0;  // stamps of a pass's first and last frames
  double pass_span_s_ = 0.0;             // a pass's duration plus one frame interval
  int skipped_ = 0;
  std::future<RgbdFrame> next_;
};

}  // namespace dynanav
