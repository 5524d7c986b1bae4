#include "slam/vocabulary/vocabulary_path.hpp"

#include <cstdlib>

#include "core/error.hpp"

namespace dynanav {

std::filesystem::path findVocabulary(const std::string& configured) {
  namespace fs = std::filesystem;
  fs::path path;
  if (!configured.empty()) {
    path = configured;
  } else if (const char* env = std::getenv("DYNANAV_VOCABULARY"); env && *env) {
    path = env;
  } else {
    std::error_code ec;
    const fs::path exe = fs::read_symlink("/proc/self/exe", ec);
    if (!ec) path = exe.parent_path().parent_path() / "share" / "dynanav" / kDefaultVocabularyName;
  }
  if (path.empty() || !fs::is_regular_file(path))
    throw InputError(path.empty() ? std::string(kDefaultVocabularyName) : path.string(),
                     "ORB vocabulary not found: build it with scripts/build_vocabulary.sh (the "
                     "build does this when opencv-doc is installed) or set loop.vocabulary");
  return path;
}

}  // namespace dynanav
