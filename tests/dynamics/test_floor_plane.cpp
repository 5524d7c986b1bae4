// The floor fitted to one depth image (dynamics/floor_plane.hpp) and a walker's range from where
// its soles meet it (dynamics/height_range.hpp, rangeFromFloorContact).
#include <gtest/gtest.h>

#include <cmath>

#include "dynamics/floor_plane.hpp"
#include "dynamics/height_range.hpp"

using namespace dynanav;

namespace {

constexpr double kCameraHeightM = 1.6;
constexpr double kPitchDeg = 5.0;  // looking down

PinholeCamera camera() {
  return {};
}  // the default: 640x480, f = 525 px, centred

/// The floor kCameraHeightM below a camera pitched down kPitchDeg: its upward normal in the
/// camera frame (y down, z ahead) and offset (n . p = offset).
CameraFloor trueFloor() {
  const double pitch = kPitchDeg * M_PI / 180.0;
  CameraFloor floor;
  // Level camera: up = -y. Pitched down by a (about x): the world's up leans toward -z.
  floor.normal_camera = Vec3(0.0, -std::cos(pitch), -std::sin(pitch));
  floor.offset_m = -kCameraHeightM;
  return floor;
}

/// Depth of that floor wherever a pixel's ray meets it within `max_range_m`, and a wall 3 m
/// ahead filling the columns from `wall_from_col` on (0 elsewhere: out of range).
cv::Mat floorDepth(const PinholeCamera& c, double max_range_m, int wall_from_col = 10000) {
  const CameraFloor floor = trueFloor();
  cv::Mat depth(c.height, c.width, CV_32F, cv::Scalar(0.f));
  for (int v = 0; v < c.height; ++v)
    for (int u = 0; u < c.width; ++u) {
      if (u >= wall_from_col) {
        depth.at<float>(v, u) = 3.f;
        continue;
      }
      const Vec3 r((u - c.cx) / c.fx, (v - c.cy) / c.fy, 1.0);
      const double along = floor.normal_camera.dot(r);
      if (along >= 0.0) continue;
      const double s = floor.offset_m / along;
      if ((s * r).norm() <= max_range_m) depth.at<float>(v, u) = float(s);
    }
  return depth;
}

double angleDeg(const Vec3& a, const Vec3& b) {
  return std::acos(std::clamp(a.normalized().dot(b.normalized()), -1.0, 1.0)) * 180.0 / M_PI;
}

}  // namespace

TEST(CameraFloor, FindsATiltedFloorBelowTheCamera) {
  const PinholeCamera c = camera();
  // A wall fills the right third: the floor still holds most of the lower image.
  const auto floor = estimateFloorPlane(floorDepth(c, 4.5, 430), c, Vec3(0.0, -1.0, 0.0));
  ASSERT_TRUE(floor);
  EXPECT_LT(angleDeg(floor->normal_camera, trueFloor().normal_camera), 0.2);
  EXPECT_NEAR(floor->offset_m, -kCameraHeightM, 0.005);
}

TEST(CameraFloor, NoneWhenOnlyAWallIsInView) {
  const PinholeCamera c = camera();
  EXPECT_FALSE(estimateFloorPlane(floorDepth(c, 4.5, 0), c, Vec3(0.0, -1.0, 0.0)));
  EXPECT_FALSE(estimateFloorPlane(cv::Mat(c.height, c.width, CV_32F, cv::Scalar(0.f)), c,
                                  Vec3(0.0, -1.0, 0.0)));
}

