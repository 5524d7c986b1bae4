#include "mapping/dense_cloud.hpp"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <fstream>
#include <sstream>

#include "core/error.hpp"

namespace dynanav {
namespace {

struct VoxelSum {
  Eigen::Vector3d p = Eigen::Vector3d::Zero();
  Eigen::Vector3d bgr = Eigen::Vector3d::Zero();
  int n = 0;
};

/// 21 bits per axis (±10 km at 1 cm) packed into one key.
uint64_t voxelKey(const Eigen::Vector3f& p, double inv_voxel) {
  auto axis = [&](float v) {
    return uint64_t(int64_t(std::floor(double(v) * inv_voxel)) + (1 << 20)) & 0x1fffff;
  };
  return axis(p.x()) | (axis(p.y()) << 21) | (axis(p.z()) << 42);
}

}  // namespace

ColouredCloud denseCloud(const std::vector<PosedKeyframe>& keyframes, const cv::Mat& rays,
                         int pixel_step, double voxel_m) {
  const int step = std::max(1, pixel_step);
  const double inv_voxel = 1.0 / voxel_m;
  // Every sample with its voxel key, then one sort: several times faster than a hash map for
  // millions of samples, and the output order (by key) is deterministic.
  struct Sample {
    uint64_t key;
    Eigen::Vector3f p;
    cv::Vec3b bgr;
  };
  std::vector<Sample> samples;
  for (const PosedKeyframe& posed : keyframes) {
    const MapKeyframe& kf = *posed.keyframe;
    const Eigen::Matrix3f R = posed.T_world_camera.linear().cast<float>();
    const Eigen::Vector3f t = posed.T_world_camera.translation().cast<float>();
    const int rows = std::min(kf.depth_m.rows, rays.rows),
              cols = std::min(kf.depth_m.cols, rays.cols);
    samples.reserve(samples.size() + size_t(rows / step + 1) * size_t(cols / step + 1));
    for (int y = 0; y < rows; y += step) {
      const float* depth = kf.depth_m.ptr<float>(y);
      const cv::Vec2f* ray = rays.ptr<cv::Vec2f>(y);
      const cv::Vec3b* colour = kf.bgr.ptr<cv::Vec3b>(y);
      for (int x = 0; x < cols; x += step) {
        const float z = depth[x];
        if (!(z > 0.0f)) continue;
        const Eigen::Vector3f p = R * Eigen::Vector3f(ray[x][0] * z, ray[x][1] * z, z) + t;
        samples.push_back({voxelKey(p, inv_voxel), p, colour[x]});
      }
    }
  }
  std::sort(samples.begin(), samples.end(),
            [](const Sample& a, const Sample& b) { return a.key < b.key; });
  ColouredCloud cloud;
  for (size_t i = 0; i < samples.size();) {
    VoxelSum v;
    size_t j = i;
    for (; j < samples.size() && samples[j].key == samples[i].key; ++j) {
      v.p += samples[j].p.cast<double>();
      v.bgr += Eigen::Vector3d(samples[j].bgr[0], samples[j].bgr[1], samples[j].bgr[2]);
      ++v.n;
    }
    i = j;
    cloud.p_world.push_back((v.p / v.n).cast<float>());
    const Eigen::Vector3d c = v.bgr / v.n;
    cloud.bgr.emplace_back(uchar(std::lround(c.x())), uchar(std::lround(c.y())),
                           uchar(std::lround(c.z())));
  }
  return cloud;
}

ColouredCloud filterCloud(const ColouredCloud& cloud,
                          const std::function<bool(const Eigen::Vector3f&)>& drop) {
  ColouredCloud out;
  for (size_t i = 0; i < cloud.size(); ++i) {
    if (drop(cloud.p_world[i])) continue;
    out.p_world.push_back(cloud.p_world[i]);
    out.bgr.push_back(cloud.bgr[i]);
  }
  return out;
}

void writePly(const std::filesystem::path& path, const ColouredCloud& cloud) {
  std::ofstream out(path, std::ios::binary);
  if (!out) throw InputError(path.string(), "cannot write");
  out << "ply\nformat binary_little_endian 1.0\ncomment dynanav static map (world = first camera, "
         "y down, metres)\nelement vertex "
      << cloud.size()
      << "\nproperty float x\nproperty float y\nproperty float z\nproperty uchar red\nproperty "
         "uchar green\nproperty uchar blue\nend_header\n";
  std::vector<char> buffer(cloud.size() * 15);
  for (size_t i = 0; i < cloud.size(); ++i) {
    char* rec = buffer.data() + i * 15;
    std::memcpy(rec, cloud.p_world[i].data(), 12);  // x86 and ARM are little-endian
    rec[12] = char(cloud.bgr[i][2]);
    rec[13] = char(cloud.bgr[i][1]);
    rec[14] = char(cloud.bgr[i][0]);
  }
  out.write(buffer.data(), std::streamsize(buffer.size()));
  if (!out) throw InputError(path.string(), "write failed");
}

ColouredCloud readPly(const std::filesystem::path& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw InputError(path.string(), "cannot open");
  std::string line;
  size_t count = 0;
  bool binary = false;
  while (std::getline(in, line)) {
    if (line.rfind("format binary_little_endian", 0) == 0) binary = true;
    if (line.rfind("element vertex ", 0) == 0) count = std::stoul(line.substr(15));
    if (line == "end_header") break;
  }
  if (!binary || line != "end_header")
    throw InputError(path.string(), "not a binary little-endian PLY written by dynanav");
  std::vector<char> buffer(count * 15);
  in.read(buffer.data(), std::streamsize(buffer.size()));
  if (size_t(in.gcount()) != buffer.size()) throw InputError(path.string(), "truncated PLY");
  ColouredCloud cloud;
  cloud.p_world.resize(count);
  cloud.bgr.resize(count);
  for (size_t i = 0; i < count; ++i) {
    const char* rec = buffer.data() + i * 15;
    std::memcpy(cloud.p_world[i].data(), rec, 12);
    cloud.bgr[i] = {uchar(rec[14]), uchar(rec[13]), uchar(rec[12])};
  }
  return cloud;
}

}  // namespace dynanav
