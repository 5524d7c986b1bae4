// Timings of the two Ceres problems on the tracking and mapping paths: pose-only optimisation
// (twice per frame) and local bundle adjustment (once per keyframe), on synthetic data of the
// sizes seen on fr1_xyz (~500 matches per frame; ~20 keyframes, ~2000 points per window).
#include <benchmark/benchmark.h>

#include <random>

#include "slam/bundle_adjuster.hpp"
#include "slam/pose_optimizer.hpp"

namespace dynanav {
namespace {

const PoseCamera kCamera{525.0, 525.0, 319.5, 239.5, 525.0 * 0.08};

Vec3 randomPoint(std::mt19937& rng) {
  std::uniform_real_distribution<double> u01(0.0, 1.0);
  return {(u01(rng) - 0.5) * 3.0, (u01(rng) - 0.5) * 2.0, 0.8 + 3.0 * u01(rng)};
}

void BM_PoseOptimization(benchmark::State& state) {
  std::mt19937 rng(1);
  std::normal_distribution<double> noise(0.0, 0.8);
  std::vector<PoseObservation> observations;
  for (int i = 0; i < state.range(0); ++i) {
    const Vec3 p = randomPoint(rng);
    PoseObservation obs;
    obs.p_world = p;
    obs.u = kCamera.fx * p.x() / p.z() + kCamera.cx + noise(rng);
    obs.v = kCamera.fy * p.y() / p.z() + kCamera.cy + noise(rng);
    if (i % 5 != 0) obs.u_right = obs.u - kCamera.bf / p.z();
    if (i % 10 == 0) obs.u += 50.0;
    observations.push_back(obs);
  }
  const SE3 start = leftPerturb((Eigen::Matrix<double, 6, 1>() << 0.01, 0.01, -0.01, 0.01, 0.0, 0.01).finished(), SE3::Identity());
  for (auto _ : state) {
    SE3 T = start;
    std::vector<uint8_t> outlier;
    benchmark::DoNotOptimize(optimizePose(observations, kCamera, PoseOptimizerOptions{}, T, outlier));
  }
}
BENCHMARK(BM_PoseOptimization)->Arg(200)->Arg(500)->Unit(benchmark::kMillisecond);

void BM_LocalBundleAdjustment(benchmark::State& state) {
  std::mt19937 rng(2);
  std::normal_distribution<double> noise(0.0, 0.7);
  BaProblem truth;
  truth.camera = kCamera;
  const int keyframes = static_cast<int>(state.range(0));
  for (int k = 0; k < keyframes; ++k) {
    const SE3 T_wc = makeSE3(Quat(Eigen::AngleAxisd(0.01 * k, Vec3::UnitY())), Vec3(0.02 * k, 0.0, 0.0));
    truth.keyframes.push_back({static_cast<uint64_t>(k), T_wc.inverse(), k < 3});
  }
  for (int j = 0; j < 2000; ++j) {
    const Vec3 p = randomPoint(rng);
    truth.points.push_back({static_cast<uint64_t>(j), p + Vec3(noise(rng), noise(rng), noise(rng)) * 0.01});
    for (int k = j % 3; k < keyframes; k += 2) {
      const Vec3 p_c = truth.keyframes[k].T_camera_world * p;
      BaObservation obs;
      obs.keyframe = k;
      obs.point = j;
      obs.u = kCamera.fx * p_c.x() / p_c.z() + kCamera.cx + noise(rng);
      obs.v = kCamera.fy * p_c.y() / p_c.z() + kCamera.cy + noise(rng);
      obs.u_right = obs.u - kCamera.bf / p_c.z();
      truth.observations.push_back(obs);
    }
  }
  BaOptions options;
  options.linear_solver = state.range(1) ? "dense_schur" : "sparse_schur";
  for (auto _ : state) {
    BaProblem problem = truth;
    benchmark::DoNotOptimize(bundleAdjust(problem, options));
  }
}
BENCHMARK(BM_LocalBundleAdjustment)->Args({10, 0})->Args({20, 0})->Args({20, 1})->Unit(benchmark::kMillisecond);

}  // namespace
}  // namespace dynanav

BENCHMARK_MAIN();
