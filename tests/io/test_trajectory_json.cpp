#include <gtest/gtest.h>

#include <fstream>

#include "core/error.hpp"
#include "io/json_io.hpp"
#include "io/trajectory.hpp"
#include "support/test_support.hpp"

using namespace dynanav;
namespace fs = std::filesystem;

TEST(Trajectory, WriteReadRoundTrip) {
  const fs::path dir = test::scratchDir("traj");
  std::vector<StampedPose> poses;
  for (int i = 0; i < 5; ++i) {
    poses.push_back({1305031102.175304 + i * 0.033,
                     makeSE3(Quat(Eigen::AngleAxisd(0.1 * i, Vec3(0, 1, 0))), Vec3(i, -i, 0.5 * i))});
  }
  writeTrajectory(dir / "t.txt", poses);
  const auto back = readTrajectory(dir / "t.txt");
  ASSERT_EQ(back.size(), poses.size());
  for (size_t i = 0; i < poses.size(); ++i) {
    EXPECT_NEAR(back[i].stamp_s, poses[i].stamp_s, 1e-6);
    EXPECT_LT((back[i].T_world_camera.matrix() - poses[i].T_world_camera.matrix()).norm(), 1e-8);
  }
}

TEST(Trajectory, RejectsBadLinesWithLineNumbers) {
  const fs::path dir = test::scratchDir("trajbad");
  std::ofstream(dir / "a.txt") << "# c\n1 0 0 0 0 0 0 1\n2 0 0 nan 0 0 0 1\n";
  try {
    readTrajectory(dir / "a.txt");
    FAIL();
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("a.txt:3"), std::string::npos);
  }
  std::ofstream(dir / "b.txt") << "1 0 0 0 0 0 0 1\n1 0 0 0 0 0 0 1\n";
  EXPECT_THROW(readTrajectory(dir / "b.txt"), InputError);
  std::ofstream(dir / "c.txt") << "1 0 0 0 0 0 0\n";
  EXPECT_THROW(readTrajectory(dir / "c.txt"), InputError);
  std::ofstream(dir / "d.txt") << "1,0,0,0,0,0,0,1\r\n";  // commas and CRLF are fine
  EXPECT_EQ(readTrajectory(dir / "d.txt").size(), 1u);
}

TEST(JsonIo, LinesAndFiles) {
  const fs::path dir = test::scratchDir("json");
  {
    JsonLinesWriter w(dir / "x.jsonl");
    w.write({{"t", 1.5}, {"objects", nlohmann::json::array()}});
    w.write({{"t", 2.5}});
  }
  const auto lines = readJsonLines(dir / "x.jsonl");
  ASSERT_EQ(lines.size(), 2u);
  EXPECT_DOUBLE_EQ(lines[1]["t"].get<double>(), 2.5);
  writeJsonFile(dir / "s.json", {{"frames", 3}});
  EXPECT_EQ(readJsonFile(dir / "s.json")["frames"].get<int>(), 3);
  EXPECT_FALSE(fs::exists(dir / "s.json.tmp"));
  std::ofstream(dir / "bad.jsonl") << "{\"a\":1}\n{oops\n";
  EXPECT_THROW(readJsonLines(dir / "bad.jsonl"), InputError);
}
