// The vocabulary loader against damaged files: random byte changes and truncations, with and
// without a recomputed checksum (so the structural checks behind the checksum are exercised too).
// Every outcome must be a loaded vocabulary or an InputError naming the file, never a crash.
#include <gtest/gtest.h>

#include <cstring>
#include <fstream>
#include <random>

#include "core/error.hpp"
#include "slam/orb_extractor.hpp"
#include "slam/vocabulary/vocabulary.hpp"
#include "support/test_support.hpp"
#include "test_orb_images.hpp"

namespace dynanav {
namespace {

uint64_t fnv1a(const std::string& bytes, size_t n) {
  uint64_t h = 0xCBF29CE484222325ull;
  for (size_t i = 0; i < n; ++i) h = (h ^ static_cast<unsigned char>(bytes[i])) * 0x100000001B3ull;
  return h;
}

TEST(VocabularyFileFuzz, DamagedFilesNeverCrashTheLoader) {
  OrbExtractor extractor{OrbConfig{}};
  std::vector<cv::KeyPoint> kps;
  std::vector<cv::Mat> descriptors(3);
  for (int i = 0; i < 3; ++i) extractor.extract(test::texturedImage(320, 240, 70 + i), kps, descriptors[i]);
  VocabularyTrainOptions options;
  options.levels = 2;
  options.branching = 6;
  const auto dir = test::scratchDir("vocabulary_fuzz");
  const std::string good = (dir / "good.dnvoc").string();
  Vocabulary::train(descriptors, options).save(good);
  const std::string original = test::readFile(good);
  ASSERT_GT(original.size(), 100u);

  std::mt19937_64 rng(2024);
  const std::string bad = (dir / "bad.dnvoc").string();
  int rejected = 0, must_reject = 0;
  for (int trial = 0; trial < 400; ++trial) {
    std::string bytes = original;
    const int kind = trial % 4;
    if (kind == 3) {
      bytes.resize(rng() % bytes.size());
    } else {
      for (int k = 0; k < 1 + static_cast<int>(rng() % 4); ++k) {
        // Mostly the header and node area, where structure lives.
        const size_t at = kind == 0 ? rng() % std::min<size_t>(64, bytes.size()) : rng() % bytes.size();
        bytes[at] = static_cast<char>(rng());
      }
    }
    if (kind != 2 && bytes.size() >= 8) {  // re-seal: the structural checks must catch it
      const uint64_t h = fnv1a(bytes, bytes.size() - 8);
      std::memcpy(bytes.data() + bytes.size() - 8, &h, 8);
    }
    // Without a fresh checksum, any change (and any truncation) must be caught.
    const bool unsealed_change = (kind == 2 || kind == 3) && bytes != original;
    must_reject += unsealed_change;
    std::ofstream(bad, std::ios::binary | std::ios::trunc).write(bytes.data(), static_cast<std::streamsize>(bytes.size()));
    try {
      const Vocabulary v = Vocabulary::load(bad);
      // Accepted: then it must be usable.
      BowVector bow;
      FeatureVector fv;
      v.transform(descriptors[0], bow, &fv, 1);
      EXPECT_FALSE(unsealed_change) << "trial " << trial << " accepted a changed file";
    } catch (const InputError& e) {
      ++rejected;
      ASSERT_NE(std::string(e.what()).find(bad), std::string::npos) << e.what();
    }
  }
  EXPECT_GE(rejected, must_reject);
  EXPECT_GT(must_reject, 190);
}

}  // namespace
}  // namespace dynanav
