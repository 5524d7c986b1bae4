#include "dynamics/object_tracker.hpp"

// What a track measures in a frame: the instance's sample pixels, their lift into the world
// with this frame's depth, and the object's centre (object_tracker.cpp uses them).
#include <cmath>

#include "core/median.hpp"
#include "dynamics/height_range.hpp"
#include "dynamics/object_points.hpp"
#include "perception/frame_prep.hpp"

namespace dynanav {
namespace {

/// A standing adult's height (m): with the median depth of a person's mask, how tall the whole
/// person would be in the image when the head or the feet are out of view (trunk band).
constexpr double kPersonHeightM = 1.7;

/// A silhouette bordered over more than this share of its outline by something nearer than the
/// person is taken as partly hidden (height_range.hpp, nearerOutlineShare): a free one borders
/// nothing nearer; one hidden along a side or below, tens of percent.
constexpr double kMaxNearerOutlineShare = 0.05;

/// How far the centre lies behind the visible surface: a person's half thickness (config); for
/// other objects half their visible width (a box or chair is about as deep as it is wide).
double behindSurface(const std::string& class_name, const std::vector<Vec3>& p_camera,
                     const ObjectTrackingConfig& config) {
  return class_name == "person" ? config.centre_behind_surface_m : 0.5 * objectWidth(p_camera);
}

}  // namespace

std::optional<double> ObjectTracker::headingAbsCos(const Track& track, const Vec3& p_camera,
                                                   const ObjectTrackerInput& input) const {
  // A walker faces the way it walks; a standing person, or one whose velocity is not known yet,
  // may face anywhere.
  const Vec3 v_world = track.filter.velocity();
  if (!filterVelocityKnown(track) || isSlow(v_world)) return std::nullopt;
  const Vec3 n = floor_->normal_camera.normalized();
  const Vec3 v = projectOntoPlane(input.T_world_camera.linear().transpose() * v_world, n);
  const Vec3 ray = projectOntoPlane(p_camera, n);
  if (!(v.norm() > 1e-6) || !(ray.norm() > 1e-6)) return std::nullopt;
  return std::abs(v.normalized().dot(ray.normalized()));
}

std::optional<ObjectTracker::Centre> ObjectTracker::measureCentre(
    const Track& track, const std::vector<Vec3>& p_camera, const Instance* instance,
    const ObjectTrackerInput& input) const {
  // Most of a person's mask without usable depth (beyond the sensor's range), head and feet in
  // view: its pixel height and a stature prior give the range (height_range.hpp) until depth
  // covers the mask.
  const bool little_depth = instance && track.depth_share < config_.min_depth_share;
  if (little_depth && track.class_name == "person" && !track.ranges_refuted)
    if (const auto extent = personExtent(input.instances.labels, *instance)) {
      const Mat3 R_world_camera = input.T_world_camera.linear();
      auto range = rangeFromHeight(*extent, input.camera, worldUpInCamera(input.T_world_camera));
      if (range && config_.floor_contact_range && floor_) {
        // Where the soles meet the floor, no stature assumed: kept when the stature's range
        // agrees within its 3 sigma (else the mask's lowest row is not the soles: legs lost
        // to erosion or hidden), and then used alone (a floor's 1-2 % against a stature's
        // population spread of 5 %: the simulated approach's second walker read 7.5 % near by
        // its height, +0.7 % by its soles, docs/tracking.md "Session 18").
        const auto contact = rangeFromFloorContact(*extent, input.camera, *floor_,
                                                   headingAbsCos(track, range->p_camera, input));
        if (contact && std::abs(contact->range_m - range->range_m) <= 3.0 * range->sigma_range_m)
          range = contact;
      }
      // Depth of the mask, or of what borders it, nearer than the range allows (2 sigma): not a
      // whole person (an arm beside a cabinet in the simulated crossing read 10 m at 3.9 m).
      const double nearest_z_m = range ? range->p_camera.z() - 2.0 * range->sigma_range_m : 0.0;
      const double z_mask_m = medianLabelDepthM(input.instances.labels, instance->id, instance->box,
                                                input.depth_m, sample_step_px_);
      if (range && !(z_mask_m > 0.0 && z_mask_m < nearest_z_m) &&
          nearerOutlineShare(input.instances.labels, input.depth_m, instance->id, instance->box,
                             nearest_z_m) < kMaxNearerOutlineShare)
        return Centre{range->p_camera,
                      R_world_camera * range->cov_frame_camera * R_world_camera.transpose(),
                      range->scale_sigma, true};
    }
  if (p_camera.size() < size_t(config_.centre_min_points)) return std::nullopt;
  auto centre = objectCentre(p_camera, config_.depth_band_m,
                             behindSurface(track.class_name, p_camera, config_));
  if (!centre) return std::nullopt;
  // An object cut by the image's left or right edge shows only part of itself: the centre of
  // what is seen slides sideways with the edge (a walker entering the view would seem to move at
  // several m/s while the visible part grows), and its depth is that of the part in view (a
  // leading shoulder and arm), not the body's: in the simulated crossing it started 0.35 m too
  // far and closed on the truth over 0.3 s, a false 1 m/s approach. Its height is still
  // measured; its sideways position and depth count as unknown, and the filter keeps the motion
  // the rigid-motion velocity measures until the object is wholly in view.
  // Likewise the height of a person of whom only the legs or an arm were sampled (the trunk not
  // in view): the centre of the whole mask is not the trunk's. And all of the centre when most
  // of the mask has no usable depth (a walker entering the sensor's range shows depth on the
  // nearest limb first: its centre sits beside and in front of the body's, and would move at
  // a walking speed sideways while the rest comes into range).
  // Carried points (the segmenter missed the object) are the last seen frame's sample: its
  // centre is as partial as that frame's was (cut, no trunk), or a carried centre would claim
  // to measure what the seen one could not (static fr1_xyz in real time: a carried false
  // "person" read the height it had not measured, a 0.16 m jump, docs/tracking.md "Session 22").
  const bool cut = track.cut_side != 0;
  const bool no_trunk = track.class_name == "person" && !track.trunk;
  if (!cut && !no_trunk && !little_depth) return Centre{*centre, std::nullopt, 0.0, true};
  const double s2 = config_.position_sigma_m * config_.position_sigma_m;
  const double u2 = kUnmeasuredSigmaM * kUnmeasuredSigmaM;
  const Mat3 cov_camera = Vec3(cut || little_depth ? u2 : s2, no_trunk || little_depth ? u2 : s2,
                               cut || little_depth ? u2 : s2)
                              .asDiagonal();
  const Mat3 R_world_camera = input.T_world_camera.linear();
  return Centre{*centre, R_world_camera * cov_camera * R_world_camera.transpose(), 0.0,
                !cut && !little_depth};
}

ObjectSample ObjectTracker::samplePixels(const Instance& instance,
                                         const ObjectTrackerInput& input) const {
  SampleOptions options{sample_step_px_, config_.max_points, config_.trunk_min_points};
  if (instance.class_name == "person")
    if (const double z = medianLabelDepthM(input.instances.labels, instance.id, instance.box,
                                           input.depth_m, 2 * sample_step_px_);
        z > 0.0)
      options.person_height_px = kPersonHeightM * input.camera.fy / z;
  return sampleObjectPixels(input.instances.labels, instance, options);
}

void ObjectTracker::lift(Track& track, const std::vector<cv::Point2f>& pixels,
                         const ObjectTrackerInput& input,
                         const std::vector<cv::Point2f>* rays) const {
  track.pixels.clear();
  track.p_world.clear();
  track.beside_nearer.clear();
  track.voters.clear();
  track.depth_share = 0.0;
  std::vector<float> z(pixels.size());
  for (size_t i = 0; i < pixels.size(); ++i) {
    z[i] = depthAt(input.depth_m, pixels[i]);
    if (!(z[i] > 0.f)) track.voters.push_back(pixels[i]);
  }
  if (track.voters.size() == pixels.size()) return;  // no depth at all (or no pixels)
  const std::vector<uint8_t> keep = withinDepthBand(z, config_.depth_band_m);
  // The pixels (and the depth image registered to them) are the lens's; the ray is the
  // undistorted pixel's (at fr1's image corners a raw pixel is up to 18 px off it, an offset
  // that changes as the point moves in the image: a still object there would read as moving).
  std::vector<cv::Point2f> undistorted;
  if (!rays) rays = &(undistorted = input.camera.undistortPixels(pixels));
  // A point is carried by the shared flow's patches that cover it, reaching half their
  // footprint from it (only the motion fit uses the flag).
  const int flow_reach_px =
      config_.motion_skips_nearer_edge ? sharedFlowFootprintPx(config_.flow_finest_scale) / 2 : 0;
  const std::vector<NearerSurface> beside =
      besideNearerSurface(pixels, z, input.instances.labels, track.instance, input.depth_m,
                          flow_reach_px, config_.depth_band_m);
  for (size_t i = 0; i < pixels.size(); ++i) {
    if (!keep[i]) continue;
    track.pixels.push_back(pixels[i]);
    const cv::Point2f& ray = (*rays)[i];
    track.p_world.push_back(input.T_world_camera * input.camera.backproject(ray.x, ray.y, z[i]));
    track.beside_nearer.push_back(beside[i]);
  }
  track.depth_share = double(track.pixels.size()) / double(pixels.size());
}

}  // namespace dynanav
