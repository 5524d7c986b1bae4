#include "slam/rigid_ransac.hpp"

#include <Eigen/Geometry>
#include <random>

namespace dynanav {

SE3 fitRigid(const std::vector<Vec3>& a, const std::vector<Vec3>& b) {
  Eigen::Matrix3Xd A(3, a.size()), B(3, b.size());
  for (size_t i = 0; i < a.size(); ++i) {
    A.col(static_cast<Eigen::Index>(i)) = a[i];
    B.col(static_cast<Eigen::Index>(i)) = b[i];
  }
  SE3 T = SE3::Identity();
  T.matrix() = Eigen::umeyama(A, B, false);
  return T;
}

RigidRansacResult estimateRigidRansac(const std::vector<Vec3>& a, const std::vector<Vec3>& b,
                                      const RigidRansacOptions& options,
                                      const std::vector<double>& b_depth_m) {
  RigidRansacResult result;
  const size_t n = a.size();
  result.inlier.assign(n, 0);
  if (n < 3 || n != b.size() || static_cast<int>(n) < options.min_inliers) return result;
  std::vector<double> threshold2(n);
  for (size_t i = 0; i < n; ++i) {
    const double depth = b_depth_m.empty() ? b[i].norm() : b_depth_m[i];
    const double t = std::max(options.min_error_m, options.relative_error * depth);
    threshold2[i] = t * t;
  }
  auto count = [&](const SE3& T, std::vector<uint8_t>& inlier) {
    int k = 0;
    for (size_t i = 0; i < n; ++i) {
      inlier[i] = (T * a[i] - b[i]).squaredNorm() < threshold2[i];
      k += inlier[i];
    }
    return k;
  };
  std::mt19937_64 rng(options.seed);
  std::uniform_int_distribution<size_t> pick(0, n - 1);
  std::vector<uint8_t> inlier(n);
  int best = 0;
  std::vector<uint8_t> best_inlier(n, 0);
  for (int it = 0; it < options.iterations; ++it) {
    size_t i0 = pick(rng), i1 = pick(rng), i2 = pick(rng);
    if (i0 == i1 || i1 == i2 || i0 == i2) continue;
    // A degenerate (nearly collinear) sample has no unique rotation.
    const Vec3 cross = (a[i1] - a[i0]).cross(a[i2] - a[i0]);
    if (cross.norm() < 1e-6) continue;
    const SE3 T = fitRigid({a[i0], a[i1], a[i2]}, {b[i0], b[i1], b[i2]});
    const int k = count(T, inlier);
    if (k > best) {
      best = k;
      best_inlier = inlier;
    }
  }
  if (best < std::max(3, options.min_inliers)) return result;
  // Refit on the consensus set, then re-classify once with the refined model.
  SE3 T = SE3::Identity();
  for (int pass = 0; pass < 2; ++pass) {
    std::vector<Vec3> ia, ib;
    for (size_t i = 0; i < n; ++i)
      if (best_inlier[i]) {
        ia.push_back(a[i]);
        ib.push_back(b[i]);
      }
    if (ia.size() < 3) return result;
    T = fitRigid(ia, ib);
    best = count(T, best_inlier);
  }
  if (best < options.min_inliers) return result;
  result.ok = true;
  result.T_b_a = T;
  result.inlier = best_inlier;
  result.inliers = best;
  return result;
}

}  // namespace dynanav
