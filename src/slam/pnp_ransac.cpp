#include "slam/pnp_ransac.hpp"

#include <opencv2/calib3d.hpp>
#include <opencv2/core/eigen.hpp>

namespace dynanav {

PnpRansacResult solvePnpRansac(const std::vector<Vec3>& p_world,
                               const std::vector<Eigen::Vector2d>& pixels,
                               const PinholeCamera& camera, const PnpRansacOptions& options) {
  PnpRansacResult result;
  result.inlier.assign(p_world.size(), 0);
  if (p_world.size() < 6 || p_world.size() != pixels.size()) return result;
  std::vector<cv::Point3d> object;
  std::vector<cv::Point2d> image;
  object.reserve(p_world.size());
  image.reserve(pixels.size());
  for (size_t i = 0; i < p_world.size(); ++i) {
    object.emplace_back(p_world[i].x(), p_world[i].y(), p_world[i].z());
    image.emplace_back(pixels[i].x(), pixels[i].y());
  }
  // solvePnPRansac samples with cv::theRNG(); seeding it keeps relocalisation deterministic.
  cv::theRNG().state = options.seed;
  cv::Mat rvec, tvec;
  std::vector<int> inliers;
  const bool ok = cv::solvePnPRansac(
      object, image, camera.K(), cv::noArray(), rvec, tvec, false, options.iterations,
      static_cast<float>(options.reprojection_px), 0.99, inliers, cv::SOLVEPNP_EPNP);
  if (!ok || static_cast<int>(inliers.size()) < options.min_inliers) return result;
  cv::Mat R_cv;
  cv::Rodrigues(rvec, R_cv);
  Mat3 R;
  cv::cv2eigen(R_cv, R);
  Vec3 t(tvec.at<double>(0), tvec.at<double>(1), tvec.at<double>(2));
  result.T_camera_world = makeSE3(Quat(R), t);
  for (const int i : inliers) result.inlier[i] = 1;
  result.inliers = static_cast<int>(inliers.size());
  result.ok = true;
  return result;
}

}  // namespace dynanav
