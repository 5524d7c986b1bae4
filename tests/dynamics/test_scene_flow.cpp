#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "dynamics/scene_flow.hpp"

using namespace dynanav;

namespace {
/// An 80 x 60 px pinhole camera, f = 50 px, centred.
PinholeCamera smallCamera() {
  PinholeCamera cam;
  cam.width = 80;
  cam.height = 60;
  cam.fx = cam.fy = 50;
  cam.cx = 40;
  cam.cy = 30;
  return cam;
}
std::vector<Vec3> blob(int n, const Vec3& centre, std::mt19937& rng) {
  std::normal_distribution<double> d(0.0, 0.15);
  std::vector<Vec3> points;
  for (int i = 0; i < n; ++i) points.push_back(centre + Vec3(d(rng), 2 * d(rng), 0.3 * d(rng)));
  return points;
}
/// p with the sensor's depth noise (depth_noise_per_z2 * z^2) along its viewing ray.
Vec3 withRayNoise(const Vec3& p, const DynamicsConfig& c, std::mt19937& rng) {
  std::normal_distribution<double> unit(0.0, 1.0);
  const double sigma = c.depth_noise_per_z2 * p.z() * p.z();
  return Vec3(p * (1.0 + sigma * unit(rng) / p.norm()));
}
}  // namespace

TEST(SceneFlow, EgoMotionAloneIsStatic) {
  std::mt19937 rng(3);
  DynamicsConfig c;
  const auto p_prev = blob(200, Vec3(0.2, 0, 2.5), rng);
  const SE3 T_cur_prev =
      makeSE3(Quat(Eigen::AngleAxisd(0.03, Vec3::UnitY())), Vec3(0.02, 0, -0.04));
  std::normal_distribution<double> noise(0.0, 0.004);
  std::vector<Vec3> p_cur;
  for (const auto& p : p_prev)
    p_cur.push_back(T_cur_prev * p + Vec3(noise(rng), noise(rng), noise(rng)));
  const auto v = sceneFlowVerdict(p_prev, p_cur, T_cur_prev, c);
  EXPECT_TRUE(v.decided);
  EXPECT_FALSE(v.dynamic);
  EXPECT_LT(v.mean_flow_m, 0.01);
}

TEST(SceneFlow, WalkingPersonIsDynamic) {
  std::mt19937 rng(4);
  DynamicsConfig c;
  const auto p_prev = blob(200, Vec3(-0.3, 0, 3.0), rng);
  const SE3 T_cur_prev = makeSE3(Quat(Eigen::AngleAxisd(0.01, Vec3::UnitY())), Vec3(0, 0, -0.03));
  // 1.2 m/s over the verifier's gap (3 frames at 30 frames/s): 0.12 m.
  const Vec3 walk(1.2 * c.scene_flow_gap_frames / 30.0, 0, 0);
  std::vector<Vec3> p_cur;
  for (size_t i = 0; i < p_prev.size(); ++i) {
    // Arms and legs swing: only 60 % of the body moves by the full step in this frame.
    p_cur.push_back(T_cur_prev * (p_prev[i] + (i % 5 < 3 ? walk : Vec3::Zero())));
  }
  const auto v = sceneFlowVerdict(p_prev, p_cur, T_cur_prev, c);
  EXPECT_TRUE(v.dynamic);
  EXPECT_NEAR(double(v.moving) / v.points, 0.6, 1e-9);
}

TEST(SceneFlow, FewPointsGiveNoVerdict) {
  DynamicsConfig c;
  const std::vector<Vec3> a = {Vec3(0, 0, 1), Vec3(0, 0, 2)};
  const std::vector<Vec3> b = {Vec3(1, 0, 1), Vec3(1, 0, 2)};
  const auto v = sceneFlowVerdict(a, b, SE3::Identity(), c);
  EXPECT_FALSE(v.decided);
  EXPECT_FALSE(v.dynamic);
}

