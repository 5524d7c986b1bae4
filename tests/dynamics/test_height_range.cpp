// Range of a person beyond the depth sensor's range from the mask's pixel height and a stature
// prior (dynamics/height_range.hpp), and the tracker using it (dynamics/object_tracker.hpp).
#include <gtest/gtest.h>

#include <cmath>

#include "box_instance.hpp"
#include "dynamics/height_range.hpp"
#include "dynamics/object_tracker.hpp"
#include "level_floor.hpp"

using namespace dynanav;

namespace {

constexpr int kW = 640, kH = 480;

PinholeCamera camera() {
  return {};
}  // the default: 640x480, f = 525 px, centred

/// An upright person of `stature_m` whose soles are at p_soles (camera frame, level camera: up
/// is -y): crown and soles projected.
PersonExtent extentOf(const Vec3& p_soles, double stature_m, const PinholeCamera& c) {
  const Vec3 crown = p_soles + Vec3(0.0, -stature_m, 0.0);
  PersonExtent e;
  e.top_px = c.project(crown).y();
  e.bottom_px = c.project(p_soles).y();
  e.column_px = c.project(p_soles).x();
  return e;
}

/// Labels with a person-shaped mask: a `width_px` wide column spanning rows [top, bottom].
Instances personMask(int left, int width_px, int top, int bottom) {
  Instances instances = Instances::none(cv::Size(kW, kH));
  test::addBoxInstance(instances, 1, "person", cv::Rect(left, top, width_px, bottom - top + 1));
  return instances;
}

/// The mask of a body 0.4 m wide standing between `top` and `bottom` (camera frame, level camera:
/// the same x and z), from the row `top` projects to (plus `inset_px`, plus `lost_top_px` rows a
/// segmenter lost) down to the row `bottom` projects to (minus `inset_px`).
Instances bodyMask(const Vec3& top, const Vec3& bottom, const PinholeCamera& c, double inset_px,
                   int lost_top_px = 0) {
  const int top_row = int(std::lround(c.project(top).y() + inset_px)) + lost_top_px;
  const int bottom_row = int(std::lround(c.project(bottom).y() - inset_px));
  const int half_width = int(std::lround(0.2 * c.fx / bottom.z()));
  const int centre = int(std::lround(c.project(bottom).x()));
  return personMask(centre - half_width, 2 * half_width + 1, top_row, bottom_row);
}

/// One frame of a walker whose mask is `instances` (id 1, found moving), its front `z_m - 0.15`
/// m away: depth on the mask when that is nearer than `depth_range_m`, none elsewhere.
std::vector<TrackedObject> stepWalker(ObjectTracker& tracker, int i, const Instances& instances,
                                      double z_m, double depth_range_m, const PinholeCamera& c) {
  cv::Mat depth(kH, kW, CV_32F, cv::Scalar(0.f));
  if (z_m - 0.15 < depth_range_m) depth.setTo(float(z_m - 0.15), instances.labels == 1);
  FrameDynamics dynamics;
  dynamics.moving_ids.push_back(1);
  return tracker.track(
      {i, i / 30.0, instances, dynamics, cv::Mat(), depth, SE3::Identity(), true, c});
}

}  // namespace

TEST(HeightRange, PersonOfThePriorStatureIsPlacedAtItsTorsoCentre) {
  const PinholeCamera c = camera();
  // Soles 1.5 m below a level camera, 8 m ahead, 0.5 m to the right.
  const Vec3 soles(0.5, 1.5, 8.0);
  const auto range = rangeFromHeight(extentOf(soles, 1.70, c), c, Vec3(0.0, -1.0, 0.0));
  ASSERT_TRUE(range);
  const Vec3 torso = soles + Vec3(0.0, -(1.0 - kTorsoCentreBelowTop) * 1.70, 0.0);
  EXPECT_LT((range->p_camera - torso).norm(), 1e-6);
  EXPECT_NEAR(range->range_m, torso.norm(), 1e-6);
  // The stature's spread (0.09 / 1.70) and 1.5 px at each end of a 112 px silhouette: ~0.45 m
  // along the ray; across it a few centimetres.
  EXPECT_NEAR(range->sigma_range_m, 0.45, 0.03);
  const Vec3 n = torso.normalized();
  EXPECT_NEAR(std::sqrt(n.dot(range->covCamera() * n)), range->sigma_range_m, 1e-9);
  const Vec3 across = n.cross(Vec3(0.0, 1.0, 0.0)).normalized();
  EXPECT_LT(std::sqrt(across.dot(range->covCamera() * across)), 0.08);
}

