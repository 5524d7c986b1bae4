#include "eval/moving_flags.hpp"

#include <algorithm>
#include <fstream>
#include <limits>
#include <map>
#include <nlohmann/json.hpp>

#include "core/error.hpp"

namespace dynanav {

ObjectTruthFrames readObjectTruth(const std::filesystem::path& path) {
  std::ifstream in(path);
  if (!in)
    throw InputError(path.string(), "cannot open (a simulated sequence has objects_gt.jsonl)");
  ObjectTruthFrames frames;
  int line_no = 0;
  for (std::string line; std::getline(in, line);) {
    ++line_no;
    if (line.empty()) continue;
    const std::string where = path.string() + ":" + std::to_string(line_no);
    std::vector<ObjectTruth> objects;
    try {
      const nlohmann::json frame = nlohmann::json::parse(line);
      for (const auto& o : frame.at("objects"))
        objects.push_back({o.at("id").get<int>(), o.at("class").get<std::string>(),
                           o.at("dynamic").get<bool>(), o.at("points").get<int>()});
    } catch (const nlohmann::json::exception& e) {
      throw InputError(where, std::string("not an objects_gt frame: ") + e.what());
    }
    frames.push_back(std::move(objects));
  }
  return frames;
}

std::vector<std::vector<int>> readMovingFlags(const std::filesystem::path& stats_json) {
  std::ifstream in(stats_json);
  if (!in) throw InputError(stats_json.string(), "cannot open");
  try {
    const nlohmann::json stats = nlohmann::json::parse(in);
    const auto& dynamics = stats.at("dynamics");
    if (!dynamics.value("enabled", false) || !dynamics.contains("per_frame"))
      throw InputError(stats_json.string(), "the run had --dynamic off: no moving flags to score");
    return dynamics.at("per_frame").at("moving_ids").get<std::vector<std::vector<int>>>();
  } catch (const nlohmann::json::exception& e) {
    throw InputError(stats_json.string(), std::string("not a dynanav stats.json: ") + e.what());
  }
}

double MovingFlagScore::precision() const {
  const int flagged = true_positive + false_positive;
  return flagged ? double(true_positive) / flagged : std::numeric_limits<double>::quiet_NaN();
}

double MovingFlagScore::recall() const {
  const int moving = true_positive + false_negative;
  return moving ? double(true_positive) / moving : std::numeric_limits<double>::quiet_NaN();
}

std::vector<MovingFlagScore> scoreMovingFlags(const ObjectTruthFrames& truth,
                                              const std::vector<std::vector<int>>& flagged,
                                              int min_visible_px) {
  std::map<int, MovingFlagScore> scores;
  const size_t frames = std::min(truth.size(), flagged.size());
  for (size_t f = 0; f < frames; ++f) {
    for (const ObjectTruth& o : truth[f]) {
      MovingFlagScore& s = scores[o.id];
      s.id = o.id;
      s.class_name = o.class_name;
      if (o.visible_px < min_visible_px) {
        ++s.out_of_view;
        continue;
      }
      const bool flag = std::find(flagged[f].begin(), flagged[f].end(), o.id) != flagged[f].end();
      if (o.dynamic)
        ++(flag ? s.true_positive : s.false_negative);
      else
        ++(flag ? s.false_positive : s.true_negative);
    }
  }
  std::vector<MovingFlagScore> out;
  for (auto& [id, s] : scores) out.push_back(std::move(s));
  return out;
}

}  // namespace dynanav
