// A track that left the field of view is remembered (objects.recall_out_of_view_s): a person
// found again where its filter predicts it takes its id back; one found elsewhere, or after the
// memory has run out, is a new track.
#include <gtest/gtest.h>

#include <cmath>

#include "box_instance.hpp"
#include "dynamics/object_tracker.hpp"

using namespace dynanav;

namespace {

constexpr int kW = 640, kH = 480;

struct Frame {
  Instances instances;
  cv::Mat depth_m;
};

/// A standing person 3 m away, 60 x 240 px with its left edge at `left` (none: nobody in view),
/// against a wall 6 m away.
Frame frame(std::optional<int> left) {
  Frame f;
  f.instances = Instances::none(cv::Size(kW, kH));
  f.depth_m = cv::Mat(kH, kW, CV_32F, cv::Scalar(6.0f));
  if (left) {
    const cv::Rect box(*left, 120, 60, 240);
    for (int y = box.y; y < box.y + box.height; ++y)
      for (int x = box.x; x < box.x + box.width; ++x)
        f.depth_m.at<float>(y, x) = 3.0f + 0.03f * float(x % 5) / 5.f;
    test::addBoxInstance(f.instances, 1, "person", box);
  }
  return f;
}

/// The camera turned `yaw_deg` about its vertical axis.
SE3 turned(double yaw_deg) {
  SE3 T = SE3::Identity();
  T.linear() = Eigen::AngleAxisd(yaw_deg * M_PI / 180.0, Vec3::UnitY()).toRotationMatrix();
  return T;
}

/// The ids reported while the person is in view: 10 frames in view, `away` frames with the head
/// turned 90 degrees away (nobody in view; the flow carries every point out of the image), then
/// 5 frames in view again with its left edge at `back_left`.
std::vector<uint64_t> idsOverTurn(const ObjectTrackingConfig& config, int away, int back_left) {
  ObjectTracker tracker(config, 5);
  FrameDynamics dynamics;
  const cv::Mat still_flow(kH / 2, kW / 2, CV_32FC2, cv::Scalar(0.f, 0.f));
  const cv::Mat turn_flow(kH / 2, kW / 2, CV_32FC2, cv::Scalar(400.f, 0.f));
  std::vector<uint64_t> ids;
  int i = 0;
  const auto step = [&](const Frame& f, const cv::Mat& flow, const SE3& T_world_camera) {
    const auto out = tracker.track({i, i / 30.0, f.instances, dynamics, flow, f.depth_m,
                                    T_world_camera, true, PinholeCamera{}});
    ++i;
    for (const TrackedObject& o : out) ids.push_back(o.id);
  };
  const Frame seen = frame(290), back = frame(back_left), nobody = frame(std::nullopt);
  for (int k = 0; k < 10; ++k) step(seen, still_flow, SE3::Identity());
  ids.clear();  // only what is reported after the turn
  step(nobody, turn_flow, turned(90.0));
  for (int k = 1; k < away; ++k) step(nobody, still_flow, turned(90.0));
  EXPECT_TRUE(ids.empty()) << "out of view, nothing is reported";
  for (int k = 0; k < 5; ++k) step(back, still_flow, SE3::Identity());
  return ids;
}

}  // namespace

TEST(TrackRecall, APersonFoundAgainWhereTheyStoodAfterAHeadTurnKeepsTheirId) {
  const std::vector<uint64_t> ids = idsOverTurn(ObjectTrackingConfig{}, 20, 290);
  ASSERT_EQ(ids.size(), 5u);
  for (const uint64_t id : ids) EXPECT_EQ(id, 1u);
}

TEST(TrackRecall, WithoutTheMemoryTheyAreANewTrack) {
  ObjectTrackingConfig config;
  config.recall_out_of_view_s = 0.0;
  const std::vector<uint64_t> ids = idsOverTurn(config, 20, 290);
  ASSERT_EQ(ids.size(), 5u);
  for (const uint64_t id : ids) EXPECT_EQ(id, 2u);
}

TEST(TrackRecall, APersonFoundElsewhereOrAfterTheMemoryRunsOutIsANewTrack) {
  // 200 px to the side at 3 m is 1.1 m from where the standing person was left.
  for (const uint64_t id : idsOverTurn(ObjectTrackingConfig{}, 20, 90)) EXPECT_EQ(id, 2u);
  // Away for 3 s (90 frames), beyond the 2 s memory.
  for (const uint64_t id : idsOverTurn(ObjectTrackingConfig{}, 90, 290)) EXPECT_EQ(id, 2u);
}
