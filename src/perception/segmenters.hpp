#pragma once
// The concrete segmenters behind makeSegmenter(); declared here for tests and benchmarks.
#include <opencv2/objdetect.hpp>
#include <optional>
#include <set>

#include "perception/box_models.hpp"
#include "perception/detector.hpp"
#include "perception/segmenter.hpp"

namespace dynanav {

/// One object before painting: its record and its mask (CV_8U, the size of record.box).
struct MaskedObject {
  Instance record;
  cv::Mat mask_in_box;
};

/// Paints objects into one label image: masks cut from depth alone first, then model-made
/// masks; within each group far ones first so that nearer objects occlude them (depth order
/// from each mask's depth mode; objects without depth go first). Ids 1..N in input order;
/// objects whose mask ends up empty are dropped.
Instances paintObjects(std::vector<MaskedObject> objects, const cv::Mat& depth_m, cv::Size size,
                       double bin_m);

class DnnSegmenter final : public Segmenter {
 public:
  DnnSegmenter(const std::filesystem::path& models_dir, const PerceptionConfig& config);
  Instances segment(const RgbdFrame& frame) override;
  [[nodiscard]] std::string name() const override { return "dnn"; }
  [[nodiscard]] std::map<std::string, double> lastTiming() const override { return timing_; }

 private:
  /// The per-box networks of one worker: a cv::dnn::Net must not run in two threads at once,
  /// so each parallel lane has its own copy (the selfie model is 0.45 MB, MoveNet 9.4 MB).
  struct PersonModels {
    PersonModels(const std::filesystem::path& models_dir, const PerceptionConfig& config);
    SelfieSegmenter selfie;
    std::optional<KeypointDetector> keypoints;
  };
  /// One network call for one person, run by one lane.
  struct PersonTask {
    size_t person = 0;
    bool keypoints = false;  ///< MoveNet, else the selfie mask
  };

  cv::Mat personMask(SelfieSegmenter& selfie, const RgbdFrame& frame, const cv::Rect& box,
                     std::string& source);
  /// Longest-first assignment of the people's network calls to the lanes (deterministic).
  /// People whose detection brought keypoints (MultiPose) need no MoveNet call.
  [[nodiscard]] std::vector<std::vector<PersonTask>> scheduleLanes(
      const std::vector<MaskedObject>& people) const;

  PerceptionConfig config_;
  std::unique_ptr<ObjectDetector> detector_;  ///< Yolo-Fastest, or MultiPose with npm models only
  std::vector<PersonModels> lanes_;           ///< 2 with parallel_person_models, else 1
  std::set<std::string> object_classes_;
  std::map<std::string, double> timing_;
};

class HogSegmenter final : public Segmenter {
 public:
  explicit HogSegmenter(const PerceptionConfig& config);
  Instances segment(const RgbdFrame& frame) override;
  [[nodiscard]] std::string name() const override { return "hog"; }
  [[nodiscard]] std::map<std::string, double> lastTiming() const override { return timing_; }

 private:
  PerceptionConfig config_;
  cv::HOGDescriptor hog_;
  std::map<std::string, double> timing_;
};

class NoneSegmenter final : public Segmenter {
 public:
  Instances segment(const RgbdFrame& frame) override { return Instances::none(frame.bgr.size()); }
  [[nodiscard]] std::string name() const override { return "none"; }
};

}  // namespace dynanav
