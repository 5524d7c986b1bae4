// Per-frame cost of the object tracker (step 8) with two people in view: two 80 x 200 px
// walkers sliding across a 640 x 480 frame with a uniform flow field, at 2 and 3 m, on a
// textured image (each person's own flow, objects.own_flow, runs on it). And the floor's fit,
// which the tracker runs in every tracked frame (since session 37, also with nobody in view).
#include <benchmark/benchmark.h>

#include "dynamics/floor_plane.hpp"
#include "dynamics/object_tracker.hpp"

using namespace dynanav;

namespace {

struct Scene {
  Instances instances;
  cv::Mat depth_m;
  cv::Mat grey_half;
};

Scene twoPeople(int frame) {
  Scene s;
  s.instances = Instances::none(cv::Size(640, 480));
  s.depth_m = cv::Mat(480, 640, CV_32F, cv::Scalar(5.0f));
  s.grey_half = cv::Mat(240, 320, CV_8U);
  cv::RNG rng(uint64(frame + 1));
  rng.fill(s.grey_half, cv::RNG::UNIFORM, 0, 256);
  const int xs[2] = {100 + 3 * frame, 400 + 2 * frame};
  const float zs[2] = {2.0f, 3.0f};
  for (int k = 0; k < 2; ++k) {
    const cv::Rect box(xs[k] % 520, 140, 80, 200);
    for (int y = box.y; y < box.y + box.height; ++y)
      for (int x = box.x; x < box.x + box.width; ++x)
        s.depth_m.at<float>(y, x) =
            zs[k] + 0.1f * float((x - box.x) % 11) / 11.f + 0.03f * float(y % 7) / 7.f;
    s.instances.labels(box).setTo(uint16_t(k + 1));
    Instance it;
    it.id = uint16_t(k + 1);
    it.class_name = "person";
    it.box = box;
    s.instances.items.push_back(it);
  }
  return s;
}

/// range(0) = 1: fr1's lens (distorted pixels are undistorted before they are lifted, session
/// 23); 0: an undistorted camera of the same size.
void BM_TrackTwoPeople(benchmark::State& state) {
  PinholeCamera camera;
  if (state.range(0)) {
    camera = PinholeCamera::tumFreiburg1();
  } else {
    camera.fx = camera.fy = 525.0;
    camera.cx = 319.5;
    camera.cy = 239.5;
  }
  ObjectTracker tracker(ObjectTrackingConfig{}, 5);
  const cv::Mat flow(240, 320, CV_32FC2, cv::Scalar(1.25f, 0.f));
  FrameDynamics dynamics;
  dynamics.moving_ids = {1, 2};
  const SE3 T = SE3::Identity();
  std::vector<Scene> scenes;
  for (int i = 0; i < 30; ++i) scenes.push_back(twoPeople(i));
  int i = 0;
  for (auto _ : state) {
    const Scene& s = scenes[size_t(i % 30)];
    auto objects = tracker.track(
        {i, i / 30.0, s.instances, dynamics, flow, s.depth_m, T, true, camera, s.grey_half});
    benchmark::DoNotOptimize(objects);
    ++i;
  }
}
/// One floor fit (estimateFloorPlane, default options) on a 640 x 480 depth image of a level
/// floor 1.5 m below a level camera, seen up to 4.5 m, with 1 cm of noise.
void BM_FitTheFloor(benchmark::State& state) {
  PinholeCamera camera;
  camera.fx = camera.fy = 525.0;
  camera.cx = 319.5;
  camera.cy = 239.5;
  cv::Mat depth_m(480, 640, CV_32F, cv::Scalar(0.f));
  cv::RNG rng(1);
  for (int v = 0; v < depth_m.rows; ++v) {
    const double z_m = v > camera.cy ? camera.fy * 1.5 / (v - camera.cy) : 0.0;
    if (z_m <= 0.0 || z_m > 4.5) continue;
    for (int u = 0; u < depth_m.cols; ++u)
      depth_m.at<float>(v, u) = float(z_m + rng.gaussian(0.01));
  }
  const Vec3 up_camera(0.0, -1.0, 0.0);
  for (auto _ : state) {
    auto floor = estimateFloorPlane(depth_m, camera, up_camera);
    benchmark::DoNotOptimize(floor);
  }
}

BENCHMARK(BM_TrackTwoPeople)->Arg(0)->Arg(1)->ArgName("fr1_lens")->Unit(benchmark::kMillisecond);

}  // namespace

BENCHMARK(BM_FitTheFloor)->Unit(benchmark::kMillisecond);
BENCHMARK_MAIN();
