#pragma once
// Frames from an RGB-D device (DESIGN.md §1, FrameSource: OpenNI2 live or .oni playback). The
// device gives raw units; this source turns them into RgbdFrames: depth in metres, timestamps
// in seconds of the device clock, strictly increasing. Frames it cannot use (wrong size, all
// black, saturated, no valid depth, a timestamp that does not advance) are skipped, logged and
// counted as a folder's bad frames are. A device that fails mid-run ends the stream; failure()
// then says why, so the run writes what it has and reports it instead of crashing.
#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <utility>

#include "io/rgbd_device.hpp"
#include "pipeline/frame_source.hpp"

namespace dynanav {

using RgbdDeviceOpener = std::function<std::unique_ptr<RgbdDevice>(const RgbdDeviceRequest&)>;

struct DeviceSourceOptions {
  RgbdDeviceRequest request;
  /// A calibration (from --camera or a camera.yaml beside the .oni) and where it came from;
  /// without one the intrinsics come from the device's field of view.
  std::optional<PinholeCamera> camera;
  std::string camera_origin;
  std::optional<std::pair<int, int>> blackout;  ///< inclusive 0-based frame range made black
  int max_frames = 0;                           ///< 0 = until the device ends (or a signal)
};

/// Pinhole intrinsics of a `width` x `height` image with these fields of view (radians): the
/// principal point in the centre, no distortion. Throws InputError naming `where` when a field
/// of view is not in (0, pi) (the device did not report one).
PinholeCamera cameraFromFieldOfView(int width, int height, double horizontal_fov_rad,
                                    double vertical_fov_rad, const std::string& where);

class DeviceSource final : public FrameSource {
 public:
  /// Opens the device with `open`; throws InputError when it cannot be opened or the
  /// calibration does not fit it.
  DeviceSource(const DeviceSourceOptions& options, const RgbdDeviceOpener& open);
  std::optional<RgbdFrame> next() override;
  [[nodiscard]] size_t expected() const override;
  [[nodiscard]] int skipped() const override { return skipped_; }
  [[nodiscard]] const PinholeCamera& camera() const override { return camera_; }
  [[nodiscard]] std::string describe() const override { return where_; }
  [[nodiscard]] std::string cameraSource() const override { return camera_source_; }
  [[nodiscard]] std::string failure() const override { return failure_; }
  [[nodiscard]] const RgbdDeviceInfo& deviceInfo() const { return device_->info(); }

 private:
  /// Why a raw frame cannot be used ("" = usable).
  [[nodiscard]] std::string problem(const RawRgbdFrame& raw, const RgbdFrame& frame) const;

  DeviceSourceOptions options_;
  std::string where_;
  std::unique_ptr<RgbdDevice> device_;
  PinholeCamera camera_;
  std::string camera_source_;
  int read_ = 0;  // frames read from the device, used or skipped (the next frame's index)
  int skipped_ = 0;
  double last_stamp_s_ = -1.0;
  std::string failure_;
};

/// True when a `dynanav run` input names a device: `openni://[URI]` or a `.oni` file.
bool isDeviceInput(const std::string& input);

/// The request for such an input: `openni://` = any device, `openni://URI` that device, a
/// `.oni` path playback (InputError naming it when the file is missing or not a file).
RgbdDeviceRequest deviceRequestFor(const std::string& input);

}  // namespace dynanav
