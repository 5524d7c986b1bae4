#pragma once
// Largest distance (m, or rad for the rotation) between a keyframe's final pose (keyframes.txt)
// and the pose trajectory.txt writes for the frame that became it. Each frame is anchored on its
// reference keyframe with the relative pose it was tracked at, so a keyframe's own frame moves
// with it through local bundle adjustment and loop correction (it did not while the relative pose
// was taken after them: 2.9 m off at a loop frame on Bonn crowd with `--segmenter none`).
#include <algorithm>
#include <filesystem>

#include "core/se3.hpp"
#include "io/trajectory.hpp"

namespace dynanav::test {

inline double keyframeFrameGap(const std::filesystem::path& out) {
  const auto keyframes = readTrajectory(out / "keyframes.txt");
  const auto frames = readTrajectory(out / "trajectory.txt");
  double gap = keyframes.empty() ? 1e9 : 0.0;
  for (const StampedPose& kf : keyframes) {
    const auto same = std::find_if(frames.begin(), frames.end(),
                                   [&](const StampedPose& f) { return f.stamp_s == kf.stamp_s; });
    if (same == frames.end()) return 1e9;
    gap = std::max(gap,
                   (same->T_world_camera.translation() - kf.T_world_camera.translation()).norm());
    gap = std::max(
        gap, rotationAngle(same->T_world_camera.linear().transpose() * kf.T_world_camera.linear()));
  }
  return gap;
}

}  // namespace dynanav::test
