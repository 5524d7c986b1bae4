// Randomised inputs for every text parser: they must either parse or throw InputError (which the
// CLI turns into exit code 2) — never crash, hang or throw anything else. Seeded: reproducible.
#include <gtest/gtest.h>

#include <fstream>
#include <random>

#include "core/config.hpp"
#include "core/error.hpp"
#include "io/camera_yaml.hpp"
#include "io/json_io.hpp"
#include "io/sequence.hpp"
#include "io/trajectory.hpp"
#include "support/test_support.hpp"

using namespace dynanav;
namespace fs = std::filesystem;

namespace {

/// Mutates a valid text: random byte flips, insertions of separators/garbage, truncation.
std::string mutate(const std::string& valid, std::mt19937& rng) {
  static const std::string alphabet = "0123456789.-+e nanif#,:\t\r\n[]{}\"'abc\x01\xff";
  std::string s = valid;
  std::uniform_int_distribution<int> ops(1, 8);
  const int n = ops(rng);
  for (int k = 0; k < n && !s.empty(); ++k) {
    std::uniform_int_distribution<size_t> pos(0, s.size() - 1);
    std::uniform_int_distribution<size_t> ch(0, alphabet.size() - 1);
    switch (rng() % 4) {
      case 0: s[pos(rng)] = alphabet[ch(rng)]; break;
      case 1: s.insert(pos(rng), 1, alphabet[ch(rng)]); break;
      case 2: s.erase(pos(rng), 1 + rng() % 5); break;
      default: s.resize(pos(rng)); break;
    }
  }
  return s;
}

template <class Parse>
void fuzz(const std::string& valid, const fs::path& file, Parse parse, int rounds = 400) {
  std::mt19937 rng(1234);
  for (int round = 0; round < rounds; ++round) {
    const std::string text = mutate(valid, rng);
    std::ofstream(file, std::ios::binary) << text;
    try {
      parse(file, text);
    } catch (const InputError&) {
      // expected for broken input
    } catch (const std::exception& e) {
      FAIL() << "round " << round << ": unexpected " << typeid(e).name() << " " << e.what()
             << " for input:\n" << text;
    }
  }
}

}  // namespace

TEST(ParserFuzz, StampedFileList) {
  const fs::path dir = test::scratchDir("fuzzlist");
  fuzz("# rgb\n1305031102.175304 rgb/1305031102.175304.png\n1305031102.211214 rgb/b.png\n",
       dir / "rgb.txt", [](const fs::path& f, const std::string&) { readStampedFileList(f); });
}

TEST(ParserFuzz, Trajectory) {
  const fs::path dir = test::scratchDir("fuzztraj");
  fuzz("# t tx ty tz qx qy qz qw\n1.0 0.1 0.2 0.3 0 0 0 1\n2.0 0.2 0.2 0.3 0.1 0 0 0.99\n",
       dir / "t.txt", [](const fs::path& f, const std::string&) { readTrajectory(f); });
}

TEST(ParserFuzz, ConfigYaml) {
  const fs::path dir = test::scratchDir("fuzzcfg");
  fuzz("orb:\n  n_features: 1200\n  scale_factor: 1.2\nrun:\n  dynamic: false\n  segmenter: hog\n",
       dir / "c.yaml", [](const fs::path&, const std::string& text) { Config::parse(text); });
}

TEST(ParserFuzz, CameraYaml) {
  const fs::path dir = test::scratchDir("fuzzcam");
  fuzz("width: 640\nheight: 480\nfx: 525\nfy: 525\ncx: 319.5\ncy: 239.5\ndistortion: [0.1, 0, 0, 0, 0]\n",
       dir / "camera.yaml", [](const fs::path& f, const std::string&) { loadCameraYaml(f); });
}

TEST(ParserFuzz, JsonLines) {
  const fs::path dir = test::scratchDir("fuzzjson");
  fuzz("{\"t\": 1.5, \"objects\": [{\"id\": 1, \"class\": \"person\"}]}\n{\"t\": 2}\n",
       dir / "x.jsonl", [](const fs::path& f, const std::string&) { readJsonLines(f); });
}
