#include "io/camera_yaml.hpp"

#include <yaml-cpp/yaml.h>

#include <fstream>

#include "core/error.hpp"

namespace dynanav {

PinholeCamera loadCameraYaml(const std::filesystem::path& path) {
  YAML::Node root;
  try {
    root = YAML::LoadFile(path.string());
  } catch (const YAML::Exception& e) {
    throw InputError(path.string(), std::string("cannot parse camera file: ") + e.what());
  }
  if (!root.IsMap()) throw InputError(path.string(), "camera file must be a YAML map");
  PinholeCamera camera;
  camera.name = path.parent_path().filename().string();
  const auto required = [&](const char* key, auto& value) {
    if (!root[key]) throw InputError(path.string(), std::string("missing key '") + key + "'");
    try {
      value = root[key].as<std::decay_t<decltype(value)>>();
    } catch (const YAML::Exception&) {
      throw InputError(path.string(), std::string("bad value for '") + key + "'");
    }
  };
  const auto optional = [&](const char* key, auto& value) {
    if (root[key]) required(key, value);
  };
  required("width", camera.width);
  required("height", camera.height);
  required("fx", camera.fx);
  required("fy", camera.fy);
  required("cx", camera.cx);
  required("cy", camera.cy);
  optional("depth_factor", camera.depth_factor);
  optional("baseline_m", camera.baseline_m);
  double readout_ms = 0.0;
  optional("rolling_shutter_readout_ms", readout_ms);
  camera.readout_s = readout_ms * 1e-3;
  if (root["distortion"]) {
    std::vector<double> d;
    required("distortion", d);
    if (d.size() != 5) throw InputError(path.string(), "'distortion' needs 5 values k1 k2 p1 p2 k3");
    std::copy(d.begin(), d.end(), camera.distortion.begin());
  }
  if (camera.width <= 0 || camera.height <= 0 || camera.fx <= 0 || camera.fy <= 0 ||
      camera.depth_factor <= 0 || camera.baseline_m <= 0 || camera.readout_s < 0) {
    throw InputError(path.string(), "width, height, fx, fy, depth_factor and baseline_m must be > 0, "
                                   "rolling_shutter_readout_ms >= 0");
  }
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
  e << YAML::EndMap;
  std::ofstream out(path);
  if (!out) throw InputError(path.string(), "cannot write camera file");
  out << e.c_str() << "\n";
}

}  // namespace dynanav
