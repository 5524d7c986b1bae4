#pragma once
// The local map around the current frame (ORB-SLAM2 Tracking::UpdateLocalMap): keyframes that
// see the frame's points, their best covisible neighbours, children and parents, and all their
// map points. The keyframe sharing most points becomes the reference keyframe.
#include <vector>

#include "slam/frame.hpp"
#include "slam/keyframe.hpp"

namespace dynanav {

struct LocalMap {
  std::vector<KeyFramePtr> keyframes;  ///< first the direct observers (by id), then neighbours
  std::vector<MapPointPtr> points;
  KeyFramePtr reference;               ///< most shared points with the frame (nullptr if none)
};

/// Rebuilds `local` for `frame` (which has its matches). `lookup` turns raw graph pointers into
/// owning ones (the map's keyframe table).
void updateLocalMap(const Frame& frame, const std::map<uint64_t, KeyFramePtr>& lookup,
                    int max_keyframes, LocalMap& local);

/// ORB-SLAM2 Frame::isInFrustum: projects the point into the frame and, if it is in the image,
/// within its scale-invariance range and seen at under 60 degrees from its mean view direction,
/// stores projection, predicted level and viewing cosine on the point. Returns whether visible.
bool prepareProjection(const Frame& frame, const Vec3& frame_center, MapPoint& point,
                       float min_view_cos = 0.5f);

}  // namespace dynanav
