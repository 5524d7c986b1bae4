// The OpenNI2 adapter behind RgbdDevice (compiled only when CMake found libopenni2; otherwise
// openni2_missing.cpp says so). Live: colour RGB888 and depth in 1 mm (or 100 µm) units, depth
// registered to colour and frame-synced when the device can. An .oni recording plays every
// frame, in order (manual playback speed); the end of the recording ends the stream.
#ifdef DYNANAV_HAVE_OPENNI2
#include <OpenNI.h>
#include <dlfcn.h>
#include <spdlog/spdlog.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <deque>
#include <filesystem>
#include <fstream>
#include <memory>
#include <mutex>
#include <opencv2/imgproc.hpp>
#include <thread>
#include <vector>

#include "core/error.hpp"
#include "io/rgbd_device.hpp"
#include "io/stream_pairing.hpp"

namespace fs = std::filesystem;

namespace dynanav {
namespace {

constexpr int kWaitMs = 2000;  // a live camera delivers every 33 ms; 2 s of silence is a fault
constexpr float kManualSpeed = -1.0f;  // OpenNI2 playback speed: a frame per request
constexpr size_t kMaxQueued = 8;       // frames of one stream waiting for the other's

void pinDrivers();

/// OpenNI2 keeps one context per process: initialised with the first device, shut down with
/// the last (its drivers allocate at initialise and free only at shutdown; ASan's leak check
/// found that). Devices and streams are closed before it goes.
class OpenNiContext {
 public:
  static std::shared_ptr<OpenNiContext> acquire() {
    static std::mutex mutex;
    static std::weak_ptr<OpenNiContext> current;
    std::lock_guard lock(mutex);
    if (auto context = current.lock()) return context;
    pinDrivers();
    if (openni::OpenNI::initialize() != openni::STATUS_OK) {
      const std::string error = openni::OpenNI::getExtendedError();
      openni::OpenNI::shutdown();
      throw InputError("OpenNI2", "cannot initialise: " + error);
    }
    auto context = std::shared_ptr<OpenNiContext>(new OpenNiContext);
    current = context;
    return context;
  }
  ~OpenNiContext() { openni::OpenNI::shutdown(); }