TEST(SceneFlow, SamplingAndLiftingThroughFlow) {
  const PinholeCamera cam = smallCamera();
  cv::Mat mask = cv::Mat::zeros(60, 80, CV_8U);
  mask(cv::Rect(20, 10, 20, 20)).setTo(255);
  const auto pixels = sampleMaskPixels(mask, 5);
  EXPECT_EQ(pixels.size(), 16u);  // 4 x 4 grid points inside a 20 x 20 square
  for (const auto& p : pixels) EXPECT_TRUE(mask.at<uchar>(p));

  // Flow of +3 px in x everywhere; depth 2 m before, 2.1 m after (hole at one target pixel).
  cv::Mat flow(60, 80, CV_32FC2, cv::Scalar(3.f, 0.f));
  cv::Mat d0(60, 80, CV_32F, cv::Scalar(2.f)), d1(60, 80, CV_32F, cv::Scalar(2.1f));
  d1.at<float>(pixels[0].y, pixels[0].x + 3) = 0.f;
  std::vector<Vec3> a, b;
  std::vector<size_t> kept;
  liftFlowCorrespondences(pixels, flow, d0, d1, cam, a, b, &kept);
  ASSERT_EQ(a.size(), pixels.size() - 1);
  EXPECT_EQ(kept.front(), 1u);
  EXPECT_NEAR(a[0].z(), 2.0, 1e-6);
  EXPECT_NEAR(b[0].z(), 2.1, 1e-6);
  EXPECT_NEAR(b[0].x(), (pixels[1].x + 3 - 40) * 2.1 / 50.0, 1e-6);
}

TEST(SceneFlow, AFlowEndOneOrTwoPixelsOffAThinPoleReadsThePolesDepthWithTheSearch) {
  const PinholeCamera cam = smallCamera();
  // A static pole 3 px wide at 1.5 m before a wall at 4 m; nothing moves, but the flow at the
  // pole's pixels is 2 px off (a patch-based flow blends the pole into the wall beside it).
  cv::Mat depth(60, 80, CV_32F, cv::Scalar(4.f));
  depth.colRange(39, 42).setTo(1.5f);
  const cv::Mat flow(60, 80, CV_32FC2, cv::Scalar(2.f, 0.f));
  const std::vector<cv::Point> pixels = {{40, 20}, {40, 30}, {40, 40}};
  std::vector<Vec3> a, b;
  liftFlowCorrespondences(pixels, flow, depth, depth, cam, a, b);
  ASSERT_EQ(b.size(), 3u);
  for (const Vec3& p : b) EXPECT_FLOAT_EQ(float(p.z()), 4.f);  // the wall: moved 2.5 m
  const DynamicsConfig config;
  FlowEndDepth search;
  search.radius_px = 2;
  search.config = &config;
  liftFlowCorrespondences(pixels, flow, depth, depth, cam, a, b, nullptr, search);
  ASSERT_EQ(b.size(), 3u);
  for (const Vec3& p : b) EXPECT_FLOAT_EQ(float(p.z()), 1.5f);
  // A pole that did come 0.5 m nearer still moves: no depth near 1.5 m lies within the window.
  cv::Mat nearer(60, 80, CV_32F, cv::Scalar(4.f));
  nearer.colRange(39, 42).setTo(1.0f);
  liftFlowCorrespondences(pixels, flow, depth, nearer, cam, a, b, nullptr, search);
  ASSERT_EQ(b.size(), 3u);
  for (const Vec3& p : b) EXPECT_FLOAT_EQ(float(p.z()), 1.0f);
}

TEST(SceneFlow, TheSearchAtAFlowsEndWidensByThePointsParallax) {
  DynamicsConfig config;
  FlowEndDepth search;
  search.config = &config;
  search.T_cur_prev.translation() = Vec3(0.03, 0.0, 0.04);  // 5 cm over the gap
  EXPECT_EQ(flowEndSearchRadiusPx(search, 1.5, 500.0), 0);  // no search at all
  search.radius_px = 2;
  EXPECT_EQ(flowEndSearchRadiusPx(search, 1.5, 500.0), 2);  // parallax off
  search.parallax = true;
  // 500 px * 0.05 m / 1.5 m = 16.7 px of parallax at 1.5 m, 5 px at 5 m.
  EXPECT_EQ(flowEndSearchRadiusPx(search, 1.5, 500.0), 19);
  EXPECT_EQ(flowEndSearchRadiusPx(search, 5.0, 500.0), 7);
  config.depth_test_max_radius_px = 10;  // capped
  EXPECT_EQ(flowEndSearchRadiusPx(search, 1.5, 500.0), 10);
  search.T_cur_prev = SE3::Identity();  // a camera that only turns gives no parallax
  search.T_cur_prev.linear() = Eigen::AngleAxisd(0.2, Vec3::UnitY()).toRotationMatrix();
  EXPECT_EQ(flowEndSearchRadiusPx(search, 1.5, 500.0), 2);
}

