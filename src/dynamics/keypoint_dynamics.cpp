#include "dynamics/keypoint_dynamics.hpp"

#include <algorithm>
#include <opencv2/imgproc.hpp>

#include "dynamics/depth_difference.hpp"

namespace dynanav {

bool isPriorDynamic(const Instance& instance, const DynamicsConfig& config) {
  const auto& classes = config.prior_dynamic_classes;
  return std::find(classes.begin(), classes.end(), instance.class_name) != classes.end();
}

cv::Mat staticExtractionMask(const Instances& instances, const DynamicsConfig& config) {
  if (instances.labels.empty()) return {};
  cv::Mat prior = cv::Mat::zeros(instances.labels.size(), CV_8U);
  bool any = false;
  for (const Instance& instance : instances.items) {
    if (!isPriorDynamic(instance, config)) continue;
    prior.setTo(255, instances.labels == instance.id);
    any = true;
  }
  if (!any) return {};
  if (config.prior_mask_dilate_px > 0) {
    const int r = config.prior_mask_dilate_px;
    cv::dilate(prior, prior, cv::getStructuringElement(cv::MORPH_ELLIPSE, cv::Size(2 * r + 1, 2 * r + 1)));
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

MoverRejection rejectDepthMovers(Frame& frame, const DynamicsConfig& config,
                                 const std::vector<uint16_t>& known_moving) {
  Features& f = frame.features;
  std::vector<DepthCheck> checks(f.keypoints.size());
  for (int i = 0; i < frame.size(); ++i) {
    checks[i].instance = f.instance_id[i];
    checks[i].measured_depth_m = f.depth_m[i];
    const MapPointPtr& point = frame.map_points[i];
    if (!point || frame.outlier[i] || point->bad) continue;
    const Vec3 p_camera = frame.T_camera_world * point->p_world;
    checks[i].predicted_depth_m = static_cast<float>(p_camera.z());
  }
  const DepthDifferenceResult result = classifyByDepthDifference(checks, config);
  MoverRejection out;
  out.checked = result.checked;
  for (const auto& [id, vote] : result.instances)
    if (vote.dynamic) out.moving_instances.push_back(id);
  for (uint16_t id : known_moving)
    if (std::find(out.moving_instances.begin(), out.moving_instances.end(), id) == out.moving_instances.end())
      out.moving_instances.push_back(id);
  std::sort(out.moving_instances.begin(), out.moving_instances.end());
  for (int i = 0; i < frame.size(); ++i) {
    const bool in_moving = f.instance_id[i] != 0 &&
                           std::binary_search(out.moving_instances.begin(), out.moving_instances.end(), f.instance_id[i]);
    if (!result.keypoint_dynamic[i] && !in_moving) continue;
    if (!f.usable[i]) continue;
    f.usable[i] = 0;
    frame.map_points[i].reset();
    frame.outlier[i] = 0;
    ++out.rejected;
  }
  return out;
}

}  // namespace dynanav
