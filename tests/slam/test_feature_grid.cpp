#include "slam/feature_grid.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>
#include <vector>

#include "core/heap.hpp"
#include "support/heap_figures.hpp"

namespace dynanav {
namespace {

struct Keypoints {
  std::vector<cv::KeyPoint> keypoints;
  std::vector<cv::Point2f> points;
};

// n keypoints spread over a 640 x 480 image (some just outside it), octaves 0-7.
Keypoints randomKeypoints(int n, unsigned seed) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<float> u(-5.f, 645.f), v(-5.f, 485.f);
  std::uniform_int_distribution<int> octave(0, 7);
  Keypoints k;
  for (int i = 0; i < n; ++i) {
    k.points.emplace_back(u(rng), v(rng));
    k.keypoints.emplace_back(k.points.back(), 7.f, -1.f, 0.f, octave(rng));
  }
  return k;
}

// The grid only narrows the search: it must return exactly the keypoints a scan of all of them
// finds inside the square, in increasing order, whatever the radius and the level limits.
TEST(FeatureGrid, FindsExactlyWhatAFullScanFinds) {
  const Keypoints k = randomKeypoints(1500, 7);
  const cv::Rect2d bounds(0, 0, 640, 480);
  const FeatureGrid grid(k.points, bounds);
  std::mt19937 rng(11);
  std::uniform_real_distribution<float> x(-20.f, 660.f), y(-20.f, 500.f), r(1.f, 60.f);
  int found_total = 0;
  for (int query = 0; query < 400; ++query) {
    const float qx = x(rng), qy = y(rng), radius = r(rng);
    const int min_level = query % 3 == 0 ? -1 : query % 4;
    const int max_level = query % 5 == 0 ? -1 : min_level + 2;
    std::vector<int> expected;
    for (int i = 0; i < static_cast<int>(k.points.size()); ++i) {
      const cv::Point2f& p = k.points[i];
      // Indexed where its rounded cell lies in the grid (ORB-SLAM2's PosInGrid: a keypoint within
      // half a cell of the right or bottom edge is not indexed).
      const int cx = static_cast<int>(std::round(p.x * FeatureGrid::kCols / 640.f));
      const int cy = static_cast<int>(std::round(p.y * FeatureGrid::kRows / 480.f));
      if (cx < 0 || cy < 0 || cx >= FeatureGrid::kCols || cy >= FeatureGrid::kRows) continue;
      const int o = k.keypoints[i].octave;
      if (min_level >= 0 && o < min_level) continue;
      if (max_level >= 0 && o > max_level) continue;
      if (std::abs(p.x - qx) < radius && std::abs(p.y - qy) < radius) expected.push_back(i);
    }
    std::vector<int> got =
        grid.featuresInArea(qx, qy, radius, k.keypoints, k.points, min_level, max_level);
    // Cells are visited row by row, so the result is grouped by cell; compare as sets.
    std::sort(got.begin(), got.end());
    ASSERT_EQ(got, expected) << "query " << query << " at (" << qx << ", " << qy << ") r "
                             << radius;
    found_total += static_cast<int>(got.size());
  }
  EXPECT_GT(found_total, 1000);  // the queries did hit keypoints
  EXPECT_TRUE(FeatureGrid().featuresInArea(320, 240, 50, k.keypoints, k.points).empty());
}

// Every keyframe keeps its grid for as long as the map keeps the keyframe: a grid of a frame's
// 1,000 keypoints must cost a few arrays, not a vector per cell (which came to about 100 KiB).
TEST(FeatureGrid, AKeyframesGridCostsLittleMemory) {
#if !DYNANAV_GLIBC_HEAP
  GTEST_SKIP() << "the heap figure needs glibc's allocator";
#else
  const Keypoints k = randomKeypoints(1000, 3);
  const double before_mb = heapInUseMb();
  std::vector<FeatureGrid> grids;
  grids.reserve(20);
  const double reserved_mb = heapInUseMb();
  for (int i = 0; i < 20; ++i) grids.emplace_back(k.points, cv::Rect2d(0, 0, 640, 480));
  const double per_grid_kib = (heapInUseMb() - reserved_mb) * 1024.0 / 20.0;
  EXPECT_GT(reserved_mb, before_mb);
  EXPECT_LT(per_grid_kib, 24.0);  // 3,073 cell starts and 1,000 indices: 16 KiB
  RecordProperty("grid_kib", static_cast<int>(per_grid_kib));
#endif
}

}  // namespace
}  // namespace dynanav