TEST(HeightRange, AStatureOffThePriorMovesTheCentreAlongTheRayWithinItsSigma) {
  const PinholeCamera c = camera();
  const Vec3 soles(-0.8, 1.4, 6.0);
  const Vec3 torso = soles + Vec3(0.0, -(1.0 - kTorsoCentreBelowTop) * 1.85, 0.0);
  // A tall person (1.85 m, 1.7 sigma above the prior's mean) reads nearer by 1.70 / 1.85.
  const auto range = rangeFromHeight(extentOf(soles, 1.85, c), c, Vec3(0.0, -1.0, 0.0));
  ASSERT_TRUE(range);
  EXPECT_NEAR(range->range_m, torso.norm() * 1.70 / 1.85, 1e-6);
  const Vec3 error = range->p_camera - torso;
  const Vec3 n = torso.normalized();
  EXPECT_LT((error - n * n.dot(error)).norm(), 1e-6);  // along the ray only
  const double mahalanobis = std::sqrt(error.dot(range->covCamera().inverse() * error));
  EXPECT_GT(mahalanobis, 1.0);
  EXPECT_LT(mahalanobis, 2.0);
}

TEST(HeightRange, PitchedCameraUsesTheWorldsUp) {
  const PinholeCamera c = camera();
  // Camera pitched 15 degrees down: a world point p_w is p_c = R p_w, with R about x.
  const double a = 15.0 * M_PI / 180.0;
  Mat3 R;
  R << 1, 0, 0, 0, std::cos(a), -std::sin(a), 0, std::sin(a), std::cos(a);
  const Vec3 soles_w(0.0, 1.5, 7.0), crown_w(0.0, 1.5 - 1.70, 7.0);
  PersonExtent e;
  e.top_px = c.project(R * crown_w).y();
  e.bottom_px = c.project(R * soles_w).y();
  e.column_px = c.cx;
  const Vec3 torso_c = R * (crown_w + kTorsoCentreBelowTop * (soles_w - crown_w));
  const auto range = rangeFromHeight(e, c, R * Vec3(0.0, -1.0, 0.0));
  ASSERT_TRUE(range);
  EXPECT_LT((range->p_camera - torso_c).norm(), 1e-6);
  // Assuming the camera level instead misplaces it (by a few centimetres at this pitch).
  const auto level = rangeFromHeight(e, c, Vec3(0.0, -1.0, 0.0));
  ASSERT_TRUE(level);
  EXPECT_GT((level->p_camera - torso_c).norm(), 0.02);
}

TEST(HeightRange, ASilhouetteTooShortToRangeIsNoRange) {
  // 4 px tall: +-53 % (the mask's ends); 12 px: +-18 %, within the 25 % bound.
  const PinholeCamera c = camera();
  const Vec3 up(0.0, -1.0, 0.0);
  EXPECT_FALSE(rangeFromHeight({200.0, 204.0, 320.0}, c, up).has_value());
  const auto range = rangeFromHeight({200.0, 212.0, 320.0}, c, up);
  ASSERT_TRUE(range.has_value());
  EXPECT_NEAR(range->sigma_range_m / range->range_m, 0.185, 0.01);
  HeightRangeOptions loose;
  loose.max_relative_sigma = 1.0;
  EXPECT_TRUE(rangeFromHeight({200.0, 204.0, 320.0}, c, up, loose).has_value());
}

