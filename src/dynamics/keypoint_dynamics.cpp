#include "dynamics/keypoint_dynamics.hpp"

#include <algorithm>
#include <cmath>
#include <opencv2/imgproc.hpp>

#include "core/median.hpp"
#include "dynamics/depth_difference.hpp"
#include "dynamics/depth_tolerance.hpp"
#include "dynamics/moving_evidence.hpp"

namespace dynanav {

bool isPriorDynamicClass(const std::string& class_name,
                         const std::vector<std::string>& prior_dynamic_classes) {
  return std::find(prior_dynamic_classes.begin(), prior_dynamic_classes.end(), class_name) !=
         prior_dynamic_classes.end();
}

bool isPriorDynamic(const Instance& instance, const DynamicsConfig& config) {
  return isPriorDynamicClass(instance.class_name, config.prior_dynamic_classes);
}

namespace {
/// Median of the valid depths under `mask` (0 if none).
float medianDepth(const cv::Mat& depth_m, const cv::Mat& mask) {
  std::vector<float> values;
  for (int y = 0; y < mask.rows; y += 2) {
    const uint8_t* m = mask.ptr<uint8_t>(y);
    const float* d = depth_m.ptr<float>(y);
    for (int x = 0; x < mask.cols; x += 2)
      if (m[x] && d[x] > 0.f && std::isfinite(d[x])) values.push_back(d[x]);
  }
  if (values.empty()) return 0.f;
  return medianInPlace(values);
}

/// Pixels of `box` whose depth lies within `band_m` of `centre_m`, set to 255 in `out`.
void markBoxDepthBand(const cv::Mat& depth_m, const cv::Rect& box, float centre_m, float band_m,
                      cv::Mat& out) {
  const cv::Rect r = box & cv::Rect(0, 0, depth_m.cols, depth_m.rows);
  for (int y = r.y; y < r.y + r.height; ++y) {
    const float* d = depth_m.ptr<float>(y);
    uint8_t* o = out.ptr<uint8_t>(y);
    for (int x = r.x; x < r.x + r.width; ++x)
      if (d[x] > 0.f && std::abs(d[x] - centre_m) < band_m) o[x] = 255;
  }
}
}  // namespace

cv::Mat staticExtractionMask(const Instances& instances, const DynamicsConfig& config,
                             const cv::Mat& depth_m) {
  if (instances.labels.empty()) return {};
  cv::Mat prior = cv::Mat::zeros(instances.labels.size(), CV_8U);
  bool any = false;
  const bool use_depth =
      !depth_m.empty() && depth_m.size() == prior.size() && config.prior_box_depth_band_m > 0;
  for (const Instance& instance : instances.items) {
    if (!isPriorDynamic(instance, config)) continue;
    const cv::Mat mask = instances.labels == instance.id;
    prior.setTo(255, mask);
    any = true;
    if (!use_depth) continue;
    const float centre_m = medianDepth(depth_m, mask);
    if (centre_m > 0.f)
      markBoxDepthBand(depth_m, instance.box, centre_m,
                       static_cast<float>(config.prior_box_depth_band_m), prior);
  }
  if (!any) return {};
  if (config.prior_mask_dilate_px > 0) {
    const int r = config.prior_mask_dilate_px;
    cv::dilate(prior, prior,
               cv::getStructuringElement(cv::MORPH_ELLIPSE, cv::Size(2 * r + 1, 2 * r + 1)));
  }
  cv::Mat allowed;
  cv::bitwise_not(prior, allowed);
  return allowed;
}

void labelKeypoints(Features& features, const cv::Mat& labels) {
  features.instance_id.assign(features.keypoints.size(), 0);
  if (labels.empty()) return;
  CV_Assert(labels.type() == CV_16U);
  for (size_t i = 0; i < features.keypoints.size(); ++i) {
    const cv::Point2f& pt = features.keypoints[i].pt;
    const int x = std::clamp(int(pt.x + 0.5f), 0, labels.cols - 1);
    const int y = std::clamp(int(pt.y + 0.5f), 0, labels.rows - 1);
    features.instance_id[i] = labels.at<uint16_t>(y, x);
  }
}

MoverVerdict findDepthMovers(const Frame& frame, const std::vector<float>& predicted_depth_m,
                             const DynamicsConfig& config, const DepthTestMotion& motion,
                             const std::vector<float>& moving_evidence) {
  const Features& f = frame.features;
  const double focal_px = f.camera ? f.camera->fx : 0.0;
  std::vector<DepthCheck> checks(f.keypoints.size());
  for (int i = 0; i < frame.size(); ++i) {
    DepthCheck& check = checks[i];
    check.instance = f.instance_id[i];
    check.measured_depth_m = f.depth_m[i];
    check.predicted_depth_m = predicted_depth_m[i];
    if (!(check.measured_depth_m > 0.f) || !(check.predicted_depth_m > 0.f)) continue;
    if (f.camera && f.scales) {
      const int octave = std::clamp(f.keypoints[i].octave, 0, int(f.scales->scale.size()) - 1);
      check.predicted_sigma_m = static_cast<float>(
          mapPointDepthSigma(check.predicted_depth_m, f.scales->scale[octave], f.camera->bf()));
    }
    const double row_offset_s =
        f.camera ? std::abs(f.keypoints[i].pt.y / f.camera->height - 0.5) * motion.readout_s : 0.0;
    const double radius_px = motionDisplacementPx(motion.velocity, check.measured_depth_m, focal_px,
                                                  motion.time_spread_s + row_offset_s);
    const int radius = std::min(config.depth_test_max_radius_px, int(std::lround(radius_px)));
    if (radius <= 0 || motion.depth_m.empty()) continue;
    const DepthRange nearby = depthRangeAround(motion.depth_m, f.keypoints[i].pt, radius);
    check.nearby_min_m = nearby.min_m;
    check.nearby_max_m = nearby.max_m;
  }
  DepthDifferenceResult result = classifyByDepthDifference(checks, config);
  MoverVerdict out;
  out.checked = result.checked;
  for (const auto& [id, vote] : result.instances)
    if (vote.dynamic) out.moving_instances.push_back(id);  // ascending: the map is ordered
  if (!moving_evidence.empty()) {
    // Outside masks, a map point's votes over frames decide (inside, the instance's vote does).
    std::vector<DepthVote> votes(checks.size(), DepthVote::kNone);
    for (size_t i = 0; i < checks.size(); ++i)
      if (checks[i].measured_depth_m > 0.f && checks[i].predicted_depth_m > 0.f)
        votes[i] = failsDepthTest(checks[i], config) ? DepthVote::kMoving : DepthVote::kStatic;
    std::vector<bool> moving;
    out.drop.moving_evidence = fuseMovingEvidence(votes, moving_evidence, config, moving);
    for (size_t i = 0; i < checks.size(); ++i)
      if (!result.instances.count(checks[i].instance) || checks[i].instance == 0)
        result.keypoint_dynamic[i] = moving[i];
  }
  // DynaSLAM's asymmetry: a keypoint nearer than its map point may just occlude it, but one
  // measured deeper means the point is no longer there -- it lay on something that moved.
  if (config.cull_vanished_points) {
    for (int i = 0; i < frame.size(); ++i)
      if (frame.map_points[i] && result.keypoint_dynamic[i] &&
          checks[i].measured_depth_m > checks[i].predicted_depth_m)
        out.drop.cull_vanished.push_back(i);
  }
  for (int i = 0; i < frame.size(); ++i) {
    const bool in_moving =
        f.instance_id[i] != 0 && std::binary_search(out.moving_instances.begin(),
                                                    out.moving_instances.end(), f.instance_id[i]);
    if ((!result.keypoint_dynamic[i] && !in_moving) || !f.usable[i]) continue;
    out.drop.drop.push_back(i);
    // A point mapped on an object while it stood still is no longer where the map says.
    out.drop.cull_on_drop.push_back(in_moving && config.cull_moving_object_points);
  }
  return out;
}

}  // namespace dynanav
