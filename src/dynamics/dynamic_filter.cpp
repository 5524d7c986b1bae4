#include "dynamics/dynamic_filter.hpp"

#include <algorithm>
#include <deque>
#include <opencv2/imgproc.hpp>
#include <opencv2/video/tracking.hpp>

#include "dynamics/scene_flow.hpp"

namespace dynanav {

/// Recent frames (grey image, depth, instances, pose) for scene flow over a few frames.
struct DynamicFilter::Previous {
  struct Snapshot {
    cv::Mat grey_small;
    cv::Mat depth_m;
    Instances instances;
    SE3 T_camera_world = SE3::Identity();
    bool tracked = false;
  };
  std::deque<Snapshot> frames;  // oldest first, at most scene_flow_gap_frames
  cv::Mat moving_mask;          // CV_8U: non-prior instances found moving in the last frame
  cv::Ptr<cv::DISOpticalFlow> dis = cv::DISOpticalFlow::create(cv::DISOpticalFlow::PRESET_ULTRAFAST);
};

namespace {
constexpr double kFlowScale = 0.5;  // scene flow on half-size images: 4x cheaper, plenty for 5 px samples

cv::Mat greySmall(const cv::Mat& bgr) {
  cv::Mat grey, small;
  if (bgr.channels() == 3) cv::cvtColor(bgr, grey, cv::COLOR_BGR2GRAY);
  else grey = bgr;
  cv::resize(grey, small, cv::Size(), kFlowScale, kFlowScale, cv::INTER_AREA);
  return small;
}
}  // namespace

DynamicFilter::DynamicFilter(const Config& config, const std::filesystem::path& sequence_dir, StageTimers* timers)
    : config_(config), enabled_(config.run.dynamic), timers_(timers), previous_(std::make_unique<Previous>()) {
  if (!enabled_) return;
  SegmenterRequest request;
  request.name = config.run.segmenter;
  request.segment_every = std::max(1, config.run.segment_every);
  request.sequence_dir = sequence_dir;
  segmenter_ = makeSegmenter(request, config.perception);
  segmenter_name_ = segmenter_->name();
}

DynamicFilter::~DynamicFilter() = default;

Instances DynamicFilter::segment(const RgbdFrame& input) {
  current_ = FrameDynamics{};
  depth_voted_.clear();
  current_depth_m_ = input.depth_m;
  if (!enabled_) return Instances::none(input.bgr.size());
  std::optional<ScopedTimer> timer;
  if (timers_) timer.emplace(*timers_, "segmentation");
  Instances instances = segmenter_->segment(input);
  for (const Instance& instance : instances.items)
    current_.prior_instances += isPriorDynamic(instance, config_.dynamics) ? 1 : 0;
  return instances;
}

cv::Mat DynamicFilter::extractionMask(const Instances& instances) {
  if (!enabled_) return {};
  cv::Mat allowed = staticExtractionMask(instances, config_.dynamics, current_depth_m_);
  // A non-prior object found moving in the last frame (scene flow or depth vote) is still
  // moving now: cut it out before its keypoints reach the pose or the map.
  const cv::Mat& moving = previous_->moving_mask;
  if (!moving.empty() && moving.size() == instances.labels.size()) {
    for (const Instance& instance : instances.items) {
      if (isPriorDynamic(instance, config_.dynamics)) continue;
      const cv::Mat mask = instances.labels == instance.id;
      const int area = cv::countNonZero(mask);
      if (area == 0 || cv::countNonZero(mask & moving) < area / 2) continue;
      if (allowed.empty()) allowed = cv::Mat(instances.labels.size(), CV_8U, cv::Scalar(255));
      allowed.setTo(0, mask);
      current_.moving_ids.push_back(instance.id);
      ++current_.moving_instances;
    }
  }
  if (!allowed.empty())
    current_.masked_share = 1.0 - double(cv::countNonZero(allowed)) / double(allowed.total());
  return allowed;
}

void DynamicFilter::labelKeypoints(Frame& frame, const Instances& instances) const {
  if (enabled_) dynanav::labelKeypoints(frame.features, instances.labels);
}

void DynamicFilter::rejectMovers(Frame& frame) {
  if (!enabled_) return;
  const MoverRejection r = rejectDepthMovers(frame, config_.dynamics);
  current_.dynamic_keypoints += r.rejected;
  current_.culled_points += r.culled;
  current_.moving_instances += static_cast<int>(r.moving_instances.size());
  current_.moving_ids.insert(current_.moving_ids.end(), r.moving_instances.begin(), r.moving_instances.end());
  depth_voted_ = r.moving_instances;
}


void DynamicFilter::verifyPriors(const RgbdFrame& input, const Instances& instances, const Frame& frame,
                                 bool tracked) {
  if (!enabled_) return;
  current_.keypoints = frame.size();
  for (int i = 0; i < frame.size(); ++i) current_.static_keypoints += frame.features.usable[i] ? 1 : 0;
  std::optional<ScopedTimer> timer;
  if (timers_) timer.emplace(*timers_, "scene_flow");
  Previous& prev = *previous_;
  cv::Mat moving_mask = cv::Mat::zeros(input.bgr.size(), CV_8U);
  const cv::Mat grey_small = instances.empty() && prev.frames.empty() ? cv::Mat() : greySmall(input.bgr);
  // Scene flow from the oldest kept frame (scene_flow_gap_frames back) to this one: objects
  // sampled in the old frame, followed by dense flow, lifted with both depths, ego-motion removed.
  if (tracked && !prev.frames.empty() && prev.frames.front().tracked && !prev.frames.front().instances.empty() &&
      prev.frames.front().grey_small.size() == grey_small.size()) {
    const Previous::Snapshot& old = prev.frames.front();
    cv::Mat flow_small, flow;
    prev.dis->calc(old.grey_small, grey_small, flow_small);
    cv::resize(flow_small, flow, input.bgr.size(), 0, 0, cv::INTER_LINEAR);
    flow *= 1.0 / kFlowScale;
    const SE3 T_cur_old = frame.T_camera_world * old.T_camera_world.inverse();
    const PinholeCamera& camera = *frame.features.camera;
    for (const Instance& instance : old.instances.items) {
      const cv::Mat old_mask = old.instances.mask(instance.id);
      const auto pixels = sampleMaskPixels(old_mask, config_.dynamics.sample_step_px);
      std::vector<Vec3> p_old, p_cur;
      liftFlowCorrespondences(pixels, flow, old.depth_m, input.depth_m, camera, p_old, p_cur);
      const SceneFlowVerdict verdict = sceneFlowVerdict(p_old, p_cur, T_cur_old, config_.dynamics);
      if (!verdict.decided) continue;
      const bool prior = isPriorDynamic(instance, config_.dynamics);
      if (prior) ++(verdict.dynamic ? current_.prior_moving : current_.prior_static);
      if (!verdict.dynamic) continue;
      if (instances.labels.empty()) continue;
      // The moving object now: where its sampled pixels went along the flow.
      if (const uint16_t now = labelAlongFlow(instances.labels, pixels, flow)) current_.moving_ids.push_back(now);
      // What is cut out of the next frame's extraction keeps the instance now covering the old
      // mask: following the flow instead (occluders drag a chair's flow along) cut fewer regions
      // and cost accuracy on Bonn crowd (0.0175 -> 0.0203 m, docs/dynamics.md).
      if (const uint16_t there = labelAlongFlow(instances.labels, pixels, cv::Mat()); there && !prior)
        moving_mask.setTo(255, instances.labels == there);
    }
  }
  // Non-prior instances voted moving by the depth test stay cut out in the next frame too (not
  // those cut out only because they moved last frame: fresh evidence each frame, no latch).
  for (uint16_t id : depth_voted_)
    if (const Instance* instance = instances.find(id); instance && !isPriorDynamic(*instance, config_.dynamics))
      moving_mask.setTo(255, instances.labels == id);
  std::sort(current_.moving_ids.begin(), current_.moving_ids.end());
  current_.moving_ids.erase(std::unique(current_.moving_ids.begin(), current_.moving_ids.end()), current_.moving_ids.end());
  prev.moving_mask = moving_mask;
  if (!grey_small.empty()) {
    prev.frames.push_back({grey_small, input.depth_m, instances, frame.T_camera_world, tracked});
    while (int(prev.frames.size()) > std::max(1, config_.dynamics.scene_flow_gap_frames)) prev.frames.pop_front();
  } else {
    prev.frames.clear();
  }
  history_.push_back(current_);
}

nlohmann::json DynamicFilter::summary() const {
  nlohmann::json out;
  out["enabled"] = enabled_;
  out["segmenter"] = segmenter_name_;
  const double n = std::max<size_t>(1, history_.size());
  double kp = 0, dyn = 0, stat = 0, prior = 0, moving = 0, prior_moving = 0, prior_static = 0, masked = 0;
  nlohmann::json series = {{"dynamic_keypoints", nlohmann::json::array()},
                           {"static_keypoints", nlohmann::json::array()},
                           {"prior_instances", nlohmann::json::array()},
                           {"dynamic_instances", nlohmann::json::array()},
                           {"moving_ids", nlohmann::json::array()}};
  for (const FrameDynamics& f : history_) {
    kp += f.keypoints;
    dyn += f.dynamic_keypoints;
    stat += f.static_keypoints;
    prior += f.prior_instances;
    moving += f.moving_instances;
    prior_moving += f.prior_moving;
    prior_static += f.prior_static;
    masked += f.masked_share;
    series["dynamic_keypoints"].push_back(f.dynamic_keypoints);
    series["static_keypoints"].push_back(f.static_keypoints);
    series["prior_instances"].push_back(f.prior_instances);
    series["dynamic_instances"].push_back(f.moving_instances + f.prior_moving);
    series["moving_ids"].push_back(f.moving_ids);
  }
  out["mean_keypoints"] = kp / n;
  out["mean_dynamic_keypoints"] = dyn / n;
  out["mean_static_keypoints"] = stat / n;
  out["mean_prior_instances"] = prior / n;
  out["mean_dynamic_instances"] = (moving + prior_moving) / n;
  out["mean_moving_nonprior_instances"] = moving / n;
  out["mean_prior_moving"] = prior_moving / n;
  out["mean_prior_static"] = prior_static / n;
  out["mean_masked_share"] = masked / n;
  int culled = 0;
  for (const FrameDynamics& f : history_) culled += f.culled_points;
  out["culled_points"] = culled;
  out["per_frame"] = series;
  return out;
}

}  // namespace dynanav