TEST(HeightRange, ExtentOnlyWhenHeadAndFeetAreInViewAndUnoccluded) {
  // Whole in view: the mask's edges (pixel edges, not centres) and the torso band's column.
  Instances whole = personMask(300, 20, 100, 211);
  whole.labels(cv::Rect(320, 150, 15, 5)).setTo(1);   // an arm out to the right, in the band
  whole.labels(cv::Rect(280, 200, 20, 12)).setTo(1);  // a leg striding left, below the band
  whole.items[0].box = cv::Rect(280, 100, 55, 112);
  const auto extent = personExtent(whole.labels, whole.items[0]);
  ASSERT_TRUE(extent);
  EXPECT_DOUBLE_EQ(extent->top_px, 99.5);
  EXPECT_DOUBLE_EQ(extent->bottom_px, 211.5);
  EXPECT_NEAR(extent->column_px, 310.0, 1.0);
  // Cut by the image's top, bottom, left or right edge.
  EXPECT_FALSE(
      personExtent(personMask(300, 20, 0, 200).labels, personMask(300, 20, 0, 200).items[0]));
  EXPECT_FALSE(personExtent(personMask(300, 20, 300, kH - 1).labels,
                            personMask(300, 20, 300, kH - 1).items[0]));
  EXPECT_FALSE(
      personExtent(personMask(0, 20, 100, 200).labels, personMask(0, 20, 100, 200).items[0]));
  EXPECT_FALSE(personExtent(personMask(kW - 20, 20, 100, 200).labels,
                            personMask(kW - 20, 20, 100, 200).items[0]));
  // Another instance right below the lowest row hides the feet.
  Instances occluded = personMask(300, 20, 100, 200);
  occluded.labels(cv::Rect(290, 201, 60, 40)).setTo(2);
  EXPECT_FALSE(personExtent(occluded.labels, occluded.items[0]));
}

TEST(ObjectTracker, APersonBeyondTheDepthRangeIsRangedByItsHeight) {
  // A 1.70 m walker approaching a level camera at 1.2 m/s from 9 m, 0.3 m right of the axis,
  // its soles 1.5 m below the camera; no depth anywhere (beyond the sensor's range).
  const PinholeCamera c = camera();
  ObjectTracker tracker(ObjectTrackingConfig{}, 5);
  const cv::Mat depth = cv::Mat(kH, kW, CV_32F, cv::Scalar(0.f));
  const cv::Mat no_flow;
  const double speed_mps = 1.2, z0_m = 9.0;
  std::vector<TrackedObject> out;
  Vec3 torso = Vec3::Zero();
  double z_m = z0_m;
  for (int i = 0; i < 60; ++i) {
    z_m = z0_m - speed_mps * i / 30.0;
    const Vec3 soles(0.3, 1.5, z_m), crown(0.3, 1.5 - 1.70, z_m);
    torso = crown + kTorsoCentreBelowTop * (soles - crown);
    Instances instances = bodyMask(crown, soles, c, 0.5);
    // The segmenter misses it in frame 30: carried (its depthless sample pixels vote for it when
    // it is seen again), it keeps its id.
    if (i == 30) instances = Instances::none(cv::Size(kW, kH));
    FrameDynamics dynamics;
    dynamics.moving_ids.push_back(1);
    out =
        tracker.track({i, i / 30.0, instances, dynamics, no_flow, depth, SE3::Identity(), true, c});
    ASSERT_EQ(out.size(), 1u) << "frame " << i;
    EXPECT_EQ(out[0].id, 1u);
    if (i == 0) {
      // Placed at once, honestly: the stature's spread along the ray (z), little across it.
      EXPECT_LT((out[0].p_world - torso).norm(), 0.15);
      EXPECT_GT(std::sqrt(out[0].covariance(2, 2)), 0.3);
      EXPECT_LT(std::sqrt(out[0].covariance(0, 0)), 0.1);
      EXPECT_LT(std::sqrt(out[0].covariance(1, 1)), 0.1);
    }
  }
  // Two seconds on: the range's pixel rounding has averaged out; the approach speed is measured.
  EXPECT_LT((out[0].p_world - torso).norm(), 0.15);
  EXPECT_NEAR(out[0].v_world_mps.z(), -speed_mps, 0.25);
  EXPECT_LT(std::abs(out[0].v_world_mps.x()), 0.15);
  EXPECT_TRUE(out[0].velocity_known);
  // Still as uncertain along the ray as the stature makes it (5 % of 6.8 m): every range shares
  // the one stature, averaging frames does not narrow that.
  EXPECT_GT(std::sqrt(out[0].covariance(2, 2)), 0.3);
}

