#pragma once
// objects.jsonl (DESIGN.md §2): one line per frame, {"t": stamp, "objects": [...]}, written by
// the run (ObjectsSink) and by the simulator (objects_gt.jsonl) through this one piece of code.
// Keys beyond DESIGN.md's: heading_deg, missed_frames, motion_inliers, sigma_position_m,
// sigma_velocity_mps, covariance (row-major 6x6, [p, v] world), predicted_path
// ([{"ahead_s", "position_world", "sigma_m"}]) and, ground truth only, in_view
// (TrackedObject::visible_share). Numbers are rounded to 6 decimals (files compare byte for byte
// between runs).
#include <filesystem>
#include <nlohmann/json.hpp>
#include <vector>

#include "core/tracked_object.hpp"
#include "io/json_io.hpp"

namespace dynanav {

struct ObjectsFrame {
  double stamp_s = 0.0;
  std::vector<TrackedObject> objects;
};

nlohmann::json toJson(const TrackedObject& object);
nlohmann::json objectsFrameJson(double stamp_s, const std::vector<TrackedObject>& objects);
/// Inverse of toJson; throws nlohmann::json::exception on a missing DESIGN.md key.
TrackedObject trackedObjectFromJson(const nlohmann::json& json);

/// Writes one line per frame, flushed.
class ObjectsWriter {
 public:
  explicit ObjectsWriter(const std::filesystem::path& path) : lines_(path) {}
  void write(double stamp_s, const std::vector<TrackedObject>& objects) {
    lines_.write(objectsFrameJson(stamp_s, objects));
  }

 private:
  JsonLinesWriter lines_;
};

/// Reads an objects.jsonl / objects_gt.jsonl; InputError naming file and line when malformed.
std::vector<ObjectsFrame> readObjectsJsonl(const std::filesystem::path& path);

}  // namespace dynanav
