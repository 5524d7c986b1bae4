#pragma once
// Instance-mask folders: the simulator's ground-truth format, which `dynanav segment` also writes
// (so its output can be read back with --segmenter masks):
//   SEQ_DIR/masks/<rgb stem>.png  16-bit single-channel PNG, the frame's size; 0 = background,
//                                 k = instance k (the same k means the same object in every frame
//                                 of a simulated sequence)
//   SEQ_DIR/masks.json            {"instances": {"1": {"class": "person"}, "2": {"class": "chair"}}}
// The `masks` segmenter can add noise for robustness tests: grow or shrink masks, drop
// instances in a share of frames, shift masks; from a seeded RNG, per frame and instance, so a
// frame's noise does not depend on which frames were read before it.
#include <filesystem>
#include <map>
#include <random>
#include <string>

#include "perception/segmenter.hpp"

namespace dynanav {

/// Reads SEQ_DIR/masks.json: instance id → class name. InputError naming the file when it is
/// missing or malformed.
std::map<uint16_t, std::string> readMaskClasses(const std::filesystem::path& masks_json);

/// Reads one label PNG into Instances (classes from `classes`, "object" for unknown ids, score 1,
/// boxes from the pixels). InputError naming the file when missing, not 16-bit 1-channel, or of
/// another size than `expected` (empty = any).
Instances readMaskPng(const std::filesystem::path& png, const std::map<uint16_t, std::string>& classes,
                      cv::Size expected = {});

/// Writes label PNGs and, on finish(), masks.json. Frame-local ids are renumbered so that an id
/// keeps one class over the whole folder (the format has one class per id): each instance takes
/// the smallest id of its class not yet used in this frame. Ids are not tracks.
class MaskFolderWriter {
 public:
  explicit MaskFolderWriter(const std::filesystem::path& out_dir);
  /// Writes OUT/masks/<stem>.png; returns the written (renumbered) instances.
  Instances write(const std::string& stem, const Instances& instances);
  /// Writes OUT/masks.json (also done by the destructor if not called).
  void finish();
  ~MaskFolderWriter();

 private:
  std::filesystem::path dir_;
  std::map<uint16_t, std::string> classes_;
  bool finished_ = false;
};

/// Noise added by the `masks` segmenter (PerceptionConfig mask_noise_*).
struct MaskNoise {
  int grow_px = 0;          ///< > 0 dilate, < 0 erode (elliptic kernel)
  double drop_share = 0.0;  ///< probability that an instance is missing from a frame
  int shift_px = 0;         ///< each instance moves by a uniform integer offset in ±shift_px
  int seed = 1;
  [[nodiscard]] bool active() const { return grow_px != 0 || drop_share > 0.0 || shift_px != 0; }
};

/// Applies noise to a frame's instances (deterministic in seed, frame_index and instance id).
Instances addMaskNoise(const Instances& clean, const MaskNoise& noise, int frame_index);

class MaskFileSegmenter final : public Segmenter {
 public:
  /// InputError when SEQ_DIR/masks/ or SEQ_DIR/masks.json is missing.
  MaskFileSegmenter(const std::filesystem::path& sequence_dir, const MaskNoise& noise);
  /// Reads masks/<stem of frame.rgb_path>.png (InputError naming it when missing).
  Instances segment(const RgbdFrame& frame) override;
  [[nodiscard]] std::string name() const override { return "masks"; }

 private:
  std::filesystem::path dir_;
  std::map<uint16_t, std::string> classes_;
  MaskNoise noise_;
};

}  // namespace dynanav
