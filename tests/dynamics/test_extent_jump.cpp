// ObjectTracker: an object that does not move by itself whose segment switches to another
// extent (merged with a neighbour's) restarts its filter instead of reading the jump as speed.
#include <gtest/gtest.h>

#include "dynamics/object_tracker.hpp"

using namespace dynanav;

namespace {

constexpr int kW = 640, kH = 480;

/// Two chairs side by side 2 m away (columns 100-159 and 160-399, rows 150-269) on a wall 4 m
/// away, nothing moving (zero flow). The segmenter reports the first alone, or (`merged`) one
/// segment covering both (its centre 0.5 m to the right of the first's).
struct Scene {
  Instances instances;
  cv::Mat depth_m;
  cv::Mat flow_half;
};
Scene scene(bool merged) {
  Scene s;
  s.instances = Instances::none(cv::Size(kW, kH));
  s.depth_m = cv::Mat(kH, kW, CV_32F, cv::Scalar(4.0f));
  const cv::Rect both(100, 150, 300, 120);
  for (int y = both.y; y < both.br().y; ++y)
    for (int x = both.x; x < both.br().x; ++x)
      s.depth_m.at<float>(y, x) = 2.0f + 0.05f * float(x % 9) / 9.f + 0.02f * float(y % 5);
  const cv::Rect first(100, 150, 60, 120);
  s.instances.labels(merged ? both : first).setTo(1);
  Instance it;
  it.id = 1;
  it.class_name = "chair";
  it.box = merged ? both : first;
  s.instances.items.push_back(it);
  s.flow_half = cv::Mat(kH / 2, kW / 2, CV_32FC2, cv::Scalar(0.f, 0.f));
  return s;
}

/// The chair's reports over 20 frames; the segments merge from frame 10, and the dynamics stage
/// (falsely) finds the segment moving in frames 9-13.
std::vector<TrackedObject> run(const ObjectTrackingConfig& config) {
  ObjectTracker tracker(config, 5);
  const PinholeCamera camera;
  std::vector<TrackedObject> reports;
  for (int i = 0; i < 20; ++i) {
    const Scene s = scene(i >= 10);
    FrameDynamics dynamics;
    if (i >= 9 && i <= 13) dynamics.moving_ids.push_back(1);
    const auto out = tracker.track({i, i / 30.0, s.instances, dynamics, s.flow_half, s.depth_m,
                                    SE3::Identity(), true, camera});
    EXPECT_EQ(out.size(), 1u) << "frame " << i;
    reports.push_back(out.empty() ? TrackedObject{} : out[0]);
  }
  return reports;
}

}  // namespace

TEST(ObjectTracker, AChairWhoseSegmentJumpsToANeighboursRestartsInsteadOfSpeeding) {
  ObjectTrackingConfig config;
  const auto restarted = run(config);
  config.restart_beyond_gate = false;
  const auto followed = run(config);
  double fastest_restarted = 0.0, fastest_followed = 0.0;
  for (size_t i = 10; i < restarted.size(); ++i) {
    EXPECT_EQ(restarted[i].id, restarted[0].id) << "frame " << i;  // the same track, restarted
    EXPECT_EQ(restarted[i].restarted, i == 10) << "frame " << i;
    fastest_restarted = std::max(fastest_restarted, restarted[i].speed_mps);
    fastest_followed = std::max(fastest_followed, followed[i].speed_mps);
  }
  EXPECT_FALSE(followed[10].restarted);
  // The centre moved 0.5 m in one frame: followed, that reads as a walker's speed (measured
  // 0.78 m/s at most); restarted, the chair's points (which did not move) say it stands (0).
  EXPECT_GT(fastest_followed, 0.5);
  EXPECT_LT(fastest_restarted, 0.2);
  // Either way the track now sits on the merged segment's centre.
  EXPECT_NEAR(restarted.back().p_world.x(), followed.back().p_world.x(), 0.1);
}
