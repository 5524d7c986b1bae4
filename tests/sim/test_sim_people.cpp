// Simulated people: the lathe meshes they are made of face outwards with outward normals, and
// objects_gt's `in_view` says how much of a person's silhouette the image shows.
#include <gtest/gtest.h>

#include "sim/mesh.hpp"
#include "sim/simulator.hpp"

namespace dynanav::sim {
namespace {

TEST(SimPeople, LatheFacesAndNormalsPointOutwards) {
  Mesh m;
  // A closed top (a point), an elliptic waist and an open, capped bottom.
  m.addLathe({{0.5f, 0.0f, 0.0f}, {0.3f, 0.2f, 0.1f}, {0.0f, 0.15f, 0.12f}}, 12, 0, {100, 50});
  ASSERT_EQ(m.normals.size(), m.positions.size());
  int side = 0, caps = 0;
  for (const Triangle& t : m.triangles) {
    const Vec3f& a = m.positions[size_t(t.v[0])];
    const Vec3f n = (m.positions[size_t(t.v[1])] - a).cross(m.positions[size_t(t.v[2])] - a);
    if (n.norm() < 1e-9f) continue;  // degenerate triangles at the pole
    const Vec3f c = (a + m.positions[size_t(t.v[1])] + m.positions[size_t(t.v[2])]) / 3.0f;
    const Vec3f radial(c.x(), 0.0f, c.z());
    if (radial.norm() > 0.05f && std::abs(n.normalized().y()) < 0.9f) {
      EXPECT_GT(n.dot(radial), 0.0f);
      ++side;
    } else {
      EXPECT_LT(n.y(), 0.0f);  // the only flat cap is the bottom one
      ++caps;
    }
  }
  EXPECT_EQ(side, 36);  // 2 bands x 12 sides x 2, less the 12 degenerate ones at the pole
  EXPECT_EQ(caps, 12);
  for (size_t i = 0; i < m.positions.size(); ++i) {
    EXPECT_NEAR(m.normals[i].norm(), 1.0f, 1e-4f);
    const Vec3f radial(m.positions[i].x(), 0.0f, m.positions[i].z());
    if (radial.norm() > 0.05f) {
      EXPECT_GT(m.normals[i].dot(radial), 0.0f) << i;
    }
  }
}

TEST(SimPeople, InViewIsTheVisibleShareOfTheSilhouette) {
  SimOptions options;
  options.scenario = "approach";
  options.noiseless = true;
  options.photos = false;
  Simulator sim(options);
  const auto person = [&](int i) { return sim.render(i).objects["objects"][0]; };
  // 4 s: the walker is far down the hall, whole and unoccluded.
  const auto far = person(120);
  EXPECT_GT(far["points"].get<int>(), 2000);
  EXPECT_GT(far["in_view"].get<double>(), 0.95);
  EXPECT_LE(far["in_view"].get<double>(), 1.0);
  // 6.5 s: close by, head and feet leave the image.
  const auto close = person(195);
  EXPECT_GT(close["in_view"].get<double>(), 0.3);
  EXPECT_LT(close["in_view"].get<double>(), 0.8);
  // 8.5 s: passed the wearer, out of view.
  const auto gone = person(255);
  EXPECT_EQ(gone["points"].get<int>(), 0);
  EXPECT_EQ(gone["in_view"].get<double>(), 0.0);
}

}  // namespace
}  // namespace dynanav::sim
