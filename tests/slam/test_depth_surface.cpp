// A frame's static depth as a surface (slam/depth_surface.hpp) and as pose evidence beside the
// keypoints (slam/pose_optimizer.hpp, DepthAlignment).
#include <gtest/gtest.h>

#include <random>

#include "slam/depth_surface.hpp"
#include "slam/pose_optimizer.hpp"

namespace dynanav {
namespace {

/// A plane n . X = c in the world (n unit).
struct Plane {
  Vec3 n;
  double c;
};

/// A room 4.5 m wide, its back wall 4 m ahead of the origin, the floor 1.4 m below (y down).
std::vector<Plane> room() {
  return {{Vec3(0, 0, 1), 4.0}, {Vec3(0, 1, 0), 1.4}, {Vec3(-1, 0, 0), 2.0}, {Vec3(1, 0, 0), 2.5}};
}

/// Depth image of `planes` seen from T_camera_world, each pixel's ray the undistorted one of the
/// (distorted) pixel, with the sensor's noise when `rng` is given.
cv::Mat renderDepth(const PinholeCamera& camera, const SE3& T_camera_world,
                    const std::vector<Plane>& planes, std::mt19937* rng = nullptr) {
  std::vector<cv::Point2f> pixels;
  for (int v = 0; v < camera.height; ++v)
    for (int u = 0; u < camera.width; ++u) pixels.emplace_back(float(u), float(v));
  const std::vector<cv::Point2f> rays = camera.undistortPixels(pixels);
  const SE3 T_wc = T_camera_world.inverse();
  cv::Mat depth(camera.height, camera.width, CV_32F, cv::Scalar(0));
  std::normal_distribution<double> unit(0.0, 1.0);
  for (size_t i = 0; i < rays.size(); ++i) {
    const Vec3 d_camera((rays[i].x - camera.cx) / camera.fx, (rays[i].y - camera.cy) / camera.fy,
                        1.0);
    const Vec3 d = T_wc.linear() * d_camera, o = T_wc.translation();
    double best = 1e9;
    for (const Plane& p : planes) {
      const double along = p.n.dot(d);
      if (std::abs(along) < 1e-9) continue;
      const double t = (p.c - p.n.dot(o)) / along;
      if (t > 0.0 && t < best) best = t;
    }
    if (best < 1e8) {
      double z = best;  // d_camera.z() == 1: the ray parameter is the depth
      if (rng) z += depthSigmaM(z) * unit(*rng);
      depth.at<float>(int(pixels[i].y), int(pixels[i].x)) = float(z);
    }
  }
  return depth;
}

/// A keypoint's observation of a world point from T_camera_world: pixel noise of `noise_px`, and
/// depth (the virtual right coordinate) when `with_depth`.
PoseObservation observe(const PinholeCamera& camera, const SE3& T_camera_world, const Vec3& p_world,
                        double noise_px, std::mt19937& rng, bool with_depth) {
  std::normal_distribution<double> noise(0.0, noise_px);
  const Vec3 p_c = T_camera_world * p_world;
  PoseObservation obs;
  obs.p_world = p_world;
  obs.u = camera.fx * p_c.x() / p_c.z() + camera.cx + (noise_px > 0.0 ? noise(rng) : 0.0);
  obs.v = camera.fy * p_c.y() / p_c.z() + camera.cy + (noise_px > 0.0 ? noise(rng) : 0.0);
  if (with_depth) obs.u_right = obs.u - camera.bf() / p_c.z() + (noise_px > 0.0 ? noise(rng) : 0.0);
  return obs;
}

/// A surface's samples placed in the world from the camera pose it was seen at.
std::vector<Vec3> samplesInWorld(const DepthSurface& surface, const SE3& T_camera_world) {
  std::vector<Vec3> out;
  const SE3 T_world_camera = T_camera_world.inverse();
  for (const Vec3& p : surfaceSamples(surface, 8)) out.push_back(T_world_camera * p);
  return out;
}

PinholeCamera undistortedCamera() {
  PinholeCamera camera;
  camera.fx = camera.fy = 525.0;
  camera.cx = 319.5;
  camera.cy = 239.5;
  return camera;
}

TEST(DepthSurface, APlaneGivesItsPointAndNormalAndMaskedOrFarPointsNone) {
  const PinholeCamera camera = undistortedCamera();
  const cv::Mat depth = renderDepth(camera, SE3::Identity(), {{Vec3(0, 0, 1), 3.0}});
  cv::Mat allowed(depth.size(), CV_8U, cv::Scalar(255));
  allowed(cv::Rect(0, 0, 200, 480)).setTo(0);  // a walker's mask on the left
  const DepthSurfaceMaker maker(camera, 8.0);
  const DepthSurface surface = maker.make(depth, allowed);
  ASSERT_EQ(surface.depth_m.size(), cv::Size(320, 240));
  const auto s = surfaceAt(surface, Vec3(0.3, -0.2, 3.01), 0.2);
  ASSERT_TRUE(s);
  EXPECT_NEAR(s->p_camera.z(), 3.0, 1e-5);
  EXPECT_NEAR(s->normal_camera.z(), -1.0, 1e-6);   // toward the camera
  EXPECT_NEAR(s->p_camera.x(), 0.3, 3.0 / 262.5);  // within a surface pixel
  EXPECT_FALSE(surfaceAt(surface, Vec3(-1.0, 0.0, 3.0), 0.2)) << "masked";
  EXPECT_FALSE(surfaceAt(surface, Vec3(0.3, -0.2, 2.5), 0.2)) << "half a metre off the surface";
  EXPECT_FALSE(surfaceAt(surface, Vec3(30.0, 0.0, 3.0), 0.2)) << "off the image";
  const DepthSurfaceMaker near_only(camera, 2.5);
  EXPECT_FALSE(surfaceAt(near_only.make(depth, {}), Vec3(0.3, -0.2, 3.0), 0.2)) << "beyond range";
  // The mask ends at full-size column 200: x = (200 - 319.5) * 3 / 525 = -0.683 m.
  for (const Vec3& p : surfaceSamples(surface, 8)) EXPECT_GT(p.x(), -0.69);
}

TEST(DepthSurface, ADepthEdgeHasNoNormal) {
  const PinholeCamera camera = undistortedCamera();
  cv::Mat depth(480, 640, CV_32F, cv::Scalar(3.0f));
  depth(cv::Rect(320, 0, 320, 480)).setTo(1.5f);  // a door frame's edge at the middle column
  const DepthSurface surface = DepthSurfaceMaker(camera, 8.0).make(depth, {});
  // Surface column 159 is full-size pixels 318-319 (3 m); its neighbour 2 columns right is 1.5 m.
  EXPECT_FALSE(surfaceAt(surface, camera.backproject(318.5, 240.5, 3.0), 0.2));
  EXPECT_TRUE(surfaceAt(surface, camera.backproject(300.5, 240.5, 3.0), 0.2));
}

TEST(DepthSurface, ADistortedCamerasDepthIsPlacedOnItsRays) {
  // fr1's lens moves corner pixels by up to 18 px: read as pinhole pixels, a tilted wall's depth
  // would land centimetres off the wall.
  const PinholeCamera camera = PinholeCamera::tumFreiburg1();
  ASSERT_TRUE(camera.isDistorted());
  const Plane wall{Vec3(-0.3, 0, 1).normalized(), 3.0 / Vec3(-0.3, 0, 1).norm()};
  const cv::Mat depth = renderDepth(camera, SE3::Identity(), {wall});
  const std::vector<Vec3> samples =
      surfaceSamples(DepthSurfaceMaker(camera, 8.0).make(depth, {}), 4);
  ASSERT_GT(samples.size(), 3000u);
  double worst = 0.0;
  for (const Vec3& p : samples) worst = std::max(worst, std::abs(wall.n.dot(p) - wall.c));
  EXPECT_LT(worst, 0.004);  // a full-size pixel's rounding on a wall tilted by 17 degrees
}

TEST(DepthSurface, DepthHoldsAPoseAlongTheDirectionFewKeypointsLeaveWeak) {
  // A crowded frame: 40 keypoints on a 0.6 m patch of the far wall (walkers hide the rest), where
  // a slide sideways and a turn the other way look alike. The room's depth outside the walkers,
  // aligned with the last frame's, tells them apart.
  const PinholeCamera camera = undistortedCamera();
  const PoseCamera pose_camera{camera.fx, camera.fy, camera.cx, camera.cy, camera.bf()};
  const SE3 T_true = makeSE3(Quat(Eigen::AngleAxisd(0.05, Vec3::UnitY())), Vec3(0.1, 0.0, 0.2));
  const SE3 T_last = makeSE3(Quat(Eigen::AngleAxisd(0.04, Vec3::UnitY())), Vec3(0.09, 0.0, 0.19));
  std::mt19937 rng(11);
  std::uniform_real_distribution<double> u01(0.0, 1.0);
  std::vector<PoseObservation> observations;
  const SE3 T_wc = T_true.inverse();
  for (int i = 0; i < 40; ++i) {
    // On the back wall (world z = 4), in front of the true camera.
    const Vec3 p_world(0.1 + (u01(rng) - 0.5) * 0.6, (u01(rng) - 0.5) * 0.4, 4.0);
    observations.push_back(observe(camera, T_true, p_world, 0.7, rng, true));
  }
  const DepthSurfaceMaker maker(camera, 8.0);
  const DepthSurface current = maker.make(renderDepth(camera, T_true, room(), &rng), {});
  const std::vector<Vec3> last_world =
      samplesInWorld(maker.make(renderDepth(camera, T_last, room(), &rng), {}), T_last);
  DepthAlignment depth;
  depth.surface = &current;
  depth.points_world = &last_world;
  depth.effective_samples = 100.0;
  // Start 3 cm to the side and turned 0.4 degrees back: what a motion model might predict.
  const SE3 T_start =
      leftPerturb((Eigen::Matrix<double, 6, 1>() << 0, -0.007, 0, 0.03, 0, 0).finished(), T_true);
  const auto error_m = [&](const SE3& T) {
    return (T.inverse().translation() - T_wc.translation()).norm();
  };
  SE3 T_points = T_start, T_with_depth = T_start;
  std::vector<uint8_t> outlier;
  optimizePose(observations, pose_camera, PoseOptimizerOptions{}, T_points, outlier);
  EXPECT_GT(loosestTranslationSigmaM(observations, outlier, pose_camera, T_points), 0.05)
      << "the keypoints alone hold the position to decimetres along their weak direction";
  depth.min_sigma_m = 0.01;  // the default: they do not hold it to a centimetre, so depth joins
  optimizePose(observations, pose_camera, PoseOptimizerOptions{}, T_with_depth, outlier, depth);
  // Weighed as 100 samples of 1-3 cm noise (the walls 4 m away): about a centimetre.
  EXPECT_LT(error_m(T_with_depth), 0.015) << "keypoints alone " << error_m(T_points);
  EXPECT_GT(error_m(T_points), 10.0 * error_m(T_with_depth))
      << "keypoints alone " << error_m(T_points) << " m, with depth " << error_m(T_with_depth);
}

TEST(DepthSurface, DepthStaysOutWhereTheKeypointsHoldThePose) {
  // 200 keypoints spread over a room hold the position to millimetres; a depth surface seen from
  // 2 cm further back (a stand-in for depth taken at another instant) then changes nothing.
  const PinholeCamera camera = undistortedCamera();
  const PoseCamera pose_camera{camera.fx, camera.fy, camera.cx, camera.cy, camera.bf()};
  std::mt19937 rng(5);
  std::uniform_real_distribution<double> u01(0.0, 1.0);
  std::vector<PoseObservation> observations;
  for (int i = 0; i < 200; ++i) {
    const Vec3 p((u01(rng) - 0.5) * 3.0, (u01(rng) - 0.5) * 2.0, 1.0 + 3.0 * u01(rng));
    observations.push_back(observe(camera, SE3::Identity(), p, 0.7, rng, true));
  }
  const DepthSurfaceMaker maker(camera, 8.0);
  const SE3 T_back = makeSE3(Quat::Identity(), Vec3(0.0, 0.0, 0.02));
  const DepthSurface current = maker.make(renderDepth(camera, T_back, room()), {});
  const std::vector<Vec3> reference =
      samplesInWorld(maker.make(renderDepth(camera, SE3::Identity(), room()), {}), SE3::Identity());
  DepthAlignment depth{&current, &reference, 100.0, 0.01};
  SE3 T_points = makeSE3(Quat::Identity(), Vec3(0.01, 0.0, 0.0));
  SE3 T_gated = T_points, T_always = T_points;
  std::vector<uint8_t> outlier;
  optimizePose(observations, pose_camera, PoseOptimizerOptions{}, T_points, outlier);
  EXPECT_LT(loosestTranslationSigmaM(observations, outlier, pose_camera, T_points), 0.005);
  optimizePose(observations, pose_camera, PoseOptimizerOptions{}, T_gated, outlier, depth);
  EXPECT_TRUE(T_gated.isApprox(T_points));
  depth.min_sigma_m = 0.0;  // always, each sample weighing fully: the surface pulls the pose
  depth.effective_samples = 1e5;
  optimizePose(observations, pose_camera, PoseOptimizerOptions{}, T_always, outlier, depth);
  EXPECT_GT((T_always.translation() - T_points.translation()).norm(), 0.001);
}

TEST(DepthSurface, NoDepthSamplesLeaveThePoseToTheKeypoints) {
  const PinholeCamera camera = undistortedCamera();
  const PoseCamera pose_camera{camera.fx, camera.fy, camera.cx, camera.cy, camera.bf()};
  std::vector<PoseObservation> observations;
  std::mt19937 rng(3);
  std::uniform_real_distribution<double> u01(0.0, 1.0);
  for (int i = 0; i < 60; ++i) {
    const Vec3 p((u01(rng) - 0.5) * 3.0, (u01(rng) - 0.5) * 2.0, 1.0 + 3.0 * u01(rng));
    observations.push_back(observe(camera, SE3::Identity(), p, 0.0, rng, false));
  }
  const DepthSurface empty_surface;
  const std::vector<Vec3> none;
  DepthAlignment depth{&empty_surface, &none, 100.0};
  SE3 a = makeSE3(Quat::Identity(), Vec3(0.02, 0.0, 0.0)), b = a;
  std::vector<uint8_t> outlier;
  optimizePose(observations, pose_camera, PoseOptimizerOptions{}, a, outlier);
  optimizePose(observations, pose_camera, PoseOptimizerOptions{}, b, outlier, depth);
  EXPECT_TRUE(a.isApprox(b));
  EXPECT_LT(a.translation().norm(), 1e-6);
}

}  // namespace
}  // namespace dynanav
