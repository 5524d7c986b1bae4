#include <gtest/gtest.h>

#include <cmath>
#include <functional>

#include "dynamics/residual_movers.hpp"
#include "slam/keyframe.hpp"
#include "slam/keypoint_drop.hpp"
#include "slam/observation_noise.hpp"
#include "slam/pyramid.hpp"

using namespace dynanav;

namespace {
/// A frame with no map points: what findResidualMovers reads of it is the keypoints' pixels and
/// depths; residuals are given beside it.
struct Scene {
  Frame frame;
  std::vector<MapResidual> residuals;

  void add(cv::Point2f px, float depth_m, bool young, Eigen::Vector2f residual_px) {
    Features& f = frame.features;
    f.keypoints.emplace_back(px, 31.f);
    f.points.push_back(px);
    f.depth_m.push_back(depth_m);
    f.usable.push_back(1);
    f.instance_id.push_back(0);
    frame.map_points.push_back(nullptr);
    frame.outlier.push_back(0);
    MapResidual r;
    r.valid = true;
    r.young = young;
    r.du_px = residual_px.x();
    r.dv_px = residual_px.y();
    residuals.push_back(r);
  }
};

/// Noise of about half a pixel that is the same on every run.
Eigen::Vector2f noise(int i) {
  return {0.5f * std::sin(1.7f * i), 0.5f * std::cos(2.3f * i)};
}

/// 60 young background points on a 10 x 6 grid 3 m away, plus a compact patch of `patch` young
/// points 1 m away around (560, 300), all off by `patch_px` (the background by `common_px`).
Scene withPatch(int patch, Eigen::Vector2f patch_px, Eigen::Vector2f common_px = {0, 0},
                bool patch_young = true) {
  Scene s;
  for (int i = 0; i < 60; ++i)
    s.add({40.f + 50.f * (i % 10), 40.f + 70.f * (i / 10)}, 3.f, true, common_px + noise(i));
  for (int k = 0; k < patch; ++k)
    s.add({550.f + 10.f * (k % 3), 280.f + 10.f * (k / 3)}, 1.f, patch_young,
          common_px + patch_px + noise(100 + k));
  return s;
}

std::vector<int> patchIndices(int patch) {
  std::vector<int> out;
  for (int k = 0; k < patch; ++k) out.push_back(60 + k);
  return out;
}
}  // namespace

TEST(ResidualMovers, AYoungPatchMovingTogetherIsAMoverAndNothingElse) {
  const DynamicsConfig c;
  const Scene s = withPatch(10, {4.f, -1.f});
  const ResidualMovers movers = findResidualMovers(s.frame, s.residuals, c);
  EXPECT_EQ(movers.regions, 1);
  EXPECT_EQ(movers.keypoints, patchIndices(10));
}

TEST(ResidualMovers, NoiseAndSmallCommonErrorsAreNotMotion) {
  const DynamicsConfig c;
  // Half a pixel of noise everywhere, and a patch whose mean is significant but under 2 px.
  Scene s = withPatch(10, {1.2f, 0.f});
  EXPECT_TRUE(findResidualMovers(s.frame, s.residuals, c).keypoints.empty());
  // Every young point off by 3 px: their keyframe's error, not motion...
  s = withPatch(10, {0.f, 0.f}, {3.f, 0.f});
  EXPECT_TRUE(findResidualMovers(s.frame, s.residuals, c).keypoints.empty());
  // ...against which a patch off by 4 px more still moves.
  s = withPatch(10, {4.f, 0.f}, {3.f, 0.f});
  EXPECT_EQ(findResidualMovers(s.frame, s.residuals, c).keypoints, patchIndices(10));
}

namespace {
/// The patch's keypoints blurred along x by `blur_sigma_px` (a fast yaw; slam/observation_noise).
void blurPatch(Scene& s, int patch, double blur_sigma_px) {
  for (int k = 0; k < patch; ++k) {
    MapResidual& r = s.residuals[size_t(60 + k)];
    const Eigen::Matrix3d W =
        measurementSqrtInformation(1.0, Eigen::Vector2d(blur_sigma_px, 0.0), false);
    r.blurred = true;
    r.whitened = (W.topLeftCorner<2, 2>() * Eigen::Vector2d(r.du_px, r.dv_px)).cast<float>();
  }
}
}  // namespace

