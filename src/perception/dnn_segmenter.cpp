// The `dnn` segmenter (issue 6): Yolo-Fastest boxes → per person box a selfie-model mask,
// refined by depth, with a depth mask as fall-back; other prior classes → depth masks.
#include <algorithm>
#include <chrono>
#include <numeric>
#include <opencv2/core/utility.hpp>
#include <opencv2/imgproc.hpp>

#include "core/timer.hpp"
#include "perception/depth_masks.hpp"
#include "perception/segmenters.hpp"

namespace dynanav {

Instances paintObjects(std::vector<MaskedObject> objects, const cv::Mat& depth_m, cv::Size size,
                       double bin_m) {
  std::vector<float> depth(objects.size(), 0.f);
  for (size_t i = 0; i < objects.size(); ++i)
    if (!depth_m.empty())
      depth[i] = depthMode(depth_m(objects[i].record.box), objects[i].mask_in_box, bin_m);
  std::vector<size_t> order(objects.size());
  std::iota(order.begin(), order.end(), 0);
  // Masks cut from depth alone (objects, fall-backs) go first: they also take whatever else
  // lies at their depth in the box (a person's legs in front of a chair), so a model-made
  // person mask overrides them. Within each group far to near; unknown depth (0) counts as
  // farthest; ties keep input order (deterministic).
  auto fromDepth = [&](size_t i) { return objects[i].record.mask_source == "depth"; };
  auto key = [&](size_t i) { return depth[i] > 0.f ? depth[i] : 1e9f; };
  std::stable_sort(order.begin(), order.end(), [&](size_t a, size_t b) {
    if (fromDepth(a) != fromDepth(b)) return fromDepth(a);
    return key(a) > key(b);
  });

  Instances out = Instances::none(size);
  for (size_t i = 0; i < objects.size(); ++i) objects[i].record.id = uint16_t(i + 1);
  for (size_t i : order) {
    const MaskedObject& o = objects[i];
    out.labels(o.record.box).setTo(cv::Scalar(o.record.id), o.mask_in_box);
  }
  for (auto& o : objects) out.items.push_back(std::move(o.record));
  tightenToLabels(out);  // drops objects fully covered or with empty masks
  return out;
}

DnnSegmenter::PersonModels::PersonModels(const std::filesystem::path& models_dir,
                                         const PerceptionConfig& config)
    : selfie(models_dir, config) {
  if (config.keypoints) keypoints.emplace(models_dir, config);
}

DnnSegmenter::DnnSegmenter(const std::filesystem::path& models_dir, const PerceptionConfig& config)
    : config_(config),
      detector_(makeObjectDetector(models_dir, config)),
      object_classes_(config.object_classes.begin(), config.object_classes.end()) {
  const int lanes = config.parallel_person_models ? 2 : 1;
  lanes_.reserve(lanes);
  for (int i = 0; i < lanes; ++i) lanes_.emplace_back(models_dir, config);
}

std::vector<std::vector<DnnSegmenter::PersonTask>> DnnSegmenter::scheduleLanes(
    const std::vector<MaskedObject>& people) const {
  // Relative single-thread costs measured by bench_perception on idle cores: MoveNet 16.4 ms,
  // selfie mask (with depth refinement) 10.8 ms per person. Longest first, each call to the
  // lane that is free first: two people → each lane runs one MoveNet and one mask.
  constexpr double kKeypointCost = 3.0, kMaskCost = 2.0;
  std::vector<PersonTask> tasks;
  if (config_.keypoints)
    for (size_t p = 0; p < people.size(); ++p)
      if (!people[p].record.keypoints) tasks.push_back({p, true});
  for (size_t p = 0; p < people.size(); ++p) tasks.push_back({p, false});
  std::vector<std::vector<PersonTask>> lanes(lanes_.size());
  std::vector<double> load(lanes_.size(), 0.0);
  for (const PersonTask& t : tasks) {
    const size_t lane = size_t(std::min_element(load.begin(), load.end()) - load.begin());
    lanes[lane].push_back(t);
    load[lane] += t.keypoints ? kKeypointCost : kMaskCost;
  }
  return lanes;
}

cv::Mat DnnSegmenter::personMask(SelfieSegmenter& selfie, const RgbdFrame& frame,
                                 const cv::Rect& box, std::string& source) {
  cv::Mat mask = selfie.maskInBox(frame.bgr, box);
  source = "selfie";
  if (frame.depth_m.empty()) return mask;
  // Keep the person's depth layer: splits two people in one box, trims leaks onto furniture.
  refineMaskByDepth(mask, frame.depth_m(box), config_.depth_bin_m, config_.depth_band_m);
  // The selfie model misses ~6 % of confident boxes (dark clothes, blur, backs; MODELS.md).
  if (cv::countNonZero(mask) < config_.selfie_min_box_share * box.area()) {
    cv::Mat fallback =
        depthMaskInBox(frame.depth_m, box, config_.depth_bin_m, config_.depth_band_m);
    if (cv::countNonZero(fallback) > cv::countNonZero(mask)) {
      source = "depth";
      return fallback;
    }
  }
  return mask;
}

Instances DnnSegmenter::segment(const RgbdFrame& frame) {
  using Clock = std::chrono::steady_clock;
  timing_.clear();
  const std::vector<Detection> detections = detector_->detect(frame.bgr);
  const DetectorTiming& dt = detector_->lastTiming();
  timing_["detect_pre"] = dt.preprocess_ms;
  timing_["detect_forward"] = dt.forward_ms;
  timing_["detect_post"] = dt.postprocess_ms;

  // Objects first (cheap depth masks), then the people's network calls, spread over two
  // parallel lanes. cv::parallel_for_ runs nested loops serially, so each network then uses one
  // thread and no time goes into per-layer synchronisation of two threads (docs/perception.md).
  auto t0 = Clock::now();
  std::vector<MaskedObject> objects;
  std::vector<MaskedObject> people;
  for (const Detection& d : detections) {
    MaskedObject o;
    o.record.class_name = d.class_name;
    o.record.score = d.score;
    o.record.box = d.box;
    if (d.class_id == 0) {
      if (d.score < config_.person_min_score || d.box.height < config_.person_min_height_px)
        continue;
      if (config_.keypoints) o.record.keypoints = d.keypoints;  // MultiPose finds them with the box
      people.push_back(std::move(o));
    } else if (object_classes_.count(d.class_name) && !frame.depth_m.empty()) {
      o.mask_in_box =
          depthMaskInBox(frame.depth_m, d.box, config_.depth_bin_m, config_.depth_band_m);
      o.record.mask_source = "depth";
      objects.push_back(std::move(o));
    }
  }
  timing_["object_masks"] = msSince(t0);

  t0 = Clock::now();
  const std::vector<std::vector<PersonTask>> schedule = scheduleLanes(people);
  std::vector<double> masks_ms(schedule.size(), 0.0), keypoints_ms(schedule.size(), 0.0);
  auto runLane = [&](size_t lane) {
    PersonModels& models = lanes_[lane];
    for (const PersonTask& t : schedule[lane]) {
      const auto start = Clock::now();
      MaskedObject& p = people[t.person];
      if (t.keypoints) {
        p.record.keypoints = models.keypoints->detect(frame.bgr, p.record.box);
        keypoints_ms[lane] += msSince(start);
      } else {
        p.mask_in_box = personMask(models.selfie, frame, p.record.box, p.record.mask_source);
        masks_ms[lane] += msSince(start);
      }
    }
  };
  if (schedule.size() > 1 && !people.empty()) {
    cv::parallel_for_(
        cv::Range(0, int(schedule.size())),
        [&](const cv::Range& r) {
          for (int lane = r.start; lane < r.end; ++lane) runLane(size_t(lane));
        },
        double(schedule.size()));
  } else {
    for (size_t lane = 0; lane < schedule.size(); ++lane) runLane(lane);
  }
  timing_["person_models"] = msSince(t0);
  // People take the first ids.
  for (MaskedObject& o : objects) people.push_back(std::move(o));
  // Summed over lanes: the time of all people's masks (keypoints), whichever lane ran them.
  timing_["masks"] = std::accumulate(masks_ms.begin(), masks_ms.end(), 0.0);
  timing_["keypoints"] = std::accumulate(keypoints_ms.begin(), keypoints_ms.end(), 0.0);
  t0 = Clock::now();
  Instances out =
      paintObjects(std::move(people), frame.depth_m, frame.bgr.size(), config_.depth_bin_m);
  timing_["paint"] = msSince(t0);
  return out;
}

HogSegmenter::HogSegmenter(const PerceptionConfig& config) : config_(config) {
  hog_.setSVMDetector(cv::HOGDescriptor::getDefaultPeopleDetector());
}

Instances HogSegmenter::segment(const RgbdFrame& frame) {
  using Clock = std::chrono::steady_clock;
  timing_.clear();
  auto t0 = Clock::now();
  // Half resolution: people near a head-worn camera are tall, and HOG costs 4× less.
  constexpr double kScale = 0.5;
  cv::Mat small;
  cv::resize(frame.bgr, small, cv::Size(), kScale, kScale, cv::INTER_AREA);
  std::vector<cv::Rect> found;
  std::vector<double> weights;
  hog_.detectMultiScale(small, found, weights, 0.0, cv::Size(8, 8), cv::Size(), 1.05, 2.0);
  timing_["detect"] = msSince(t0);

  t0 = Clock::now();
  std::vector<MaskedObject> objects;
  const cv::Rect image(0, 0, frame.bgr.cols, frame.bgr.rows);
  for (size_t i = 0; i < found.size(); ++i) {
    const cv::Rect& r = found[i];
    const cv::Rect box = cv::Rect(cvRound(r.x / kScale), cvRound(r.y / kScale),
                                  cvRound(r.width / kScale), cvRound(r.height / kScale)) &
                         image;
    if (box.area() == 0 || frame.depth_m.empty()) continue;  // HOG boxes need depth for a mask
    MaskedObject o;
    o.record.class_name = "person";
    o.record.score = float(std::clamp(i < weights.size() ? weights[i] : 1.0, 0.0, 1.0));
    o.record.box = box;
    o.record.mask_source = "depth";
    o.mask_in_box = depthMaskInBox(frame.depth_m, box, config_.depth_bin_m, config_.depth_band_m);
    objects.push_back(std::move(o));
  }
  Instances out =
      paintObjects(std::move(objects), frame.depth_m, frame.bgr.size(), config_.depth_bin_m);
  timing_["masks"] = msSince(t0);
  return out;
}

}  // namespace dynanav
