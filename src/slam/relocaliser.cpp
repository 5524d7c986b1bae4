#include "slam/relocaliser.hpp"

#include <spdlog/spdlog.h>

#include <set>

#include "slam/frame_tracker.hpp"
#include "slam/local_map.hpp"
#include "slam/matcher.hpp"
#include "slam/pnp_ransac.hpp"
#include "slam/vocabulary/bow_matching.hpp"

namespace dynanav {
namespace {

int countInliers(const Frame& frame) {
  int n = 0;
  for (int i = 0; i < frame.size(); ++i) n += frame.map_points[i] && !frame.outlier[i];
  return n;
}

/// Projects the keyframe's points that the frame has not matched yet and matches them in a window
/// (ORB-SLAM2 SearchByProjection(Frame, KeyFrame, ...) with a wide window after EPnP).
int searchCandidatePoints(Frame& frame, const KeyFrame& candidate, float radius_factor) {
  std::set<const MapPoint*> matched;
  for (const auto& p : frame.map_points)
    if (p) matched.insert(p.get());
  std::vector<MapPointPtr> points;
  const Vec3 center = frame.center();
  for (const auto& p : candidate.map_points) {
    if (!p || p->bad || matched.count(p.get())) continue;
    if (prepareProjection(frame, center, *p)) points.push_back(p);
  }
  if (points.empty()) return 0;
  return matcher::matchLocalPoints(frame, points, radius_factor, 0.9f);
}

}  // namespace

int Relocaliser::tryKeyFrame(Frame& frame, const FeatureVector& frame_features,
                             const KeyFrame& candidate) const {
  const Features& kf = candidate.features;
  const Features& f = frame.features;
  BowMatchOptions options;
  options.nn_ratio = 0.75f;
  const auto usable = [&](int i) {
    const MapPointPtr& p = candidate.map_points[i];
    return p && !p->bad && kf.usable[i];
  };
  auto matches = matchByDirectIndex(candidate.bow_features, kf.descriptors, kf.keypoints,
                                    frame_features, f.descriptors, f.keypoints, options, usable);
  std::erase_if(matches, [&](const cv::DMatch& m) { return !f.usable[m.trainIdx]; });
  if (static_cast<int>(matches.size()) < loop_.reloc_min_bow_matches) return 0;
  std::vector<Vec3> p_world;
  std::vector<Eigen::Vector2d> pixels;
  for (const auto& m : matches) {
    p_world.push_back(candidate.map_points[m.queryIdx]->p_world);
    pixels.emplace_back(f.points[m.trainIdx].x, f.points[m.trainIdx].y);
  }
  PnpRansacOptions pnp;
  pnp.seed = frame.id + 1;
  const PnpRansacResult solved = solvePnpRansac(p_world, pixels, *f.camera, pnp);
  if (!solved.ok) return 0;
  frame.clearMatches();
  frame.T_camera_world = solved.T_camera_world;
  for (size_t k = 0; k < matches.size(); ++k) {
    if (solved.inlier[k])
      frame.map_points[matches[k].trainIdx] = candidate.map_points[matches[k].queryIdx];
  }
  optimizeFramePose(frame, tracking_);
  int good = discardOutliers(frame);
  if (good < 10) return 0;
  // Thin support: look for more of the candidate's points around the new pose, first in a wide
  // window, then a narrow one once the pose is refined (ORB-SLAM2 uses windows of 10 and 3 px).
  for (const float radius : {4.0f, 1.5f}) {
    if (good >= loop_.reloc_min_inliers) break;
    searchCandidatePoints(frame, candidate, radius);
    optimizeFramePose(frame, tracking_);
    good = discardOutliers(frame);
  }
  return countInliers(frame);
}

RelocalisationResult Relocaliser::relocalise(Frame& frame, const Map& map) const {
  RelocalisationResult result;
  if (places_.size() == 0 || frame.size() == 0) return result;
  BowVector bow;
  FeatureVector features;
  places_.computeBow(frame, bow, features);
  PlaceQuery query;
  query.min_score = 0.0;
  query.min_common_words_ratio = loop_.min_common_words_ratio;
  query.min_accumulated_ratio = loop_.min_accumulated_ratio;
  query.covisible = PlaceIndex::covisibleOf(map);
  const auto candidates = places_.database().query(bow, query);
  const SE3 lost_pose = frame.T_camera_world;
  for (const auto& c : candidates) {
    KeyFrame* kf = findKeyFrame(map, c.id);
    if (!kf || kf->bow.empty()) continue;
    ++result.candidates;
    const int inliers = tryKeyFrame(frame, features, *kf);
    spdlog::debug("relocalisation frame {}: keyframe {} (score {:.3f}) -> {} inliers", frame.id,
                  kf->id, c.score, inliers);
    if (inliers >= loop_.reloc_min_inliers) {
      result.ok = true;
      result.keyframe_id = kf->id;
      result.inliers = inliers;
      return result;
    }
  }
  frame.clearMatches();
  frame.T_camera_world = lost_pose;
  return result;
}

}  // namespace dynanav