TEST(ResidualMovers, AnOffsetAlongTheBlurStreakIsNotMotionButOneAcrossItIs) {
  const DynamicsConfig c;
  // 4 px along a streak whose spread is 4 px: about one sigma there.
  Scene s = withPatch(10, {4.f, 0.f});
  blurPatch(s, 10, 4.0);
  EXPECT_TRUE(findResidualMovers(s.frame, s.residuals, c).keypoints.empty());
  // 4 px across it counts as without blur.
  s = withPatch(10, {0.f, 4.f});
  blurPatch(s, 10, 4.0);
  EXPECT_EQ(findResidualMovers(s.frame, s.residuals, c).keypoints, patchIndices(10));
}

TEST(ResidualMovers, TooFewPointsOrEstablishedPointsAreNotJudged) {
  const DynamicsConfig c;
  Scene s = withPatch(4, {8.f, 0.f});  // under residual_region_min_points
  EXPECT_TRUE(findResidualMovers(s.frame, s.residuals, c).keypoints.empty());
  s = withPatch(10, {8.f, 0.f}, {0.f, 0.f}, false);  // the refitted pose rests on these
  EXPECT_TRUE(findResidualMovers(s.frame, s.residuals, c).keypoints.empty());
  s = withPatch(10, {8.f, 0.f});
  for (int k : patchIndices(10)) s.residuals[k].valid = false;  // no established pose
  EXPECT_TRUE(findResidualMovers(s.frame, s.residuals, c).keypoints.empty());
}

TEST(ResidualMovers, RegionsAreSeparatedByDepth) {
  DynamicsConfig c;
  Scene s = withPatch(10, {5.f, 0.f});
  // Static young points interleaved with the patch in the image but 2 m behind it.
  for (int k = 0; k < 10; ++k)
    s.add({555.f + 10.f * (k % 3), 285.f + 10.f * (k / 3)}, 3.f, true, noise(200 + k));
  EXPECT_EQ(findResidualMovers(s.frame, s.residuals, c).keypoints, patchIndices(10));
  c.residual_region_depth_band_m = 5.0;  // one region: its mean is diluted, but still 2.5 px
  EXPECT_EQ(findResidualMovers(s.frame, s.residuals, c).keypoints.size(), 20u);
}

