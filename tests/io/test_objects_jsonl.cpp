// objects.jsonl: what the writer writes the reader reads back (DESIGN.md §2 keys plus ours).
#include <gtest/gtest.h>

#include <fstream>

#include "core/error.hpp"
#include "io/objects_jsonl.hpp"
#include "support/test_support.hpp"

using namespace dynanav;
using dynanav::test::scratchDir;

TEST(ObjectsJsonl, RoundTrip) {
  const auto dir = scratchDir("objects_jsonl");
  TrackedObject a;
  a.id = 7;
  a.class_name = "person";
  a.dynamic = true;
  a.p_world = Vec3(1.25, -0.5, 3.0);
  a.p_camera = Vec3(0.5, -0.25, 2.75);
  a.v_world_mps = Vec3(0.9, 0.0, -0.4);
  fillViewGeometry(a);
  a.points = 123;
  a.missed_frames = 2;
  a.motion_inliers = 99;
  a.velocity_known = false;  // a young track: its velocity is the prior
  for (int k = 0; k < 6; ++k) a.covariance(k, k) = 0.01 * (k + 1);
  a.covariance(0, 3) = a.covariance(3, 0) = 0.002;
  a.predicted_path = {{0.5, Vec3(1.7, -0.5, 2.8), 0.2}, {1.0, Vec3(2.15, -0.5, 2.6), 0.5}};
  TrackedObject b;  // a ground-truth style record: no covariance, visible share
  b.id = 2;
  b.class_name = "box";
  b.p_world = Vec3(0.0, 0.3, 2.0);
  b.p_camera = b.p_world;
  fillViewGeometry(b);
  b.visible_share = 0.42;
  {
    ObjectsWriter writer(dir / "objects.jsonl");
    writer.write(0.0, {a, b});
    writer.write(1.0 / 30.0, {});
  }
  const auto frames = readObjectsJsonl(dir / "objects.jsonl");
  ASSERT_EQ(frames.size(), 2u);
  EXPECT_NEAR(frames[1].stamp_s, 0.033333, 1e-9);
  EXPECT_TRUE(frames[1].objects.empty());
  ASSERT_EQ(frames[0].objects.size(), 2u);
  const TrackedObject& ra = frames[0].objects[0];
  EXPECT_EQ(ra.id, 7u);
  EXPECT_EQ(ra.class_name, "person");
  EXPECT_TRUE(ra.dynamic);
  EXPECT_TRUE(ra.p_world.isApprox(a.p_world, 1e-9));
  EXPECT_TRUE(ra.v_world_mps.isApprox(a.v_world_mps, 1e-9));
  EXPECT_NEAR(ra.speed_mps, a.speed_mps, 1e-6);
  EXPECT_NEAR(ra.bearing_deg, a.bearing_deg, 1e-6);
  EXPECT_EQ(ra.clock, a.clock);
  EXPECT_EQ(ra.points, 123);
  EXPECT_EQ(ra.missed_frames, 2);
  EXPECT_FALSE(ra.velocity_known);
  EXPECT_LT((ra.covariance - a.covariance).norm(), 1e-6);
  ASSERT_EQ(ra.predicted_path.size(), 2u);
  EXPECT_TRUE(ra.predicted_path[1].p_world.isApprox(a.predicted_path[1].p_world, 1e-9));
  const TrackedObject& rb = frames[0].objects[1];
  EXPECT_NEAR(rb.visible_share, 0.42, 1e-9);
  EXPECT_TRUE(rb.velocity_known);
  EXPECT_TRUE(rb.covariance.isZero());
  EXPECT_LT(ra.predicted_path.size() + rb.predicted_path.size(), 3u);
}

TEST(ObjectsJsonl, MalformedLineNamesFileAndLine) {
  const auto dir = scratchDir("objects_jsonl_bad");
  std::ofstream(dir / "bad.jsonl") << R"({"t":0,"objects":[]})"
                                   << "\n"
                                   << R"({"t":1,"objects":[{"id":1}]})"
                                   << "\n";
  try {
    (void)readObjectsJsonl(dir / "bad.jsonl");
    FAIL() << "expected InputError";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("bad.jsonl:2"), std::string::npos) << e.what();
  }
}
