#pragma once
// The simulator: renders a scenario frame by frame with exact ground truth, and writes it as a
// TUM-layout sequence (rgb/, depth/, masks/, rgb.txt, depth.txt, groundtruth.txt, camera.yaml,
// masks.json, objects_gt.jsonl). The world frame of every output is the first camera frame
// (camera x right, y down, z forward), as DESIGN.md §2 asks.
#include <filesystem>
#include <functional>
#include <memory>
#include <nlohmann/json.hpp>
#include <string>

#include "core/camera.hpp"
#include "sim/rasterizer.hpp"
#include "sim/scenarios.hpp"
#include "sim/sensor.hpp"

namespace dynanav::sim {

struct SimOptions {
  std::string scenario = "office";
  int frames = 0;  ///< 0 = the scenario's own length
  uint64_t seed = 1;
  double fps = 30.0;
  bool noiseless =
      false;           ///< exact depth everywhere (no noise, range limits, holes), no colour noise
  bool photos = true;  ///< posters may use Debian's opencv-doc images when installed
  float texels_per_m = 200.0f;  ///< texture resolution on surfaces
  /// Rolling-shutter readout (s) of the camera, colour and depth alike: row v is seen
  /// (v/H - 1/2) * readout after the frame's stamp (the middle row's time, which the ground
  /// truth pose describes). 0 = global shutter.
  double readout_s = 0.0;
  /// Exposure time (s) of the colour camera (issue 18): each row's colour is the mean of renders
  /// at times spread evenly over [t_row - E/2, t_row + E/2], so whatever moves across the image
  /// during the exposure (the camera turning, a walker) is smeared along its own image path:
  /// motion blur. Depth and masks stay those of t_row. 0 = an instantaneous exposure.
  double exposure_s = 0.0;
  DepthSensorModel depth;
  ColourSensorModel colour;
};

/// One rendered frame with its ground truth.
struct SimFrame {
  int index = 0;
  double stamp_s = 0.0;
  cv::Mat bgr;           ///< what the colour camera gives (CV_8UC3)
  cv::Mat depth_m;       ///< what the depth sensor gives (CV_32F, 0 = invalid)
  cv::Mat depth_true_m;  ///< exact camera z of the visible surface (CV_32F, 0 = nothing)
  cv::Mat instance;      ///< CV_16U instance ids, 0 = background
  SE3 T_world_camera = SE3::Identity();
  nlohmann::json objects;  ///< the objects_gt.jsonl record of this frame (io/objects_jsonl)
};

class Simulator {
 public:
  /// Throws InputError for an unknown scenario or bad options.
  explicit Simulator(const SimOptions& options);
  ~Simulator();

  [[nodiscard]] int frameCount() const { return frames_; }
  /// Stamp of frame i, rounded to the 6 decimals every file carries (so all files agree).
  [[nodiscard]] double stamp(int i) const;
  [[nodiscard]] static std::string stampName(double stamp_s);
  [[nodiscard]] const PinholeCamera& camera() const { return camera_; }
  [[nodiscard]] const Scene& scene() const { return *scene_; }
  [[nodiscard]] const SimOptions& options() const { return options_; }
  /// Room frame -> world (first camera) frame.
  [[nodiscard]] const SE3& T_world_room() const { return T_world_room_; }
  /// {"instances": {"1": {"class": "person"}, ...}}
  [[nodiscard]] nlohmann::json masksJson() const;

  [[nodiscard]] SimFrame render(int i);
  /// The world-frame draw list of frame i (the geometry behind render(i); for tests).
  void drawItems(int i, std::vector<DrawItem>& items) const;
  /// The same at any time (a rolling shutter sees each band of rows at its own time).
  void drawItemsAt(double stamp_s, std::vector<DrawItem>& items) const;

 private:
  SimOptions options_;
  std::unique_ptr<Scene> scene_;
  PinholeCamera camera_;
  SE3 T_world_room_ = SE3::Identity();
  int frames_ = 0;
  /// Renders frame f's image band by band, each band from the pose and scene at its rows' time.
  void renderRollingShutter(const SimFrame& f, const Lighting& lighting, RenderBuffers& out);
  /// Renders rows [y0, y1) as seen at time t from T_world_camera (the pose at t), with motion
  /// blur over the exposure when options_.exposure_s > 0.
  void renderRows(double t, const SE3& T_world_camera, int y0, int y1, const Lighting& lighting,
                  RenderBuffers& out);
  /// Replaces the colour of rows [y0, y1) by the mean over the exposure centred on t.
  void blurRows(double t, int y0, int y1, const Lighting& lighting, RenderBuffers& out);
  /// Share of object `id`'s whole silhouette (inside the image or not, occluded or not) that
  /// shows in this frame: visible_px / the pixels it would cover alone on an unbounded image.
  /// Uses items_ (this frame's scene).
  double inViewShare(uint16_t id, int visible_px, const SE3& T_camera_world);
  Rasterizer rasterizer_;
  std::vector<DrawItem> items_, silhouette_items_;
  RenderBuffers exposure_sample_;  // one instant of the exposure (blurRows)
};

/// How many instants blurRows averages over an exposure of `exposure_s` centred on t: enough
/// that consecutive instants are at most kExposureStepPx apart in the image, for the camera's
/// rotation (angle x fx), its translation and the fastest mover seen at 1 m
/// (displacement x fx / 1 m); 1 (no blur) for a still scene, at most kMaxExposureSamples.
constexpr double kExposureStepPx = 1.5;
constexpr int kMaxExposureSamples = 16;
int exposureSamples(const Scene& scene, const PinholeCamera& camera, double t, double exposure_s);

struct WriteStats {
  int frames = 0;
  double seconds = 0.0;
};

/// Renders every frame and writes the sequence into `out_dir` (created if needed). Rendering and
/// PNG encoding overlap on two threads. `progress(i)` is called after each frame is rendered.
WriteStats writeSequence(Simulator& sim, const std::filesystem::path& out_dir,
                         const std::function<void(int)>& progress = {});

}  // namespace dynanav::sim
