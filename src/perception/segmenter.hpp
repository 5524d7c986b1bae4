#pragma once
// The segmenter interface and its factory (DESIGN.md §1, perception). Providers:
//   dnn   — Yolo-Fastest boxes, a selfie-model mask per person box, depth masks for objects
//   hog   — OpenCV's built-in people detector + depth masks (needs no model files)
//   masks — precomputed instance PNGs (the simulator's ground truth, or `dynanav segment` output)
//   none  — no instances
//   auto  — dnn when its model files are found, else hog (logged)
#include <filesystem>
#include <map>
#include <memory>
#include <string>

#include "core/config/perception.hpp"
#include "core/frame.hpp"
#include "perception/instances.hpp"

namespace dynanav {

class Segmenter {
 public:
  virtual ~Segmenter() = default;
  /// Instances of one frame; labels have the frame's size. Frames must come in sequence order
  /// (a propagating segmenter carries masks from the previous call).
  virtual Instances segment(const RgbdFrame& frame) = 0;
  /// The provider's name ("dnn", "hog", "masks", "none"; "dnn/every3" when propagating).
  [[nodiscard]] virtual std::string name() const = 0;
  /// Milliseconds per step of the last segment() call, e.g. {"detect": 12.1, "masks": 9.0}.
  [[nodiscard]] virtual std::map<std::string, double> lastTiming() const { return {}; }
};

struct SegmenterRequest {
  std::string name = "auto";           ///< auto | dnn | hog | masks | none
  int segment_every = 1;               ///< k > 1: segment every k-th frame, propagate between
  std::filesystem::path sequence_dir;  ///< for `masks`: SEQ_DIR holding masks/ and masks.json
};

/// Builds a segmenter. Throws InputError for an unknown name, a missing model file (naming
/// it), or a missing masks folder. `auto` logs which provider it chose and why.
std::unique_ptr<Segmenter> makeSegmenter(const SegmenterRequest& request, const PerceptionConfig& config);

}  // namespace dynanav
