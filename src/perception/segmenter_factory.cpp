#include <spdlog/spdlog.h>

#include "core/error.hpp"
#include "io/json_io.hpp"
#include "perception/instance_memory.hpp"
#include "perception/lagged_segmenter.hpp"
#include "perception/mask_files.hpp"
#include "perception/model_files.hpp"
#include "perception/propagation.hpp"
#include "perception/segmenters.hpp"

namespace fs = std::filesystem;

namespace dynanav {
namespace {

std::string joined(const std::vector<fs::path>& dirs) {
  std::string out;
  for (const auto& d : dirs) out += (out.empty() ? "" : ", ") + d.string();
  return out;
}

/// The models folder for `dnn`, or InputError naming the first missing file.
fs::path dnnModelsDir(const PerceptionConfig& config) {
  const auto files = dnnModelFiles(config.keypoints);
  fs::path dir = findDnnModelsDir(config.models_dir, config.keypoints);
  if (!dir.empty()) return dir;
  const auto search = modelSearchPath(config.models_dir);
  if (!config.models_dir.empty()) {
    for (const auto& f : files) requireModelFile(config.models_dir, f);  // throws naming the file
  }
  throw InputError(files.front(),
                   "model file not found in any of: " + joined(search) + " (nor the npm set with " +
                       std::string(model_files::kMultiPose) +
                       "; get the models with scripts/fetch_models.sh DIR, then pass "
                       "--models DIR or set DYNANAV_MODELS)");
}

std::unique_ptr<Segmenter> makeProvider(const SegmenterRequest& request,
                                        const PerceptionConfig& config) {
  const std::string& name = request.name;
  if (name == "none") return std::make_unique<NoneSegmenter>();
  if (name == "hog") return std::make_unique<HogSegmenter>(config);
  if (name == "dnn") return std::make_unique<DnnSegmenter>(dnnModelsDir(config), config);
  if (name == "masks") {
    if (request.sequence_dir.empty())
      throw InputError("--segmenter masks", "needs a sequence folder");
    const MaskNoise noise{config.mask_noise_grow_px, config.mask_noise_drop_share,
                          config.mask_noise_shift_px, config.mask_noise_seed};
    return std::make_unique<MaskFileSegmenter>(request.sequence_dir, noise);
  }
  if (name == "auto") {
    const fs::path dir = findDnnModelsDir(config.models_dir, config.keypoints);
    if (!dir.empty()) {
      spdlog::info("segmenter auto: dnn with the models in {}", dir.string());
      return std::make_unique<DnnSegmenter>(dir, config);
    }
    spdlog::warn(
        "segmenter auto: model files not found in {}; falling back to hog (fewer, looser "
        "person masks). Get them with scripts/fetch_models.sh and pass --models DIR.",
        joined(modelSearchPath(config.models_dir)));
    return std::make_unique<HogSegmenter>(config);
  }
  throw InputError("--segmenter",
                   "unknown segmenter '" + name + "' (use auto, dnn, hog, masks or none)");
}

/// `segmentation_arrivals` of a real-time run's stats.json: [[segmented, arrived_on], ...].
std::map<int, int> readArrivals(const fs::path& stats_json) {
  const nlohmann::json stats = readJsonFile(stats_json);
  const auto it = stats.find("segmentation_arrivals");
  if (it == stats.end() || !it->is_array() || it->empty())
    throw InputError(stats_json, "no segmentation_arrivals (not a real-time run's stats.json?)");
  std::map<int, int> arrivals;
  for (const auto& pair : *it) {
    if (!pair.is_array() || pair.size() != 2 || !pair[0].is_number_integer() ||
        !pair[1].is_number_integer() || pair[1].get<int>() < pair[0].get<int>())
      throw InputError(stats_json,
                       "segmentation_arrivals: expected [segmented, arrived_on] "
                       "frame index pairs, arrived_on >= segmented");
    arrivals[pair[0].get<int>()] = pair[1].get<int>();
  }
  return arrivals;
}

}  // namespace

std::unique_ptr<Segmenter> makeSegmenter(const SegmenterRequest& request,
                                         const PerceptionConfig& config) {
  if (request.segment_every < 1)
    throw InputError("--segment-every",
                     "must be at least 1, got " + std::to_string(request.segment_every));
  std::unique_ptr<Segmenter> segmenter = makeProvider(request, config);
  if (request.name == "none") return segmenter;
  if (request.segment_every > 1)
    segmenter =
        std::make_unique<PropagatingSegmenter>(std::move(segmenter), request.segment_every, config);
  if (config.mask_memory_frames > 0)
    segmenter = std::make_unique<RememberingSegmenter>(std::move(segmenter),
                                                       config.mask_memory_frames, config);
  if (!config.replay_arrivals.empty())
    return std::make_unique<LaggedSegmenter>(std::move(segmenter),
                                             readArrivals(config.replay_arrivals), config);
  if (config.emulated_lag_frames > 0)
    segmenter =
        std::make_unique<LaggedSegmenter>(std::move(segmenter), config.emulated_lag_frames, config);
  return segmenter;
}

}  // namespace dynanav