 private:
  OpenNiContext() = default;
};

/// Where OpenNI2 looks for its drivers: OpenNI.ini's [Drivers] Repository, else OpenNI2/Drivers
/// beside libOpenNI2.so (OpenNI2 2.2's rule).
fs::path driverRepository() {
  fs::path repository = "OpenNI2/Drivers";
  std::ifstream ini("/etc/openni2/OpenNI.ini");
  for (std::string line; std::getline(ini, line);)
    if (line.rfind("Repository=", 0) == 0) repository = line.substr(11);
  if (repository.is_relative()) {
    Dl_info where{};
    if (dladdr(reinterpret_cast<void*>(&oniInitialize), &where) && where.dli_fname)
      repository = fs::path(where.dli_fname).parent_path() / repository;
  }
  return repository;
}

/// The driver libraries in the repository, sorted by file name.
std::vector<fs::path> driverLibraries(const fs::path& repository) {
  std::vector<fs::path> drivers;
  std::error_code ec;
  for (const auto& entry : fs::directory_iterator(repository, ec))
    if (entry.path().extension() == ".so") drivers.push_back(entry.path());
  std::sort(drivers.begin(), drivers.end());
  return drivers;
}

/// Keeps the drivers mapped after OpenNI::shutdown unloads them. OpenNI2 2.2's drivers do not
/// free everything at shutdown; once unmapped, what they kept is a leak of "<unknown module>"
/// that LeakSanitizer can neither name nor be told to ignore. Mapped, it is attributed to the
/// driver (scripts/lsan_suppressions.txt lists them). Costs nothing: they are loaded anyway.
void pinDrivers() {
  for (const fs::path& driver : driverLibraries(driverRepository()))
    dlopen(driver.c_str(),
           RTLD_NOW | RTLD_LOCAL | RTLD_NODELETE);  // a failure is OpenNI's to report
}

/// The driver repository and the libraries found there, for messages.
std::string driversFound() {
  const fs::path repository = driverRepository();
  std::vector<std::string> drivers;
  for (const fs::path& driver : driverLibraries(repository))
    drivers.push_back(driver.filename().string());
  std::string text = "OpenNI2 " + std::to_string(ONI_VERSION_MAJOR) + "." +
                     std::to_string(ONI_VERSION_MINOR) + " drivers in " + repository.string() +
                     ": ";
  if (drivers.empty()) return text + "none";
  for (size_t i = 0; i < drivers.size(); ++i) text += (i ? ", " : "") + drivers[i];
  return text;
}

std::string devicesEnumerated() {
  openni::Array<openni::DeviceInfo> list;
  openni::OpenNI::enumerateDevices(&list);
  if (list.getSize() == 0) return "no device enumerated";
  std::string text = std::to_string(list.getSize()) + " device(s) enumerated:";
  for (int i = 0; i < list.getSize(); ++i)
    text += std::string(" ") + list[i].getUri() + " (" + list[i].getVendor() + " " +
            list[i].getName() + ")";
  return text;
}

/// A live mode of `size` and `format`, the requested rate preferred.
const openni::VideoMode* findMode(const openni::SensorInfo& sensor, openni::PixelFormat format,
                                  const RgbdDeviceRequest& request) {
  const openni::VideoMode* best = nullptr;
  const auto& modes = sensor.getSupportedVideoModes();
  for (int i = 0; i < modes.getSize(); ++i) {
    const openni::VideoMode& m = modes[i];
    if (m.getPixelFormat() != format || m.getResolutionX() != request.width ||
        m.getResolutionY() != request.height)
      continue;
    if (!best || std::abs(m.getFps() - request.fps) < std::abs(best->getFps() - request.fps))
      best = &m;
  }
  return best;
}

class OpenNi2Device final : public RgbdDevice {
 public:
  explicit OpenNi2Device(const RgbdDeviceRequest& request)
      : where_(describe(request)), context_(OpenNiContext::acquire()) {
    const char* uri = request.uri.empty() ? openni::ANY_DEVICE : request.uri.c_str();
    if (device_.open(uri) != openni::STATUS_OK) {
      const std::string error = openni::OpenNI::getExtendedError();
      if (request.is_file) throw InputError(where_, "cannot open the recording: " + error);
      throw InputError(where_, "no OpenNI2 device could be opened (" + error +
                                   "). Looked for: " + driversFound() + "; " + devicesEnumerated() +
                                   ". Is the camera plugged in, listed by lsusb, and may this "
                                   "user open it (udev rules)?");
    }
    info_.uri = device_.getDeviceInfo().getUri();
    info_.name =
        std::string(device_.getDeviceInfo().getVendor()) + " " + device_.getDeviceInfo().getName();
    info_.is_file = device_.isFile();
    createStream(colour_, openni::SENSOR_COLOR, "colour");
    createStream(depth_, openni::SENSOR_DEPTH, "depth");
    if (!info_.is_file) chooseModes(request);
    if (request.register_depth_to_colour &&
        device_.isImageRegistrationModeSupported(openni::IMAGE_REGISTRATION_DEPTH_TO_COLOR))
      device_.setImageRegistrationMode(openni::IMAGE_REGISTRATION_DEPTH_TO_COLOR);
    info_.depth_registered =
        device_.getImageRegistrationMode() == openni::IMAGE_REGISTRATION_DEPTH_TO_COLOR;
    if (request.sync_depth_and_colour && !info_.is_file) device_.setDepthColorSyncEnabled(true);
    info_.synced = device_.getDepthColorSyncEnabled();
    if (info_.is_file) {
      requireCropping(colour_, "colour");
      requireCropping(depth_, "depth");
      openni::PlaybackControl* playback = device_.getPlaybackControl();
      playback->setRepeatEnabled(false);
      // A recording that was not closed properly says -1: its end is found by waiting.
      info_.frames = std::max(
          0, std::min(playback->getNumberOfFrames(colour_), playback->getNumberOfFrames(depth_)));
      // Manual speed: the player hands over one recorded frame each time a wait asks for one,
      // so every frame arrives, in the file's order, however slow the pipeline is. Pacing at
      // the recorded rate is the real-time runner's job, as for a folder.
      playback->setSpeed(kManualSpeed);
    }

    checkFormats();
  }

  ~OpenNi2Device() override {
    stopStreams();
    // OpenNI2 2.2's file player thread walks the device's stream list without its lock, every
    // 10 ms once no stream runs: destroying a stream while it walks crashed about one run in
    // 100 here. Stopped streams and a pause put it in its sleep first.
    if (info_.is_file) std::this_thread::sleep_for(std::chrono::milliseconds(30));
    colour_.destroy();
    depth_.destroy();
    device_.close();
  }

  [[nodiscard]] const RgbdDeviceInfo& info() const override { return info_; }

