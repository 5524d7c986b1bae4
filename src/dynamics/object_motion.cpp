#include "dynamics/object_motion.hpp"

#include <ceres/ceres.h>
#include <ceres/rotation.h>

#include "slam/pnp_ransac.hpp"

namespace dynanav {
namespace {

/// Reprojection of a previous-frame world point moved by the object motion (angle-axis, t)
/// into the current camera.
struct MovedPointCost {
  MovedPointCost(const Vec3& p_prev_world, const Eigen::Vector2d& pixel, const SE3& T_camera_world,
                 const PinholeCamera& camera, double depth_m)
      : p(p_prev_world),
        uv(pixel),
        T(T_camera_world),
        fx(camera.fx),
        fy(camera.fy),
        cx(camera.cx),
        cy(camera.cy),
        z(depth_m),
        inv_sigma_z(depth_m > 0.0 ? 1.0 / (0.01 + 0.003 * depth_m * depth_m) : 0.0) {}

  template <class S>
  bool operator()(const S* motion, S* residual) const {
    const S point[3] = {S(p.x()), S(p.y()), S(p.z())};
    S moved[3];
    ceres::AngleAxisRotatePoint(motion, point, moved);
    for (int k = 0; k < 3; ++k) moved[k] += motion[3 + k];
    S c[3];
    for (int r = 0; r < 3; ++r)
      c[r] = S(T.linear()(r, 0)) * moved[0] + S(T.linear()(r, 1)) * moved[1] +
             S(T.linear()(r, 2)) * moved[2] + S(T.translation()(r));
    residual[0] = S(fx) * c[0] / c[2] + S(cx) - S(uv.x());
    residual[1] = S(fy) * c[1] / c[2] + S(cy) - S(uv.y());
    residual[2] = S(inv_sigma_z) * (c[2] - S(z));
    return true;
  }

  Vec3 p;
  Eigen::Vector2d uv;
  SE3 T;
  double fx, fy, cx, cy;
  double z, inv_sigma_z;
};

int countInliers(const std::vector<Vec3>& p_prev_world, const std::vector<Eigen::Vector2d>& pixels,
                 const SE3& T_camera_object, const PinholeCamera& camera, double threshold_px,
                 std::vector<uint8_t>& inlier) {
  inlier.assign(p_prev_world.size(), 0);
  int count = 0;
  const double t2 = threshold_px * threshold_px;
  for (size_t i = 0; i < p_prev_world.size(); ++i) {
    const Vec3 p = T_camera_object * p_prev_world[i];
    if (p.z() <= 0.0) continue;
    if ((camera.project(p) - pixels[i]).squaredNorm() <= t2) {
      inlier[i] = 1;
      ++count;
    }
  }
  return count;
}

SE3 refine(const std::vector<Vec3>& p_prev_world, const std::vector<Eigen::Vector2d>& pixels,
           const std::vector<double>& depth_m, const std::vector<uint8_t>& inlier,
           const SE3& T_camera_world, const PinholeCamera& camera, const SE3& H0,
           const ObjectMotionOptions& options) {
  double motion[6];
  const Eigen::AngleAxisd aa(H0.linear());
  const Vec3 w = aa.angle() * aa.axis();
  for (int k = 0; k < 3; ++k) {
    motion[k] = w(k);
    motion[3 + k] = H0.translation()(k);
  }
  ceres::Problem::Options problem_options;
  problem_options.loss_function_ownership = ceres::DO_NOT_TAKE_OWNERSHIP;
  ceres::Problem problem(problem_options);
  ceres::HuberLoss loss(options.huber_px);
  for (size_t i = 0; i < p_prev_world.size(); ++i) {
    if (!inlier[i]) continue;
    const double z = i < depth_m.size() ? depth_m[i] : 0.0;
    problem.AddResidualBlock(
        new ceres::AutoDiffCostFunction<MovedPointCost, 3, 6>(
            new MovedPointCost(p_prev_world[i], pixels[i], T_camera_world, camera, z)),
        &loss, motion);
  }
  ceres::Solver::Options solver;
  solver.linear_solver_type = ceres::DENSE_QR;
  solver.max_num_iterations = options.refine_iterations;
  solver.num_threads = 1;
  solver.logging_type = ceres::SILENT;
  ceres::Solver::Summary summary;
  ceres::Solve(solver, &problem, &summary);
  SE3 H = SE3::Identity();
  const Vec3 w1(motion[0], motion[1], motion[2]);
  const double angle = w1.norm();
  if (angle > 1e-12) H.linear() = Eigen::AngleAxisd(angle, w1 / angle).toRotationMatrix();
  H.translation() = Vec3(motion[3], motion[4], motion[5]);
  return H;
}

}  // namespace

Vec3 centroidDisplacement(const SE3& H_world, const Vec3& c_world) {
  return H_world.translation() - (Mat3::Identity() - H_world.linear()) * c_world;
}

Vec3 inlierCentroidVelocity(const ObjectMotion& motion, const std::vector<Vec3>& p_prev_world,
                            double dt_s) {
  Vec3 c = Vec3::Zero();
  for (size_t i = 0; i < motion.inlier.size(); ++i)
    if (motion.inlier[i]) c += p_prev_world[i];
  c /= double(motion.inliers);
  return centroidDisplacement(motion.H_world, c) / dt_s;  // v = (t - (I - R) c) / dt
}

ObjectMotion estimateObjectMotion(const std::vector<Vec3>& p_prev_world,
                                  const std::vector<Eigen::Vector2d>& pixels,
                                  const SE3& T_camera_world, const PinholeCamera& camera,
                                  const SE3& prior, const ObjectMotionOptions& options,
                                  const std::vector<double>& depth_m) {
  ObjectMotion out;
  const int n = static_cast<int>(p_prev_world.size());
  if (n < options.min_points || pixels.size() != p_prev_world.size()) return out;
  // Hypothesis 1: the object keeps moving as it did (constant motion prior).
  std::vector<uint8_t> prior_inlier;
  const int prior_inliers = countInliers(p_prev_world, pixels, T_camera_world * prior, camera,
                                         options.reprojection_px, prior_inlier);
  // Hypothesis 2: EPnP in RANSAC; its pose is T_camera_world * H.
  PnpRansacOptions pnp;
  pnp.iterations = options.ransac_iterations;
  pnp.reprojection_px = options.reprojection_px;
  pnp.min_inliers = options.min_points;
  pnp.seed = options.seed;
  const PnpRansacResult ransac = solvePnpRansac(p_prev_world, pixels, camera, pnp);
  SE3 H = prior;
  std::vector<uint8_t> inlier = prior_inlier;
  int inliers = prior_inliers;
  out.from_prior = true;
  if (ransac.ok) {
    const SE3 H_ransac = T_camera_world.inverse() * ransac.T_camera_world;
    std::vector<uint8_t> ransac_inlier;
    const int ransac_inliers = countInliers(p_prev_world, pixels, ransac.T_camera_world, camera,
                                            options.reprojection_px, ransac_inlier);
    if (ransac_inliers > prior_inliers) {
      H = H_ransac;
      inlier = std::move(ransac_inlier);
      inliers = ransac_inliers;
      out.from_prior = false;
    }
  }
  if (inliers < options.min_points) return out;
  H = refine(p_prev_world, pixels, depth_m, inlier, T_camera_world, camera, H, options);
  out.inliers = countInliers(p_prev_world, pixels, T_camera_world * H, camera,
                             options.reprojection_px, out.inlier);
  out.H_world = H;
  out.ok = out.inliers >= options.min_points;
  return out;
}

}  // namespace dynanav
