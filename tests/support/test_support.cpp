#include "support/test_support.hpp"

#include "core/error.hpp"

#include <gtest/gtest.h>

#include <sys/wait.h>
#include <array>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <nlohmann/json.hpp>
#include <sstream>

namespace fs = std::filesystem;

namespace dynanav::test {

fs::path sharedDir() {
  if (const char* env = std::getenv("DYNANAV_SHARED"); env && fs::is_directory(env)) return env;
  const fs::path dir = DYNANAV_SHARED_DIR;
  return fs::is_directory(dir) ? fs::canonical(dir) : fs::path{};
}

fs::path sharedSequence(const std::string& name) {
  const fs::path shared = sharedDir();
  if (shared.empty()) return {};
  const fs::path seq = shared / "data" / name;
  return fs::is_directory(seq) ? seq : fs::path{};
}

fs::path sharedModels() {
  if (const char* env = std::getenv("DYNANAV_MODELS"); env && fs::is_directory(env)) return env;
  const fs::path shared = sharedDir();
  if (shared.empty() || !fs::is_directory(shared / "models")) return {};
  return shared / "models";
}

fs::path scratchDir(const std::string& tag) {
  const auto* info = ::testing::UnitTest::GetInstance()->current_test_info();
  std::string name = tag;
  if (info) name += std::string("_") + info->test_suite_name() + "_" + info->name();
  for (char& c : name)
    if (!std::isalnum(static_cast<unsigned char>(c)) && c != '_') c = '_';
  const fs::path dir = fs::temp_directory_path() / ("dynanav_test_" + name);
  fs::remove_all(dir);
  fs::create_directories(dir);
  return dir;
}

int runCli(const std::string& args, std::string* output) {
  const std::string cmd = std::string("\"") + DYNANAV_CLI + "\" " + args + " 2>&1";
  FILE* pipe = popen(cmd.c_str(), "r");
  if (!pipe) return -1;
  std::array<char, 4096> buffer{};
  std::string text;
  while (fgets(buffer.data(), int(buffer.size()), pipe)) text += buffer.data();
  const int status = pclose(pipe);
  if (output) *output = text;
  return WIFEXITED(status) ? WEXITSTATUS(status) : -1;
}

double ateRmse(const fs::path& gt, const fs::path& est) {
  std::string out;
  const int code = runCli("eval --gt " + gt.string() + " --est " + est.string() + " --json", &out);
  EXPECT_EQ(code, 0) << out;
  const auto begin = out.find('{');
  if (code != 0 || begin == std::string::npos) return 1e9;
  return nlohmann::json::parse(out.substr(begin))["ate_m"]["rmse"].get<double>();
}

std::string errorOf(const std::function<void()>& f) {
  try {
    f();
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}

std::string readFile(const fs::path& path) {
  std::ifstream in(path, std::ios::binary);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

}  // namespace dynanav::test