TEST(ObjectTracker, DepthTakesOverFromTheHeightRangeWithoutAVelocityJump) {
  // A tall walker (1.87 m: the prior reads it 10 % near) approaching at 1.2 m/s from 9 m; the
  // sensor's depth reaches it once it is nearer than 6 m (its front 0.15 m before the torso).
  const PinholeCamera c = camera();
  ObjectTracker tracker(ObjectTrackingConfig{}, 5);
  const double speed_mps = 1.2, z0_m = 9.0, stature_m = 1.87, depth_range_m = 6.0;
  double worst_speed_error_after = 0.0, error_before = 0.0, error_after = 0.0;
  for (int i = 0; i < 110; ++i) {
    const double z_m = z0_m - speed_mps * i / 30.0;
    const Vec3 soles(-0.4, 1.5, z_m), crown(-0.4, 1.5 - stature_m, z_m);
    const Vec3 torso = crown + kTorsoCentreBelowTop * (soles - crown);
    const Instances instances = bodyMask(crown, soles, c, 0.5);
    const auto out = stepWalker(tracker, i, instances, z_m, depth_range_m, c);
    ASSERT_EQ(out.size(), 1u) << "frame " << i;
    EXPECT_EQ(out[0].id, 1u);
    const double error_m = (out[0].p_world - torso).norm();
    const double sigma_z = std::sqrt(out[0].covariance(2, 2));
    if (z_m - 0.15 >= depth_range_m) {
      // Placed by its height: off by the stature, but within what its covariance says.
      error_before = error_m;
      EXPECT_LT(error_m, 2.5 * sigma_z) << "frame " << i;
    } else {
      worst_speed_error_after =
          std::max(worst_speed_error_after, std::abs(out[0].v_world_mps.z() + speed_mps));
      error_after = error_m;
    }
  }
  EXPECT_GT(error_before, 0.4);  // 10 % of 6 m
  EXPECT_LT(error_after, 0.05);  // depth took over
  // The depth fixes the scale of position and velocity together: no spurious approach speed.
  EXPECT_LT(worst_speed_error_after, 0.4);
}

