#include "perception/model_files.hpp"

#include <cstdlib>

#include "core/error.hpp"

namespace fs = std::filesystem;

namespace dynanav {

std::vector<fs::path> modelSearchPath(const std::string& explicit_dir) {
  if (!explicit_dir.empty()) return {fs::path(explicit_dir)};
  std::vector<fs::path> dirs;
  if (const char* env = std::getenv("DYNANAV_MODELS"); env && *env) dirs.emplace_back(env);
  dirs.emplace_back(fs::current_path() / "models");
  dirs.emplace_back(fs::current_path() / ".." / "shared" / "models");
  // Next to an installed or copied binary: <bin>/models and <prefix>/share/dynanav/models.
  std::error_code ec;
  if (const fs::path exe = fs::read_symlink("/proc/self/exe", ec); !ec && !exe.empty()) {
    dirs.emplace_back(exe.parent_path() / "models");
    dirs.emplace_back(exe.parent_path() / ".." / "share" / "dynanav" / "models");
  }
#ifdef DYNANAV_PERCEPTION_SOURCE_DIR
  // A developer running <repo>/build/x/bin/dynanav from anywhere still finds the shared models.
  dirs.emplace_back(fs::path(DYNANAV_PERCEPTION_SOURCE_DIR) / ".." / "shared" / "models");
#endif
  return dirs;
}

fs::path findModelsDir(const std::string& explicit_dir, const std::vector<std::string>& required) {
  for (const fs::path& dir : modelSearchPath(explicit_dir)) {
    std::error_code ec;
    bool all = fs::is_directory(dir, ec);
    for (const auto& file : required) all = all && fs::is_regular_file(dir / file, ec);
    if (all) return fs::weakly_canonical(dir, ec);
  }
  return {};
}

fs::path requireModelFile(const fs::path& dir, const std::string& relative) {
  const fs::path file = dir / relative;
  std::error_code ec;
  if (!fs::is_regular_file(file, ec))
    throw InputError(file.string(),
                     "model file not found (get the models with scripts/fetch_models.sh DIR and "
                     "pass --models DIR or set DYNANAV_MODELS)");
  return file;
}

std::vector<std::string> dnnModelFiles(bool with_keypoints) {
  std::vector<std::string> files{model_files::kDetectorCfg, model_files::kDetectorWeights,
                                 model_files::kCocoNames, model_files::kSelfie};
  if (with_keypoints) files.emplace_back(model_files::kMoveNet);
  return files;
}

std::vector<std::string> dnnNpmModelFiles(bool with_keypoints) {
  std::vector<std::string> files{model_files::kMultiPose, model_files::kSelfie};
  if (with_keypoints) files.emplace_back(model_files::kMoveNet);
  return files;
}

fs::path findDnnModelsDir(const std::string& explicit_dir, bool with_keypoints) {
  for (const fs::path& dir : modelSearchPath(explicit_dir)) {
    for (const auto& files : {dnnModelFiles(with_keypoints), dnnNpmModelFiles(with_keypoints)}) {
      if (fs::path found = findModelsDir(dir.string(), files); !found.empty()) return found;
    }
  }
  return {};
}

}  // namespace dynanav
