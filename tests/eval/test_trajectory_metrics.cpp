// Known-answer tests of the TUM-convention ATE / RPE.
#include <gtest/gtest.h>

#include "core/error.hpp"
#include "eval/trajectory_metrics.hpp"

using namespace dynanav;

namespace {

/// A smooth synthetic ground truth at 100 Hz.
std::vector<StampedPose> groundTruth(int n, double t0 = 1000.0) {
  std::vector<StampedPose> gt;
  for (int i = 0; i < n; ++i) {
    const double s = i * 0.01;
    const Vec3 t(std::sin(s), 0.3 * std::cos(2 * s), 0.5 * s);
    const Quat q(Eigen::AngleAxisd(0.4 * std::sin(s), Vec3(0.2, 1.0, 0.1).normalized()));
    gt.push_back({t0 + s, makeSE3(q, t)});
  }
  return gt;
}

SE3 someRigid() {
  return makeSE3(Quat(Eigen::AngleAxisd(1.1, Vec3(1, -2, 0.5).normalized())), Vec3(3, -1, 2));
}

}  // namespace

TEST(Ate, RigidTransformGivesZero) {
  const auto gt = groundTruth(300);
  auto est = gt;
  for (auto& p : est) p.T_world_camera = someRigid() * p.T_world_camera;
  const AteResult r = computeAte(gt, est);
  EXPECT_EQ(r.matched, 300u);
  EXPECT_LT(r.translation_m.rmse, 1e-9);
  EXPECT_LT((r.T_gt_est * someRigid()).matrix().isIdentity(1e-9) ? 0.0 : 1.0, 0.5);
}

TEST(Ate, BalancedOffsetGivesExactlyTheOffset) {
  // Each ground-truth position appears twice; the estimate puts it 0.01 m above and below. The
  // perturbations cancel in every sum the alignment uses, so the best alignment is the rigid
  // transform itself and every residual is exactly 0.01 m.
  const auto base = groundTruth(200);
  std::vector<StampedPose> gt, est;
  for (size_t i = 0; i < base.size(); ++i) {
    for (int k = 0; k < 2; ++k) {
      StampedPose p = base[i];
      p.stamp_s = 2000.0 + double(2 * i + k) * 0.05;
      gt.push_back(p);
      SE3 moved = p.T_world_camera;
      moved.translation() += Vec3(0, 0, k == 0 ? 0.01 : -0.01);
      est.push_back({p.stamp_s, someRigid() * moved});
    }
  }
  const AteResult r = computeAte(gt, est);
  EXPECT_NEAR(r.translation_m.rmse, 0.01, 1e-9);
  EXPECT_NEAR(r.translation_m.max, 0.01, 1e-9);
  EXPECT_NEAR(r.translation_m.min, 0.01, 1e-9);
  // Each matched pose's error, in time order, with the estimate's stamp.
  ASSERT_EQ(r.error_by_stamp_m.size(), est.size());
  for (size_t i = 0; i < est.size(); ++i) {
    EXPECT_EQ(r.error_by_stamp_m[i].first, est[i].stamp_s);
    EXPECT_NEAR(r.error_by_stamp_m[i].second, 0.01, 1e-9);
  }
}

TEST(Rpe, OneDegreePerFrameRotationError) {
  // Ground truth moves along z and turns about z; the estimate adds 1 degree about z per frame.
  // Rotations about z commute with this motion, so every relative error is exactly 1 degree.
  std::vector<StampedPose> gt, est;
  for (int i = 0; i < 100; ++i) {
    const SE3 g = makeSE3(Quat(Eigen::AngleAxisd(0.02 * i, Vec3::UnitZ())), Vec3(0, 0, 0.01 * i));
    gt.push_back({10.0 + i / 30.0, g});
    est.push_back({10.0 + i / 30.0, g * SE3(Eigen::AngleAxisd(i * M_PI / 180.0, Vec3::UnitZ()))});
  }
  const RpeResult r = computeRpe(gt, est);
  EXPECT_EQ(r.pairs, 98u);  // 99 consecutive pairs, the one ending at the last pose dropped
  EXPECT_NEAR(r.rotation_deg.rmse, 1.0, 1e-9);
  EXPECT_NEAR(r.rotation_deg.min, 1.0, 1e-9);
  EXPECT_LT(r.translation_m.max, 1e-12);
}

TEST(Rpe, PairsSpanDroppedFramesAndSkipFarGroundTruth) {
  const auto gt = groundTruth(300);
  std::vector<StampedPose> est;
  for (size_t i = 0; i < gt.size(); ++i)
    if (i % 10 != 3) est.push_back(gt[i]);  // lost frames are simply absent
  const RpeResult r = computeRpe(gt, est);
  EXPECT_EQ(r.pairs, est.size() - 2);
  EXPECT_LT(r.translation_m.max, 1e-12);

  // Poses 1 s and 2 s past the end of the ground truth have no GT within 2x its interval: the
  // pair reaching the first of them is skipped, the pair ending at the last pose is dropped, and
  // the pair ending at the old last pose now counts (gt.size() - 1 pairs in all).
  auto est2 = gt;
  est2.push_back({gt.back().stamp_s + 1.0, gt.back().T_world_camera});
  est2.push_back({gt.back().stamp_s + 2.0, gt.back().T_world_camera});
  EXPECT_EQ(computeRpe(gt, est2).pairs, gt.size() - 1);
}

TEST(Ate, DroppedFramesAndTimeOffsets) {
  const auto gt = groundTruth(300);
  std::vector<StampedPose> est;
  for (size_t i = 0; i < gt.size(); i += 3)
    est.push_back({gt[i].stamp_s + 0.004, gt[i].T_world_camera});
  const AteResult r = computeAte(gt, est);
  EXPECT_EQ(r.matched, est.size());
  EXPECT_LT(r.translation_m.rmse, 1e-9);

  // Beyond the association window nothing matches: a clear error, not a number.
  for (auto& p : est) p.stamp_s += 50.0;
  EXPECT_THROW(computeAte(gt, est), InputError);
}

TEST(Eval, FindClosestIndexAndAssociation) {
  const std::vector<double> v = {1.0, 2.0, 3.0, 4.0};
  EXPECT_EQ(findClosestIndex(v, 2.4), 1u);
  EXPECT_EQ(findClosestIndex(v, 2.6), 2u);
  EXPECT_EQ(findClosestIndex(v, -5), 0u);
  EXPECT_EQ(findClosestIndex(v, 50), 3u);
  const auto m = associateStamps({1.0, 1.03}, {1.012, 1.025}, 0.02);
  ASSERT_EQ(m.size(), 2u);
  EXPECT_EQ(m[0], std::make_pair(size_t(0), size_t(0)));
  EXPECT_EQ(m[1], std::make_pair(size_t(1), size_t(1)));
}

TEST(Eval, CoverageCountsGaps) {
  const auto gt = groundTruth(301);  // 3 s
  std::vector<StampedPose> est;
  for (size_t i = 0; i < gt.size(); ++i)
    if (i < 100 || i >= 200) est.push_back(gt[i]);  // one second lost
  const Coverage c = computeCoverage(gt, est, 301, 0.05);
  EXPECT_NEAR(c.gt_span_s, 3.0, 1e-9);
  EXPECT_NEAR(c.covered_span_s, 1.99, 1e-6);
  EXPECT_EQ(c.tracked_frames, 201u);
}
