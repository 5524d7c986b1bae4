#include "eval/mask_scores.hpp"

#include <algorithm>
#include <cstdio>
#include <map>
#include <opencv2/imgcodecs.hpp>
#include <opencv2/imgproc.hpp>

#include "core/error.hpp"
#include "io/json_io.hpp"

namespace dynanav {

namespace fs = std::filesystem;

namespace {
std::set<uint16_t> personIds(const fs::path& masks_json) {
  const nlohmann::json j = readJsonFile(masks_json);
  std::set<uint16_t> ids;
  try {
    for (const auto& [key, value] : j.at("instances").items())
      if (value.at("class").get<std::string>() == "person") ids.insert(uint16_t(std::stoi(key)));
  } catch (const std::exception& e) {
    throw InputError(masks_json.string(), std::string("not a masks.json: ") + e.what());
  }
  return ids;
}

cv::Mat readLabels(const fs::path& png) {
  const cv::Mat m = cv::imread(png.string(), cv::IMREAD_UNCHANGED);
  if (m.empty() || m.type() != CV_16UC1)
    throw InputError(png.string(), "missing or not a 16-bit instance mask");
  return m;
}

double median(std::vector<double> v) {
  if (v.empty()) return 0.0;
  std::sort(v.begin(), v.end());
  const size_t n = v.size();
  return n % 2 ? v[n / 2] : 0.5 * (v[n / 2 - 1] + v[n / 2]);
}

std::string stampStem(double t) {
  char buffer[32];
  std::snprintf(buffer, sizeof buffer, "%.6f", t);
  return buffer;
}
}  // namespace

double bestPersonIou(const cv::Mat& truth_mask, const cv::Mat& labels,
                     const std::set<uint16_t>& person_ids) {
  CV_Assert(truth_mask.type() == CV_8UC1 && labels.type() == CV_16UC1 &&
            truth_mask.size() == labels.size());
  std::map<uint16_t, int> area, overlap;
  int truth_px = 0;
  for (int y = 0; y < labels.rows; ++y) {
    const uint16_t* l = labels.ptr<uint16_t>(y);
    const uint8_t* t = truth_mask.ptr<uint8_t>(y);
    for (int x = 0; x < labels.cols; ++x) {
      truth_px += t[x] != 0;
      if (l[x] == 0 || !person_ids.count(l[x])) continue;
      ++area[l[x]];
      if (t[x]) ++overlap[l[x]];
    }
  }
  double best = 0.0;
  for (const auto& [id, inter] : overlap)
    best = std::max(best, double(inter) / double(truth_px + area[id] - inter));
  return best;
}

MaskScoreSummary scorePersonMasks(const fs::path& sim_dir, const fs::path& seg_dir,
                                  const MaskScoreOptions& options) {
  const std::set<uint16_t> truth_people = personIds(sim_dir / "masks.json");
  const std::set<uint16_t> found_people = personIds(seg_dir / "masks.json");
  const auto frames = readJsonLines(sim_dir / "objects_gt.jsonl");
  MaskScoreSummary summary;
  std::vector<double> found_iou, all_iou;
  for (const nlohmann::json& frame : frames) {
    const std::string stem = stampStem(frame.at("t").get<double>());
    std::vector<std::pair<int, double>> candidates;  // (id, in_view) with pixels in view
    for (const auto& o : frame.at("objects")) {
      if (!truth_people.count(uint16_t(o.at("id").get<int>())) || o.at("points").get<int>() == 0)
        continue;
      if (!o.contains("in_view"))
        throw InputError((sim_dir / "objects_gt.jsonl").string(),
                         "no `in_view` field: simulate the sequence again with this version");
      candidates.emplace_back(o.at("id").get<int>(), o.at("in_view").get<double>());
    }
    ++summary.frames;
    if (candidates.empty()) continue;
    const cv::Mat truth = readLabels(sim_dir / "masks" / (stem + ".png"));
    const cv::Mat labels = readLabels(seg_dir / "masks" / (stem + ".png"));
    if (truth.size() != labels.size())
      throw InputError((seg_dir / "masks" / (stem + ".png")).string(), "size differs from truth");
    for (const auto& [id, in_view] : candidates) {
      const cv::Mat mask = truth == id;
      const cv::Rect box = cv::boundingRect(mask);
      if (in_view < options.min_in_view || box.height < options.min_height_px) continue;
      PersonMaskScore s{stem, id, in_view, box.height, bestPersonIou(mask, labels, found_people)};
      all_iou.push_back(s.iou);
      if (s.iou >= options.match_iou) {
        ++summary.found;
        found_iou.push_back(s.iou);
      }
      summary.scored.push_back(s);
    }
  }
  summary.median_iou_found = median(found_iou);
  summary.median_iou_all = median(all_iou);
  return summary;
}

}  // namespace dynanav
