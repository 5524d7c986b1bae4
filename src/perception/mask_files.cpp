#include "perception/mask_files.hpp"

#include <spdlog/spdlog.h>

#include <algorithm>
#include <fstream>
#include <nlohmann/json.hpp>
#include <opencv2/imgcodecs.hpp>
#include <opencv2/imgproc.hpp>
#include <set>

#include "core/error.hpp"
#include "io/json_io.hpp"

namespace fs = std::filesystem;

namespace dynanav {

std::map<uint16_t, std::string> readMaskClasses(const fs::path& masks_json) {
  std::ifstream in(masks_json);
  if (!in) throw InputError(masks_json.string(), "cannot open the mask class file");
  nlohmann::json doc;
  try {
    doc = nlohmann::json::parse(in);
  } catch (const nlohmann::json::exception& e) {
    throw InputError(masks_json.string(), std::string("not valid JSON: ") + e.what());
  }
  if (!doc.is_object() || !doc.contains("instances") || !doc["instances"].is_object())
    throw InputError(masks_json.string(), "expected {\"instances\": {\"<id>\": {\"class\": ...}}}");
  std::map<uint16_t, std::string> classes;
  for (const auto& [key, value] : doc["instances"].items()) {
    int id = 0;
    try {
      size_t used = 0;
      id = std::stoi(key, &used);
      if (used != key.size()) id = 0;
    } catch (const std::exception&) {
      id = 0;
    }
    if (id < 1 || id > 65535)
      throw InputError(masks_json.string(), "instance id '" + key + "' is not in 1..65535");
    if (!value.is_object() || !value.contains("class") || !value["class"].is_string())
      throw InputError(masks_json.string(), "instance '" + key + "' has no \"class\" string");
    classes[uint16_t(id)] = value["class"].get<std::string>();
  }
  return classes;
}

Instances readMaskPng(const fs::path& png, const std::map<uint16_t, std::string>& classes, cv::Size expected) {
  if (!fs::is_regular_file(png)) throw InputError(png.string(), "mask file not found");
  const cv::Mat labels = cv::imread(png.string(), cv::IMREAD_UNCHANGED);
  if (labels.empty()) throw InputError(png.string(), "cannot decode the mask PNG");
  if (labels.type() != CV_16UC1)
    throw InputError(png.string(), "mask must be a 16-bit single-channel PNG (instance ids)");
  if (!expected.empty() && labels.size() != expected)
    throw InputError(png.string(), cv::format("mask is %dx%d, the frame %dx%d", labels.cols, labels.rows,
                                              expected.width, expected.height));
  Instances out;
  out.labels = labels;
  std::set<uint16_t> ids;
  for (int y = 0; y < labels.rows; ++y) {
    const auto* row = labels.ptr<uint16_t>(y);
    for (int x = 0; x < labels.cols; ++x)
      if (row[x]) ids.insert(row[x]);
  }
  for (uint16_t id : ids) {
    Instance item;
    item.id = id;
    const auto it = classes.find(id);
    item.class_name = it == classes.end() ? "object" : it->second;
    item.score = 1.f;
    item.mask_source = "file";
    out.items.push_back(item);
  }
  tightenToLabels(out);
  return out;
}

MaskFolderWriter::MaskFolderWriter(const fs::path& out_dir) : dir_(out_dir) {
  fs::create_directories(dir_ / "masks");
}

Instances MaskFolderWriter::write(const std::string& stem, const Instances& instances) {
  Instances out;
  out.labels = cv::Mat::zeros(instances.labels.size(), CV_16U);
  std::set<uint16_t> used;
  for (const Instance& item : instances.items) {
    uint16_t id = 0;
    for (const auto& [known_id, name] : classes_)
      if (name == item.class_name && !used.count(known_id)) {
        id = known_id;
        break;
      }
    if (id == 0) {
      id = uint16_t(classes_.empty() ? 1 : classes_.rbegin()->first + 1);
      classes_[id] = item.class_name;
    }
    used.insert(id);
    out.labels.setTo(cv::Scalar(id), instances.labels == item.id);
    Instance copy = item;
    copy.id = id;
    out.items.push_back(copy);
  }
  std::sort(out.items.begin(), out.items.end(), [](const Instance& a, const Instance& b) { return a.id < b.id; });
  const fs::path png = dir_ / "masks" / (stem + ".png");
  if (!cv::imwrite(png.string(), out.labels)) throw InputError(png.string(), "cannot write the mask PNG");
  return out;
}

void MaskFolderWriter::finish() {
  nlohmann::ordered_json instances = nlohmann::ordered_json::object();  // ids in numeric order
  for (const auto& [id, name] : classes_) instances[std::to_string(id)] = {{"class", name}};
  writeTextFile(dir_ / "masks.json", nlohmann::ordered_json{{"instances", instances}}.dump(2) + "\n");
  finished_ = true;
}

MaskFolderWriter::~MaskFolderWriter() {
  if (finished_) return;
  try {
    finish();
  } catch (const std::exception& e) {
    spdlog::error("cannot write {}: {}", (dir_ / "masks.json").string(), e.what());
  }
}

Instances addMaskNoise(const Instances& clean, const MaskNoise& noise, int frame_index) {
  if (!noise.active()) return clean;
  Instances out = Instances::none(clean.labels.size());
  const cv::Mat kernel = noise.grow_px == 0
                             ? cv::Mat()
                             : cv::getStructuringElement(cv::MORPH_ELLIPSE,
                                                         cv::Size(2 * std::abs(noise.grow_px) + 1,
                                                                  2 * std::abs(noise.grow_px) + 1));
  for (const Instance& item : clean.items) {
    std::seed_seq seq{noise.seed, frame_index, int(item.id)};
    std::mt19937 rng(seq);
    std::uniform_real_distribution<double> unit(0.0, 1.0);
    if (unit(rng) < noise.drop_share) continue;
    cv::Mat m = clean.mask(item.id);
    if (noise.grow_px > 0) cv::dilate(m, m, kernel);
    if (noise.grow_px < 0) cv::erode(m, m, kernel);
    if (noise.shift_px != 0) {
      std::uniform_int_distribution<int> offset(-std::abs(noise.shift_px), std::abs(noise.shift_px));
      const int dx = offset(rng), dy = offset(rng);
      const cv::Matx23d shift(1, 0, dx, 0, 1, dy);
      cv::warpAffine(m, m, shift, m.size(), cv::INTER_NEAREST, cv::BORDER_CONSTANT, cv::Scalar());
    }
    // Painted in id order onto background only; grown masks also keep off their neighbours'
    // original pixels, so growing one instance does not eat another.
    cv::Mat allowed = out.labels == 0;
    if (noise.grow_px > 0) allowed &= (clean.labels == 0) | (clean.labels == item.id);
    out.labels.setTo(cv::Scalar(item.id), m & allowed);
    out.items.push_back(item);
  }
  tightenToLabels(out);
  return out;
}

MaskFileSegmenter::MaskFileSegmenter(const fs::path& sequence_dir, const MaskNoise& noise)
    : dir_(sequence_dir), noise_(noise) {
  if (!fs::is_directory(dir_ / "masks"))
    throw InputError((dir_ / "masks").string(), "mask folder not found (needed by --segmenter masks)");
  classes_ = readMaskClasses(dir_ / "masks.json");
}

Instances MaskFileSegmenter::segment(const RgbdFrame& frame) {
  const std::string stem = fs::path(frame.rgb_path).stem().string();
  if (stem.empty()) throw InputError(dir_.string(), "the masks segmenter needs frames read from files");
  const Instances clean = readMaskPng(dir_ / "masks" / (stem + ".png"), classes_, frame.bgr.size());
  return addMaskNoise(clean, noise_, frame.index);
}

}  // namespace dynanav
