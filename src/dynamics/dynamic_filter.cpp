#include "dynamics/dynamic_filter.hpp"

#include <opencv2/imgproc.hpp>
#include <opencv2/video/tracking.hpp>

#include "dynamics/scene_flow.hpp"

namespace dynanav {

/// The last frame's grey image, depth, prior objects and pose, for scene flow.
struct DynamicFilter::Previous {
  cv::Mat grey_small;
  cv::Mat depth_m;
  Instances instances;
  SE3 T_camera_world = SE3::Identity();
  bool tracked = false;
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
  current_.moving_instances = static_cast<int>(r.moving_instances.size());
  current_.moving_ids = r.moving_instances;
}

void DynamicFilter::verifyPriors(const RgbdFrame& input, const Instances& instances, const Frame& frame,
                                 bool tracked) {
  if (!enabled_) return;
  current_.keypoints = frame.size();
  for (int i = 0; i < frame.size(); ++i) current_.static_keypoints += frame.features.usable[i] ? 1 : 0;
  std::optional<ScopedTimer> timer;
  if (timers_) timer.emplace(*timers_, "scene_flow");
  Previous& prev = *previous_;
  const bool has_priors = current_.prior_instances > 0;
  cv::Mat grey_small;
  if (has_priors || !prev.instances.empty()) grey_small = greySmall(input.bgr);
  // Scene flow needs the previous frame's prior objects, both poses and both images.
  if (tracked && prev.tracked && !prev.instances.empty() && !prev.grey_small.empty() &&
      prev.grey_small.size() == grey_small.size()) {
    cv::Mat flow_small, flow;
    prev.dis->calc(prev.grey_small, grey_small, flow_small);
    cv::resize(flow_small, flow, input.bgr.size(), 0, 0, cv::INTER_LINEAR);
    flow *= 1.0 / kFlowScale;
    const SE3 T_cur_prev = frame.T_camera_world * prev.T_camera_world.inverse();
    const PinholeCamera& camera = *frame.features.camera;
    for (const Instance& instance : prev.instances.items) {
      if (!isPriorDynamic(instance, config_.dynamics)) continue;
      const auto pixels = sampleMaskPixels(prev.instances.mask(instance.id), config_.dynamics.sample_step_px);
      std::vector<Vec3> p_prev, p_cur;
      liftFlowCorrespondences(pixels, flow, prev.depth_m, input.depth_m, camera, p_prev, p_cur);
      const SceneFlowVerdict verdict = sceneFlowVerdict(p_prev, p_cur, T_cur_prev, config_.dynamics);
      if (!verdict.decided) continue;
      if (verdict.dynamic) {
        ++current_.prior_moving;
        current_.moving_ids.push_back(instance.id);
      } else {
        ++current_.prior_static;
      }
    }
  }
  prev.grey_small = grey_small;
  prev.depth_m = input.depth_m;
  prev.T_camera_world = frame.T_camera_world;
  prev.tracked = tracked;
  prev.instances = Instances{};
  if (has_priors) prev.instances = instances;
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
  out["per_frame"] = series;
  return out;
}

}  // namespace dynanav
