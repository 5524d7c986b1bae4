// Assistive feedback end to end: simulate -> run (--segmenter masks) -> eval-events. An
// approaching walker gets an urgent warning at least 2 s before the ground-truth closest
// approach (seed 1, in German); a room with nobody in it gives an empty events.jsonl; bad
// options and files exit 2 naming them.
#include <gtest/gtest.h>

#include <fstream>
#include <nlohmann/json.hpp>

#include "support/test_support.hpp"

namespace dynanav {
namespace {

namespace fs = std::filesystem;

void simulateAndRun(const std::string& scenario, int frames, const fs::path& seq,
                    const fs::path& out, const std::string& flags = "") {
  std::string log;
  ASSERT_EQ(test::runCli("simulate --scenario " + scenario + " --frames " + std::to_string(frames) +
                             " --seed 1 --out " + seq.string(),
                         &log),
            0)
      << log;
  ASSERT_EQ(test::runCli("run " + seq.string() + " --out " + out.string() +
                             " --segmenter masks --deterministic --quiet " + flags,
                         &log),
            0)
      << log;
}

TEST(FeedbackE2e, ApproachingWalkerIsWarnedTwoSecondsAhead) {
  const fs::path seq = test::scratchDir("feedback_approach_seq");
  const fs::path out = test::scratchDir("feedback_approach_out");
  // Seed 1's closest approach comes at 7.3 s: 230 frames cover it.
  simulateAndRun("approach", 230, seq, out, "--language de");
  std::string log;
  ASSERT_EQ(test::runCli("eval-events --gt " + (seq / "objects_gt.jsonl").string() + " --events " +
                             (out / "events.jsonl").string() + " --json",
                         &log),
            0)
      << log;
  const auto json = nlohmann::json::parse(log.substr(log.find('{')));
  ASSERT_EQ(json["people"].size(), 1u);
  const auto& walker = json["people"][0];
  EXPECT_TRUE(walker["in_corridor"].get<bool>());
  ASSERT_FALSE(walker["lead_s"].is_null()) << log;
  EXPECT_GE(walker["lead_s"].get<double>(), 2.0);
  EXPECT_EQ(json["unchanged_repeats"].get<int>(), 0);
  EXPECT_LE(json["max_non_urgent_in_window"].get<int>(), 1);
  // German messages; the feedback stage is timed in stats.json.
  EXPECT_NE(test::readFile(out / "events.jsonl").find(" Uhr, "), std::string::npos);
  const auto stats = nlohmann::json::parse(test::readFile(out / "stats.json"));
  EXPECT_TRUE(stats["stage_ms"].contains("feedback")) << stats["stage_ms"].dump();
}

TEST(FeedbackE2e, EmptyRoomSaysNothing) {
  const fs::path seq = test::scratchDir("feedback_static_seq");
  const fs::path out = test::scratchDir("feedback_static_out");
  simulateAndRun("static-room", 60, seq, out);
  ASSERT_TRUE(fs::exists(out / "events.jsonl"));
  EXPECT_EQ(fs::file_size(out / "events.jsonl"), 0u);
}

TEST(FeedbackE2e, BadInputExitsTwo) {
  const fs::path dir = test::scratchDir("feedback_bad");
  std::string log;
  EXPECT_EQ(test::runCli("run " + dir.string() + " --out " + dir.string() + " --language fr", &log),
            2);
  EXPECT_NE(log.find("--language"), std::string::npos) << log;
  std::ofstream(dir / "c.yaml") << "assist:\n  corridor_m: -1\n";
  EXPECT_EQ(test::runCli("run " + dir.string() + " --out " + (dir / "o").string() + " --config " +
                             (dir / "c.yaml").string(),
                         &log),
            2);
  EXPECT_NE(log.find("corridor_m"), std::string::npos) << log;
  // eval-events: objects_gt.jsonl without groundtruth.txt beside it.
  std::ofstream(dir / "objects_gt.jsonl") << R"({"t":0,"objects":[]})"
                                          << "\n";
  std::ofstream(dir / "events.jsonl") << "";
  EXPECT_EQ(test::runCli("eval-events --gt " + (dir / "objects_gt.jsonl").string() + " --events " +
                             (dir / "events.jsonl").string(),
                         &log),
            2);
  EXPECT_NE(log.find("groundtruth.txt"), std::string::npos) << log;
}

}  // namespace
}  // namespace dynanav
