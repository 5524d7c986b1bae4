#pragma once
// Scoring a segmenter's person masks (dynanav segment's OUT/masks/) against a simulated
// sequence's exact ground truth (SIM/masks/, SIM/objects_gt.jsonl): does the segmenter find
// each person who is clearly in view, and how well does its mask fit?
//
// A person is scored in a frame ("eligible") when at least `min_in_view` of its silhouette shows
// (objects_gt `in_view`: visible pixels over the pixels it would cover alone, unoccluded, on an
// unbounded image) and its visible mask is at least `min_height_px` rows tall. It is found when
// some person instance of the segmenter overlaps it with IoU >= `match_iou`; its IoU is that of
// the best-overlapping person instance (0 when there is none).
#include <filesystem>
#include <opencv2/core.hpp>
#include <set>
#include <string>
#include <vector>

namespace dynanav {

struct MaskScoreOptions {
  double min_in_view = 0.3;
  int min_height_px = 100;
  double match_iou = 0.5;
};

struct PersonMaskScore {
  std::string stem;  ///< frame (image stem)
  int id = 0;        ///< ground-truth instance id
  double in_view = 0.0;
  int height_px = 0;
  double iou = 0.0;  ///< best IoU with a segmented person instance
};

struct MaskScoreSummary {
  int frames = 0;                       ///< frames read
  std::vector<PersonMaskScore> scored;  ///< every eligible (frame, person)
  int found = 0;                        ///< scored with iou >= match_iou
  double median_iou_found = 0.0;        ///< over the found ones (0 when none)
  double median_iou_all = 0.0;          ///< over every scored one, misses counted as 0
  [[nodiscard]] double recall() const {
    return scored.empty() ? 0.0 : double(found) / double(scored.size());
  }
};

/// Best IoU between the ground-truth mask (CV_8U, non-zero = the person) and any instance of
/// `labels` (CV_16U instance ids) whose id is in `person_ids`; 0 when none overlaps.
double bestPersonIou(const cv::Mat& truth_mask, const cv::Mat& labels,
                     const std::set<uint16_t>& person_ids);

/// Reads both folders and scores every frame of the simulated sequence. InputError when a file
/// is missing or malformed (e.g. a segment run over fewer frames).
MaskScoreSummary scorePersonMasks(const std::filesystem::path& sim_dir,
                                  const std::filesystem::path& segmentation_dir,
                                  const MaskScoreOptions& options = {});

}  // namespace dynanav
