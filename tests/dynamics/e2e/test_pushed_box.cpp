// The dynamics stage end to end on a short simulated scene: a person pushes a box 1 m (a
// non-prior mover) while the wearer walks. With ground-truth masks the box must be flagged
// moving while it moves and static before and after, and the trajectory must stay accurate.
#include <gtest/gtest.h>

#include <fstream>
#include <nlohmann/json.hpp>

#include "io/json_io.hpp"
#include "support/test_support.hpp"

namespace dynanav {
namespace {

namespace fs = std::filesystem;

using test::ateRmse;  // ATE RMSE as `dynanav eval --json` prints it

/// Per frame: is object `id` moving in the simulator's ground truth?
std::vector<bool> groundTruthMoving(const fs::path& objects_gt, int id) {
  std::vector<bool> moving;
  std::ifstream in(objects_gt);
  for (std::string line; std::getline(in, line);) {
    bool m = false;
    const auto frame = nlohmann::json::parse(line);  // named: a temporary would die before the loop
    for (const auto& o : frame["objects"])
      if (o["id"] == id) m = o["dynamic"].get<bool>();
    moving.push_back(m);
  }
  return moving;
}

TEST(DynamicsE2E, PushedBoxIsFlaggedWhileItMovesAndTrackingStaysAccurate) {
  const fs::path seq = test::scratchDir("dyn_pushed_box_seq");
  const fs::path out = test::scratchDir("dyn_pushed_box_out");
  std::string log;
  // 10 s at 15 frames/s: the whole push in 150 frames.
  ASSERT_EQ(test::runCli("simulate --scenario pushed-box --frames 150 --fps 15 --out " + seq.string(), &log), 0) << log;
  ASSERT_EQ(test::runCli("run " + seq.string() + " --out " + out.string() + " --segmenter masks --quiet", &log), 0)
      << log;
  const auto stats = readJsonFile(out / "stats.json");
  EXPECT_EQ(stats["tracked"], 150);
  ASSERT_TRUE(stats.contains("dynamics"));
  EXPECT_EQ(stats["dynamics"]["segmenter"], "masks");
  // 0.008 m on the full 30 Hz scene (docs/dynamics.md); 15 Hz doubles the motion per frame.
  EXPECT_LT(ateRmse(seq / "groundtruth.txt", out / "trajectory.txt"), 0.02);

  const auto gt = groundTruthMoving(seq / "objects_gt.jsonl", 2);  // the box
  const auto& flagged = stats["dynamics"]["per_frame"]["moving_ids"];
  ASSERT_EQ(flagged.size(), gt.size());
  int tp = 0, fp = 0, fn = 0;
  for (size_t i = 0; i < gt.size(); ++i) {
    bool f = false;
    for (const auto& id : flagged[i]) f = f || id == 2;
    tp += gt[i] && f;
    fp += !gt[i] && f;
    fn += gt[i] && !f;
  }
  ASSERT_GT(tp + fn, 10) << "the box never moved in ground truth?";
  const double precision = double(tp) / std::max(1, tp + fp), recall = double(tp) / (tp + fn);
  EXPECT_GE(precision, 0.8) << tp << " tp, " << fp << " fp";
  EXPECT_GE(recall, 0.8) << tp << " tp, " << fn << " fn";
}

TEST(DynamicsE2E, DynamicOffIsThePlainBaseline) {
  const fs::path seq = test::scratchDir("dyn_off_seq");
  const fs::path out = test::scratchDir("dyn_off_out");
  std::string log;
  ASSERT_EQ(test::runCli("simulate --scenario pushed-box --frames 30 --fps 15 --out " + seq.string(), &log), 0) << log;
  ASSERT_EQ(test::runCli("run " + seq.string() + " --out " + out.string() + " --dynamic off --quiet", &log), 0) << log;
  const auto stats = readJsonFile(out / "stats.json");
  EXPECT_FALSE(stats["dynamics"]["enabled"].get<bool>());
  EXPECT_FALSE(stats["stage_ms"].contains("segmentation"));
}

TEST(DynamicsE2E, MissingModelsGiveAClearError) {
  const fs::path seq = test::scratchDir("dyn_models_seq");
  std::string log;
  ASSERT_EQ(test::runCli("simulate --scenario pushed-box --frames 3 --out " + seq.string(), &log), 0) << log;
  const fs::path empty = test::scratchDir("dyn_no_models");
  const int code = test::runCli("run " + seq.string() + " --out " + (empty / "out").string() +
                                    " --segmenter dnn --models " + empty.string() + " --quiet",
                                &log);
  EXPECT_EQ(code, 2) << log;
  EXPECT_NE(log.find(empty.string()), std::string::npos) << log;
}

}  // namespace
}  // namespace dynanav
