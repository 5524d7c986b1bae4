#include "perception/model_files.hpp"

#include <cstdlib>
#include <map>
#include <mutex>
#include <set>

#include "core/error.hpp"
#include "io/file_digest.hpp"

namespace fs = std::filesystem;

namespace dynanav {
namespace {

/// The SHA-256 of each model file we know (scripts/fetch_models.sh pins the same values;
/// ../shared/models/SHA256SUMS lists the shared copies). The selfie and MoveNet graphs exist in
/// two byte-different but equivalent conversions: the shared copies and fetch_models.sh's.
const std::map<std::string, std::vector<std::string>>& knownModelDigests() {
  static const std::map<std::string, std::vector<std::string>> digests = {
      {model_files::kDetectorCfg,
       {"c458427acc4fbeabceff4528ef7b65b066c0308ce599460f8ba299eba63abad3"}},
      {model_files::kDetectorWeights,
       {"fac5fb41786c1f38f04972a658443b189f48720d7d117f9a044100e98a35b0c5"}},
      {model_files::kCocoNames,
       {"634a1132eb33f8091d60f2c346ababe8b905ae08387037aed883953b7329af84"}},
      {model_files::kSelfie,
       {"7e37b5275bdbf79737769e4aa4a0c7108cba12f3f22a5fed10a766c8f6ad8bb3",
        "cee7db25d8e810d6f20ad56746901da0da4f4c356564d7c16efa3fb4590412ca"}},
      {model_files::kMoveNet,
       {"4f1da046965910e3197db40ab32edb6b008a44e717dd7273aae769545af4e3e9",
        "694bec6ade4d529cc181bbf442009ba171b92ecf85a07217609cdcfb7514e5f1"}},
      {model_files::kMultiPose,
       {"3e2fa4340ee562150a00a296e2c1bffd6e0dc281c141aede51926a4cf073a08b"}},
  };
  return digests;
}

}  // namespace

void verifyModelFile(const fs::path& file, const std::string& relative) {
  // Each file is hashed once per process (the factory and each model ask for it).
  static std::mutex mutex;
  static std::set<std::string> verified;
  const std::lock_guard lock(mutex);
  std::error_code ec;
  const auto size = fs::file_size(file, ec);
  const std::string key = file.string() + "#" + std::to_string(ec ? 0 : size);
  if (verified.count(key)) return;
  if (ec || size == 0) throw InputError(file.string(), "model file is empty or unreadable");
  const auto known = knownModelDigests().find(relative);
  if (known != knownModelDigests().end()) {
    const std::string digest = sha256Hex(file);
    bool match = false;
    for (const std::string& expected : known->second) match = match || digest == expected;
    if (!match)
      throw InputError(file.string(), "model file is damaged or another version (SHA-256 " +
                                          digest + ", expected " + known->second.front() + "; " +
                                          std::to_string(size) +
                                          " bytes): get it again with scripts/fetch_models.sh");
  }
  verified.insert(key);
}

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
  verifyModelFile(file, relative);
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
