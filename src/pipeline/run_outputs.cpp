#include "pipeline/run_outputs.hpp"

#include "core/error.hpp"

namespace dynanav {

const std::vector<std::string>& runOutputNames() {
  static const std::vector<std::string> names = {
      "config_used.yaml", "trajectory.txt", "trajectory_online.txt", "keyframes.txt", "stats.json",
      "stats.json.tmp",   "objects.jsonl",  "events.jsonl",          "feedback.wav",
  };
  return names;
}

int removeEarlierRunOutputs(const std::filesystem::path& out_dir) {
  int removed = 0;
  for (const std::string& name : runOutputNames()) {
    const std::filesystem::path file = out_dir / name;
    std::error_code ec;
    const auto status = std::filesystem::symlink_status(file, ec);
    if (ec || !std::filesystem::exists(status)) continue;
    if (std::filesystem::is_directory(status))
      throw InputError(file.string(), "is a folder where the run writes a file");
    if (!std::filesystem::remove(file, ec) || ec)
      throw InputError(file.string(), "cannot remove the earlier run's file: " + ec.message());
    ++removed;
  }
  return removed;
}

}  // namespace dynanav
