// The tracker's point carrying (object_tracker.hpp, step 1 and after association): the shared
// dense flow, and each object's own flow (object_flow.hpp) where it applies.
#include "dynamics/object_flow.hpp"
#include "dynamics/object_points.hpp"
#include "dynamics/object_tracker.hpp"
#include "perception/frame_prep.hpp"

namespace dynanav {

ObjectTracker::Carried ObjectTracker::carry(const Track& track, const ObjectTrackerInput& input,
                                            const CroppedFlow* own) {
  const cv::Size size = input.depth_m.size();
  Carried out;
  for (size_t i = 0; i < track.pixels.size(); ++i) {
    cv::Point2f px = track.pixels[i];
    if (!(own && carryByCroppedFlow(*own, size, px))) {
      px = track.pixels[i];
      if (!carryByFlow(input.flow_half, size, px)) continue;
    }
    out.p_prev_world.push_back(track.p_world[i]);
    out.beside_nearer.push_back(track.beside_nearer[i]);
    out.pixels.emplace_back(px.x, px.y);
  }
  for (cv::Point2f px : track.voters)
    if (carryByFlow(input.flow_half, size, px)) out.voters.emplace_back(px.x, px.y);
  return out;
}

CroppedFlow ObjectTracker::ownFlow(const Track& track, const Instance& instance,
                                   const ObjectTrackerInput& input) {
  // A person's own flow only on the trunk: a whole-mask sample (a walker cut by the image's
  // side, or too little trunk in view) holds swinging arms and legs, whose own motion it reads
  // truly and the rigid fit then reads as the body's (crossing seed 1's walker, entering at the
  // side at 1.40 m/s, read 1.86; docs/tracking.md "Session 33").
  const bool swinging_limbs = track.prior_dynamic && !track.trunk;
  // A track held still (a seated person, a chair not found moving) has its velocity clamped at
  // zero: the shared flow is enough to see it set off, and the crowd's furniture costs nothing.
  if (!config_.own_flow || swinging_limbs || track.stationary || track.instance == 0 ||
      track.pixels.empty() || input.grey_half.empty() ||
      previous_grey_half_.size() != input.grey_half.size() ||
      previous_labels_.size() != input.instances.labels.size())
    return {};
  if (!own_dis_) {  // the shared flow's settings (FramePrep)
    own_dis_ = cv::DISOpticalFlow::create(cv::DISOpticalFlow::PRESET_ULTRAFAST);
    own_dis_->setPatchSize(kSharedFlowPatchPx);
    own_dis_->setFinestScale(config_.flow_finest_scale);
    own_dis_->setVariationalRefinementIterations(config_.flow_refinement_iterations);
  }
  // Where the shared flow says the object went: the current crop is taken there.
  const cv::Point shift_half = medianShiftHalf(input.flow_half, input.depth_m.size(), track.pixels);
  // Around where the object was and where it is now (moved back by the shift), plus the
  // patches' reach; what lies more than depth_band_m nearer than the object's median depth
  // hides it (besideNearerSurface's test).
  const cv::Rect was = cv::boundingRect(track.pixels);
  const int margin_px = sharedFlowFootprintPx(config_.flow_finest_scale) / 2;
  const auto hidingDepthM = [&](const cv::Mat& labels, uint16_t label, cv::Rect box,
                                const cv::Mat& depth_m) {
    const double z_m = medianLabelDepthM(labels, label, box, depth_m, 4);
    return z_m > 0.0 ? z_m - config_.depth_band_m : 0.0;
  };
  const double was_nearer_than_m =
      hidingDepthM(previous_labels_, track.instance, was, previous_depth_m_);
  const double now_nearer_than_m =
      hidingDepthM(input.instances.labels, instance.id, instance.box, input.depth_m);
  return objectFlow(
      {previous_grey_half_, previous_labels_, track.instance, previous_depth_m_, was_nearer_than_m},
      {input.grey_half, input.instances.labels, instance.id, input.depth_m, now_nearer_than_m},
      was | (instance.box - 2 * shift_half), shift_half, margin_px, config_.own_flow_fill_offset,
      *own_dis_);
}

}  // namespace dynanav
