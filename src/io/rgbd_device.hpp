#pragma once
// An RGB-D device as the frame source needs it (DESIGN.md §1, io: "OpenNI2 live when
// available"): open, read colour + depth pairs in order, end of a recording. The OpenNI2 adapter
// (openni2_device.cpp) is one implementation; tests drive the source with a fake one. The
// device hands over raw units (depth in device units, timestamps in microseconds of the
// device's clock); the source converts them, so the conversion is tested without hardware.
#include <cstdint>
#include <memory>
#include <opencv2/core.hpp>
#include <optional>
#include <stdexcept>
#include <string>

namespace dynanav {

/// A device that stopped working after it was opened (unplugged, stream stopped, a read that
/// failed). Opening problems are InputErrors (exit 2 before the run starts).
class DeviceError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

/// What the source asks of the device when it opens it.
struct RgbdDeviceRequest {
  std::string uri;                          ///< OpenNI2 URI ("" = any device) or an .oni path
  bool is_file = false;                     ///< `uri` is a recording (.oni) to play back
  bool register_depth_to_colour = true;     ///< depth pixels re-projected onto the colour image
  bool sync_depth_and_colour = true;        ///< pairs taken at the same moment (frame sync)
  int width = 640, height = 480, fps = 30;  ///< the mode asked for (live devices)
};

/// What the device is and delivers, once opened.
struct RgbdDeviceInfo {
  std::string uri;
  std::string name;  ///< vendor and model, for the log
  bool is_file = false;
  int frames = 0;             ///< frames in a recording (0 = live or unknown)
  int width = 0, height = 0;  ///< of both colour and depth (the adapter picks equal modes)
  double fps = 0.0;
  /// Field of view of the colour camera (radians); 0 when the device does not report it.
  double horizontal_fov_rad = 0.0, vertical_fov_rad = 0.0;
  double depth_unit_m = 0.001;    ///< metres per raw depth unit (OpenNI2 DEPTH_1_MM: 0.001)
  bool depth_registered = false;  ///< registration to colour is on (asked for and granted)
  bool synced = false;            ///< depth-colour frame sync is on
};

/// One colour/depth pair as the device gives it.
struct RawRgbdFrame {
  cv::Mat bgr;                   ///< CV_8UC3
  cv::Mat depth_raw;             ///< CV_16U in RgbdDeviceInfo::depth_unit_m, 0 = no measurement
  uint64_t colour_stamp_us = 0;  ///< device clock
  uint64_t depth_stamp_us = 0;
};

class RgbdDevice {
 public:
  virtual ~RgbdDevice() = default;
  [[nodiscard]] virtual const RgbdDeviceInfo& info() const = 0;
  /// The next pair in order; nullopt at the end of a recording. Throws DeviceError.
  virtual std::optional<RawRgbdFrame> read() = 0;
};

/// Opens an OpenNI2 device or .oni recording. Throws InputError naming the URI or file when none
/// can be opened, saying what was looked for (drivers found, devices enumerated); in a build
/// without OpenNI2 it says that instead.
std::unique_ptr<RgbdDevice> openOpenNi2Device(const RgbdDeviceRequest& request);

/// True when this build has the OpenNI2 adapter.
bool haveOpenNi2();

}  // namespace dynanav