TEST(ObjectTracker, RangesThatReadNoWalkersSpeedAreWithdrawn) {
  // A walker approaching at 1.0 m/s from 5.8 m whose mask loses its top rows the farther it is
  // (80 px per metre beyond 4.5 m: the simulated approach's eroded masks lost head and shoulders
  // far away), so its height ranges read it far and closing ever faster; depth reaches it at
  // 4.5 m. Once the ranges' rate leaves a walker's (above 4 m/s) they are withdrawn: the track
  // never reports a rush at the wearer much beyond that, holds its velocity unknown until depth,
  // and its first depth frame reads the walker's speed or the prior's zero. With whole masks the
  // ranges stay in use and read the walk.
  const PinholeCamera c = camera();
  const double speed_mps = 1.0, z0_m = 5.8, depth_range_m = 4.5;
  for (const bool rows_lost : {false, true}) {
    ObjectTracker tracker(ObjectTrackingConfig{}, 5);
    double fastest_ranged = 0.0, first_depth_error = -1.0;
    bool unknown_before_depth = false;
    for (int i = 0; i < 90; ++i) {
      const double z_m = z0_m - speed_mps * i / 30.0;
      const Vec3 soles(0.2, 1.5, z_m), crown(0.2, 1.5 - 1.70, z_m);
      const int lost =
          rows_lost ? int(std::lround(std::max(0.0, 80.0 * (z_m - depth_range_m)))) : 0;
      const Instances instances = bodyMask(crown, soles, c, 0.5, lost);
      const bool in_depth = z_m - 0.15 < depth_range_m;
      const auto out = stepWalker(tracker, i, instances, z_m, depth_range_m, c);
      ASSERT_EQ(out.size(), 1u) << "frame " << i;
      if (!in_depth) {
        fastest_ranged = std::max(fastest_ranged, out[0].speed_mps);
        unknown_before_depth = !out[0].velocity_known;
      } else if (first_depth_error < 0.0) {
        first_depth_error = std::abs(out[0].speed_mps - speed_mps);
      }
    }
    ASSERT_GE(first_depth_error, 0.0);
    if (rows_lost) {
      EXPECT_GT(fastest_ranged, 3.0) << "the ranges did start a rush (the case under test)";
      EXPECT_LT(fastest_ranged, 4.5) << "and were withdrawn at a walker's limit";
      EXPECT_TRUE(unknown_before_depth);
    } else {
      EXPECT_LT(fastest_ranged, 2.0);
    }
    // The first depth frame: the speed is the walker's or the prior's zero, never the rush.
    EXPECT_LE(first_depth_error, speed_mps + 1e-6) << (rows_lost ? "rows lost" : "whole");
  }
}

TEST(ObjectTracker, APersonBeyondTheDepthRangeCutByTheImageGetsNoRange) {
  // Feet below the image's bottom edge, no depth: nothing places it (no track starts).
  ObjectTracker tracker(ObjectTrackingConfig{}, 5);
  const cv::Mat depth = cv::Mat(kH, kW, CV_32F, cv::Scalar(0.f));
  const cv::Mat no_flow;
  const Instances instances = personMask(300, 30, 300, kH - 1);
  FrameDynamics dynamics;
  dynamics.moving_ids.push_back(1);
  const PinholeCamera c = camera();
  const auto out =
      tracker.track({0, 0.0, instances, dynamics, no_flow, depth, SE3::Identity(), true, c});
  EXPECT_TRUE(out.empty());
}

TEST(ObjectTracker, ASilhouetteAFewPixelsTallGetsNoRange) {
  // 4 rows of a person's mask, no depth: a 1.70 m person would stand 220 m away, known to
  // +-53 % by those rows' ends. No track starts; 12 rows (74 m, +-18 %) are ranged.
  const PinholeCamera c = camera();
  FrameDynamics dynamics;
  dynamics.moving_ids.push_back(1);
  const cv::Mat no_flow, depth = cv::Mat(kH, kW, CV_32F, cv::Scalar(0.f));
  for (const int rows : {4, 12}) {
    ObjectTracker tracker(ObjectTrackingConfig{}, 5);
    const auto out = tracker.track({0, 0.0, personMask(300, 3, 200, 200 + rows - 1), dynamics,
                                    no_flow, depth, SE3::Identity(), true, c});
    if (rows == 4) {
      EXPECT_TRUE(out.empty()) << out[0].p_camera.transpose();
    } else {
      ASSERT_EQ(out.size(), 1u);
      EXPECT_NEAR(out[0].p_camera.z(), 1.70 * c.fy / rows, 10.0);
    }
  }
}

