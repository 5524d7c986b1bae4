#pragma once
// Config section `perception` (see core/config.hpp for how sections are loaded and echoed).
// To add a tunable: the member with its default, and one v("key", member, "doc", valid) line in
// visit(); `valid` (core/config/range.hpp) is the documented range the loader enforces.
// Which segmenter runs and how often are run-level choices (RunConfig::segmenter, segment_every).
#include "core/config/range.hpp"

#include <string>
#include <vector>

namespace dynanav {

/// Segmentation and keypoints.
struct PerceptionConfig {
  std::string models_dir;  // empty = search $DYNANAV_MODELS, then ../shared/models
  int threads = 2;         // cv::setNumThreads for the DNN and flow stages (0 = OpenCV default)

  // Detector (Yolo-Fastest-1.1-xl, MODELS.md).
  int detector_input_px = 320;
  double detector_min_score = 0.3;
  double detector_nms_iou = 0.45;
  double person_min_score = 0.35;
  double min_box_height_px = 24.0;
  double person_min_height_px = 72.0;
  std::vector<std::string> object_classes{"bicycle",  "car",      "motorbike", "cat",      "dog",
                                          "backpack", "umbrella", "handbag",   "suitcase", "chair"};

  // Person masks (MediaPipe selfie segmentation on a square crop per box).
  double selfie_crop_scale = 1.25;
  double selfie_threshold = 0.5;
  double selfie_min_box_share = 0.2;

  // Depth refinement and depth-only masks.
  double depth_band_m = 0.5;
  double depth_bin_m = 0.05;

  // Keypoints (MoveNet Lightning per person box).
  bool keypoints = false;
  double keypoint_crop_scale = 1.15;
  bool parallel_person_models = true;
  int segmenter_nice = 0;

  // Propagation between segmented frames (DIS optical flow).
  double flow_scale = 0.5;
  double propagation_depth_band_m = 0.6;
  int mask_memory_frames = 2;
  int carry_history_frames = 12;
  int emulated_lag_frames = 0;
  std::string replay_arrivals;  // a real-time run's stats.json (empty: off)
  int carry_grow_px = 4;

  // Noise injection for the `masks` segmenter (robustness tests; all off by default).
  int mask_noise_grow_px = 0;
  double mask_noise_drop_share = 0.0;
  int mask_noise_shift_px = 0;
  int mask_noise_seed = 1;

  template <class V>
  void visit(V&& v) {
    v("models_dir", models_dir,
      "folder with the model files (empty: $DYNANAV_MODELS, ../shared/models)");
    v("threads", threads,
      "OpenCV threads for DNN and flow (cv::setNumThreads; 0 = OpenCV's default)", Range{0, 256});
    v("detector_input_px", detector_input_px, "Yolo-Fastest input side (px); 320 as trained",
      Range{64, 1024});
    v("detector_min_score", detector_min_score, "detections below this class score are dropped",
      Range{0, 1});
    v("detector_nms_iou", detector_nms_iou, "non-maximum suppression IoU per class", Range{0, 1});
    v("person_min_score", person_min_score, "person boxes below this score are not segmented",
      Range{0, 1});
    v("min_box_height_px", min_box_height_px, "boxes lower than this (px) are ignored",
      Range{0, 10000});
    v("person_min_height_px", person_min_height_px,
      "person boxes lower than this (px) are ignored (Bonn's ceiling marker is a 26x40 px "
      "'person'; "
      "a 1.7 m person 10 m away is ~90 px tall)",
      Range{0, 10000});
    v("object_classes", object_classes, "COCO classes besides person that get depth masks");
    v("selfie_crop_scale", selfie_crop_scale,
      "square crop side / longer box side for the selfie model", Range{1, 4});
    v("selfie_threshold", selfie_threshold, "selfie probability above which a pixel is person",
      Range{0, 1});
    v("selfie_min_box_share", selfie_min_box_share,
      "a selfie mask covering less of its box than this falls back to the depth mask", Range{0, 1});
    v("depth_band_m", depth_band_m,
      "pixels farther than this from an instance's depth mode are dropped (m)",
      Range{0, 100, Range::kOpenLow});
    v("depth_bin_m", depth_bin_m, "histogram bin for the depth mode (m)",
      Range{0, 10, Range::kOpenLow});
    v("keypoints", keypoints,
      "run MoveNet on person boxes (shoulders, hips); off by default: no stage of `run` needs "
      "them and they cost ~30 % of dnn segmentation (docs/pipeline.md)");
    v("segmenter_nice", segmenter_nice,
      "real time: nice value of the segmenter thread; higher yields to tracking but starves the "
      "segmenter, whose masks then arrive late (at 10: up to 25 frames, paced Bonn ATE ~5x "
      "worse; docs/pipeline.md)",
      Range{0, 19});
    v("keypoint_crop_scale", keypoint_crop_scale, "square crop side / longer box side for MoveNet",
      Range{1, 4});
    v("parallel_person_models", parallel_person_models,
      "spread the people's selfie and MoveNet calls over two single-thread lanes (else in turn, "
      "each on all threads)");
    v("flow_scale", flow_scale, "image scale at which DIS flow is computed for propagation",
      Range{0, 1, Range::kOpenLow});
    v("mask_memory_frames", mask_memory_frames,
      "an instance the segmenter loses is carried by optical flow for up to this many frames (0 = "
      "off)",
      Range{0, 1000});
    v("carry_history_frames", carry_history_frames,
      "frame-to-frame flows kept to carry a late segmentation to the current frame by chaining "
      "them (real time); a segmentation older than this is carried by one direct flow "
      "(1: always direct)",
      Range{1, 64});
    v("carry_grow_px", carry_grow_px,
      "a carried mask also takes pixels up to this far (px) from it that lie in its depth band: "
      "the part of a moving body a late mask has not reached (0: off)",
      Range{0, 100});
    v("replay_arrivals", replay_arrivals,
      "deterministic replay of a real-time run's segmentations: its stats.json, whose "
      "segmentation_arrivals say which frames were segmented and on which frame each result "
      "arrived (empty: off; ignored with --realtime)");
    v("emulated_lag_frames", emulated_lag_frames,
      "deterministic replay of real-time segmentation: frame s's masks are used from frame s+N "
      "on, carried by flow, the next segmentation starting there (0: off; ignored with "
      "--realtime)",
      Range{0, 100});
    v("propagation_depth_band_m", propagation_depth_band_m,
      "propagated pixels farther than this from the instance's depth mode are dropped (m)",
      Range{0, 100, Range::kOpenLow});
    v("mask_noise_grow_px", mask_noise_grow_px, "masks segmenter: dilate (>0) or erode (<0) by px",
      Range{-100, 100});
    v("mask_noise_drop_share", mask_noise_drop_share,
      "masks segmenter: share of frames an instance is dropped", Range{0, 1});
    v("mask_noise_shift_px", mask_noise_shift_px,
      "masks segmenter: shift masks by up to px in x and y", Range{0, 100});
    v("mask_noise_seed", mask_noise_seed, "masks segmenter: seed of the noise RNG",
      Range{0, 2147483647});
  }
};

}  // namespace dynanav