TEST(SceneFlow, OnOneNoisySurfaceTheFlowEndKeepsItsOwnDepth) {
  const PinholeCamera cam = smallCamera();
  // A walker 4 m away came 9 cm nearer; depth noise 2.6 cm per pixel. The nearest of the 25
  // noisy depths around each end would take back most of the 9 cm: the search must not look.
  std::mt19937 rng(3);
  std::normal_distribution<float> noise(0.f, 0.026f);
  cv::Mat before(60, 80, CV_32F, cv::Scalar(4.f)), after(60, 80, CV_32F);
  for (int v = 0; v < 60; ++v)
    for (int u = 0; u < 80; ++u) after.at<float>(v, u) = 3.91f + noise(rng);
  const cv::Mat still(60, 80, CV_32FC2, cv::Scalar(0.f, 0.f));
  const auto pixels = sampleMaskPixels(cv::Mat(60, 80, CV_8U, cv::Scalar(255)), 10);
  const DynamicsConfig config;
  FlowEndDepth search;
  search.radius_px = 2;
  search.config = &config;
  std::vector<Vec3> a, b, a_own, b_own;
  liftFlowCorrespondences(pixels, still, before, after, cam, a, b, nullptr, search);
  liftFlowCorrespondences(pixels, still, before, after, cam, a_own, b_own);
  ASSERT_EQ(b.size(), b_own.size());
  for (size_t i = 0; i < b.size(); ++i) EXPECT_EQ(b[i].z(), b_own[i].z());
}

namespace {

TEST(SceneFlow, LabelFollowsTheFlowNotTheOldMask) {
  // A 20 px wide object moved 30 px right: its old and new masks do not overlap at all.
  cv::Mat labels(100, 200, CV_16U, cv::Scalar(0));
  labels(cv::Rect(80, 20, 20, 60)).setTo(7);
  cv::Mat old_mask(100, 200, CV_8U, cv::Scalar(0));
  old_mask(cv::Rect(50, 20, 20, 60)).setTo(255);
  const auto pixels = sampleMaskPixels(old_mask, 5);
  const cv::Mat moved(100, 200, CV_32FC2, cv::Scalar(30.f, 0.f));
  EXPECT_EQ(labelAlongFlow(labels, pixels, moved), 7);
  const cv::Mat still(100, 200, CV_32FC2, cv::Scalar(0.f, 0.f));
  EXPECT_EQ(labelAlongFlow(labels, pixels, still), 0);  // without the flow: nothing there
  const cv::Mat out_of_view(100, 200, CV_32FC2, cv::Scalar(500.f, 0.f));
  EXPECT_EQ(labelAlongFlow(labels, pixels, out_of_view), 0);
  labels(cv::Rect(50, 20, 20, 60)).setTo(3);  // something now stands where the object was
  EXPECT_EQ(labelAlongFlow(labels, pixels, cv::Mat()), 3);  // empty flow: where the pixels were
}

}  // namespace

TEST(SceneFlow, PointThresholdGrowsWithDepthNoise) {
  DynamicsConfig c;
  EXPECT_DOUBLE_EQ(sceneFlowPointThreshold(1.0, 1.0, c), c.scene_flow_point_m);  // near: fixed
  // 4 m: sigma 0.0016 * 16 = 2.56 cm per end, 3 * sqrt(2) * 2.56 cm = 10.9 cm.
  EXPECT_NEAR(sceneFlowPointThreshold(4.0, 4.0, c), 3.0 * std::sqrt(2.0) * 0.0256, 1e-9);
  c.scene_flow_point_sigmas = 0;
  EXPECT_DOUBLE_EQ(sceneFlowPointThreshold(4.0, 4.0, c), c.scene_flow_point_m);
}