TEST(ObjectTracker, ASilhouetteBorderedByANearerObjectGetsNoRange) {
  // An 85 px tall sliver of a walker without depth (a 1.70 m person would be 10 m away),
  // bordered on its left by a cabinet 3 m away: part of a nearer person hidden by the cabinet,
  // not a whole one far away. No centre (no track starts); without the cabinet it is ranged.
  const PinholeCamera c = camera();
  const Instances instances = personMask(300, 16, 300, 384);
  FrameDynamics dynamics;
  dynamics.moving_ids.push_back(1);
  const cv::Mat no_flow;
  cv::Mat depth(kH, kW, CV_32F, cv::Scalar(0.f));
  {
    ObjectTracker tracker(ObjectTrackingConfig{}, 5);
    const auto out =
        tracker.track({0, 0.0, instances, dynamics, no_flow, depth, SE3::Identity(), true, c});
    ASSERT_EQ(out.size(), 1u);
    EXPECT_NEAR(out[0].p_camera.z(), 10.0, 0.5);
  }
  depth(cv::Rect(280, 250, 20, 200)).setTo(3.0f);
  {
    ObjectTracker tracker(ObjectTrackingConfig{}, 5);
    const auto out =
        tracker.track({0, 0.0, instances, dynamics, no_flow, depth, SE3::Identity(), true, c});
    EXPECT_TRUE(out.empty());
  }
  // Depth at 3.9 m on the left third of the mask (a quarter of the sampled points: fewer than
  // min_depth_share): that depth, far nearer than the 10 m the height says, rules the height
  // out; the centre stays unknown in every component. (So few points place no centre by
  // default, objects.centre_min_points; allowed here to see what the range rule leaves.)
  depth.setTo(0.f);
  depth(cv::Rect(300, 300, 5, 85)).setTo(3.9f);
  {
    ObjectTrackingConfig few_points;
    few_points.centre_min_points = 1;
    ObjectTracker tracker(few_points, 5);
    const auto out =
        tracker.track({0, 0.0, instances, dynamics, no_flow, depth, SE3::Identity(), true, c});
    ASSERT_EQ(out.size(), 1u);
    for (int k = 0; k < 3; ++k) EXPECT_GT(std::sqrt(out[0].covariance(k, k)), 0.5) << k;
  }
}

TEST(ObjectTracker, DepthThatContradictsTheHeightRangeRestartsTheFilter) {
  // A mask that lost head and legs (the torso only, 35 % of the person's height: eroded, or a
  // segmenter at its limit) reads the walker ~3 times too far, and its ranges "approach" ~3 times
  // too fast. When depth reaches the walker (6 m) its centre lies far outside what the ranges'
  // covariance allows: the filter starts afresh there instead of keeping that velocity.
  const PinholeCamera c = camera();
  ObjectTracker tracker(ObjectTrackingConfig{}, 5);
  const double speed_mps = 1.2, z0_m = 9.0, depth_range_m = 6.0;
  double fastest_after_mps = 0.0;
  bool ranged = false;
  for (int i = 0; i < 110; ++i) {
    const double z_m = z0_m - speed_mps * i / 30.0;
    const Vec3 shoulders(0.2, -0.1, z_m), hips(0.2, 0.5, z_m);
    const Instances instances = bodyMask(shoulders, hips, c, 0.0);
    const bool in_range = z_m - 0.15 < depth_range_m;
    const auto out = stepWalker(tracker, i, instances, z_m, depth_range_m, c);
    ASSERT_EQ(out.size(), 1u) << "frame " << i;
    if (!in_range && out[0].p_camera.z() > 2.0 * z_m) ranged = true;
    if (in_range) fastest_after_mps = std::max(fastest_after_mps, out[0].speed_mps);
  }
  EXPECT_TRUE(ranged);  // the torso did read far too far
  EXPECT_LT(fastest_after_mps, speed_mps + 0.4);
}

