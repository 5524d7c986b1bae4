// dynanav eval on the real ground-truth files in ../shared/data against perturbed copies.
// Reference values were computed from the same perturbed files with the TUM benchmark's
// evaluate_ate.py / evaluate_rpe.py algorithms (numpy, run outside the project; see README).
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include "eval/trajectory_metrics.hpp"
#include "io/trajectory.hpp"
#include "support/test_support.hpp"

using namespace dynanav;
namespace fs = std::filesystem;

namespace {

/// A deterministic perturbation of every 3rd ground-truth pose: a rigid transform of the whole
/// trajectory, a per-pose wobble of a few mm and tenths of a degree, and a 4 ms time offset.
std::vector<StampedPose> perturbed(const std::vector<StampedPose>& gt) {
  const SE3 rigid = makeSE3(Quat(Eigen::AngleAxisd(0.7, Vec3(0.3, -1, 0.2).normalized())), Vec3(1, 2, -0.5));
  std::vector<StampedPose> est;
  for (size_t i = 0; i < gt.size(); i += 3) {
    const double k = double(i);
    SE3 wobble = SE3::Identity();
    wobble.translation() = Vec3(0.01 * std::sin(k), 0.005 * std::cos(2 * k), 0.002 * double(i % 7) - 0.006);
    wobble.linear() = expSO3(Vec3(std::sin(k), std::cos(k), 1.0).normalized() *
                             (0.5 * M_PI / 180.0) * std::sin(0.3 * k));
    est.push_back({gt[i].stamp_s + 0.004, rigid * gt[i].T_world_camera * wobble});
  }
  return est;
}

struct Reference {
  const char* sequence;
  double ate_rmse, ate_max, rpe_trans_rmse, rpe_rot_rmse;
  size_t matched, pairs;
};

// Printed by the numpy port of evaluate_ate.py / evaluate_rpe.py on the files this test writes.
const Reference kReferenceFr1{"rgbd_dataset_freiburg1_xyz", 0.008830770, 0.012786955, 0.015682221,
                              0.499014054, 341, 339};
const Reference kReferenceBonn{"rgbd_bonn_crowd", 0.008821013, 0.012653816, 0.015645249,
                               0.499041926, 187, 185};

void checkAgainstReference(const Reference& ref) {
  DYNANAV_REQUIRE_SEQUENCE(dir, ref.sequence);
  const auto gt = readTrajectory(dir / "groundtruth.txt");
  const fs::path out = test::scratchDir(ref.sequence);
  writeTrajectory(out / "est.txt", perturbed(gt));
  const auto est = readTrajectory(out / "est.txt");  // as written: 6-decimal stamps, 9-digit poses
  const AteResult ate = computeAte(gt, est);
  const RpeResult rpe = computeRpe(gt, est);
  EXPECT_EQ(ate.matched, ref.matched);
  EXPECT_EQ(rpe.pairs, ref.pairs);
  EXPECT_NEAR(ate.translation_m.rmse, ref.ate_rmse, 1e-6);
  EXPECT_NEAR(ate.translation_m.max, ref.ate_max, 1e-6);
  EXPECT_NEAR(rpe.translation_m.rmse, ref.rpe_trans_rmse, 1e-6);
  EXPECT_NEAR(rpe.rotation_deg.rmse, ref.rpe_rot_rmse, 1e-6);

  // The CLI prints the same figures.
  std::string text;
  ASSERT_EQ(test::runCli("eval --json --gt " + (dir / "groundtruth.txt").string() + " --est " +
                             (out / "est.txt").string(), &text), 0) << text;
  const auto json = nlohmann::json::parse(text);
  EXPECT_NEAR(json["ate_m"]["rmse"].get<double>(), ref.ate_rmse, 1e-6);
  EXPECT_NEAR(json["rpe_rotation_deg"]["rmse"].get<double>(), ref.rpe_rot_rmse, 1e-6);
}

}  // namespace

TEST(EvalSharedGt, RigidCopyOfRealGroundTruthGivesZero) {
  for (const char* name : {"rgbd_dataset_freiburg1_xyz", "rgbd_bonn_crowd"}) {
    const auto dir = test::sharedSequence(name);
    if (dir.empty()) GTEST_SKIP() << "../shared/data/" << name << " not found: skipped";
    const auto gt = readTrajectory(dir / "groundtruth.txt");
    auto est = gt;
    const SE3 rigid = makeSE3(Quat(Eigen::AngleAxisd(2.0, Vec3(1, 1, 0).normalized())), Vec3(-3, 0, 1));
    for (auto& p : est) p.T_world_camera = rigid * p.T_world_camera;
    EXPECT_LT(computeAte(gt, est).translation_m.rmse, 1e-9) << name;
    // arccos near 1 limits the resolution of a zero angle to ~1e-6 deg (as in the TUM script).
    EXPECT_LT(computeRpe(gt, est).rotation_deg.rmse, 1e-5) << name;
  }
}

TEST(EvalSharedGt, Freiburg1MatchesTumScripts) {
  checkAgainstReference(kReferenceFr1);
}

TEST(EvalSharedGt, BonnMatchesTumScripts) {
  checkAgainstReference(kReferenceBonn);
}
