#pragma once
// TUM RGB-D layout reader (TUM and Bonn): rgb.txt, depth.txt, rgb/, depth/, optional
// groundtruth.txt and camera.yaml. Colour and depth are associated by nearest timestamp within
// IoConfig::max_association_dt_s, greedily by smallest gap as TUM's associate.py does.
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "core/camera.hpp"
#include "core/config.hpp"
#include "core/frame.hpp"

namespace dynanav {

/// One line of rgb.txt or depth.txt.
struct StampedFile {
  double stamp_s = 0.0;
  std::string relative_path;
  int line = 0;  ///< 1-based line in the list file (for error messages)
};

/// An associated colour/depth pair.
struct FramePair {
  StampedFile rgb;
  StampedFile depth;
};

/// Parses a TUM list file ("timestamp path" per line; '#' comments, blank lines, CRLF allowed).
/// Throws InputError naming file and line for malformed, unsorted or duplicate timestamps.
std::vector<StampedFile> readStampedFileList(const std::filesystem::path& list_file);

/// Greedy nearest-timestamp association (associate.py, offset 0): pairs sorted by colour time.
std::vector<FramePair> associate(const std::vector<StampedFile>& rgb,
                                 const std::vector<StampedFile>& depth, double max_dt_s);

/// Reads a 16-bit depth PNG into metres (CV_32F, 0 = invalid). Throws InputError on a missing
/// or corrupt file, or a wrong type or size (expected_size empty = any size).
cv::Mat readDepthPng(const std::filesystem::path& path, double depth_factor,
                     cv::Size expected_size = {});
/// Writes metres as a 16-bit PNG (0 for invalid or out of range).
void writeDepthPng(const std::filesystem::path& path, const cv::Mat& depth_m, double depth_factor);

class TumSequence {
 public:
  /// Opens SEQ_DIR. The camera comes from SEQ_DIR/camera.yaml, else the folder name
  /// (freiburg1|2|3, bonn), else `fallback_camera`; with none of them it throws InputError.
  static TumSequence open(const std::filesystem::path& dir, const IoConfig& config,
                          const std::optional<PinholeCamera>& fallback_camera = std::nullopt);

  [[nodiscard]] size_t size() const { return pairs_.size(); }
  [[nodiscard]] const std::vector<FramePair>& pairs() const { return pairs_; }
  [[nodiscard]] const PinholeCamera& camera() const { return camera_; }
  [[nodiscard]] const std::filesystem::path& dir() const { return dir_; }
  /// Where the camera came from: "camera.yaml", "folder name", "config".
  [[nodiscard]] const std::string& cameraSource() const { return camera_source_; }
  /// groundtruth.txt if present.
  [[nodiscard]] std::optional<std::filesystem::path> groundTruthPath() const;

  /// Loads frame i. Throws InputError (naming the file) when an image is missing, empty,
  /// truncated, corrupt, of the wrong type or size, when the colour image is all black,
  /// saturated or flat, or when no depth pixel is valid; callers that can go on count and log
  /// the skip (SequenceSource: stats.json `skipped_corrupt`).
  [[nodiscard]] RgbdFrame load(size_t i) const;

 private:
  std::filesystem::path dir_;
  PinholeCamera camera_;
  std::string camera_source_;
  std::vector<FramePair> pairs_;
};

}  // namespace dynanav
