#pragma once
// TUM trajectory files: "t tx ty tz qx qy qz qw" per line, camera-to-world (T_world_camera).
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include "core/se3.hpp"

namespace dynanav {

struct StampedPose {
  double stamp_s = 0.0;
  SE3 T_world_camera = SE3::Identity();
};

/// Reads a TUM trajectory ('#' comments, blank lines, CRLF, commas as separators allowed).
/// Throws InputError naming file and line for malformed lines, NaNs or unsorted/duplicate stamps.
std::vector<StampedPose> readTrajectory(const std::filesystem::path& path);

/// One TUM line (no newline), 9 significant digits for poses and 6 decimals for stamps.
std::string formatTumLine(const StampedPose& pose);

/// Appends poses and flushes each line, so an interrupted run keeps what it wrote. Every write
/// is checked: a full disk or an I/O error is an InputError naming the file, never a short file.
class TrajectoryWriter {
 public:
  explicit TrajectoryWriter(const std::filesystem::path& path);
  void write(const StampedPose& pose);
  /// Closes the file, throwing InputError if the last bytes could not be written.
  void close();

 private:
  void check(const char* what);
  std::filesystem::path path_;
  std::ofstream out_;
};

/// Writes a whole trajectory (replacing the file).
void writeTrajectory(const std::filesystem::path& path, const std::vector<StampedPose>& poses);

}  // namespace dynanav