TEST(CameraFloor, TheAverageLeavesOutAFitFarFromTheFloor) {
  // Ten frames of the floor, then a table top 0.9 m higher: the average stays on the floor.
  FloorAverage average;
  const SE3 pose = SE3::Identity();
  for (int i = 0; i < 10; ++i) ASSERT_TRUE(average.update(trueFloor(), pose));
  CameraFloor table = trueFloor();
  table.offset_m += 0.9;
  const auto seen = average.update(table, pose);
  ASSERT_TRUE(seen);
  EXPECT_NEAR(seen->offset_m, -kCameraHeightM, 1e-6);
  // The camera rises 0.1 m: the averaged floor is seen 0.1 m further below it.
  SE3 raised = SE3::Identity();
  raised.translation() = 0.1 * trueFloor().normal_camera;  // world = the first camera's frame
  const auto from_raised = average.update(std::nullopt, raised);
  ASSERT_TRUE(from_raised);
  EXPECT_NEAR(from_raised->offset_m, -kCameraHeightM - 0.1, 1e-6);
}

TEST(CameraFloor, TheFeetLeadTheBodyByTheToesAlongTheRayAndByTheShoesSideAcrossIt) {
  const FloorContactOptions options;
  EXPECT_DOUBLE_EQ(footLeadM(options, 1.0), 0.19);  // toward or away from the camera
  EXPECT_DOUBLE_EQ(footLeadM(options, 0.0), 0.05);  // side on
  EXPECT_DOUBLE_EQ(footLeadM(options, 0.5), 0.12);  // in proportion between
  EXPECT_NEAR(footLeadM(options, std::nullopt), 0.05 + 0.14 * 2.0 / M_PI, 1e-12);  // unknown
}

TEST(CameraFloor, TheSolesOnTheFloorPlaceAWalkerWhateverItsStature) {
  // A 1.55 m walker 10 m ahead on the floor of a camera pitched down 5 degrees, facing the
  // camera: the stature prior (1.70 m) reads it ~9 % near; its soles on the floor read it
  // within a few centimetres, the lowest row being its toe tips 0.19 m in front of its axis.
  const PinholeCamera c = camera();
  const CameraFloor floor = trueFloor();
  const Vec3 up = floor.normal_camera;
  const double stature_m = 1.55;
  const Vec3 ahead = (Vec3(0.0, 0.0, 1.0) - up * up.z()).normalized();  // level, ahead
  const Vec3 soles = -kCameraHeightM * up + 10.0 * ahead;
  ASSERT_NEAR(up.dot(soles), floor.offset_m, 1e-9);
  const FloorContactOptions options;
  const double lead_m = footLeadM(options, 1.0);  // walking at the camera
  ASSERT_DOUBLE_EQ(lead_m, options.foot_lead_along_m);
  const Vec3 toes = soles - lead_m * ahead + options.foot_outline_height_m * up;
  const Vec3 crown = soles + stature_m * up;
  const Vec3 torso = crown + kTorsoCentreBelowTop * (soles - crown);
  PersonExtent extent;
  extent.top_px = c.project(crown).y();
  extent.bottom_px = c.project(toes).y();
  extent.column_px = c.project(soles).x();
  const auto contact = rangeFromFloorContact(extent, c, floor, 1.0, options);
  ASSERT_TRUE(contact);
  EXPECT_LT((contact->p_camera - torso).norm(), 0.02);
  EXPECT_GT(contact->scale_sigma, 0.0);
  EXPECT_LT(contact->scale_sigma, 0.05);  // the floor's 2 cm and 0.1 degrees: ~1.5 % at 10 m
  // Read as if the lowest row lay on the floor under the body's axis, it is near: by the toes'
  // lead, less the 12 cm further that the toes' outline 2 cm up puts the ray's floor point.
  FloorContactOptions on_the_axis;
  on_the_axis.foot_lead_along_m = on_the_axis.foot_lead_side_m = 0.0;
  on_the_axis.foot_outline_height_m = 0.0;
  const auto under_axis = rangeFromFloorContact(extent, c, floor, 1.0, on_the_axis);
  ASSERT_TRUE(under_axis);
  EXPECT_LT(under_axis->range_m, torso.norm() - 0.05);
  const auto stature = rangeFromHeight(extent, c, up);
  ASSERT_TRUE(stature);
  EXPECT_GT((stature->p_camera - torso).norm(), 0.06 * torso.norm());
}
