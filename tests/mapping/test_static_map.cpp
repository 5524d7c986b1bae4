// Unit tests of the static map's pieces (issue 15) on small synthetic inputs.
#include <gtest/gtest.h>

#include <opencv2/imgproc.hpp>

#include "mapping/floor_grid.hpp"
#include "mapping/render_cloud.hpp"
#include "mapping/static_map.hpp"
#include "support/test_support.hpp"

namespace dynanav {
namespace {

TEST(StaticMask, RemovesDynamicInstancesGrownByTheDilation) {
  cv::Mat labels = cv::Mat::zeros(40, 40, CV_16U);
  labels(cv::Rect(10, 10, 5, 5)).setTo(1);  // dynamic
  labels(cv::Rect(25, 25, 5, 5)).setTo(2);  // static
  const cv::Mat m = staticMask(labels, {1}, 2);
  EXPECT_EQ(m.at<uint8_t>(12, 12), 0);
  EXPECT_EQ(m.at<uint8_t>(8, 12), 0);    // 2 px outside the mask: removed too
  EXPECT_EQ(m.at<uint8_t>(5, 12), 255);  // far enough
  EXPECT_EQ(m.at<uint8_t>(27, 27), 255);
}

TEST(KeepKeyframe, DropsDynamicAndFarDepthAndHalvesTheSize) {
  cv::Mat bgr(40, 60, CV_8UC3, cv::Scalar(10, 20, 30));
  cv::Mat depth(40, 60, CV_32F, cv::Scalar(2.0f));
  depth(cv::Rect(0, 0, 30, 40)).setTo(9.0f);  // too far
  cv::Mat mask(40, 60, CV_8U, cv::Scalar(255));
  mask(cv::Rect(40, 0, 20, 40)).setTo(0);  // dynamic
  const MapKeyframe kf = keepKeyframe(1.5, bgr, depth, mask, 2, 4.0);
  ASSERT_EQ(kf.depth_m.size(), cv::Size(30, 20));
  EXPECT_EQ(kf.depth_m.at<float>(5, 5), 0.0f);
  EXPECT_EQ(kf.depth_m.at<float>(5, 17), 2.0f);
  EXPECT_EQ(kf.depth_m.at<float>(5, 25), 0.0f);
  EXPECT_EQ(kf.bgr.at<cv::Vec3b>(3, 3), cv::Vec3b(10, 20, 30));
}

/// A keyframe looking down +z at a wall `wall_m` away, optionally with a block in front.
MapKeyframe wallKeyframe(double stamp, float wall_m, bool block) {
  cv::Mat depth(120, 160, CV_32F, cv::Scalar(wall_m));
  if (block) depth(cv::Rect(60, 40, 40, 40)).setTo(1.5f);
  cv::Mat bgr(120, 160, CV_8UC3, cv::Scalar(100, 150, 200));
  return keepKeyframe(stamp, bgr, depth, cv::Mat(), 1, 4.0);
}

PinholeCamera smallCamera() {
  PinholeCamera c;
  c.width = 160, c.height = 120, c.fx = c.fy = 130, c.cx = 79.5, c.cy = 59.5;
  return c;
}

TEST(DenseCloud, OnePointPerVoxelAtTheMeanWithItsColour) {
  const MapKeyframe kf = wallKeyframe(0, 3.0f, false);
  const cv::Mat rays = rayTable(smallCamera(), 1);
  const ColouredCloud cloud = denseCloud({{&kf, SE3::Identity()}}, rays, 1, 0.05);
  ASSERT_GT(cloud.size(), 100u);
  // Pixels are ~2.3 cm apart at 3 m, so 5 cm voxels merge several of them.
  EXPECT_LT(cloud.size(), size_t(160 * 120) / 2);
  for (size_t i = 0; i < cloud.size(); ++i) {
    EXPECT_NEAR(cloud.p_world[i].z(), 3.0f, 1e-4);
    EXPECT_EQ(cloud.bgr[i], cv::Vec3b(100, 150, 200));
  }
}

// GCC 12 warns falsely on small std::vector<cv::Vec3b> literals (-Wmaybe-uninitialized).
#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wmaybe-uninitialized"
TEST(DenseCloud, PlyRoundTrip) {
  ColouredCloud cloud;
  cloud.p_world = {{1, 2, 3}, {-0.5f, 0.25f, 7}};
  cloud.bgr = {cv::Vec3b(1, 2, 3), cv::Vec3b(250, 128, 0)};
  const auto path = test::scratchDir("ply") / "c.ply";
  writePly(path, cloud);
  const ColouredCloud back = readPly(path);
  ASSERT_EQ(back.size(), 2u);
  EXPECT_EQ(back.p_world[1], cloud.p_world[1]);
  EXPECT_EQ(back.bgr[1], cloud.bgr[1]);
}
#pragma GCC diagnostic pop

TEST(Octree, LaterFreeSpaceClearsABlockThatWentAway) {
  const MapKeyframe before = wallKeyframe(0, 3.0f, true), after = wallKeyframe(1, 3.0f, false);
  const cv::Mat rays = rayTable(smallCamera(), 1);
  OctreeOptions options{0.05, 4.0, 1};
  const auto with_block = buildOctree({{&before, SE3::Identity()}}, rays, options);
  const Vec3 block_centre(0.0, 0.0, 1.5 + 0.02);
  EXPECT_EQ(cellAt(*with_block, block_centre), CellState::kOccupied);
  // One hit (log-odds +0.85) takes three misses (-0.4 each) to undo: OctoMap's defaults.
  const auto still = buildOctree(
      {{&before, SE3::Identity()}, {&after, SE3::Identity()}, {&after, SE3::Identity()}}, rays,
      options);
  EXPECT_EQ(cellAt(*still, block_centre), CellState::kOccupied);
  const auto tree = buildOctree({{&before, SE3::Identity()},
                                 {&after, SE3::Identity()},
                                 {&after, SE3::Identity()},
                                 {&after, SE3::Identity()}},
                                rays, options);
  EXPECT_EQ(cellAt(*tree, block_centre), CellState::kFree);
  EXPECT_EQ(cellAt(*tree, Vec3(0.0, 0.0, 3.02)), CellState::kOccupied);  // the wall stays
  // The standard .bt reads back as a plain OcTree with the same answer.
  const auto path = test::scratchDir("bt") / "m.bt";
  writeBinaryOctree(path, *tree);
  octomap::OcTree plain(0.05);
  ASSERT_TRUE(plain.readBinary(path.string()));
  EXPECT_EQ(cellAt(plain, block_centre), CellState::kFree);
  EXPECT_EQ(cellAt(plain, Vec3(0.0, 0.0, 3.02)), CellState::kOccupied);
}

TEST(Floor, FindsTheLowestLargeHorizontalPlaneAndTheGridAboveIt) {
  // Floor 1.5 m below the camera (y down), tilted 10 degrees about x; a smaller table at 0.8 m.
  const SE3 tilt(Eigen::AngleAxisd(10 * M_PI / 180, Vec3::UnitX()));
  ColouredCloud cloud;
  for (double x = -2; x <= 2; x += 0.05)
    for (double z = 0.5; z <= 4; z += 0.05) {
      cloud.p_world.push_back((tilt * Vec3(x, 1.5, z)).cast<float>());
      cloud.bgr.emplace_back(0, 0, 0);
    }
  for (double x = -0.5; x <= 0.5; x += 0.05)
    for (double z = 1; z <= 2; z += 0.05) {
      cloud.p_world.push_back((tilt * Vec3(x, 0.7, z)).cast<float>());
      cloud.bgr.emplace_back(0, 0, 0);
    }
  const FloorPlane floor = estimateFloor(cloud, {Vec3::Zero()});
  ASSERT_TRUE(floor.found);
  EXPECT_NEAR(floor.height(Vec3::Zero()), 1.5, 0.01);
  EXPECT_GT(floor.up.dot(tilt.linear() * Vec3(0, -1, 0)), std::cos(M_PI / 180));
  const cv::Mat top = renderCloud(cloud, floor, {"top", {200, 150}});
  EXPECT_GT(cv::countNonZero(top.reshape(1) != 40), 1000);
}

TEST(Grid, OccupiedInTheWalkingBandFreeBelowUnknownElsewhere) {
  octomap::ColorOcTree tree(0.05);
  FloorPlane floor;
  floor.found = true;
  floor.up = Vec3(0, -1, 0);
  floor.offset_m = 1.5;  // floor at y = 1.5
  // A column (obstacle at 1.0 m height) and free space at 1.0 m elsewhere; occupied at 0.1 m
  // height (below the band: ignored).
  tree.updateNode(0.0f, 0.5f, 1.0f, true);
  tree.updateNode(1.0f, 0.5f, 1.0f, false);
  tree.updateNode(0.5f, 1.4f, 1.0f, true);
  const OccupancyGrid grid = occupancyGrid(tree, floor, 0.3, 1.8, 0.05);
  ASSERT_FALSE(grid.cells.empty());
  auto at = [&](double x, double z) {
    const cv::Point2f p = grid.pixel(Vec3(x, 1.0, z));
    return grid.cells.at<uint8_t>(int(p.y), int(p.x));
  };
  EXPECT_EQ(at(0.01, 1.01), OccupancyGrid::kOccupied);
  EXPECT_EQ(at(1.01, 1.01), OccupancyGrid::kFree);
  EXPECT_EQ(at(0.51, 1.01), OccupancyGrid::kUnknown);
}

}  // namespace
}  // namespace dynanav