TEST(ObjectTracker, APersonBeyondTheDepthRangeStandsWhereItsSolesMeetTheFloor) {
  // A 1.55 m person 9 m ahead of a level camera 1.5 m above the floor: the floor has depth up to
  // 4.5 m (the image's bottom rows), the person none. Its stature reads it 9 % near; its soles
  // on the fitted floor place it within a few centimetres.
  const PinholeCamera c = camera();
  const double floor_below_m = 1.5, stature_m = 1.55;
  const cv::Mat depth = test::levelFloorDepth(c, floor_below_m, 4.5);
  const Vec3 soles(0.3, floor_below_m, 9.0), crown(0.3, floor_below_m - stature_m, 9.0);
  const Vec3 torso = crown + kTorsoCentreBelowTop * (soles - crown);
  const Instances instances = bodyMask(crown, soles, c, 0.5);
  const auto placedAt = [&](bool floor_contact) {
    ObjectTrackingConfig config;
    config.floor_contact_range = floor_contact;
    ObjectTracker tracker(config, 5);
    std::vector<TrackedObject> out;
    for (int i = 0; i < 10; ++i) {
      FrameDynamics dynamics;
      out = tracker.track(
          {i, i / 30.0, instances, dynamics, cv::Mat(), depth, SE3::Identity(), true, c});
    }
    return out.size() == 1 ? out[0].p_world : Vec3::Zero();
  };
  EXPECT_LT((placedAt(true) - torso).norm(), 0.15);
  EXPECT_GT((placedAt(false) - torso).norm(), 0.6);
}

TEST(ObjectTracker, AWalkerSideOnBeyondTheDepthRangeStandsBehindItsShoesSide) {
  // A 1.70 m walker crossing 7 m ahead of a level camera 1.5 m above the floor at 1 m/s, side
  // on: the lowest row of its silhouette is the side of its nearer shoe, half a shoe's width in
  // front of its axis (not the toes' 0.19 m of a walker facing the camera), 2 cm up. Once its
  // velocity is known the tracker reads its heading across the ray and places it behind that
  // side; with the heading unknown (the mean lead over headings, 0.139 m) it would stand ~9 cm
  // too far.
  const PinholeCamera c = camera();
  const double floor_below_m = 1.5, stature_m = 1.70, speed_mps = 1.0;
  const FloorContactOptions feet;
  const cv::Mat depth = test::levelFloorDepth(c, floor_below_m, 4.5);
  // The shoe's side projects to the lower edge of row 350 (PersonExtent reads a row's lower
  // edge), so the mask's rounding adds nothing.
  const double shoe_z_m = c.fy * (floor_below_m - feet.foot_outline_height_m) / (350 + 0.5 - c.cy);
  const double axis_z_m = shoe_z_m + feet.foot_lead_side_m;
  ObjectTracker tracker(ObjectTrackingConfig{}, 5);
  double sum_error_z_m = 0.0;
  int scored = 0;
  for (int i = 0; i < 60; ++i) {
    const double x_m = -0.6 + speed_mps * i / 30.0;
    const Vec3 soles(x_m, floor_below_m, axis_z_m), crown(x_m, floor_below_m - stature_m, axis_z_m);
    const Vec3 torso = crown + kTorsoCentreBelowTop * (soles - crown);
    const int top_row = int(std::lround(c.project(crown).y() + 0.5));
    const int half_width = int(std::lround(0.2 * c.fx / axis_z_m));
    const int column = int(std::lround(c.project(soles).x()));
    const Instances instances = personMask(column - half_width, 2 * half_width + 1, top_row, 350);
    FrameDynamics dynamics;
    dynamics.moving_ids.push_back(1);
    const auto out = tracker.track(
        {i, i / 30.0, instances, dynamics, cv::Mat(), depth, SE3::Identity(), true, c});
    ASSERT_EQ(out.size(), 1u) << "frame " << i;
    if (i < 40) continue;
    ASSERT_TRUE(out[0].velocity_known) << "frame " << i;
    EXPECT_NEAR(out[0].v_world_mps.x(), speed_mps, 0.3) << "frame " << i;
    sum_error_z_m += out[0].p_camera.z() - torso.z();
    ++scored;
  }
  EXPECT_LT(std::abs(sum_error_z_m / scored), 0.04) << sum_error_z_m / scored;
}
