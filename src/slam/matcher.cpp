#include "slam/matcher.hpp"

#include <algorithm>
#include <array>
#include <cmath>

namespace dynanav::matcher {
namespace {

constexpr int kHistogramBins = 30;

float angleDifference(float a, float b) {
  float d = a - b;
  if (d < 0.f) d += 360.f;
  return d;
}

int distance(const cv::Mat& a, int ra, const cv::Mat& b, int rb) { return descriptorRowDistance(a, ra, b, rb); }

}  // namespace

std::vector<int> rotationOutliers(const std::vector<std::pair<int, float>>& pairs) {
  std::array<std::vector<int>, kHistogramBins> bins;
  for (const auto& [index, diff] : pairs) {
    int bin = static_cast<int>(std::round(diff * (1.0f / 360.f) * kHistogramBins));
    if (bin == kHistogramBins) bin = 0;
    bins[bin].push_back(index);
  }
  // The three largest bins (ORB-SLAM2 ComputeThreeMaxima): the 2nd/3rd count only if they hold
  // at least 10 % of the largest.
  int m1 = -1, m2 = -1, m3 = -1;
  size_t c1 = 0, c2 = 0, c3 = 0;
  for (int i = 0; i < kHistogramBins; ++i) {
    const size_t c = bins[i].size();
    if (c > c1) {
      m3 = m2; c3 = c2; m2 = m1; c2 = c1; m1 = i; c1 = c;
    } else if (c > c2) {
      m3 = m2; c3 = c2; m2 = i; c2 = c;
    } else if (c > c3) {
      m3 = i; c3 = c;
    }
  }
  if (c2 < 0.1 * c1) m2 = m3 = -1;
  else if (c3 < 0.1 * c1) m3 = -1;
  std::vector<int> drop;
  for (int i = 0; i < kHistogramBins; ++i) {
    if (i == m1 || i == m2 || i == m3) continue;
    drop.insert(drop.end(), bins[i].begin(), bins[i].end());
  }
  return drop;
}

int matchLastFrame(Frame& current, const Frame& last, float radius_px, bool check_orientation) {
  const Features& cf = current.features;
  const PinholeCamera& cam = *cf.camera;
  const PyramidScales& scales = *cf.scales;
  const SE3& T_cw = current.T_camera_world;
  // Camera centre of the current frame seen from the last one: moving forward makes points
  // appear at coarser levels, backward at finer ones (ORB-SLAM2 SearchByProjection).
  const Vec3 t_last_current = last.T_camera_world * current.center();
  const bool forward = t_last_current.z() > cam.baseline_m;
  const bool backward = -t_last_current.z() > cam.baseline_m;

  std::vector<std::pair<int, float>> rotation_pairs;
  int matches = 0;
  for (int i = 0; i < last.size(); ++i) {
    const MapPointPtr& point = last.map_points[i];
    if (!point || last.outlier[i]) continue;
    const Vec3 p_c = T_cw * point->p_world;
    if (p_c.z() <= 0.0) continue;
    const Eigen::Vector2d uv = cam.project(p_c);
    if (!cf.inBounds(uv.x(), uv.y())) continue;
    const int last_octave = last.features.keypoints[i].octave;
    const float radius = radius_px * scales.scale[last_octave];
    std::vector<int> candidates;
    if (forward) candidates = cf.featuresInArea(uv.x(), uv.y(), radius, last_octave);
    else if (backward) candidates = cf.featuresInArea(uv.x(), uv.y(), radius, 0, last_octave);
    else candidates = cf.featuresInArea(uv.x(), uv.y(), radius, std::max(0, last_octave - 1), last_octave + 1);
    if (candidates.empty()) continue;
    const double u_right = uv.x() - cam.bf() / p_c.z();
    int best_dist = 256, best_index = -1;
    for (const int j : candidates) {
      if (!cf.usable[j]) continue;
      if (current.map_points[j] && current.map_points[j]->numObservations() > 0) continue;
      if (cf.u_right[j] > 0.f && std::abs(u_right - cf.u_right[j]) > radius) continue;
      const int d = distance(point->descriptor, 0, cf.descriptors, j);
      if (d < best_dist) {
        best_dist = d;
        best_index = j;
      }
    }
    if (best_dist <= kDistanceHigh) {
      current.map_points[best_index] = point;
      ++matches;
      if (check_orientation)
        rotation_pairs.emplace_back(best_index, angleDifference(last.features.keypoints[i].angle,
                                                                cf.keypoints[best_index].angle));
    }
  }
  if (check_orientation) {
    for (const int j : rotationOutliers(rotation_pairs)) {
      current.map_points[j].reset();
      --matches;
    }
  }
  return matches;
}

int matchLocalPoints(Frame& frame, const std::vector<MapPointPtr>& points, float radius_factor,
                     float nn_ratio) {
  const Features& f = frame.features;
  const PyramidScales& scales = *f.scales;
  int matches = 0;
  for (const auto& point : points) {
    if (!point->track_in_view || point->bad) continue;
    const int level = point->track_level;
    // Search wider for points seen obliquely (ORB-SLAM2 RadiusByViewingCos).
    float r = point->track_view_cos > 0.998f ? 2.5f : 4.0f;
    r *= radius_factor * scales.scale[level];
    const auto candidates = f.featuresInArea(point->track_u, point->track_v, r, std::max(0, level - 1), level);
    if (candidates.empty()) continue;
    int best = 256, second = 256, best_level = -1, second_level = -1, best_index = -1;
    for (const int j : candidates) {
      if (!f.usable[j]) continue;
      if (frame.map_points[j] && frame.map_points[j]->numObservations() > 0) continue;
      if (f.u_right[j] > 0.f && std::abs(point->track_u_right - f.u_right[j]) > r) continue;
      const int d = distance(point->descriptor, 0, f.descriptors, j);
      if (d < best) {
        second = best;
        second_level = best_level;
        best = d;
        best_level = f.keypoints[j].octave;
        best_index = j;
      } else if (d < second) {
        second = d;
        second_level = f.keypoints[j].octave;
      }
    }
    if (best > kDistanceHigh) continue;
    if (best_level == second_level && best > nn_ratio * second) continue;
    frame.map_points[best_index] = point;
    ++matches;
  }
  return matches;
}

int matchKeyFrame(const KeyFrame& keyframe, Frame& frame, float nn_ratio, bool check_orientation) {
  const Features& kf = keyframe.features;
  const Features& f = frame.features;
  std::vector<int> best_kf_index(f.size(), -1);
  std::vector<int> best_dist(f.size(), 256);
  for (int i = 0; i < kf.size(); ++i) {
    const MapPointPtr& point = keyframe.map_points[i];
    if (!point || point->bad || !kf.usable[i]) continue;
    int best = 256, second = 256, best_j = -1;
    for (int j = 0; j < f.size(); ++j) {
      if (!f.usable[j]) continue;
      const int d = distance(kf.descriptors, i, f.descriptors, j);
      if (d < best) {
        second = best;
        best = d;
        best_j = j;
      } else if (d < second) {
        second = d;
      }
    }
    if (best > kDistanceLow || static_cast<float>(best) >= nn_ratio * second) continue;
    if (best < best_dist[best_j]) {  // one keyframe point per frame keypoint, the closest
      best_dist[best_j] = best;
      best_kf_index[best_j] = i;
    }
  }
  std::vector<std::pair<int, float>> rotation_pairs;
  int matches = 0;
  for (int j = 0; j < f.size(); ++j) {
    if (best_kf_index[j] < 0) continue;
    frame.map_points[j] = keyframe.map_points[best_kf_index[j]];
    ++matches;
    if (check_orientation)
      rotation_pairs.emplace_back(j, angleDifference(kf.keypoints[best_kf_index[j]].angle, f.keypoints[j].angle));
  }
  if (check_orientation) {
    for (const int j : rotationOutliers(rotation_pairs)) {
      frame.map_points[j].reset();
      --matches;
    }
  }
  return matches;
}

std::vector<IndexPair> matchForTriangulation(const KeyFrame& kf1, const KeyFrame& kf2,
                                             const Mat3& F12, bool check_orientation) {
  const Features& f1 = kf1.features;
  const Features& f2 = kf2.features;
  const PinholeCamera& cam = *f1.camera;
  const PyramidScales& scales = *f1.scales;
  // Epipole of camera 1 in image 2: points near it give unreliable depth (ORB-SLAM2).
  const Vec3 c1_in_2 = kf2.T_camera_world() * kf1.center();
  const double inv_z = 1.0 / c1_in_2.z();
  const double ex = cam.fx * c1_in_2.x() * inv_z + cam.cx;
  const double ey = cam.fy * c1_in_2.y() * inv_z + cam.cy;

  std::vector<int> unmatched2;
  for (int j = 0; j < f2.size(); ++j) {
    if (f2.usable[j] && !(kf2.map_points[j] && !kf2.map_points[j]->bad)) unmatched2.push_back(j);
  }
  std::vector<int> match_of_2(f2.size(), -1);
  std::vector<int> dist_of_2(f2.size(), 256);
  for (int i = 0; i < f1.size(); ++i) {
    if (!f1.usable[i] || (kf1.map_points[i] && !kf1.map_points[i]->bad)) continue;
    const bool stereo1 = f1.u_right[i] >= 0.f;
    const Eigen::Vector3d x1(f1.points[i].x, f1.points[i].y, 1.0);
    const Eigen::Vector3d line = x1.transpose() * F12;  // a*u2 + b*v2 + c = 0
    const double line_norm2 = line.x() * line.x() + line.y() * line.y();
    if (line_norm2 == 0.0) continue;
    int best = kDistanceLow + 1, best_j = -1;
    for (const int j : unmatched2) {
      const auto& p2 = f2.points[j];
      const int octave2 = f2.keypoints[j].octave;
      const double num = line.x() * p2.x + line.y() * p2.y + line.z();
      if (num * num / line_norm2 >= 3.84 * scales.sigma2[octave2]) continue;  // chi2(1 dof, 95%)
      const bool stereo2 = f2.u_right[j] >= 0.f;
      if (!stereo1 && !stereo2) {
        const double dx = ex - p2.x, dy = ey - p2.y;
        if (dx * dx + dy * dy < 100.0 * scales.scale[octave2]) continue;
      }
      const int d = distance(f1.descriptors, i, f2.descriptors, j);
      if (d < best) {
        best = d;
        best_j = j;
      }
    }
    if (best_j < 0 || best > kDistanceLow) continue;
    if (best < dist_of_2[best_j]) {
      dist_of_2[best_j] = best;
      match_of_2[best_j] = i;
    }
  }
  std::vector<IndexPair> pairs;
  std::vector<std::pair<int, float>> rotation_pairs;
  for (int j = 0; j < f2.size(); ++j) {
    if (match_of_2[j] < 0) continue;
    rotation_pairs.emplace_back(static_cast<int>(pairs.size()),
                                angleDifference(f1.keypoints[match_of_2[j]].angle, f2.keypoints[j].angle));
    pairs.push_back({match_of_2[j], j});
  }
  if (check_orientation) {
    std::vector<uint8_t> dropped(pairs.size(), 0);
    for (const int k : rotationOutliers(rotation_pairs)) dropped[k] = 1;
    std::vector<IndexPair> kept;
    for (size_t k = 0; k < pairs.size(); ++k)
      if (!dropped[k]) kept.push_back(pairs[k]);
    pairs = std::move(kept);
  }
  return pairs;
}

int fuse(KeyFrame& keyframe, const std::vector<MapPointPtr>& points, float radius_px) {
  const Features& f = keyframe.features;
  const PinholeCamera& cam = *f.camera;
  const PyramidScales& scales = *f.scales;
  const Vec3 center = keyframe.center();
  int fused = 0;
  for (const auto& point : points) {
    if (!point || point->bad || point->observedBy(&keyframe)) continue;
    const Vec3 p_c = keyframe.T_camera_world() * point->p_world;
    if (p_c.z() <= 0.0) continue;
    const Eigen::Vector2d uv = cam.project(p_c);
    if (!cam.inImage(uv.x(), uv.y())) continue;
    const double u_right = uv.x() - cam.bf() / p_c.z();
    const Vec3 po = point->p_world - center;
    const double dist = po.norm();
    if (dist < point->min_distance_m || dist > point->max_distance_m) continue;
    if (po.dot(point->normal) < 0.5 * dist) continue;  // viewing angle over 60 degrees
    const int level = point->predictLevel(dist, scales);
    const float radius = radius_px * scales.scale[level];
    int best = 256, best_index = -1;
    for (const int j : f.featuresInArea(uv.x(), uv.y(), radius)) {
      if (!f.usable[j]) continue;
      const int octave = f.keypoints[j].octave;
      if (octave < level - 1 || octave > level) continue;
      const double ex = uv.x() - f.points[j].x, ey = uv.y() - f.points[j].y;
      double e2 = ex * ex + ey * ey;
      double threshold = 5.99;  // chi2(2 dof, 95%)
      if (f.u_right[j] >= 0.f) {
        const double er = u_right - f.u_right[j];
        e2 += er * er;
        threshold = 7.8;  // chi2(3 dof, 95%)
      }
      if (e2 * scales.inv_sigma2[octave] > threshold) continue;
      const int d = distance(point->descriptor, 0, f.descriptors, j);
      if (d < best) {
        best = d;
        best_index = j;
      }
    }
    if (best > kDistanceLow) continue;
    const MapPointPtr existing = keyframe.map_points[best_index];
    if (existing && !existing->bad) {
      // Keep the better-observed point, as ORB-SLAM2 does.
      if (existing->numObservations() > point->numObservations()) point->replaceWith(existing);
      else existing->replaceWith(point);
    } else {
      point->addObservation(&keyframe, best_index);
      keyframe.map_points[best_index] = point;
    }
    ++fused;
  }
  return fused;
}

}  // namespace dynanav::matcher

