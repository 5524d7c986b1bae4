#include "pipeline/device_source.hpp"

#include <spdlog/spdlog.h>

#include <cmath>
#include <filesystem>
#include <numbers>

#include "core/error.hpp"
#include "io/image_file.hpp"

namespace fs = std::filesystem;

namespace dynanav {
namespace {

constexpr std::string_view kScheme = "openni://";

std::string size(int width, int height) {
  return std::to_string(width) + "x" + std::to_string(height);
}

double degrees(double rad) {
  return rad * 180.0 / std::numbers::pi;
}

}  // namespace

PinholeCamera cameraFromFieldOfView(int width, int height, double horizontal_fov_rad,
                                    double vertical_fov_rad, const std::string& where) {
  const auto valid = [](double fov) {
    return std::isfinite(fov) && fov > 0 && fov < std::numbers::pi;
  };
  if (!valid(horizontal_fov_rad) || !valid(vertical_fov_rad))
    throw InputError(where, "the device reports no usable field of view (" +
                                std::to_string(horizontal_fov_rad) + ", " +
                                std::to_string(vertical_fov_rad) +
                                " rad): give its calibration with --camera CAMERA.yaml");
  PinholeCamera camera;
  camera.name = "device field of view";
  camera.width = width;
  camera.height = height;
  // A pixel's centre is at integer coordinates, so the image spans [-0.5, width - 0.5].
  camera.fx = 0.5 * width / std::tan(0.5 * horizontal_fov_rad);
  camera.fy = 0.5 * height / std::tan(0.5 * vertical_fov_rad);
  camera.cx = 0.5 * (width - 1);
  camera.cy = 0.5 * (height - 1);
  return camera;
}

DeviceSource::DeviceSource(const DeviceSourceOptions& options, const RgbdDeviceOpener& open)
    : options_(options),
      where_(options.request.is_file ? options.request.uri
                                     : std::string(kScheme) + options.request.uri),
      device_(open(options.request)) {
  const RgbdDeviceInfo& info = device_->info();
  if (options.camera) {
    camera_ = *options.camera;
    camera_source_ = options.camera_origin;
    if (camera_.width != info.width || camera_.height != info.height)
      throw InputError(options.camera_origin,
                       "calibration is for " + size(camera_.width, camera_.height) + ", " + where_ +
                           " delivers " + size(info.width, info.height));
  } else {
    camera_ = cameraFromFieldOfView(info.width, info.height, info.horizontal_fov_rad,
                                    info.vertical_fov_rad, where_);
    camera_.depth_factor = 1.0 / info.depth_unit_m;
    camera_source_ = fmt::format("device field of view {:.1f}° x {:.1f}°",
                                 degrees(info.horizontal_fov_rad), degrees(info.vertical_fov_rad));
  }
  spdlog::info(
      "{}: {} ({}), {} at {:g} frames/s, depth unit {:g} m, depth registered to colour: "
      "{}, frame sync: {}",
      where_, info.name, info.is_file ? std::to_string(info.frames) + " frames recorded" : "live",
      size(info.width, info.height), info.fps, info.depth_unit_m,
      info.depth_registered ? "yes" : "no", info.synced ? "yes" : "no");
  if (options.request.register_depth_to_colour && !info.depth_registered)
    spdlog::warn(
        "{}: depth is not registered to colour (the {} cannot): depth pixels are "
        "offset from the colour pixels they are used with",
        where_, info.is_file ? "recording" : "device");
  spdlog::info("{}: camera fx {:.1f} fy {:.1f} cx {:.1f} cy {:.1f} from {}", where_, camera_.fx,
               camera_.fy, camera_.cx, camera_.cy, camera_source_);
}

size_t DeviceSource::expected() const {
  const int recorded = device_->info().frames;
  if (options_.max_frames > 0 && (recorded == 0 || options_.max_frames < recorded))
    return size_t(options_.max_frames);
  return size_t(recorded);
}

std::string DeviceSource::problem(const RawRgbdFrame& raw, const RgbdFrame& frame) const {
  if (raw.bgr.type() != CV_8UC3 || raw.bgr.cols != camera_.width || raw.bgr.rows != camera_.height)
    return "colour image is not " + size(camera_.width, camera_.height) + " BGR";
  if (raw.depth_raw.type() != CV_16U || raw.depth_raw.size() != raw.bgr.size())
    return "depth image is not " + size(camera_.width, camera_.height) + " 16-bit";
  if (last_stamp_s_ >= 0 && !(frame.stamp_s > last_stamp_s_))
    return fmt::format("timestamp {:.6f} s does not come after the previous frame's {:.6f} s",
                       frame.stamp_s, last_stamp_s_);
  if (const std::string colour = colourFrameProblem(raw.bgr); !colour.empty())
    return "colour image is " + colour;
  if (cv::countNonZero(raw.depth_raw) == 0) return "depth image has no valid pixel (all 0)";
  return {};
}

std::optional<RgbdFrame> DeviceSource::next() {
  while (options_.max_frames <= 0 || read_ < options_.max_frames) {
    std::optional<RawRgbdFrame> raw;
    try {
      raw = device_->read();
    } catch (const std::exception& e) {
      // An unplugged camera must not take the run with it: end the frames, keep the outputs.
      failure_ = e.what();
      spdlog::error("{} after {} frames; the run ends here and writes what it has", failure_,
                    read_);
      return std::nullopt;
    }
    if (!raw) return std::nullopt;  // the end of a recording
    RgbdFrame frame;
    frame.index = read_++;
    frame.stamp_s = double(raw->colour_stamp_us) * 1e-6;
    frame.depth_stamp_s = double(raw->depth_stamp_us) * 1e-6;
    if (const std::string why = problem(*raw, frame); !why.empty()) {
      ++skipped_;
      spdlog::warn("frame {} skipped: {}: {}", frame.index, where_, why);
      continue;
    }
    last_stamp_s_ = frame.stamp_s;
    frame.bgr = std::move(raw->bgr);
    raw->depth_raw.convertTo(frame.depth_m, CV_32F, device_->info().depth_unit_m);
    const auto& blackout = options_.blackout;
    if (blackout && frame.index >= blackout->first && frame.index <= blackout->second) {
      frame.bgr.setTo(cv::Scalar::all(0));
      frame.depth_m.setTo(0.0f);
    }
    return frame;
  }
  return std::nullopt;
}

bool isDeviceInput(const std::string& input) {
  if (input.rfind(kScheme, 0) == 0) return true;
  std::string extension = fs::path(input).extension().string();
  for (char& c : extension) c = char(std::tolower(static_cast<unsigned char>(c)));
  return extension == ".oni";
}

RgbdDeviceRequest deviceRequestFor(const std::string& input) {
  RgbdDeviceRequest request;
  if (input.rfind(kScheme, 0) == 0) {
    request.uri = input.substr(kScheme.size());
    return request;
  }
  std::error_code ec;
  if (!fs::exists(input, ec)) throw InputError(input, "recording (.oni) not found");
  if (!fs::is_regular_file(input, ec)) throw InputError(input, "recording (.oni) is not a file");
  request.uri = input;
  request.is_file = true;
  return request;
}

}  // namespace dynanav