TEST(SceneFlow, FarStaticObjectWithEgoMotionErrorStaysStaticWalkerStillMoves) {
  // A chair 4 m away; the pose error leaves 2.5 cm of apparent motion and the sensor adds its
  // z^2 noise along each ray: with a fixed 2 cm point threshold over half its points "move".
  std::mt19937 rng(5);
  DynamicsConfig c;
  const auto p_prev = blob(200, Vec3(0.5, 0, 4.0), rng);
  auto noisy = [&](const Vec3& p) { return withRayNoise(p, c, rng); };
  const Vec3 pose_error(0.025, 0, 0);
  std::vector<Vec3> chair_prev, chair_cur, walker_cur;
  for (const auto& p : p_prev) {
    chair_prev.push_back(noisy(p));
    chair_cur.push_back(noisy(p) + pose_error);
    walker_cur.push_back(noisy(p) + pose_error + Vec3(0.12, 0, 0));  // 1.2 m/s over 3 frames
  }
  DynamicsConfig fixed = c;
  fixed.scene_flow_point_sigmas = 0;
  EXPECT_TRUE(sceneFlowVerdict(chair_prev, chair_cur, SE3::Identity(), fixed).dynamic);
  EXPECT_FALSE(sceneFlowVerdict(chair_prev, chair_cur, SE3::Identity(), c).dynamic);
  EXPECT_TRUE(sceneFlowVerdict(chair_prev, walker_cur, SE3::Identity(), c).dynamic);
}

TEST(SceneFlow, StillNeedsTheObjectsMeanToStayPutNotOnlyItsPoints) {
  // 4 m away: a person standing, and one walking 0.8 m/s (8 cm over the verifier's 3 frames,
  // below each point's noise-grown threshold of 10.9 cm). Neither is dynamic; only the one whose
  // mean displacement stays within scene_flow_point_m is still (a walker must not be called
  // "verified static": the tracker would hold its speed at 0).
  std::mt19937 rng(6);
  DynamicsConfig c;
  const auto p_prev = blob(200, Vec3(0.5, 0, 4.0), rng);
  auto noisy = [&](const Vec3& p) { return withRayNoise(p, c, rng); };
  std::vector<Vec3> prev, standing, walking;
  for (const auto& p : p_prev) {
    prev.push_back(noisy(p));
    standing.push_back(noisy(p));
    walking.push_back(noisy(p) + Vec3(0.08, 0, 0));
  }
  const auto still = sceneFlowVerdict(prev, standing, SE3::Identity(), c);
  EXPECT_TRUE(still.decided);
  EXPECT_FALSE(still.dynamic);
  EXPECT_TRUE(still.still);
  const auto walker = sceneFlowVerdict(prev, walking, SE3::Identity(), c);
  EXPECT_TRUE(walker.decided);
  EXPECT_FALSE(walker.dynamic);
  EXPECT_FALSE(walker.still);
  // Too few points: no verdict of either kind.
  EXPECT_FALSE(sceneFlowVerdict({Vec3(0, 0, 1)}, {Vec3(0, 0, 1)}, SE3::Identity(), c).still);
}

TEST(SceneFlow, BackgroundMotionIsItsMedianAndRobustSpread) {
  // The surroundings shifted 5 cm sideways with 1 cm of noise per axis; a fifth of them dragged
  // 40 cm along by a walker's flow. The median and the spread ignore the dragged fifth.
  std::mt19937 rng(7);
  DynamicsConfig c;
  const auto prev = blob(400, Vec3(0, 0, 2.5), rng);
  std::normal_distribution<double> noise(0.0, 0.01);
  std::vector<Vec3> cur;
  for (size_t i = 0; i < prev.size(); ++i)
    cur.push_back(prev[i] + Vec3(0.05, 0, 0) + Vec3(noise(rng), noise(rng), noise(rng)) +
                  (i % 5 == 0 ? Vec3(0.4, 0, 0) : Vec3::Zero()));
  const BackgroundMotion m = backgroundMotion(prev, cur, SE3::Identity(), c);
  EXPECT_NEAR(m.displacement_m.x(), 0.05, 0.005);
  EXPECT_NEAR(m.displacement_m.y(), 0.0, 0.005);
  EXPECT_NEAR(m.sigma_m, 0.01, 0.004);
  // Too few points for surroundings: none, and the verdict is the camera-only one.
  const std::vector<Vec3> few(prev.begin(), prev.begin() + c.scene_flow_min_points - 1);
  const BackgroundMotion none = backgroundMotion(few, few, SE3::Identity(), c);
  EXPECT_EQ(none.displacement_m, Vec3::Zero());
  EXPECT_EQ(none.sigma_m, 0.0);
}