  std::optional<RawRgbdFrame> read() override {
    // Streams start at the first read, not at open: a recording plays from its start then,
    // instead of running past while the pipeline loads its models.
    if (!started_) {
      started_ = true;
      if (colour_.start() != openni::STATUS_OK || depth_.start() != openni::STATUS_OK)
        throw InputError(
            where_, std::string("cannot start the streams: ") + openni::OpenNI::getExtendedError());
    }
    if (info_.is_file && info_.frames > 0 && read_ >= info_.frames) {
      stopStreams();  // at its end the player would otherwise spin a core until closed
      return std::nullopt;
    }
    while (true) {
      if (!colour_queue_.empty() && !depth_queue_.empty()) {
        const uint64_t colour_us = colour_queue_.front().getTimestamp();
        const uint64_t depth_us = depth_queue_.front().getTimestamp();
        const PairStep step = pairStep(colour_us, depth_us, info_.fps);
        if (step == PairStep::kPair) break;
        const bool colour_goes = step == PairStep::kDropColour;
        spdlog::warn("{}: {} frame at {} us has no {} frame within {} us; dropped", where_,
                     colour_goes ? "colour" : "depth", colour_goes ? colour_us : depth_us,
                     colour_goes ? "depth" : "colour", pairingToleranceUs(info_.fps));
        (colour_goes ? colour_queue_ : depth_queue_).pop_front();
        continue;
      }
      if (!readNext()) {
        stopStreams();
        return std::nullopt;
      }
    }
    RawRgbdFrame frame = toRaw(colour_queue_.front(), depth_queue_.front());
    colour_queue_.pop_front();
    depth_queue_.pop_front();
    ++read_;
    return frame;
  }

 private:
  void stopStreams() {
    if (stopped_) return;
    stopped_ = true;
    colour_.stop();
    depth_.stop();
  }

  static std::string describe(const RgbdDeviceRequest& request) {
    return request.is_file ? request.uri : "openni://" + request.uri;
  }

  void createStream(openni::VideoStream& stream, openni::SensorType type, const char* what) {
    if (!device_.hasSensor(type))
      throw InputError(where_, std::string("the device has no ") + what + " sensor");
    if (stream.create(device_, type) != openni::STATUS_OK)
      throw InputError(where_, std::string("cannot open the ") + what +
                                   " stream: " + openni::OpenNI::getExtendedError());
  }

  void chooseModes(const RgbdDeviceRequest& request) {
    const openni::VideoMode* colour = findMode(*device_.getSensorInfo(openni::SENSOR_COLOR),
                                               openni::PIXEL_FORMAT_RGB888, request);
    const openni::VideoMode* depth = findMode(*device_.getSensorInfo(openni::SENSOR_DEPTH),
                                              openni::PIXEL_FORMAT_DEPTH_1_MM, request);
    if (!depth)
      depth = findMode(*device_.getSensorInfo(openni::SENSOR_DEPTH),
                       openni::PIXEL_FORMAT_DEPTH_100_UM, request);
    if (!colour || !depth)
      throw InputError(where_, "the device has no " + std::to_string(request.width) + "x" +
                                   std::to_string(request.height) +
                                   " RGB888 colour and millimetre depth modes");
    colour_.setVideoMode(*colour);
    depth_.setVideoMode(*depth);
  }

  void checkFormats() {
    const openni::VideoMode colour = colour_.getVideoMode(), depth = depth_.getVideoMode();
    if (colour.getPixelFormat() != openni::PIXEL_FORMAT_RGB888)
      throw InputError(where_, "colour pixel format " + std::to_string(colour.getPixelFormat()) +
                                   " is not RGB888");
    if (depth.getPixelFormat() == openni::PIXEL_FORMAT_DEPTH_1_MM)
      info_.depth_unit_m = 0.001;
    else if (depth.getPixelFormat() == openni::PIXEL_FORMAT_DEPTH_100_UM)
      info_.depth_unit_m = 0.0001;
    else
      throw InputError(where_, "depth pixel format " + std::to_string(depth.getPixelFormat()) +
                                   " is not millimetres or 100 µm");
    if (colour.getResolutionX() != depth.getResolutionX() ||
        colour.getResolutionY() != depth.getResolutionY())
      throw InputError(where_, "colour " + std::to_string(colour.getResolutionX()) + "x" +
                                   std::to_string(colour.getResolutionY()) + " and depth " +
                                   std::to_string(depth.getResolutionX()) + "x" +
                                   std::to_string(depth.getResolutionY()) + " sizes differ");
    info_.width = colour.getResolutionX();
    info_.height = colour.getResolutionY();
    info_.fps = colour.getFps();
    info_.horizontal_fov_rad = colour_.getHorizontalFieldOfView();
    info_.vertical_fov_rad = colour_.getVerticalFieldOfView();
  }

