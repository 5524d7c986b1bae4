#include "io/camera_yaml.hpp"

#include <yaml-cpp/yaml.h>

#include <cmath>
#include <fstream>
#include <map>
#include <sstream>
#include <string>
#include <vector>

#include "core/error.hpp"

namespace dynanav {

namespace {

/// A camera.yaml key and its valid values (README, "Sequences"); NaN and infinity never pass.
struct CameraKey {
  const char* key;
  bool required;
  double lo;
  double hi;
};

constexpr CameraKey kCameraKeys[] = {
    {"width", true, 16, 8192},
    {"height", true, 16, 8192},
    {"fx", true, 1, 100000},
    {"fy", true, 1, 100000},
    {"cx", true, 0, 8192},  // also within [0, width], checked below
    {"cy", true, 0, 8192},
    {"distortion", false, -100, 100},  // each of k1 k2 p1 p2 k3
    {"depth_factor", false, 1e-3, 1e6},
    {"baseline_m", false, 1e-3, 10},
    {"rolling_shutter_readout_ms", false, 0, 1000},
    {"exposure_ms", false, 0, 1000},
};

std::string rangeText(const CameraKey& k) {
  std::ostringstream s;
  s << "[" << k.lo << ", " << k.hi << "]";
  return s.str();
}

}  // namespace

PinholeCamera loadCameraYaml(const std::filesystem::path& path) {
  const std::string file = path.string();
  YAML::Node root;
  try {
    root = YAML::LoadFile(file);
  } catch (const YAML::Exception& e) {
    throw InputError(file, std::string("cannot parse camera file: ") + e.what());
  }
  if (!root.IsMap()) throw InputError(file, "camera file must be a YAML map");
  for (const auto& kv : root) {
    std::string key;
    try {
      key = kv.first.as<std::string>();
    } catch (const YAML::Exception&) {
      throw InputError(file, "camera file keys must be plain words");
    }
    bool known = false;
    for (const CameraKey& k : kCameraKeys) known = known || key == k.key;
    if (!known) throw InputError(file, "unknown key '" + key + "'");
  }
  std::map<std::string, std::vector<double>> values;
  for (const CameraKey& k : kCameraKeys) {
    const YAML::Node node = root[k.key];
    if (!node) {
      if (k.required) throw InputError(file, std::string("missing key '") + k.key + "'");
      continue;
    }
    std::vector<double> v;
    try {
      if (std::string(k.key) == "distortion") {
        v = node.as<std::vector<double>>();
        if (v.size() != 5)
          throw InputError(
              file, "'distortion' needs 5 values k1 k2 p1 p2 k3, got " + std::to_string(v.size()));
      } else {
        v = {node.as<double>()};
      }
    } catch (const YAML::Exception&) {
      throw InputError(file, std::string("bad value for '") + k.key + "': not a number" +
                                 (std::string(k.key) == "distortion" ? " list" : ""));
    }
    for (const double x : v) {
      if (!std::isfinite(x) || x < k.lo || x > k.hi) {
        std::ostringstream shown;
        shown << x;
        throw InputError(file, std::string("'") + k.key + "' = " + shown.str() +
                                   " is out of range, expected " + rangeText(k));
      }
    }
    values[k.key] = v;
  }
  PinholeCamera camera;
  camera.name = path.parent_path().filename().string();
  for (const char* key : {"width", "height"}) {
    if (values[key][0] != std::floor(values[key][0]))
      throw InputError(file, std::string("'") + key + "' must be a whole number of pixels");
  }
  camera.width = static_cast<int>(values["width"][0]);
  camera.height = static_cast<int>(values["height"][0]);
  camera.fx = values["fx"][0];
  camera.fy = values["fy"][0];
  camera.cx = values["cx"][0];
  camera.cy = values["cy"][0];
  if (camera.cx > camera.width || camera.cy > camera.height)
    throw InputError(file, "principal point ('cx', 'cy') lies outside the " +
                               std::to_string(camera.width) + "x" + std::to_string(camera.height) +
                               " image");
  if (values.count("distortion"))
    std::copy(values["distortion"].begin(), values["distortion"].end(), camera.distortion.begin());
  if (values.count("depth_factor")) camera.depth_factor = values["depth_factor"][0];
  if (values.count("baseline_m")) camera.baseline_m = values["baseline_m"][0];
  if (values.count("rolling_shutter_readout_ms"))
    camera.readout_s = values["rolling_shutter_readout_ms"][0] * 1e-3;
  if (values.count("exposure_ms")) camera.exposure_s = values["exposure_ms"][0] * 1e-3;
  return camera;
}

void saveCameraYaml(const std::filesystem::path& path, const PinholeCamera& camera) {
  YAML::Emitter e;
  e << YAML::BeginMap;
  e << YAML::Key << "width" << YAML::Value << camera.width;
  e << YAML::Key << "height" << YAML::Value << camera.height;
  e << YAML::Key << "fx" << YAML::Value << camera.fx;
  e << YAML::Key << "fy" << YAML::Value << camera.fy;
  e << YAML::Key << "cx" << YAML::Value << camera.cx;
  e << YAML::Key << "cy" << YAML::Value << camera.cy;
  e << YAML::Key << "distortion" << YAML::Value << YAML::Flow
    << std::vector<double>(camera.distortion.begin(), camera.distortion.end());
  e << YAML::Key << "depth_factor" << YAML::Value << camera.depth_factor;
  e << YAML::Key << "baseline_m" << YAML::Value << camera.baseline_m;
  e << YAML::Key << "rolling_shutter_readout_ms" << YAML::Value << camera.readout_s * 1e3;
  if (camera.exposure_s > 0.0)
    e << YAML::Key << "exposure_ms" << YAML::Value << camera.exposure_s * 1e3;
  e << YAML::EndMap;
  std::ofstream out(path);
  if (!out) throw InputError(path.string(), "cannot write camera file");
  out << e.c_str() << "\n";
  out.close();
  if (!out) throw InputError(path.string(), "cannot write camera file (disk full?)");
}

}  // namespace dynanav
