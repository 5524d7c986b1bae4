#include "io/sequence.hpp"

#include <spdlog/spdlog.h>
#include <algorithm>
#include <opencv2/imgcodecs.hpp>
#include <tuple>

#include "core/error.hpp"
#include "io/camera_yaml.hpp"
#include "io/image_file.hpp"
#include "io/text_lines.hpp"

namespace fs = std::filesystem;

namespace dynanav {

std::vector<StampedFile> readStampedFileList(const fs::path& list_file) {
  std::vector<StampedFile> files;
  for (const auto& line : readContentLines(list_file)) {
    const auto fields = splitFields(line.text);
    StampedFile entry;
    if (fields.size() != 2 || !parseFiniteDouble(fields[0], entry.stamp_s)) {
      throw InputError(where(list_file, line.number),
                       "expected 'timestamp path', got '" + line.text + "'");
    }
    entry.relative_path = fields[1];
    entry.line = line.number;
    if (!files.empty() && entry.stamp_s <= files.back().stamp_s) {
      throw InputError(where(list_file, line.number),
                       entry.stamp_s == files.back().stamp_s
                           ? "duplicate timestamp " + fields[0]
                           : "timestamps not sorted (" + fields[0] + " after line " +
                                 std::to_string(files.back().line) + ")");
    }
    files.push_back(std::move(entry));
  }
  if (files.empty()) throw InputError(list_file.string(), "lists no images");
  return files;
}

std::vector<FramePair> associate(const std::vector<StampedFile>& rgb,
                                 const std::vector<StampedFile>& depth, double max_dt_s) {
  // associate.py: all pairs closer than max_dt, taken greedily by smallest gap, then sorted by
  // colour time. Both lists are sorted, so candidates come from a window search.
  std::vector<std::tuple<double, size_t, size_t>> candidates;
  size_t lo = 0;
  for (size_t i = 0; i < rgb.size(); ++i) {
    while (lo < depth.size() && depth[lo].stamp_s <= rgb[i].stamp_s - max_dt_s) ++lo;
    for (size_t j = lo; j < depth.size() && depth[j].stamp_s < rgb[i].stamp_s + max_dt_s; ++j) {
      const double gap = std::abs(rgb[i].stamp_s - depth[j].stamp_s);
      if (gap < max_dt_s) candidates.emplace_back(gap, i, j);
    }
  }
  std::sort(candidates.begin(), candidates.end());
  std::vector<bool> rgb_used(rgb.size(), false), depth_used(depth.size(), false);
  std::vector<std::pair<size_t, size_t>> matches;
  for (const auto& [gap, i, j] : candidates) {
    if (rgb_used[i] || depth_used[j]) continue;
    rgb_used[i] = depth_used[j] = true;
    matches.emplace_back(i, j);
  }
  std::sort(matches.begin(), matches.end());
  std::vector<FramePair> pairs;
  pairs.reserve(matches.size());
  for (const auto& [i, j] : matches) pairs.push_back({rgb[i], depth[j]});
  return pairs;
}

cv::Mat readDepthPng(const fs::path& path, double depth_factor, cv::Size expected_size) {
  const cv::Mat raw = readImageFile(path, cv::IMREAD_UNCHANGED, "depth image");
  if (raw.type() != CV_16UC1) {
    throw InputError(path.string(), "depth image must be 16-bit single-channel, got type " +
                                        cv::typeToString(raw.type()));
  }
  if (!expected_size.empty() && raw.size() != expected_size) {
    throw InputError(path.string(), "depth image is " + std::to_string(raw.cols) + "x" +
                                        std::to_string(raw.rows) + ", colour image is " +
                                        std::to_string(expected_size.width) + "x" +
                                        std::to_string(expected_size.height));
  }
  cv::Mat depth_m;
  raw.convertTo(depth_m, CV_32F, 1.0 / depth_factor);
  return depth_m;
}

void writeDepthPng(const fs::path& path, const cv::Mat& depth_m, double depth_factor) {
  CV_Assert(depth_m.type() == CV_32FC1);
  cv::Mat raw(depth_m.size(), CV_16UC1);
  for (int v = 0; v < depth_m.rows; ++v) {
    const float* src = depth_m.ptr<float>(v);
    auto* dst = raw.ptr<uint16_t>(v);
    for (int u = 0; u < depth_m.cols; ++u) {
      const double value = validDepth(src[u]) ? std::round(src[u] * depth_factor) : 0.0;
      dst[u] = value > 65535.0 ? 0 : static_cast<uint16_t>(value);
    }
  }
  if (!cv::imwrite(path.string(), raw)) throw InputError(path.string(), "cannot write depth image");
}

TumSequence TumSequence::open(const fs::path& dir, const IoConfig& config,
                              const std::optional<PinholeCamera>& fallback_camera) {
  if (!fs::is_directory(dir)) throw InputError(dir.string(), "sequence folder not found");
  TumSequence seq;
  seq.dir_ = dir;
  const fs::path camera_file = dir / "camera.yaml";
  // The folder name identifies TUM/Bonn sequences (rgbd_dataset_freiburg1_xyz, rgbd_bonn_crowd).
  const std::string folder_name = fs::absolute(dir).lexically_normal().filename().string();
  if (fs::exists(camera_file)) {
    seq.camera_ = loadCameraYaml(camera_file);
    seq.camera_source_ = "camera.yaml";
  } else if (PinholeCamera::fromSequenceName(folder_name, seq.camera_)) {
    seq.camera_source_ = "folder name";
  } else if (fallback_camera) {
    seq.camera_ = *fallback_camera;
    seq.camera_source_ = "config";
  } else {
    throw InputError(dir.string(),
                     "no camera calibration: add camera.yaml, name the folder after "
                     "freiburg1|2|3 or bonn, or pass --config with a camera");
  }
  const auto rgb = readStampedFileList(dir / "rgb.txt");
  const auto depth = readStampedFileList(dir / "depth.txt");
  seq.pairs_ = associate(rgb, depth, config.max_association_dt_s);
  if (seq.pairs_.empty()) {
    throw InputError(dir.string(), "no colour image has a depth image within " +
                                       std::to_string(config.max_association_dt_s) + " s");
  }
  spdlog::debug("{}: {} colour, {} depth, {} associated pairs; camera from {}", dir.string(),
                rgb.size(), depth.size(), seq.pairs_.size(), seq.camera_source_);
  return seq;
}

std::optional<fs::path> TumSequence::groundTruthPath() const {
  const fs::path gt = dir_ / "groundtruth.txt";
  return fs::exists(gt) ? std::optional<fs::path>(gt) : std::nullopt;
}

RgbdFrame TumSequence::load(size_t i) const {
  const FramePair& pair = pairs_.at(i);
  RgbdFrame frame;
  frame.index = static_cast<int>(i);
  frame.stamp_s = pair.rgb.stamp_s;
  frame.depth_stamp_s = pair.depth.stamp_s;
  frame.rgb_path = (dir_ / pair.rgb.relative_path).string();
  frame.depth_path = (dir_ / pair.depth.relative_path).string();
  frame.bgr = readImageFile(frame.rgb_path, cv::IMREAD_COLOR, "colour image");
  if (frame.bgr.cols != camera_.width || frame.bgr.rows != camera_.height) {
    throw InputError(frame.rgb_path, "image is " + std::to_string(frame.bgr.cols) + "x" +
                                         std::to_string(frame.bgr.rows) + ", camera expects " +
                                         std::to_string(camera_.width) + "x" +
                                         std::to_string(camera_.height));
  }
  if (const std::string problem = colourFrameProblem(frame.bgr); !problem.empty())
    throw InputError(frame.rgb_path, "colour image is " + problem);
  frame.depth_m = readDepthPng(frame.depth_path, camera_.depth_factor, frame.bgr.size());
  if (cv::countNonZero(frame.depth_m) == 0)
    throw InputError(frame.depth_path, "depth image has no valid pixel (all 0)");
  return frame;
}

}  // namespace dynanav
