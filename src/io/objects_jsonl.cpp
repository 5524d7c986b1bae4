#include "io/objects_jsonl.hpp"

#include <Eigen/Eigenvalues>
#include <cmath>

#include "core/error.hpp"
#include "io/text_lines.hpp"

namespace dynanav {
namespace {

double round6(double v) {
  return std::round(v * 1e6) / 1e6 + 0.0;  // + 0.0: no "-0.0" in files
}
nlohmann::json vec(const Vec3& v) {
  return {round6(v.x()), round6(v.y()), round6(v.z())};
}
Vec3 vec3(const nlohmann::json& j) {
  return {j.at(0).get<double>(), j.at(1).get<double>(), j.at(2).get<double>()};
}
double sigma(const Eigen::Matrix3d& block) {
  const Eigen::Matrix3d sym = 0.5 * (block + block.transpose());
  return std::sqrt(
      std::max(0.0, Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d>(sym).eigenvalues().maxCoeff()));
}

}  // namespace

nlohmann::json toJson(const TrackedObject& o) {
  nlohmann::json j = {{"id", o.id},
                      {"class", o.class_name},
                      {"dynamic", o.dynamic},
                      {"position_world", vec(o.p_world)},
                      {"position_camera", vec(o.p_camera)},
                      {"distance", round6(o.distance_m)},
                      {"bearing_deg", round6(o.bearing_deg)},
                      {"clock", o.clock},
                      {"velocity_world", vec(o.v_world_mps)},
                      {"speed", round6(o.speed_mps)},
                      {"velocity_known", o.velocity_known},
                      {"heading_deg", round6(o.heading_deg)},
                      {"points", o.points}};
  if (o.visible_share >= 0.0) j["in_view"] = round6(o.visible_share);
  if (!o.covariance.isZero()) {
    j["missed_frames"] = o.missed_frames;
    j["motion_inliers"] = o.motion_inliers;
    j["sigma_position_m"] = round6(sigma(o.covariance.topLeftCorner<3, 3>()));
    j["sigma_velocity_mps"] = round6(sigma(o.covariance.bottomRightCorner<3, 3>()));
    nlohmann::json cov = nlohmann::json::array();
    for (int r = 0; r < 6; ++r)
      for (int c = 0; c < 6; ++c) cov.push_back(round6(o.covariance(r, c)));
    j["covariance"] = cov;
  }
  if (!o.predicted_path.empty()) {
    nlohmann::json path = nlohmann::json::array();
    for (const PathPoint& p : o.predicted_path)
      path.push_back({{"ahead_s", round6(p.ahead_s)},
                      {"position_world", vec(p.p_world)},
                      {"sigma_m", round6(p.sigma_m)}});
    j["predicted_path"] = path;
  }
  return j;
}

nlohmann::json objectsFrameJson(double stamp_s, const std::vector<TrackedObject>& objects) {
  nlohmann::json list = nlohmann::json::array();
  for (const TrackedObject& o : objects) list.push_back(toJson(o));
  return {{"t", round6(stamp_s)}, {"objects", list}};
}

TrackedObject trackedObjectFromJson(const nlohmann::json& j) {
  TrackedObject o;
  o.id = j.at("id").get<uint64_t>();
  o.class_name = j.at("class").get<std::string>();
  o.dynamic = j.at("dynamic").get<bool>();
  o.p_world = vec3(j.at("position_world"));
  o.p_camera = vec3(j.at("position_camera"));
  o.distance_m = j.at("distance").get<double>();
  o.bearing_deg = j.at("bearing_deg").get<double>();
  o.clock = j.at("clock").get<int>();
  o.v_world_mps = vec3(j.at("velocity_world"));
  o.speed_mps = j.at("speed").get<double>();
  o.velocity_known = j.value("velocity_known", true);  // files written before it: known
  o.points = j.at("points").get<int>();
  o.heading_deg = j.value("heading_deg", 0.0);
  o.visible_share = j.value("in_view", -1.0);
  o.missed_frames = j.value("missed_frames", 0);
  o.motion_inliers = j.value("motion_inliers", 0);
  if (j.contains("covariance")) {
    const auto& cov = j.at("covariance");
    if (cov.size() != 36) throw std::invalid_argument("covariance must have 36 numbers");
    for (int k = 0; k < 36; ++k) o.covariance(k / 6, k % 6) = cov.at(k).get<double>();
  }
  if (j.contains("predicted_path"))
    for (const auto& p : j.at("predicted_path"))
      o.predicted_path.push_back({p.at("ahead_s").get<double>(), vec3(p.at("position_world")),
                                  p.at("sigma_m").get<double>()});
  return o;
}

std::vector<ObjectsFrame> readObjectsJsonl(const std::filesystem::path& path) {
  std::vector<ObjectsFrame> frames;
  for (const auto& line : readContentLines(path)) {
    try {
      const nlohmann::json j = nlohmann::json::parse(line.text);
      ObjectsFrame frame;
      frame.stamp_s = j.at("t").get<double>();
      for (const auto& o : j.at("objects")) frame.objects.push_back(trackedObjectFromJson(o));
      frames.push_back(std::move(frame));
    } catch (const std::exception& e) {
      throw InputError(where(path, line.number),
                       std::string("not an objects.jsonl frame: ") + e.what());
    }
  }
  return frames;
}

}  // namespace dynanav
