#include "test_loop_scene.hpp"

#include <Eigen/Geometry>

namespace dynanav::test {

LoopScene makeLoopScene(int count, double radius_m, double orbit_m, uint64_t seed) {
  LoopScene s;
  auto camera = std::make_shared<PinholeCamera>();
  camera->width = 640;
  camera->height = 480;
  s.camera = camera;
  s.scales = std::make_shared<const PyramidScales>(PyramidScales::fromConfig(OrbConfig{}));
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> angle(-M_PI, M_PI), height(-1.2, 1.2);
  s.descriptors = cv::Mat(count, 32, CV_8U);
  for (int i = 0; i < count; ++i) {
    const double a = angle(rng);
    s.points.emplace_back(radius_m * std::sin(a), height(rng), radius_m * std::cos(a) - orbit_m);
    for (int b = 0; b < 32; ++b)
      s.descriptors.at<uint8_t>(i, b) = static_cast<uint8_t>(rng() & 0xFF);
  }
  // Vocabulary trained on the points' descriptors, grouped into 40 "images" of 100.
  std::vector<cv::Mat> groups;
  for (int i = 0; i + 100 <= count; i += 100)
    groups.push_back(s.descriptors.rowRange(i, i + 100).clone());
  VocabularyTrainOptions options;
  options.branching = 8;
  options.levels = 3;
  options.seed = seed;
  s.vocabulary = std::make_shared<const Vocabulary>(Vocabulary::train(groups, options));
  return s;
}

SE3 orbitPose(double angle_rad, double orbit_m) {
  // The camera sits orbit_m from the room's axis, looking outward along the radius; at angle 0
  // it is at the origin looking along +z.
  const Vec3 axis_point(0.0, 0.0, -orbit_m);
  const Mat3 R_world_camera = Eigen::AngleAxisd(angle_rad, Vec3::UnitY()).toRotationMatrix();
  const Vec3 center = axis_point + R_world_camera * Vec3(0.0, 0.0, orbit_m);
  SE3 T_world_camera = SE3::Identity();
  T_world_camera.linear() = R_world_camera;
  T_world_camera.translation() = center;
  return T_world_camera.inverse();
}

View renderView(const LoopScene& scene, const SE3& T_camera_world, int flip_bits, uint64_t seed) {
  std::mt19937_64 rng(seed);
  const PinholeCamera& cam = *scene.camera;
  std::vector<cv::KeyPoint> keypoints;
  std::vector<int> point_of;
  cv::Mat depth(cam.height, cam.width, CV_32F, cv::Scalar(0.f));
  cv::Mat descriptors;
  for (size_t i = 0; i < scene.points.size(); ++i) {
    const Vec3 p_c = T_camera_world * scene.points[i];
    if (p_c.z() < 0.3 || p_c.z() > 7.0) continue;
    const Eigen::Vector2d uv = cam.project(p_c);
    const int u = static_cast<int>(std::lround(uv.x())), v = static_cast<int>(std::lround(uv.y()));
    if (u < 5 || v < 5 || u >= cam.width - 5 || v >= cam.height - 5) continue;
    if (depth.at<float>(v, u) > 0.f) continue;  // one point per pixel
    // Keypoints sit on whole pixels, so the depth read there is the point's exact depth.
    depth.at<float>(v, u) = static_cast<float>(p_c.z());
    keypoints.emplace_back(cv::Point2f(static_cast<float>(u), static_cast<float>(v)), 31.f, 0.f,
                           1.f, 0);
    cv::Mat d = scene.descriptors.row(static_cast<int>(i)).clone();
    const int flips = flip_bits > 0 ? static_cast<int>(rng() % (flip_bits + 1)) : 0;
    for (int k = 0; k < flips; ++k) {
      const int bit = static_cast<int>(rng() % 256);
      d.at<uint8_t>(0, bit / 8) ^= static_cast<uint8_t>(1u << (bit % 8));
    }
    descriptors.push_back(d);
    point_of.push_back(static_cast<int>(i));
  }
  // Small depth error is not modelled: the pixel centre differs from the projection by < 0.5 px.
  View view;
  view.features =
      makeFeatures(std::move(keypoints), descriptors, depth, 8.0, scene.camera, scene.scales);
  view.point_of = std::move(point_of);
  return view;
}

std::vector<KeyFramePtr> buildMap(const LoopScene& scene, const std::vector<SE3>& T_cw_true,
                                  const std::vector<SE3>& T_cw_estimated, Map& map, int flip_bits) {
  std::vector<KeyFramePtr> keyframes;
  std::vector<MapPointPtr> latest(scene.points.size());
  std::vector<int> last_seen(scene.points.size(), -100);
  for (size_t k = 0; k < T_cw_true.size(); ++k) {
    View view = renderView(scene, T_cw_true[k], flip_bits, 1000 + k);
    const int n = view.features.size();
    auto kf = std::make_shared<KeyFrame>(k, k, static_cast<double>(k), std::move(view.features),
                                         T_cw_estimated[k], std::vector<MapPointPtr>(n));
    map.addKeyFrame(kf);
    const SE3 T_wc = kf->T_world_camera();
    for (int i = 0; i < n; ++i) {
      const int pi = view.point_of[i];
      MapPointPtr point;
      if (last_seen[pi] >= static_cast<int>(k) - 3 && latest[pi]) {
        point = latest[pi];
      } else {
        point = map.createPoint(T_wc * kf->features.backproject(i), kf.get());
        point->first_keyframe_id = k;
        latest[pi] = point;
      }
      point->addObservation(kf.get(), i);
      kf->map_points[i] = point;
      last_seen[pi] = static_cast<int>(k);
    }
    for (const auto& p : kf->map_points) {
      p->updateDescriptor();
      p->updateNormalAndDepth(*scene.scales);
    }
    kf->updateConnections(15);
    keyframes.push_back(kf);
  }
  return keyframes;
}

}  // namespace dynanav::test
