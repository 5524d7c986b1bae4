// Still points seen through a distorting lens (TUM fr1's colour camera) while the camera moves:
// the flow and the registered depth are in the lens's pixels, the rays are the undistorted ones.
// Lifted along the raw pixels instead, a still point near the image's corner reads as moving (the
// lens's shift, up to 18 px there, changes as the point moves in the image).
#include <gtest/gtest.h>

#include "dynamics/object_tracker.hpp"
#include "dynamics/scene_flow.hpp"

using namespace dynanav;

namespace {

/// The raw (lens) pixel at which camera b sees the still point that camera a sees along the
/// undistorted pixel `ray_px` at `depth_m`; T_b_a maps camera a's coordinates into camera b's.
cv::Point2f rawPixelFrom(const PinholeCamera& cam, const cv::Point2f& ray_px, double depth_m,
                         const SE3& T_b_a) {
  const Vec3 p_b = T_b_a * cam.backproject(ray_px.x, ray_px.y, depth_m);
  const Eigen::Vector2d u = cam.project(p_b);
  const cv::Point2d raw = cam.distortPixel({u.x(), u.y()});
  return {float(raw.x), float(raw.y)};
}

}  // namespace

TEST(LensDistortion, SceneFlowLiftsStillPointsAtTheCornerToOnePlace) {
  // A wall 2 m away, the camera slides 3 cm left and 2 cm up: the lifted ends of every flow
  // vector near the top-left corner are the same world point (within 2 mm; along the raw pixels'
  // rays up to 9.5 mm apart, at the corner pixel).
  const PinholeCamera cam = PinholeCamera::tumFreiburg1();
  const SE3 T_cur_prev = makeSE3(Quat::Identity(), Vec3(0.03, 0.02, 0.0));
  const cv::Mat depth(cam.height, cam.width, CV_32F, cv::Scalar(2.0f));
  cv::Mat flow(cam.height, cam.width, CV_32FC2, cv::Scalar(0.f, 0.f));
  std::vector<cv::Point> starts;
  std::vector<cv::Point2f> raw;
  for (int v = 10; v <= 90; v += 20)
    for (int u = 10; u <= 90; u += 20) starts.emplace_back(u, v), raw.emplace_back(u, v);
  const std::vector<cv::Point2f> rays = cam.undistortPixels(raw);
  for (size_t i = 0; i < starts.size(); ++i) {
    const cv::Point2f end = rawPixelFrom(cam, rays[i], 2.0, T_cur_prev);
    flow.at<cv::Vec2f>(starts[i]) = cv::Vec2f(end.x - raw[i].x, end.y - raw[i].y);
  }
  std::vector<Vec3> p_prev, p_cur;
  liftFlowCorrespondences(starts, flow, depth, depth, cam, p_prev, p_cur);
  ASSERT_EQ(p_prev.size(), starts.size());
  for (size_t i = 0; i < p_prev.size(); ++i)
    EXPECT_LT((p_cur[i] - T_cur_prev * p_prev[i]).norm(), 0.002) << "pixel " << starts[i];
}

TEST(LensDistortion, AStillObjectAtTheCornerStaysWhereItIsWhileTheCameraMoves) {
  // A box 2 m away in the top-left of the view, a wall 4 m away; the camera slides left 1 cm per
  // frame, so the box crosses ~40 px of the lens's strongly distorted corner in 16 frames. Its
  // tracked centre stays within 1.5 cm (lifted along the raw pixels it drifts further).
  const PinholeCamera cam = PinholeCamera::tumFreiburg1();
  std::vector<cv::Point2f> raw;
  for (int v = 0; v < cam.height; ++v)
    for (int u = 0; u < cam.width; ++u) raw.emplace_back(float(u), float(v));
  const std::vector<cv::Point2f> rays = cam.undistortPixels(raw);
  const auto ray = [&](int u, int v) { return rays[size_t(v) * cam.width + u]; };
  // The box's face (world x, y), 2 m away.
  const double x0 = -1.05, x1 = -0.75, y0 = -0.85, y1 = -0.55, box_z = 2.0, wall_z = 4.0;
  const Vec3 step_world(-0.01, 0.0, 0.0);  // the camera's motion per frame
  ObjectTracker tracker(ObjectTrackingConfig{}, 5);
  std::optional<Vec3> first;
  for (int i = 0; i < 16; ++i) {
    const Vec3 camera_world = double(i) * step_world;
    const SE3 T_world_camera = makeSE3(Quat::Identity(), camera_world);
    Instances instances = Instances::none(cv::Size(cam.width, cam.height));
    cv::Mat depth(cam.height, cam.width, CV_32F, cv::Scalar(float(wall_z)));
    cv::Rect box;
    for (int v = 0; v < cam.height; ++v)
      for (int u = 0; u < cam.width; ++u) {
        const Vec3 on_box = camera_world + cam.backproject(ray(u, v).x, ray(u, v).y, box_z);
        if (on_box.x() < x0 || on_box.x() > x1 || on_box.y() < y0 || on_box.y() > y1) continue;
        depth.at<float>(v, u) = float(box_z);
        instances.labels.at<uint16_t>(v, u) = 1;
        box |= cv::Rect(u, v, 1, 1);
      }
    Instance it;
    it.id = 1;
    it.class_name = "box";
    it.box = box;
    instances.items.push_back(it);
    // Flow from the last frame into this one, half size, as FramePrep gives it.
    cv::Mat flow_half(cam.height / 2, cam.width / 2, CV_32FC2, cv::Scalar(0.f, 0.f));
    const SE3 T_now_last = makeSE3(Quat::Identity(), -step_world);
    for (int y = 0; y < flow_half.rows; ++y)
      for (int x = 0; x < flow_half.cols; ++x) {
        const int u = 2 * x, v = 2 * y;
        const Vec3 seen_last =
            camera_world - step_world + cam.backproject(ray(u, v).x, ray(u, v).y, box_z);
        const bool on_box = seen_last.x() >= x0 && seen_last.x() <= x1 && seen_last.y() >= y0 &&
                            seen_last.y() <= y1;
        const cv::Point2f end = rawPixelFrom(cam, ray(u, v), on_box ? box_z : wall_z, T_now_last);
        flow_half.at<cv::Vec2f>(y, x) = cv::Vec2f((end.x - float(u)) / 2, (end.y - float(v)) / 2);
      }
    const FrameDynamics no_verdict;
    const auto out =
        tracker.track({i, i / 30.0, instances, no_verdict, i > 0 ? flow_half : cv::Mat(), depth,
                       T_world_camera, true, cam});
    ASSERT_EQ(out.size(), 1u) << "frame " << i;
    if (!first) first = out[0].p_world;
    EXPECT_LT((out[0].p_world - *first).norm(), 0.015) << "frame " << i;
  }
}
