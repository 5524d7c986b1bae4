#include "support/test_support.hpp"

#include "core/error.hpp"

#include <gtest/gtest.h>

#include <signal.h>
#include <spawn.h>
#include <sys/wait.h>
#include <array>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <nlohmann/json.hpp>
#include <sstream>
#include <thread>

namespace fs = std::filesystem;

extern char** environ;

namespace dynanav::test {

namespace {

pid_t spawnCli(const std::vector<std::string>& args) {
  std::vector<std::string> argv_s = {DYNANAV_CLI};
  argv_s.insert(argv_s.end(), args.begin(), args.end());
  std::vector<char*> argv;
  for (auto& a : argv_s) argv.push_back(a.data());
  argv.push_back(nullptr);
  pid_t pid = 0;
  if (posix_spawn(&pid, DYNANAV_CLI, nullptr, nullptr, argv.data(), environ) != 0) return -1;
  return pid;
}

int exitCode(int status) {
  return WIFEXITED(status) ? WEXITSTATUS(status)
                           : -1000 - (WIFSIGNALED(status) ? WTERMSIG(status) : 0);
}

}  // namespace

int runAndSignal(const std::vector<std::string>& args, int signal_number,
                 std::chrono::milliseconds delay) {
  return runAndSignalWhen(
      args, signal_number, [] { return false; }, delay);
}

int runAndSignalWhen(const std::vector<std::string>& args, int signal_number,
                     const std::function<bool()>& ready, std::chrono::milliseconds timeout) {
  const pid_t pid = spawnCli(args);
  if (pid < 0) return -1;
  const auto deadline = std::chrono::steady_clock::now() + timeout;
  int status = 0;
  while (!ready() && std::chrono::steady_clock::now() < deadline) {
    if (waitpid(pid, &status, WNOHANG) == pid) return exitCode(status);
    std::this_thread::sleep_for(std::chrono::milliseconds(50));
  }
  kill(pid, signal_number);
  waitpid(pid, &status, 0);
  return exitCode(status);
}

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

void removeScratchDir(const fs::path& dir) {
  if (dir.empty() || std::getenv("DYNANAV_KEEP_TEST_OUTPUT")) return;
  std::error_code ignored;  // a folder already gone is fine
  fs::remove_all(dir, ignored);
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