TEST(SceneFlow, AnObjectDisplacedWithItsSurroundingsIsNotMovingAPushedOneIs) {
  // A chair 2.2 m away whose flow is off by 5 cm, as is its surroundings' (a blurred turn, or a
  // walker's flow dragged over both): against the camera's motion alone it moves; against its
  // surroundings it does not. Pushed 6 cm past still surroundings, it moves either way.
  std::mt19937 rng(8);
  DynamicsConfig c;
  auto noisy = [&](const Vec3& p) { return withRayNoise(p, c, rng); };
  const auto chair = blob(200, Vec3(0.3, 0.2, 2.2), rng);
  const auto around = blob(300, Vec3(0.3, 0.2, 2.4), rng);
  const Vec3 flow_error(0.05, 0, 0), push(0.06, 0, 0);
  std::vector<Vec3> chair_prev, chair_off, chair_pushed, around_prev, around_off, around_still;
  for (const auto& p : chair) {
    chair_prev.push_back(noisy(p));
    chair_off.push_back(noisy(p) + flow_error);
    chair_pushed.push_back(noisy(p) + push);
  }
  for (const auto& p : around) {
    around_prev.push_back(noisy(p));
    around_off.push_back(noisy(p) + flow_error);
    around_still.push_back(noisy(p));
  }
  const SE3 I = SE3::Identity();
  EXPECT_TRUE(sceneFlowVerdict(chair_prev, chair_off, I, c).dynamic);
  const auto off = backgroundMotion(around_prev, around_off, I, c);
  const auto judged = sceneFlowVerdict(chair_prev, chair_off, I, c, off);
  EXPECT_FALSE(judged.dynamic);
  EXPECT_TRUE(judged.still);
  const auto still = backgroundMotion(around_prev, around_still, I, c);
  EXPECT_TRUE(sceneFlowVerdict(chair_prev, chair_pushed, I, c, still).dynamic);
}

TEST(SceneFlow, ScatteredSurroundingsRaiseThePointThreshold) {
  // Dense flow that scatters every point by ~3 cm (its error, not motion): an object scattered
  // like its surroundings has over 30 % of its points past the depth-noise threshold, but not
  // past three of the surroundings' sigmas.
  std::mt19937 rng(9);
  DynamicsConfig c;
  std::normal_distribution<double> scatter(0.0, 0.03);
  auto scattered = [&](const Vec3& p) -> Vec3 { return p + Vec3(scatter(rng), scatter(rng), 0.0); };
  const auto object = blob(200, Vec3(0, 0, 2.0), rng);
  const auto around = blob(300, Vec3(0, 0, 2.2), rng);
  std::vector<Vec3> object_cur, around_cur;
  for (const auto& p : object) object_cur.push_back(scattered(p));
  for (const auto& p : around) around_cur.push_back(scattered(p));
  const SE3 I = SE3::Identity();
  const auto alone = sceneFlowVerdict(object, object_cur, I, c);
  EXPECT_GT(double(alone.moving), c.scene_flow_share * alone.points);
  const auto background = backgroundMotion(around, around_cur, I, c);
  EXPECT_GT(background.sigma_m, 0.015);
  const auto judged = sceneFlowVerdict(object, object_cur, I, c, background);
  EXPECT_LT(double(judged.moving), c.scene_flow_share * judged.points);
  EXPECT_FALSE(judged.dynamic);
}

TEST(SceneFlow, RingPixelsAreTheBackgroundAroundTheObjectOnTheSampleGrid) {
  cv::Mat labels(160, 200, CV_16U, cv::Scalar(0));
  const cv::Rect object(80, 60, 20, 30);
  labels(object).setTo(1);
  labels(cv::Rect(100, 60, 15, 30)).setTo(2);  // another instance right beside it
  const int inner = 10, outer = 30, step = 5;
  const auto pixels = sampleRingPixels(labels == 1, labels, inner, outer, step);
  ASSERT_FALSE(pixels.empty());
  const auto grown = [&](int px) {
    return cv::Rect(object.x - px, object.y - px, object.width + 2 * px, object.height + 2 * px);
  };
  bool left = false;
  for (const cv::Point& p : pixels) {
    EXPECT_EQ(labels.at<uint16_t>(p), 0) << p;          // neither the object nor the other instance
    EXPECT_TRUE(grown(outer + step).contains(p)) << p;  // to the grid's resolution
    EXPECT_FALSE(grown(inner).contains(p)) << p;        // beyond the inner gap
    EXPECT_EQ(p.x % step, step / 2);
    EXPECT_EQ(p.y % step, step / 2);
    left = left || p.x < object.x;
  }
  EXPECT_TRUE(left);
  EXPECT_TRUE(sampleRingPixels(labels == 3, labels, inner, outer, step).empty());  // no object
  EXPECT_TRUE(sampleRingPixels(labels == 1, labels, inner, inner, step).empty());  // no band
}
