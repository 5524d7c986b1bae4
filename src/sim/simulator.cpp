#include "sim/simulator.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "core/error.hpp"
#include "io/objects_jsonl.hpp"

namespace dynanav::sim {

Simulator::Simulator(const SimOptions& options) : options_(options) {
  if (!(options.fps > 0.0 && options.fps <= 1000.0))
    throw InputError("--fps", "must be in (0, 1000], got " + std::to_string(options.fps));
  if (options.frames < 0) throw InputError("--frames", "must be >= 0 (0 = the scenario's length)");
  if (!(options.texels_per_m >= 10.0f && options.texels_per_m <= 1000.0f))
    throw InputError("texels_per_m", "must be in [10, 1000]");
  if (!(options.exposure_s >= 0.0 && options.exposure_s <= 1.0 / options.fps))
    throw InputError("--exposure-ms", "must be in [0, frame period = " +
                                          std::to_string(1000.0 / options.fps) + " ms]");
  if (!(options.readout_s >= 0.0 && options.readout_s <= 1.0 / options.fps))
    throw InputError("--rolling-shutter-ms", "must be in [0, frame period = " +
                                                 std::to_string(1000.0 / options.fps) + " ms]");
  const PhotoLibrary photos = options.photos ? PhotoLibrary::systemDefault() : PhotoLibrary();
  scene_ = buildScenario(options.scenario, options.seed, photos, options.texels_per_m);
  frames_ = options.frames > 0 ? options.frames
                               : std::max(1, int(std::lround(scene_->duration_s * options.fps)));
  camera_.name = "dynanav-sim";
  camera_.width = 640;
  camera_.height = 480;
  camera_.fx = camera_.fy = 525.0;
  camera_.cx = 319.5;
  camera_.cy = 239.5;
  camera_.depth_factor = 5000.0;
  camera_.readout_s = options.readout_s;    // camera.yaml says it: SLAM re-times with the truth
  camera_.exposure_s = options.exposure_s;  // and the depth test widens with the true blur
  options_.depth.focal_px = camera_.fx;
  // The world frame is the first camera frame, so the first ground-truth pose is the identity.
  T_world_room_ = scene_->T_room_camera(stamp(0)).inverse();
}

Simulator::~Simulator() = default;

double Simulator::stamp(int i) const {
  return std::stod(stampName(double(i) / options_.fps));
}

std::string Simulator::stampName(double stamp_s) {
  char buffer[32];
  std::snprintf(buffer, sizeof(buffer), "%.6f", stamp_s);
  return buffer;
}

nlohmann::json Simulator::masksJson() const {
  nlohmann::json instances = nlohmann::json::object();
  for (const Mover& m : scene_->movers) instances[std::to_string(m.id)] = {{"class", m.cls}};
  return {{"instances", instances}};
}

void Simulator::drawItems(int i, std::vector<DrawItem>& items) const {
  drawItemsAt(stamp(i), items);
}

void Simulator::drawItemsAt(double stamp_s, std::vector<DrawItem>& items) const {
  scene_->drawItems(stamp_s, items);
  const Pose3f T = T_world_room_.cast<float>();
  for (DrawItem& item : items) item.T_world_mesh = T * item.T_world_mesh;
}

SimFrame Simulator::render(int i) {
  SimFrame f;
  f.index = i;
  f.stamp_s = stamp(i);
  const SE3 T_room_camera = scene_->T_room_camera(f.stamp_s);
  // Frame 0 is the identity by definition (not just up to rounding), as the files promise.
  f.T_world_camera = i == 0 ? SE3::Identity() : SE3(T_world_room_ * T_room_camera);
  Lighting lighting;
  lighting.towards_light_world =
      T_world_room_.linear().cast<float>() * lighting.towards_light_world;
  RenderBuffers buffers;
  if (options_.readout_s > 0.0) {
    renderRollingShutter(f, lighting, buffers);
  } else {
    renderRows(f.stamp_s, f.T_world_camera, 0, camera_.height, lighting, buffers);
  }
  f.bgr = buffers.bgr;
  f.depth_true_m = buffers.depth_m;
  f.instance = buffers.instance;
  simulateColour(f.bgr, options_.colour, options_.seed, i, f.stamp_s, !options_.noiseless);
  f.depth_m = options_.noiseless ? f.depth_true_m.clone()
                                 : simulateDepth(f.depth_true_m, options_.depth, options_.seed, i);

  // Ground truth of every mover, visible or not (points = 0 when out of view).
  std::vector<int> pixels(1 << 16, 0);
  for (int y = 0; y < f.instance.rows; ++y) {
    const uint16_t* row = f.instance.ptr<uint16_t>(y);
    for (int x = 0; x < f.instance.cols; ++x) ++pixels[row[x]];
  }
  const SE3 T_camera_world = f.T_world_camera.inverse();
  // Bands and exposure instants left another instant's scene in items_.
  if (options_.readout_s > 0.0 || options_.exposure_s > 0.0) drawItems(i, items_);
  std::vector<TrackedObject> objects;
  for (const Mover& m : scene_->movers) {
    TrackedObject& o = objects.emplace_back();
    o.id = m.id;
    o.class_name = m.cls;
    o.p_world = T_world_room_ * scene_->moverCentre(m, f.stamp_s);
    o.v_world_mps = T_world_room_.linear() * scene_->moverVelocity(m, f.stamp_s);
    o.p_camera = T_camera_world * o.p_world;
    fillViewGeometry(o);
    o.dynamic = o.speed_mps > 1e-6;
    o.points = pixels[m.id];
    o.visible_share = inViewShare(m.id, pixels[m.id], T_camera_world);  // objects_gt in_view
  }
  f.objects = objectsFrameJson(f.stamp_s, objects);
  return f;
}

double Simulator::inViewShare(uint16_t id, int visible_px, const SE3& T_camera_world) {
  if (visible_px == 0) return 0.0;
  // The object alone, seen by a camera with the same centre and orientation but three times
  // the field of view each way at a third of the resolution: its whole silhouette (unless it
  // is closer than about 0.4 m) without occluders, in pixels of the real image (x 9).
  silhouette_items_.clear();
  for (const DrawItem& item : items_)
    if (item.instance_id == id) silhouette_items_.push_back(item);
  PinholeCamera wide = camera_;
  wide.fx = wide.fy = camera_.fx / 3.0;
  wide.cx = (camera_.cx + camera_.width) / 3.0;
  wide.cy = (camera_.cy + camera_.height) / 3.0;
  RenderBuffers alone;
  rasterizer_.render(wide, T_camera_world.cast<float>(), silhouette_items_, scene_->world.textures,
                     alone);
  const double silhouette_px = 9.0 * cv::countNonZero(alone.instance == id);
  return silhouette_px > 0.0 ? std::min(1.0, visible_px / silhouette_px) : 0.0;
}

void Simulator::renderRollingShutter(const SimFrame& f, const Lighting& lighting,
                                     RenderBuffers& out) {
  // Bands of 16 rows: at a 25 ms readout each band spans 0.8 ms, far below what tracking sees.
  constexpr int kBandRows = 16;
  for (int y0 = 0; y0 < camera_.height; y0 += kBandRows) {
    const int y1 = std::min(camera_.height, y0 + kBandRows);
    const double t = f.stamp_s + (0.5 * (y0 + y1) / camera_.height - 0.5) * options_.readout_s;
    renderRows(t, T_world_room_ * scene_->T_room_camera(t), y0, y1, lighting, out);
  }
}

void Simulator::renderRows(double t, const SE3& T_world_camera, int y0, int y1,
                           const Lighting& lighting, RenderBuffers& out) {
  drawItemsAt(t, items_);
  rasterizer_.render(camera_, T_world_camera.inverse().cast<float>(), items_,
                     scene_->world.textures, out, lighting, y0, y1);
  if (options_.exposure_s > 0.0) blurRows(t, y0, y1, lighting, out);
}

void Simulator::blurRows(double t, int y0, int y1, const Lighting& lighting, RenderBuffers& out) {
  const double exposure = options_.exposure_s;
  const int n = exposureSamples(*scene_, camera_, t, exposure);
  if (n <= 1) return;  // nothing moves far enough to blur: the instant at t stands for all
  cv::Mat sum(y1 - y0, camera_.width, CV_32FC3, cv::Scalar::all(0.0));
  cv::Mat sample;
  for (int k = 0; k < n; ++k) {
    // Midpoints of n equal slices of the exposure (a box shutter, integrated by the midpoint rule).
    const double tk = t + ((k + 0.5) / n - 0.5) * exposure;
    drawItemsAt(tk, items_);
    const SE3 T_world_camera = T_world_room_ * scene_->T_room_camera(tk);
    rasterizer_.render(camera_, T_world_camera.inverse().cast<float>(), items_,
                       scene_->world.textures, exposure_sample_, lighting, y0, y1);
    exposure_sample_.bgr.rowRange(y0, y1).convertTo(sample, CV_32FC3);
    sum += sample;
  }
  sum.convertTo(out.bgr.rowRange(y0, y1), CV_8UC3, 1.0 / n);  // rounds to nearest
}

int exposureSamples(const Scene& scene, const PinholeCamera& camera, double t, double exposure_s) {
  if (!(exposure_s > 0.0)) return 1;
  const SE3 a = scene.T_room_camera(t - exposure_s / 2),
            b = scene.T_room_camera(t + exposure_s / 2);
  double travel_px = rotationAngle(a.linear().transpose() * b.linear()) * camera.fx;
  double travel_m = (b.translation() - a.translation()).norm();
  for (const Mover& m : scene.movers)
    travel_m = std::max(travel_m, (scene.moverCentre(m, t + exposure_s / 2) -
                                   scene.moverCentre(m, t - exposure_s / 2))
                                      .norm());
  travel_px += travel_m * camera.fx / 1.0;  // seen at 1 m
  return std::clamp(int(std::ceil(travel_px / kExposureStepPx)) + 1, 1, kMaxExposureSamples);
}

}  // namespace dynanav::sim
