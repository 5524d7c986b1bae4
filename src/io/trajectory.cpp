#include "io/trajectory.hpp"

#include <array>
#include <cstdio>

#include "core/error.hpp"
#include "io/text_lines.hpp"

namespace dynanav {

std::vector<StampedPose> readTrajectory(const std::filesystem::path& path) {
  std::vector<StampedPose> poses;
  for (const auto& line : readContentLines(path)) {
    const auto fields = splitFields(line.text);
    if (fields.size() != 8) {
      throw InputError(
          where(path, line.number),
          "expected 8 values 't tx ty tz qx qy qz qw', got " + std::to_string(fields.size()));
    }
    std::array<double, 8> v{};
    for (size_t k = 0; k < 8; ++k) {
      if (!parseFiniteDouble(fields[k], v[k])) {
        throw InputError(where(path, line.number), "not a finite number: '" + fields[k] + "'");
      }
    }
    const Quat q(v[7], v[4], v[5], v[6]);
    if (q.norm() < 1e-6) throw InputError(where(path, line.number), "quaternion has zero norm");
    if (!poses.empty() && v[0] <= poses.back().stamp_s) {
      throw InputError(where(path, line.number), v[0] == poses.back().stamp_s
                                                     ? "duplicate timestamp"
                                                     : "timestamps not sorted");
    }
    poses.push_back({v[0], makeSE3(q, Vec3(v[1], v[2], v[3]))});
  }
  return poses;
}

std::string formatTumLine(const StampedPose& pose) {
  const Vec3 t = pose.T_world_camera.translation();
  Quat q(pose.T_world_camera.linear());
  q.normalize();
  if (q.w() < 0) q.coeffs() *= -1.0;  // one canonical sign, so files compare byte for byte
  char buffer[256];
  std::snprintf(buffer, sizeof(buffer), "%.6f %.9f %.9f %.9f %.9f %.9f %.9f %.9f", pose.stamp_s,
                t.x(), t.y(), t.z(), q.x(), q.y(), q.z(), q.w());
  return buffer;
}

TrajectoryWriter::TrajectoryWriter(const std::filesystem::path& path) : path_(path), out_(path) {
  if (!out_) throw InputError(path.string(), "cannot write trajectory");
  out_ << "# timestamp tx ty tz qx qy qz qw (camera-to-world, TUM format)\n";
  out_.flush();
  check("writing the trajectory");
}

void TrajectoryWriter::check(const char* what) {
  if (!out_) throw InputError(path_.string(), std::string(what) + " failed (disk full?)");
}

void TrajectoryWriter::write(const StampedPose& pose) {
  out_ << formatTumLine(pose) << '\n';
  out_.flush();
  check("writing the trajectory");
}

void TrajectoryWriter::close() {
  if (!out_.is_open()) return;
  out_.close();
  check("closing the trajectory");
}

void writeTrajectory(const std::filesystem::path& path, const std::vector<StampedPose>& poses) {
  TrajectoryWriter writer(path);
  for (const auto& pose : poses) writer.write(pose);
  writer.close();
}

}  // namespace dynanav
