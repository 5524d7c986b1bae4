#include "pipeline/map_sink.hpp"

#include <spdlog/spdlog.h>

#include <chrono>
#include <opencv2/imgcodecs.hpp>

#include "core/timer.hpp"
#include "mapping/static_map.hpp"
#include "pipeline/system.hpp"
#include "slam/slam_system.hpp"

namespace dynanav {

std::vector<uint16_t> dynamicInstanceIds(const FrameResult& result) {
  std::vector<uint16_t> ids;
  for (const InstanceVerdict& v : result.verdicts)
    if (v.prior_dynamic || v.moving) ids.push_back(v.id);
  return ids;
}

MapSink::MapSink(std::filesystem::path out_dir, const OutputsConfig& config,
                 const PinholeCamera& camera)
    : out_dir_(std::move(out_dir)), config_(config), camera_(camera) {}

void MapSink::consume(const RgbdFrame& frame, const FrameResult& result) {
  for (const TrackedObject& o : result.objects) {
    ObjectPath& path = object_paths_[o.id];
    path.class_name = o.class_name;
    path.p_world.push_back(o.p_world);
  }
  if (!result.tracked) return;
  const bool due = config_.map_frame_interval_s > 0 &&
                   (keyframes_.empty() ||
                    result.stamp_s - keyframes_.back().stamp_s >= config_.map_frame_interval_s);
  if (!result.keyframe && !due) return;
  cv::Mat static_mask;
  if (!result.instances.labels.empty())
    static_mask =
        staticMask(result.instances.labels, dynamicInstanceIds(result), config_.mask_dilation_px);
  keyframes_.push_back(keepKeyframe(result.stamp_s, frame.bgr, frame.depth_m, static_mask,
                                    config_.keyframe_downscale, config_.max_depth_m));
}

void MapSink::finish(const RunEnd& end) {
  const auto start = std::chrono::steady_clock::now();
  const SlamSystem& slam = end.system.slam();
  // Final (globally adjusted) keyframe poses by stamp; kept frames that are not keyframes (any
  // more: culled, or kept for time) take their pose re-anchored on a surviving keyframe.
  std::map<double, SE3> poses, refined;
  for (const StampedPose& p : slam.keyframePoses()) poses[p.stamp_s] = p.T_world_camera;
  for (const StampedPose& p : slam.refinedTrajectory()) refined[p.stamp_s] = p.T_world_camera;
  auto lookup = [](const std::map<double, SE3>& m, double t, SE3& pose) {
    auto it = m.lower_bound(t - 1e-6);
    if (it == m.end() || std::abs(it->first - t) > 1e-6) return false;
    pose = it->second;
    return true;
  };
  std::vector<PosedKeyframe> posed;
  int reanchored = 0;
  for (const MapKeyframe& kf : keyframes_) {
    PosedKeyframe p{&kf, SE3::Identity()};
    if (lookup(poses, kf.stamp_s, p.T_world_camera)) {
      posed.push_back(p);
    } else if (lookup(refined, kf.stamp_s, p.T_world_camera)) {
      posed.push_back(p);
      ++reanchored;
    }
  }
  if (posed.empty()) {
    spdlog::warn("map: no keyframe with a pose; no map written");
    return;
  }
  StaticMapOptions options;
  options.voxel_m = config_.cloud_voxel_m;
  options.cloud_pixel_step = config_.cloud_pixel_step;
  options.octree = {config_.octree_resolution_m, config_.max_depth_m, config_.octree_pixel_step};
  options.walk_min_height_m = config_.walk_min_height_m;
  options.walk_max_height_m = config_.walk_max_height_m;
  options.grid_cell_m = config_.grid_cell_m;
  const cv::Mat rays = rayTable(camera_, config_.keyframe_downscale);
  const StaticMap map = buildStaticMap(posed, rays, options);
  writeStaticMap(out_dir_, map);
  if (!map.grid.cells.empty()) {
    std::vector<Vec3> wearer;
    for (const auto& [t, T] : refined) wearer.push_back(T.translation());
    cv::imwrite((out_dir_ / "topview.png").string(), drawTopView(map.grid, wearer, object_paths_));
  } else {
    spdlog::warn("map: no floor plane found; no occupancy.png or topview.png");
  }
  spdlog::info(
      "map: {} frames ({} of them not keyframes, placed re-anchored) -> map.ply {} points, map.bt "
      "{} leaves; {:.0f} ms (cloud {:.0f}, octree {:.0f}, filter {:.0f}, grid {:.0f})",
      posed.size(), reanchored, map.cloud.size(), map.tree->getNumLeafNodes(), msSince(start),
      map.cloud_ms, map.octree_ms, map.filter_ms, map.grid_ms);
}

}  // namespace dynanav
