// The renderer against an independent ray caster: every pixel's noiseless depth must be the
// distance along the pixel's ray to the nearest triangle, and its mask label that triangle's
// object.
#include <gtest/gtest.h>

#include <limits>

#include "sim/rasterizer.hpp"
#include "sim/simulator.hpp"

namespace dynanav::sim {
namespace {

struct Hit {
  double z = 0.0;  // camera z of the nearest hit, 0 = none
  uint16_t id = 0;
};

struct CameraTriangle {
  Vec3 a, b, c;
  uint16_t id;
};

/// Möller–Trumbore along the ray (x, y, 1) from the camera centre: t is the camera z directly.
Hit castRay(const std::vector<CameraTriangle>& tris, const Vec3& dir) {
  Hit best;
  double best_t = std::numeric_limits<double>::infinity();
  for (const auto& t : tris) {
    const Vec3 e1 = t.b - t.a, e2 = t.c - t.a;
    const Vec3 p = dir.cross(e2);
    const double det = e1.dot(p);
    if (std::abs(det) < 1e-12) continue;
    const Vec3 s = -t.a;
    const double u = s.dot(p) / det;
    if (u < 0 || u > 1) continue;
    const Vec3 q = s.cross(e1);
    const double v = dir.dot(q) / det;
    if (v < 0 || u + v > 1) continue;
    const double z = e2.dot(q) / det;
    if (z > Rasterizer::kNearPlaneM && z < best_t) {
      best_t = z;
      best = {z, t.id};
    }
  }
  return best;
}

std::vector<CameraTriangle> cameraTriangles(const std::vector<DrawItem>& items,
                                            const SE3& T_world_camera) {
  const SE3 T_camera_world = T_world_camera.inverse();
  std::vector<CameraTriangle> out;
  for (const DrawItem& item : items) {
    const SE3 T = T_camera_world * item.T_world_mesh.cast<double>();
    for (const Triangle& tri : item.mesh->triangles) {
      const auto at = [&](int k) {
        return Vec3(T * item.mesh->positions[size_t(tri.v[size_t(k)])].cast<double>());
      };
      out.push_back({at(0), at(1), at(2), item.instance_id});
    }
  }
  return out;
}

/// `need_mover`: the frame must show a mover, whose pixels the ray caster must also find.
/// `readout_s` > 0: a rolling shutter; row v is cast from the pose and scene at its own time,
/// stamp + ((v + 1/2) / H - 1/2) * readout.
void expectMatchesRayCaster(const std::string& scenario, int frame_index, bool need_mover,
                            double readout_s = 0.0) {
  SimOptions options;
  options.readout_s = readout_s;
  options.scenario = scenario;
  options.noiseless = true;
  options.photos = false;
  options.texels_per_m = 80.0f;  // geometry does not depend on texture resolution
  Simulator sim(options);
  const SimFrame frame = sim.render(frame_index);
  ASSERT_EQ(cv::countNonZero(frame.depth_m != frame.depth_true_m), 0)
      << "noiseless depth must be exact";
  uint16_t must_see_id = 0;
  int most_points = 0;
  for (const auto& o : frame.objects["objects"])
    if (o["points"].get<int>() > most_points) {
      most_points = o["points"].get<int>();
      must_see_id = o["id"].get<uint16_t>();
    }
  if (need_mover) {
    ASSERT_GT(most_points, 500) << scenario << " frame " << frame_index << " should show a mover";
  }
  std::vector<DrawItem> items;
  const PinholeCamera& cam = sim.camera();
  int samples = 0, agree = 0, saw_id = 0;
  double worst_agreeing_error = 0.0;
  std::vector<CameraTriangle> tris;
  for (int v = 3; v < cam.height; v += 8) {
    if (readout_s > 0.0 || tris.empty()) {
      const double t = frame.stamp_s + ((v + 0.5) / cam.height - 0.5) * readout_s;
      sim.drawItemsAt(t, items);
      tris = cameraTriangles(items, SE3(sim.T_world_room() * sim.scene().T_room_camera(t)));
    }
    for (int u = 5; u < cam.width; u += 8) {
      const Hit hit = castRay(tris, Vec3((u - cam.cx) / cam.fx, (v - cam.cy) / cam.fy, 1.0));
      const double z = frame.depth_true_m.at<float>(v, u);
      const uint16_t id = frame.instance.at<uint16_t>(v, u);
      ++samples;
      if (hit.id == must_see_id && hit.id != 0) ++saw_id;
      // A sample on a silhouette edge may fall either side; count those as disagreements.
      if (hit.id == id && std::abs(hit.z - z) < 1e-3 * std::max(1.0, hit.z)) {
        ++agree;
        worst_agreeing_error = std::max(worst_agreeing_error, std::abs(hit.z - z));
      }
    }
  }
  EXPECT_GE(agree, samples * 995 / 1000)
      << scenario << " frame " << frame_index << ": " << agree << " of " << samples;
  // The renderer quantises row times to bands of 16 rows (0.5 ms at a 30 ms readout): a
  // far, grazing surface moves a few millimetres in that time.
  EXPECT_LT(worst_agreeing_error, readout_s > 0.0 ? 5e-3 : 2e-3);
  if (need_mover) {
    EXPECT_GT(saw_id, 10) << "the ray caster should also hit object " << must_see_id;
  }
}

TEST(SimGeometry, OfficeDepthAndMasksMatchRayCasting) {
  expectMatchesRayCaster("office", 135, true);
}
TEST(SimGeometry, PushedBoxDepthAndMasksMatchRayCasting) {
  expectMatchesRayCaster("pushed-box", 120, true);
}
TEST(SimGeometry, LoopDoorwayMatchesRayCasting) {
  expectMatchesRayCaster("loop", 240, false);
}

TEST(SimGeometry, RollingShutterRowsMatchRayCastingAtTheirOwnTime) {
  // Office frame 135: the wearer walks and a person crosses; 30 ms readout.
  expectMatchesRayCaster("office", 135, true, 0.030);
}

TEST(SimGeometry, RollingShutterFrameIsNotTheGlobalShutterOne) {
  // The same frame rendered with a rolling shutter, checked as if it had a global shutter: many
  // rows away from the middle disagree (guards against a readout the renderer ignores).
  SimOptions options;
  options.scenario = "office";
  options.noiseless = true;
  options.photos = false;
  options.texels_per_m = 80.0f;
  const SimFrame global = Simulator(options).render(135);
  options.readout_s = 0.030;
  const SimFrame rolling = Simulator(options).render(135);
  EXPECT_TRUE(rolling.T_world_camera.isApprox(global.T_world_camera, 1e-12)) << "pose at the stamp";
  const int rows = global.depth_true_m.rows;
  const auto differing = [&](int y0, int y1) {
    cv::Mat diff;
    cv::absdiff(global.depth_true_m.rowRange(y0, y1), rolling.depth_true_m.rowRange(y0, y1), diff);
    return cv::countNonZero(diff > 1e-3f);
  };
  const int top = differing(0, rows / 8), bottom = differing(rows - rows / 8, rows);
  EXPECT_GT(top + bottom, 5000) << "top " << top << ", bottom " << bottom;
}

TEST(SimGeometry, QuadAtKnownDepth) {
  // A 2 x 2 m wall 3 m ahead, facing the camera: every covered pixel has depth 3.
  Mesh wall;
  wall.addQuad(Vec3f(-1, -1, 3), Vec3f(2, 0, 0), Vec3f(0, 2, 0), 0, 100.0f);
  TextureSet textures{Texture(cv::Mat(64, 64, CV_8UC3, cv::Scalar(10, 200, 30)))};
  PinholeCamera cam;
  Rasterizer r;
  RenderBuffers out;
  r.render(cam, Pose3f::Identity(), {{&wall, Pose3f::Identity(), 7}}, textures, out);
  // The quad spans pixels within 525 * 1/3 = 175 px of the centre.
  EXPECT_FLOAT_EQ(out.depth_m.at<float>(240, 320), 3.0f);
  EXPECT_EQ(out.instance.at<uint16_t>(240, 320), 7);
  EXPECT_NEAR(out.depth_m.at<float>(240 + 170, 320 - 170), 3.0f, 1e-5);
  EXPECT_EQ(out.depth_m.at<float>(240 + 180, 320), 0.0f);
  EXPECT_EQ(out.instance.at<uint16_t>(5, 5), 0);
  // Pixel centres u in [cx - 175, cx + 175] = [144.5, 494.5]: 350 columns, likewise 350 rows.
  EXPECT_EQ(cv::countNonZero(out.instance), 350 * 350);
  // Seen from behind, a one-sided surface disappears.
  Pose3f behind = Pose3f::Identity();
  behind.linear() = Eigen::AngleAxisf(float(M_PI), Vec3f::UnitY()).toRotationMatrix();
  behind.translation() = Vec3f(0, 0, 6);
  r.render(cam, behind.inverse(), {{&wall, Pose3f::Identity(), 7}}, textures, out);
  EXPECT_EQ(cv::countNonZero(out.instance), 0);
}

}  // namespace
TEST(SimGeometry, BoxWithoutOffsetsStartsEveryFaceAtTexelZero) {
  // A 0.5 m box at 100 texels/m: one tile per face, its texture coordinates 0..50 texels.
  // (The default offsets were once left uninitialised and read as garbage under ASan.)
  Mesh box;
  box.addBox(Vec3f(0, 0, 2), Vec3f(0.5f, 0.5f, 0.5f), {0, 1, 2, 3, 4, 5}, 100.0f);
  ASSERT_EQ(box.uvs.size(), 6u * 4u);
  for (size_t f = 0; f < 6; ++f) EXPECT_EQ(box.uvs[4 * f], Vec2f::Zero()) << "face " << f;
  for (const Vec2f& uv : box.uvs) {
    EXPECT_GE(uv.minCoeff(), 0.0f);
    EXPECT_LE(uv.maxCoeff(), 50.0f + 1e-3f);
  }
}

}  // namespace dynanav::sim