namespace {
/// Features with the default camera and ORB scales, no keypoint yet.
Features cameraFeatures() {
  Features f;
  f.camera = std::make_shared<PinholeCamera>();
  f.scales = std::make_shared<PyramidScales>(PyramidScales::fromConfig(OrbConfig{}));
  return f;
}

/// A level-0 keypoint at (u + shift_px, v) with depth z in `instance`; returns where its map point
/// lies in the world (the camera at the identity saw it at (u, v)).
Vec3 addShiftedKeypoint(Features& f, double u, double v, double z, float shift_px,
                        uint16_t instance = 0) {
  f.keypoints.emplace_back(cv::Point2f(float(u) + shift_px, float(v)), 31.f);
  f.points.emplace_back(float(u) + shift_px, float(v));
  f.depth_m.push_back(static_cast<float>(z));
  f.u_right.push_back(-1.f);
  f.usable.push_back(1);
  f.instance_id.push_back(instance);
  return f.camera->backproject(u, v, z);
}

/// Two keyframes at the identity holding `f`; keypoint i of `frame` is matched to a map point at
/// world[i] observed by the first observers(i) of them.
std::vector<MapPointPtr> matchToMapPoints(Frame& frame, const Features& f,
                                          const std::vector<Vec3>& world,
                                          const std::function<int(int)>& observers,
                                          std::vector<std::shared_ptr<KeyFrame>>& keyframes) {
  const int n = static_cast<int>(world.size());
  for (int k = 0; k < 2; ++k)
    keyframes.push_back(
        std::make_shared<KeyFrame>(k, k, 0.1 * k, f, SE3::Identity(), std::vector<MapPointPtr>(n)));
  std::vector<MapPointPtr> points;
  for (int i = 0; i < n; ++i) {
    auto point = std::make_shared<MapPoint>(i, world[i], keyframes[0].get());
    for (int k = 0; k < observers(i); ++k) point->addObservation(keyframes[k].get(), i);
    frame.map_points[i] = point;
    points.push_back(point);
  }
  return points;
}

/// A frame at the identity seeing 60 established points (two keyframes each) exactly where they
/// are, and 12 young points (one keyframe) at 1 m that moved 6 px to the right since mapped.
/// The frame's own pose is pulled 2 cm sideways, as young movers pull it.
struct MappedScene {
  Frame frame;
  std::vector<std::shared_ptr<KeyFrame>> keyframes;
  std::vector<MapPointPtr> points;
};

MappedScene mappedScene() {
  MappedScene s;
  Features f = cameraFeatures();
  std::vector<Vec3> world;
  for (int i = 0; i < 72; ++i) {
    const bool young = i >= 60;
    const double z = young ? 1.0 : 2.0 + 0.03 * i;
    const double u = young ? 500 + 10 * (i % 4) : 40 + 55 * (i % 10);
    const double v = young ? 250 + 10 * ((i - 60) / 4) : 40 + 60 * (i / 10);
    world.push_back(addShiftedKeypoint(f, u, v, z, young ? 6.f : 0.f));
  }
  s.frame = Frame(9, 0.3, f);
  s.points = matchToMapPoints(
      s.frame, f, world, [](int i) { return i < 60 ? 2 : 1; }, s.keyframes);
  s.frame.T_camera_world = makeSE3(Quat::Identity(), Vec3(0.02, 0, 0));
  return s;
}
}  // namespace

TEST(EstablishedResiduals, YoungMoversShowTheirMotionAgainstTheEstablishedPoints) {
  const MappedScene s = mappedScene();
  const std::vector<MapResidual> r = residualsToEstablishedPoints(s.frame, TrackingConfig{}, 30);
  ASSERT_EQ(r.size(), 72u);
  for (int i = 0; i < 72; ++i) {
    ASSERT_TRUE(r[i].valid) << i;
    EXPECT_EQ(r[i].young, i >= 60) << i;
    const float expected_u = i >= 60 ? 6.f : 0.f;
    EXPECT_NEAR(r[i].du_px, expected_u, 0.05) << i;
    EXPECT_NEAR(r[i].dv_px, 0.f, 0.05) << i;
    EXPECT_FLOAT_EQ(r[i].sigma_px, 1.f);
  }
  EXPECT_TRUE(s.frame.T_camera_world.translation().isApprox(Vec3(0.02, 0, 0)))
      << "the frame's own pose is not changed";
  // Together: the young patch is found.
  const ResidualMovers movers = findResidualMovers(s.frame, r, DynamicsConfig{});
  EXPECT_EQ(movers.regions, 1);
  EXPECT_EQ(movers.keypoints.size(), 12u);
}

TEST(EstablishedResiduals, TooFewEstablishedPointsGiveNoResiduals) {
  const MappedScene s = mappedScene();
  for (const MapResidual& r : residualsToEstablishedPoints(s.frame, TrackingConfig{}, 61))
    EXPECT_FALSE(r.valid);
}

TEST(KeypointDropMerge, AddDropsKeepsTheListAscendingUniqueAndCullsIfEitherAsks) {
  KeypointDrop drop;
  drop.drop = {2, 5, 9};
  drop.cull_on_drop = {false, true, false};
  addDrops(drop, {1, 5, 9, 12}, false);
  EXPECT_EQ(drop.drop, (std::vector<int>{1, 2, 5, 9, 12}));
  EXPECT_EQ(drop.cull_on_drop, (std::vector<bool>{false, false, true, false, false}));
  addDrops(drop, {2}, true);
  EXPECT_EQ(drop.cull_on_drop, (std::vector<bool>{false, true, true, false, false}));
}

