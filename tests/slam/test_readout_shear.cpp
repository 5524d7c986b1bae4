// The rolling-shutter readout estimated by bundle adjustment (slam/readout_shear): keyframes that
// turned differently, their keypoints seen row by row and re-timed with whatever readout tracking
// used, must give back the readout they were seen with; a still window must not decide it.
#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "core/config.hpp"
#include "slam/readout_shear.hpp"
#include "test_rolling_shutter_motion.hpp"

namespace dynanav {
namespace {

using testing::makeVelocity;
using testing::seenByRow;

struct Window {
  BaProblem problem;
  std::vector<KeyFramePtr> keyframes;  ///< parallel to problem.keyframes
  [[nodiscard]] std::vector<const KeyFrame*> views() const {
    std::vector<const KeyFrame*> out;
    for (const auto& kf : keyframes) out.push_back(kf.get());
    return out;
  }
};

/// Six keyframes along a short walk looking at 400 points 1-5 m ahead; the first two are fixed
/// (the window's anchors). Keyframe k moved by `motions[k]` while its rows were read out over
/// `true_readout_s`; its keypoints were re-timed to the middle row with `used_readout_s`, as
/// tracking does (compensateRollingShutter), plus 0.5 px of noise. Free poses start 1 cm / 0.3
/// degrees off, points 2 cm off.
Window makeWindow(const std::vector<CameraVelocity>& motions, double true_readout_s,
                  double used_readout_s, unsigned seed) {
  auto camera = std::make_shared<PinholeCamera>();
  auto scales = std::make_shared<PyramidScales>(PyramidScales::fromConfig(OrbConfig{}));
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> u01(0.0, 1.0);
  std::normal_distribution<double> pixel_noise(0.0, 0.5), pose_noise(0.0, 0.005),
      point_noise(0.0, 0.02);
  Window w;
  w.problem.camera = {camera->fx, camera->fy, camera->cx, camera->cy, camera->bf()};
  std::vector<Vec3> points_world;
  for (int j = 0; j < 400; ++j) {
    const double z = 1.0 + 4.0 * u01(rng);
    points_world.emplace_back((u01(rng) - 0.5) * 1.4 * z, (u01(rng) - 0.5) * 1.0 * z, z);
    w.problem.points.push_back(
        {uint64_t(j),
         points_world.back() + Vec3(point_noise(rng), point_noise(rng), point_noise(rng))});
  }
  for (size_t k = 0; k < motions.size(); ++k) {
    const SE3 T_world_camera = makeSE3(Quat(Eigen::AngleAxisd(0.03 * double(k), Vec3::UnitY())),
                                       Vec3(0.1 * double(k), 0.0, 0.0));
    const SE3 T_camera_world = T_world_camera.inverse();
    Features f;
    std::vector<int> point_of_keypoint;
    for (size_t j = 0; j < points_world.size(); ++j) {
      const Vec3 p_row =
          seenByRow(*camera, motions[k], true_readout_s, T_camera_world * points_world[j]);
      const Eigen::Vector2d uv = camera->project(p_row);
      if (p_row.z() <= 0.0 || !camera->inImage(uv.x(), uv.y(), 1.0)) continue;
      cv::KeyPoint kp(float(uv.x()), float(uv.y()), 31.f);
      kp.octave = 0;
      f.keypoints.push_back(kp);
      f.points.push_back(kp.pt);
      f.depth_m.push_back(float(p_row.z()));
      f.u_right.push_back(float(uv.x() - camera->bf() / p_row.z()));
      point_of_keypoint.push_back(int(j));
    }
    f.usable.assign(f.keypoints.size(), 1);
    f.instance_id.assign(f.keypoints.size(), 0);
    f.camera = camera;
    f.scales = scales;
    f.bounds = cv::Rect2d(0, 0, camera->width, camera->height);
    compensateRollingShutter(f, motions[k], used_readout_s);
    SE3 T_start = T_camera_world;
    if (k >= 2) {
      Eigen::Matrix<double, 6, 1> xi;
      for (int i = 0; i < 6; ++i) xi(i) = pose_noise(rng);
      T_start = leftPerturb(xi, T_start);
    }
    w.problem.keyframes.push_back({uint64_t(k), T_start, k < 2});
    for (int i = 0; i < f.size(); ++i) {
      BaObservation obs;
      obs.keyframe = int(k);
      obs.point = point_of_keypoint[i];
      obs.keypoint = i;
      obs.u = f.points[i].x + pixel_noise(rng);
      obs.v = f.points[i].y + pixel_noise(rng);
      obs.u_right = f.u_right[i] + pixel_noise(rng);
      w.problem.observations.push_back(obs);
    }
    auto kf = std::make_shared<KeyFrame>(k, k, 0.0, std::move(f), T_start,
                                         std::vector<MapPointPtr>(point_of_keypoint.size()));
    kf->motion = motions[k];
    kf->readout_used_s = used_readout_s;
    w.keyframes.push_back(kf);
  }
  return w;
}

// Head turns of 60-100 deg/s in different directions, one keyframe walking straight.
const std::vector<CameraVelocity> kTurns = {
    makeVelocity(Vec3(0.0, 0.058, 0.0), Vec3(0.01, 0.0, 0.0)),
    makeVelocity(Vec3(0.0, -0.058, 0.0), Vec3(0.0, 0.0, 0.03)),
    makeVelocity(Vec3(0.035, 0.0, 0.0), Vec3::Zero()),
    makeVelocity(Vec3::Zero(), Vec3(0.0, 0.0, 0.03)),
    makeVelocity(Vec3(-0.02, 0.04, 0.0), Vec3(-0.01, 0.0, 0.0)),
    makeVelocity(Vec3(0.0, -0.035, 0.01), Vec3::Zero())};

struct Adjusted {
  double readout_s = 0.0, sigma_s = 0.0;
  BaResult result;
};

/// Adjusts the window with the readout as an unknown, starting from `start_s`.
Adjusted adjustWithReadout(Window& w, double start_s) {
  addReadoutShear(w.problem, w.views(), start_s);
  Adjusted a;
  a.result = bundleAdjust(w.problem, BaOptions{});
  a.readout_s = w.problem.readout_s;
  a.sigma_s = readoutSigmaS(w.problem, a.result.outlier);
  return a;
}

TEST(ReadoutShear, BundleAdjustmentGivesBackTheReadoutWhateverTheKeyframesWereReTimedWith) {
  for (const double used_s : {0.0, 0.015, 0.025, 0.033}) {
    for (const double start_s : {0.0, 0.025}) {
      Window w = makeWindow(kTurns, 0.025, used_s, 5);
      const Adjusted a = adjustWithReadout(w, start_s);
      EXPECT_NEAR(a.readout_s, 0.025, 0.001) << used_s << " " << start_s;
      EXPECT_LT(a.sigma_s, 0.0005) << used_s << " " << start_s;
      EXPECT_LT(a.result.final_rms_px, 0.8) << used_s;  // the 0.5 px noise per axis, not the shear
    }
  }
}

TEST(ReadoutShear, TheStandardErrorMatchesTheScatterOverNoise) {
  // The windows' pixel noise is 0.5 px and the adjustment weighs 1 px: the estimates' scatter over
  // noise draws should be half the standard error they report (a loose factor: 10 draws).
  std::vector<double> estimates;
  double sigma_s = 0.0;
  for (unsigned seed = 20; seed < 30; ++seed) {
    Window w = makeWindow(kTurns, 0.025, 0.0, seed);
    const Adjusted a = adjustWithReadout(w, 0.0);
    estimates.push_back(a.readout_s);
    sigma_s += a.sigma_s / 10.0;
  }
  double mean = 0.0, scatter = 0.0;
  for (const double x : estimates) mean += x / 10.0;
  for (const double x : estimates) scatter += (x - mean) * (x - mean) / 9.0;
  scatter = std::sqrt(scatter);
  EXPECT_GT(scatter, 0.2 * sigma_s);
  EXPECT_LT(scatter, 1.0 * sigma_s);
}

TEST(ReadoutShear, WithoutTheReadoutTheShearStaysInTheResiduals) {
  Window ignored = makeWindow(kTurns, 0.025, 0.0, 6);
  Window estimated = ignored;
  const BaResult ignoring = bundleAdjust(ignored.problem, BaOptions{});
  const Adjusted estimating = adjustWithReadout(estimated, 0.0);
  EXPECT_GT(ignoring.final_rms_px, 1.5 * estimating.result.final_rms_px);
}

TEST(ReadoutShear, AGlobalShutterReadsNoReadout) {
  Window w = makeWindow(kTurns, 0.0, 0.0, 7);
  const Adjusted a = adjustWithReadout(w, 0.010);
  EXPECT_GE(a.readout_s, 0.0);  // bounded: noise must not shear the map the other way
  EXPECT_LT(a.readout_s, 0.001);
}

TEST(ReadoutShear, AStillWindowLeavesTheReadoutUndeterminedAndUnadopted) {
  const std::vector<CameraVelocity> still(6, makeVelocity(Vec3::Zero(), Vec3::Zero()));
  Window w = makeWindow(still, 0.025, 0.0, 8);
  const Adjusted a = adjustWithReadout(w, 0.010);
  EXPECT_FALSE(std::isfinite(a.sigma_s));  // nothing in the residuals depends on it
  Map map;
  map.readout.estimate = true;
  map.readout.readout_s = 0.010;
  EXPECT_FALSE(adoptReadout(map, w.problem, a.sigma_s));
  EXPECT_EQ(map.readout.readout_s, 0.010);
  EXPECT_EQ(map.readout.adopted, 0);
}

TEST(ReadoutShear, AWellDeterminedEstimateIsAdoptedWithItsWindow) {
  Window w = makeWindow(kTurns, 0.025, 0.0, 9);
  const Adjusted a = adjustWithReadout(w, 0.0);
  Map map;
  map.readout.estimate = true;
  ASSERT_TRUE(adoptReadout(map, w.problem, a.sigma_s));
  EXPECT_NEAR(map.readout.readout_s, 0.025, 0.001);
  EXPECT_EQ(map.readout.sigma_s, a.sigma_s);
  EXPECT_EQ(map.readout.window_keyframes, 6);
  EXPECT_EQ(map.readout.adopted, 1);
}

TEST(ReadoutShear, AKeyframeWithoutAKnownMotionIsTakenAsItIs) {
  Window w = makeWindow(kTurns, 0.025, 0.0, 10);
  w.keyframes[3]->motion = CameraVelocity{};
  addReadoutShear(w.problem, w.views(), 0.0);
  int sheared = 0;
  for (const auto& obs : w.problem.observations) {
    if (obs.keyframe == 3) {
      EXPECT_EQ(obs.readout_px_per_s, Vec3::Zero());
    } else if (obs.readout_px_per_s.norm() > 0.0) {
      ++sheared;
    }
  }
  EXPECT_GT(sheared, 1000);
}

}  // namespace
}  // namespace dynanav
