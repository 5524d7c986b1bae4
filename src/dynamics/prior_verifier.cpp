#include "dynamics/prior_verifier.hpp"

#include <algorithm>
#include <cmath>
#include <opencv2/imgproc.hpp>

#include "dynamics/keypoint_dynamics.hpp"
#include "dynamics/object_points.hpp"
#include "dynamics/scene_flow.hpp"
#include "perception/frame_prep.hpp"

namespace dynanav {
namespace {
constexpr double kFlowScale =
    0.5;  // scene flow on half-size images: 4x cheaper, plenty for 5 px samples
}  // namespace

PriorVerifier::PriorVerifier(const DynamicsConfig& config) : config_(config) {}

PriorVerdicts PriorVerifier::verify(const VerifierInput& input,
                                    const std::vector<uint16_t>& depth_voted) {
  PriorVerdicts out;
  const Instances& instances = input.instances;
  cv::Mat moving_mask = cv::Mat::zeros(input.depth_m.size(), CV_8U);
  // Nothing to follow and nothing kept: the frame is not worth remembering.
  const cv::Mat grey_half = instances.empty() && frames_.empty() ? cv::Mat() : input.grey_half;
  if (input.tracked && !frames_.empty() && frames_.front().tracked &&
      !frames_.front().instances.empty() && frames_.front().grey_half.size() == grey_half.size()) {
    const Snapshot& old = frames_.front();
    cv::Mat flow_half, flow;
    dis_->calc(old.grey_half, grey_half, flow_half);
    cv::resize(flow_half, flow, input.depth_m.size(), 0, 0, cv::INTER_LINEAR);
    flow *= 1.0 / kFlowScale;
    const SE3 T_cur_old = input.T_camera_world * old.T_camera_world.inverse();
    for (const Instance& instance : old.instances.items) {
      const cv::Mat mask = old.instances.mask(instance.id);
      const auto pixels = sampleMaskPixels(mask, config_.sample_step_px);
      std::vector<Vec3> p_old, p_cur;
      const bool prior = isPriorDynamic(instance, config_);
      // The wider search (the parallax) only for objects that do not move by themselves: it
      // also finds any surface at the old depth within reach — the floor at a walker's feet
      // (simulated office: speed RMSE 0.140 -> 0.177 m/s with it for people too) — and a walker
      // read as still is worse for the wearer than a chair read as moving.
      const FlowEndDepth end_depth{T_cur_old, config_.scene_flow_end_search_px,
                                   config_.scene_flow_end_parallax && !prior, &config_};
      liftFlowCorrespondences(pixels, flow, old.depth_m, input.depth_m, input.camera, p_old, p_cur,
                              nullptr, end_depth);
      // A person's mask grown over a static occluder or the wall beside them reads those points'
      // flow, and their standstill outvotes the body (simulated office, masks grown 5 px: a
      // walker coming into view partly hidden was verified static while its points moved 0.8-1.0
      // m/s). A body is shallow: points far from the sampled median depth are not the person's.
      if (prior && config_.scene_flow_prior_depth_band_m > 0) keepWithinDepthBand(p_old, p_cur);
      // An object that does not move by itself (a chair) moves only relative to the static
      // background around it: most of Bonn crowd's chairs found moving had surroundings whose
      // dense flow was off as much as theirs (docs/dynamics.md "Session 13"). The surroundings
      // start beyond the flow's patch footprint: nearer, the patches that cover the object fill
      // in its own motion (a pushed box's ring then moved more than the box). People keep the
      // test against the camera's motion: a walker's surroundings hold the flow they drag along.
      BackgroundMotion background;
      if (!prior && config_.scene_flow_reference_px > 0) {
        const int footprint_px = flowFootprintPx();
        const auto ring = sampleRingPixels(mask, old.instances.labels, footprint_px,
                                           footprint_px + config_.scene_flow_reference_px,
                                           config_.sample_step_px);
        std::vector<Vec3> q_old, q_cur;
        liftFlowCorrespondences(ring, flow, old.depth_m, input.depth_m, input.camera, q_old, q_cur,
                                nullptr, end_depth);
        background = backgroundMotion(q_old, q_cur, T_cur_old, config_);
      }
      const SceneFlowVerdict verdict =
          sceneFlowVerdict(p_old, p_cur, T_cur_old, config_, background);
      if (!verdict.decided) continue;
      if (prior && (verdict.dynamic || verdict.still))
        ++(verdict.dynamic ? out.prior_moving : out.prior_static);
      if (instances.labels.empty()) continue;
      // The object now: where its sampled pixels went along the flow.
      const uint16_t now = labelAlongFlow(instances.labels, pixels, flow);
      if (!verdict.dynamic) {
        if (prior && now && verdict.still) out.static_ids.push_back(now);
        continue;
      }
      if (now) out.moving_ids.push_back(now);
      // What is cut out of the next frame's extraction keeps the instance now covering the old
      // mask: following the flow instead (occluders drag a chair's flow along) cut fewer regions
      // and cost accuracy on Bonn crowd (0.0175 -> 0.0203 m, docs/dynamics.md).
      if (const uint16_t there = labelAlongFlow(instances.labels, pixels, cv::Mat());
          there && !prior)
        moving_mask.setTo(255, instances.labels == there);
    }
  }
  // Non-prior instances voted moving by the depth test stay cut out in the next frame too (not
  // those cut out only because they moved last frame: fresh evidence each frame, no latch).
  for (uint16_t id : depth_voted)
    if (const Instance* instance = instances.find(id);
        instance && !isPriorDynamic(*instance, config_))
      moving_mask.setTo(255, instances.labels == id);
  moving_mask_ = moving_mask;
  if (!grey_half.empty()) {
    frames_.push_back({grey_half, input.depth_m, instances, input.T_camera_world, input.tracked});
    while (int(frames_.size()) > std::max(1, config_.scene_flow_gap_frames)) frames_.pop_front();
  } else {
    frames_.clear();
  }
  for (auto* ids : {&out.moving_ids, &out.static_ids}) {
    std::sort(ids->begin(), ids->end());
    ids->erase(std::unique(ids->begin(), ids->end()), ids->end());
  }
  return out;
}

void PriorVerifier::keepWithinDepthBand(std::vector<Vec3>& p_old, std::vector<Vec3>& p_cur) const {
  std::vector<float> z_old_m(p_old.size());
  for (size_t i = 0; i < p_old.size(); ++i) z_old_m[i] = float(p_old[i].z());
  const std::vector<uint8_t> keep = withinDepthBand(z_old_m, config_.scene_flow_prior_depth_band_m);
  size_t kept = 0;
  for (size_t i = 0; i < p_old.size(); ++i) {
    if (!keep[i]) continue;
    p_old[kept] = p_old[i];
    p_cur[kept] = p_cur[i];
    ++kept;
  }
  p_old.resize(kept);
  p_cur.resize(kept);
}

int PriorVerifier::flowFootprintPx() const {
  return disPatchFootprintPx(dis_->getPatchSize(), dis_->getFinestScale(), kFlowScale);
}

std::vector<uint16_t> cutOutMovingObjects(cv::Mat& allowed, const Instances& instances,
                                          const cv::Mat& moving_mask,
                                          const DynamicsConfig& config) {
  std::vector<uint16_t> ids;
  if (moving_mask.empty() || moving_mask.size() != instances.labels.size()) return ids;
  for (const Instance& instance : instances.items) {
    if (isPriorDynamic(instance, config)) continue;
    const cv::Mat mask = instances.labels == instance.id;
    const int area = cv::countNonZero(mask);
    if (area == 0 || cv::countNonZero(mask & moving_mask) < area / 2) continue;
    if (allowed.empty()) allowed = cv::Mat(instances.labels.size(), CV_8U, cv::Scalar(255));
    allowed.setTo(0, mask);
    ids.push_back(instance.id);
  }
  return ids;
}

}  // namespace dynanav
