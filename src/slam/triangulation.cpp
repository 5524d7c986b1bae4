#include "slam/triangulation.hpp"

#include <Eigen/SVD>
#include <cmath>

#include "slam/matcher.hpp"
#include "slam/rgbd_jacobian.hpp"

namespace dynanav {
namespace {

/// F_12 with x1^T F_12 x2 = 0 (ORB-SLAM2 ComputeF12).
Mat3 fundamental(const KeyFrame& kf1, const KeyFrame& kf2, const PinholeCamera& cam) {
  const SE3 T_12 = kf1.T_camera_world() * kf2.T_world_camera();
  Mat3 K;
  K << cam.fx, 0, cam.cx, 0, cam.fy, cam.cy, 0, 0, 1;
  const Mat3 K_inv = K.inverse();
  return K_inv.transpose() * skewSymmetric(T_12.translation()) * T_12.linear() * K_inv;
}

/// Reprojection check of a new point in one keyframe (chi2 95 %: 5.991 mono, 7.8 with depth).
bool reprojects(const KeyFrame& kf, int i, const Vec3& p_world) {
  const Features& f = kf.features;
  const PinholeCamera& cam = *f.camera;
  const Vec3 p = kf.T_camera_world() * p_world;
  if (p.z() <= 0.0) return false;
  const double inv_z = 1.0 / p.z();
  const double u = cam.fx * p.x() * inv_z + cam.cx;
  const double v = cam.fy * p.y() * inv_z + cam.cy;
  const double ex = u - f.points[i].x, ey = v - f.points[i].y;
  const double sigma2 = f.scales->sigma2[f.keypoints[i].octave];
  if (f.u_right[i] < 0.f) return ex * ex + ey * ey <= 5.991 * sigma2;
  const double er = u - cam.bf() * inv_z - f.u_right[i];
  return ex * ex + ey * ey + er * er <= 7.8 * sigma2;
}

}  // namespace

bool triangulateLinear(const Eigen::Vector2d& xn1, const Eigen::Vector2d& xn2, const SE3& T_c1w,
                       const SE3& T_c2w, Vec3& p_world) {
  const Eigen::Matrix<double, 3, 4> P1 = T_c1w.matrix().topRows<3>();
  const Eigen::Matrix<double, 3, 4> P2 = T_c2w.matrix().topRows<3>();
  Eigen::Matrix4d A;
  A.row(0) = xn1.x() * P1.row(2) - P1.row(0);
  A.row(1) = xn1.y() * P1.row(2) - P1.row(1);
  A.row(2) = xn2.x() * P2.row(2) - P2.row(0);
  A.row(3) = xn2.y() * P2.row(2) - P2.row(1);
  const Eigen::JacobiSVD<Eigen::Matrix4d> svd(A, Eigen::ComputeFullV);
  const Eigen::Vector4d x = svd.matrixV().col(3);
  if (std::abs(x(3)) < 1e-12) return false;
  p_world = x.head<3>() / x(3);
  return true;
}

std::vector<MapPointPtr> triangulateWithNeighbours(KeyFrame& kf1, Map& map, int neighbours) {
  std::vector<MapPointPtr> created;
  const Features& f1 = kf1.features;
  const PinholeCamera& cam = *f1.camera;
  const PyramidScales& scales = *f1.scales;
  const Vec3 center1 = kf1.center();
  const double ratio_factor = 1.5 * scales.scale_factor;
  for (KeyFrame* kf2_ptr : kf1.bestCovisible(neighbours)) {
    KeyFrame& kf2 = *kf2_ptr;
    if (kf2.bad) continue;
    const Vec3 center2 = kf2.center();
    // Baselines shorter than the virtual stereo baseline add nothing over the depth sensor.
    if ((center2 - center1).norm() < cam.baseline_m) continue;
    const Features& f2 = kf2.features;
    const Mat3 F12 = fundamental(kf1, kf2, cam);
    for (const auto& [i1, i2] : matcher::matchForTriangulation(kf1, kf2, F12, false)) {
      const Eigen::Vector2d xn1((f1.points[i1].x - cam.cx) / cam.fx,
                                (f1.points[i1].y - cam.cy) / cam.fy);
      const Eigen::Vector2d xn2((f2.points[i2].x - cam.cx) / cam.fx,
                                (f2.points[i2].y - cam.cy) / cam.fy);
      const Vec3 ray1 = kf1.T_world_camera().linear() * Vec3(xn1.x(), xn1.y(), 1.0);
      const Vec3 ray2 = kf2.T_world_camera().linear() * Vec3(xn2.x(), xn2.y(), 1.0);
      const double cos_rays = ray1.dot(ray2) / (ray1.norm() * ray2.norm());
      const bool stereo1 = f1.u_right[i1] >= 0.f, stereo2 = f2.u_right[i2] >= 0.f;
      const double cos_stereo1 =
          stereo1 ? std::cos(2.0 * std::atan2(cam.baseline_m / 2, f1.depth_m[i1])) : 2.0;
      const double cos_stereo2 =
          stereo2 ? std::cos(2.0 * std::atan2(cam.baseline_m / 2, f2.depth_m[i2])) : 2.0;
      const double cos_stereo = std::min(cos_stereo1, cos_stereo2);
      Vec3 p_world;
      if (cos_rays < cos_stereo && cos_rays > 0.0 && (stereo1 || stereo2 || cos_rays < 0.9998)) {
        if (!triangulateLinear(xn1, xn2, kf1.T_camera_world(), kf2.T_camera_world(), p_world))
          continue;
      } else if (stereo1 && cos_stereo1 < cos_stereo2) {
        p_world = kf1.T_world_camera() * f1.backproject(i1);
      } else if (stereo2 && cos_stereo2 < cos_stereo1) {
        p_world = kf2.T_world_camera() * f2.backproject(i2);
      } else {
        continue;  // too little parallax and no depth
      }
      if (!reprojects(kf1, i1, p_world) || !reprojects(kf2, i2, p_world)) continue;
      // Scale consistency: the distance ratio must agree with the pyramid-level ratio.
      const double dist1 = (p_world - center1).norm(), dist2 = (p_world - center2).norm();
      if (dist1 == 0.0 || dist2 == 0.0) continue;
      const double ratio_dist = dist2 / dist1;
      const double ratio_octave =
          scales.scale[f1.keypoints[i1].octave] / scales.scale[f2.keypoints[i2].octave];
      if (ratio_dist * ratio_factor < ratio_octave || ratio_dist > ratio_octave * ratio_factor)
        continue;
      auto point = map.createPoint(p_world, &kf1);
      point->addObservation(&kf1, i1);
      point->addObservation(&kf2, i2);
      kf1.map_points[i1] = point;
      kf2.map_points[i2] = point;
      point->updateDescriptor();
      point->updateNormalAndDepth(scales);
      created.push_back(point);
    }
  }
  return created;
}

}  // namespace dynanav