  /// A recording without a cropping property cannot be played by OpenNI2 2.2: its file
  /// player (PlayerStream::OnNewDataCallback) drops every frame of a stream whose recorded
  /// properties lack one, so the reads would only time out. Recordings of drivers that do not
  /// report cropping have none (OpenNI2's own DummyDevice); PrimeSense devices report it.
  void requireCropping(openni::VideoStream& stream, const char* what) {
    OniCropping cropping{};
    if (stream.getProperty(ONI_STREAM_PROPERTY_CROPPING, &cropping) != openni::STATUS_OK)
      throw InputError(where_, std::string("the recording's ") + what +
                                   " stream has no cropping property (xnCropping): OpenNI2 " +
                                   std::to_string(ONI_VERSION_MAJOR) + "." +
                                   std::to_string(ONI_VERSION_MINOR) +
                                   "'s player delivers no frame of such a stream (recorded "
                                   "from a driver that does not report cropping)");
  }

  /// Waits for a frame of either stream and queues it: waiting on both at once takes each
  /// frame as the driver (or, in manual playback, the file) hands it over, so neither
  /// stream's single-frame holder is overwritten while the other is awaited. False at the end
  /// of a recording; DeviceError when a live stream goes silent or fails.
  bool readNext() {
    openni::VideoStream* streams[] = {&colour_, &depth_};
    int ready = -1;
    if (openni::OpenNI::waitForAnyStream(streams, 2, &ready, kWaitMs) != openni::STATUS_OK) {
      if (info_.is_file) {
        spdlog::warn("{}: the recording ended after {} of {} frames", where_, read_, info_.frames);
        return false;
      }
      throw DeviceError(where_ + ": no frame for " + std::to_string(kWaitMs) + " ms (" +
                        openni::OpenNI::getExtendedError() + ")");
    }
    const char* what = ready == 0 ? "colour" : "depth";
    openni::VideoFrameRef frame;
    if (streams[ready]->readFrame(&frame) != openni::STATUS_OK || !frame.isValid())
      throw DeviceError(where_ + ": reading a " + what +
                        " frame failed: " + openni::OpenNI::getExtendedError());
    auto& queue = ready == 0 ? colour_queue_ : depth_queue_;
    queue.push_back(frame);
    if (queue.size() > kMaxQueued) {
      spdlog::warn("{}: {} frames arrive without {} frames; the oldest is dropped", where_, what,
                   ready == 0 ? "depth" : "colour");
      queue.pop_front();
    }
    return true;
  }

  static RawRgbdFrame toRaw(const openni::VideoFrameRef& colour,
                            const openni::VideoFrameRef& depth) {
    RawRgbdFrame frame;
    frame.colour_stamp_us = colour.getTimestamp();
    frame.depth_stamp_us = depth.getTimestamp();
    const cv::Mat rgb(colour.getHeight(), colour.getWidth(), CV_8UC3,
                      const_cast<void*>(colour.getData()), size_t(colour.getStrideInBytes()));
    cv::cvtColor(rgb, frame.bgr, cv::COLOR_RGB2BGR);  // copies out of OpenNI's buffer
    frame.depth_raw = cv::Mat(depth.getHeight(), depth.getWidth(), CV_16U,
                              const_cast<void*>(depth.getData()), size_t(depth.getStrideInBytes()))
                          .clone();
    return frame;
  }

  std::string where_;
  std::shared_ptr<OpenNiContext> context_;  // first member to come, last to go
  openni::Device device_;
  openni::VideoStream colour_, depth_;
  RgbdDeviceInfo info_;
  std::deque<openni::VideoFrameRef> colour_queue_, depth_queue_;  // read, not yet paired
  int read_ = 0;                                                  // pairs delivered
  bool started_ = false;
  bool stopped_ = false;
};

}  // namespace

std::unique_ptr<RgbdDevice> openOpenNi2Device(const RgbdDeviceRequest& request) {
  return std::make_unique<OpenNi2Device>(request);
}

bool haveOpenNi2() {
  return true;
}

}  // namespace dynanav
#endif  // DYNANAV_HAVE_OPENNI2