namespace {
/// A frame at the identity seeing 32 established background points where they are and an
/// object (instance 1, `object` points at 1.5 m, established too: it stood still while mapped)
/// that moved `moved_px` to the right since. The object has more matches than the background,
/// so the frame's own optimisation followed it and rejected the background (outlier flags).
struct ObjectScene {
  Frame frame;
  Instances instances;
  std::vector<std::shared_ptr<KeyFrame>> keyframes;
};

ObjectScene objectScene(int object, float moved_px, const std::string& class_name = "box") {
  ObjectScene s;
  Features f = cameraFeatures();
  const int n = 32 + object;
  std::vector<Vec3> world;
  for (int i = 0; i < n; ++i) {
    const bool on_object = i >= 32;
    const int k = on_object ? i - 32 : i;
    const double z = on_object ? 1.5 : 2.0 + 0.05 * i;
    const double u = on_object ? 380 + 12 * (k % 8) : 40 + 70 * (k % 8);
    const double v = on_object ? 150 + 15 * (k / 8) : 40 + 100 * (k / 8);
    world.push_back(addShiftedKeypoint(f, u, v, z, on_object ? moved_px : 0.f, on_object ? 1 : 0));
  }
  s.frame = Frame(9, 0.3, f);
  matchToMapPoints(
      s.frame, f, world, [](int) { return 2; }, s.keyframes);
  for (int i = 0; i < 32; ++i) s.frame.outlier[i] = moved_px != 0.f;
  // The pose the object pulled: its 6 px at 1.5 m are 1.7 cm.
  s.frame.T_camera_world = makeSE3(Quat::Identity(), Vec3(moved_px * 1.5 / f.camera->fx, 0, 0));
  s.instances = Instances::none(cv::Size(640, 480));
  Instance it;
  it.id = 1;
  it.class_name = class_name;
  it.box = cv::Rect(370, 140, 110, 90);
  s.instances.items.push_back(it);
  return s;
}
}  // namespace

TEST(ResidualInstances, AnObjectThatPulledThePoseMovesAgainstTheBackground) {
  const ObjectScene s = objectScene(40, 6.f);
  const std::vector<MapResidual> r = residualsToBackground(s.frame, TrackingConfig{}, 30);
  ASSERT_EQ(r.size(), 72u);
  for (int i = 0; i < 72; ++i) {
    ASSERT_TRUE(r[i].valid) << i << ": rejected matches are measured too";
    EXPECT_NEAR(r[i].du_px, i >= 32 ? 6.f : 0.f, 0.05) << i;
  }
  // Against every established point the object's majority hides it (the old test's view).
  const std::vector<MapResidual> all = residualsToEstablishedPoints(s.frame, TrackingConfig{}, 30);
  EXPECT_LT(std::abs(all[40].du_px), 1.f);
  const ResidualInstances moved = findResidualInstances(s.frame, r, s.instances, DynamicsConfig{});
  EXPECT_EQ(moved.ids, (std::vector<uint16_t>{1}));
  ASSERT_EQ(moved.keypoints.size(), 40u);
  EXPECT_EQ(moved.keypoints.front(), 32);
}

TEST(ResidualInstances, StillObjectsPeopleAndSmallShiftsAreNotMoving) {
  const DynamicsConfig c;
  ObjectScene s = objectScene(40, 0.f);  // stood still
  EXPECT_TRUE(findResidualInstances(s.frame, residualsToBackground(s.frame, TrackingConfig{}, 30),
                                    s.instances, c)
                  .ids.empty());
  s = objectScene(40, 1.2f);  // significant but under residual_region_min_px
  EXPECT_TRUE(findResidualInstances(s.frame, residualsToBackground(s.frame, TrackingConfig{}, 30),
                                    s.instances, c)
                  .ids.empty());
  s = objectScene(40, 6.f, "person");  // prior-dynamic classes are the segmenter's to cut out
  EXPECT_TRUE(findResidualInstances(s.frame, residualsToBackground(s.frame, TrackingConfig{}, 30),
                                    s.instances, c)
                  .ids.empty());
  s = objectScene(4, 6.f);  // too few matches to judge
  EXPECT_TRUE(findResidualInstances(s.frame, residualsToBackground(s.frame, TrackingConfig{}, 30),
                                    s.instances, c)
                  .ids.empty());
}
