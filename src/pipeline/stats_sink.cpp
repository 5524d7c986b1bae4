// StatsSink: stats.json, assembled here from the records the pipeline returned (FrameResult)
// and the stage timers; no module builds JSON of its own.

#include <sys/resource.h>
#include <cmath>

#include "core/heap.hpp"
#include "io/json_io.hpp"
#include "pipeline/sinks.hpp"
#include "pipeline/system.hpp"
#include "slam/loop_closer.hpp"
#include "slam/slam_system.hpp"

namespace dynanav {
namespace {

/// CPU seconds (user + system, all threads) this process has used: a steadier throughput
/// measure than wall time on a shared machine.
double processCpuSeconds() {
  rusage usage{};
  getrusage(RUSAGE_SELF, &usage);
  return static_cast<double>(usage.ru_utime.tv_sec + usage.ru_stime.tv_sec) +
         1e-6 * static_cast<double>(usage.ru_utime.tv_usec + usage.ru_stime.tv_usec);
}

nlohmann::json timingJson(const TimingSummary& t) {
  return {{"mean", t.mean_ms},
          {"p95", t.p95_ms},
          {"max", t.max_ms},
          {"count", t.count},
          {"cpu_mean", t.cpu_mean_ms}};
}

/// Issue 7: dynamic keypoints and instances, means and per-frame series.
nlohmann::json dynamicsJson(const std::vector<FrameDynamics>& history, const std::string& segmenter,
                            bool enabled) {
  nlohmann::json out;
  out["enabled"] = enabled;
  out["segmenter"] = segmenter;
  const double n = std::max<size_t>(1, history.size());
  double kp = 0, dyn = 0, stat = 0, prior = 0, moving = 0, prior_moving = 0, prior_static = 0,
         masked = 0;
  int culled = 0, residual_regions = 0;
  nlohmann::json series = {{"dynamic_keypoints", nlohmann::json::array()},
                           {"static_keypoints", nlohmann::json::array()},
                           {"prior_instances", nlohmann::json::array()},
                           {"dynamic_instances", nlohmann::json::array()},
                           {"moving_ids", nlohmann::json::array()},
                           {"residual_regions", nlohmann::json::array()}};
  for (const FrameDynamics& f : history) {
    kp += f.keypoints;
    dyn += f.dynamic_keypoints;
    stat += f.static_keypoints;
    prior += f.prior_instances;
    moving += f.moving_instances;
    prior_moving += f.prior_moving;
    prior_static += f.prior_static;
    masked += f.masked_share;
    culled += f.culled_points;
    residual_regions += f.residual_regions;
    series["dynamic_keypoints"].push_back(f.dynamic_keypoints);
    series["static_keypoints"].push_back(f.static_keypoints);
    series["prior_instances"].push_back(f.prior_instances);
    series["dynamic_instances"].push_back(f.moving_instances + f.prior_moving);
    series["moving_ids"].push_back(f.moving_ids);
    series["residual_regions"].push_back(f.residual_regions);
  }
  out["mean_keypoints"] = kp / n;
  out["mean_dynamic_keypoints"] = dyn / n;
  out["mean_static_keypoints"] = stat / n;
  out["mean_prior_instances"] = prior / n;
  out["mean_dynamic_instances"] = (moving + prior_moving) / n;
  out["mean_moving_nonprior_instances"] = moving / n;
  out["mean_prior_moving"] = prior_moving / n;
  out["mean_prior_static"] = prior_static / n;
  out["mean_masked_share"] = masked / n;
  out["culled_points"] = culled;
  out["residual_regions"] = residual_regions;  // summed over frames
  out["per_frame"] = series;
  return out;
}

/// Issue 14: what the audio stage did; latency from a frame's arrival (real time) or its stamp
/// (deterministic: the wait for the channel only) to its message's start in the stream.
void addAudioJson(const AudioFeedbackStats& a, nlohmann::json& stats) {
  const TimingSummary latency = summarize(a.latency_ms);
  const TimingSummary length = summarize(a.message_s);
  const TimingSummary prepare = summarize(a.prepare_ms);
  const TimingSummary stage = summarize(a.stage_ms);
  auto figure = [&](double v) { return latency.count ? nlohmann::json(v) : nlohmann::json(); };
  stats["feedback_latency_ms"] = {{"mean", figure(latency.mean_ms)},
                                  {"p95", figure(latency.p95_ms)},
                                  {"max", figure(latency.max_ms)},
                                  {"count", latency.count}};  // null figures: no message played
  stats["feedback_audio"] = {
      {"output", a.output},
      {"messages", a.scheduler.offered + a.dropped_queue},
      {"rendered", a.scheduler.played},
      {"dropped_stale", a.scheduler.dropped_stale},
      {"dropped_busy", a.scheduler.dropped_busy},
      {"dropped_queue", a.dropped_queue},
      {"interrupted", a.scheduler.interrupted},
      {"message_s", {{"mean", length.mean_ms}, {"max", length.max_ms}}},
      {"prepare_ms", {{"mean", prepare.mean_ms}, {"p95", prepare.p95_ms}, {"max", prepare.max_ms}}},
      {"stage_ms", {{"mean", stage.mean_ms}, {"p95", stage.p95_ms}, {"max", stage.max_ms}}},
      {"stream_s", a.stream_s},
      {"voice", a.voice},
      {"hrtf", a.hrtf},
      {"hrtf_data", a.hrtf_name},
      {"resampler", a.resampler}};
  if (a.output == "live")
    stats["feedback_audio"]["live"] = {{"device", a.live_device}, {"underruns", a.live_underruns}};
}

/// Issue 18: the readout configured and the one estimated online (docs/dynamics.md).
nlohmann::json rollingShutterJson(const SlamSystem& slam) {
  const auto number_or_null = [](double x) {
    return std::isfinite(x) ? nlohmann::json(x) : nlohmann::json(nullptr);
  };
  const ReadoutEstimator& estimator = slam.readoutEstimator();
  nlohmann::json stages = nlohmann::json::array();
  for (const ReadoutStage& stage : slam.onlineReadoutStages())
    stages.push_back({{"from_frame", stage.frame},
                      {"readout_ms", stage.readout_s * 1e3},
                      {"sigma_ms", stage.sigma_s * 1e3},
                      {"window_keyframes", stage.window_keyframes}});
  const auto& all = slam.onlineReadoutStages();
  return {{"configured_ms", slam.configuredReadoutS() * 1e3},
          {"online", slam.readoutOnline()},
          // Online: the readout re-timing used last (null before bundle adjustment adopted one).
          {"online_readout_ms",
           all.empty() ? nlohmann::json(nullptr) : nlohmann::json(slam.onlineReadoutS() * 1e3)},
          {"online_stages", stages},
          // The tracking residuals' own estimate since the last adopted readout (the whole run when
          // not online), linearised at the readout in use: unbiased only when that is the true one.
          {"estimate_ms", estimator.frames() > 0 ? number_or_null(estimator.readoutS() * 1e3)
                                                 : nlohmann::json(nullptr)},
          {"sigma_ms", number_or_null(estimator.sigmaS() * 1e3)},
          {"frames", estimator.frames()}};
}

}  // namespace

void StatsSink::consume(const RgbdFrame&, const FrameResult& result) {
  latency_ms_.push_back(result.latency_ms);
  if (latency_ms_.size() % 100 == 1) {
    rss_mb_.emplace_back(int(latency_ms_.size()), currentRssMb());
    heap_mb_.emplace_back(int(latency_ms_.size()), heapInUseMb());
    keyframes_curve_.push_back(
        {int64_t(latency_ms_.size()), int64_t(result.map_keyframes), KeyFrame::instances()});
  }
  if (result.dynamics) dynamics_.push_back(*result.dynamics);
  const int segmented = result.instances.segmented_index;
  if (segmented >= 0 && (arrivals_.empty() || segmented > arrivals_.back().first))
    arrivals_.emplace_back(segmented, result.index);
}

void StatsSink::finish(const RunEnd& end) {
  const RunSummary& s = end.summary;
  const SlamSystem& slam = end.system.slam();
  nlohmann::json stages = nlohmann::json::object();
  for (const auto& [stage, t] : end.system.timers().summary()) stages[stage] = timingJson(t);
  const TimingSummary latency = summarize(latency_ms_);
  const auto mapping = slam.mappingStats();
  // Issue 4: loops with the frames that closed them (frame = the SLAM frame counter, which is
  // the input index unless corrupt frames were skipped).
  nlohmann::json loops = nlohmann::json::array();
  nlohmann::json loop_frames = nlohmann::json::array();
  for (const LoopEvent& e : slam.loops()) {
    loop_frames.push_back(e.frame_id);
    loops.push_back({{"frame", e.frame_id},
                     {"t", e.stamp_s},
                     {"loop_frame", e.loop_frame_id},
                     {"keyframe", e.keyframe_id},
                     {"loop_keyframe", e.loop_keyframe_id},
                     {"matches", e.matches},
                     {"correction_m", e.correction_m}});
  }
  const size_t offered = s.frames + s.dropped;
  nlohmann::json stats = {
      {"mode", end.mode},
      {"interrupted", s.interrupted_by_signal != 0},
      {"source_failure", s.source_failure},
      {"frames", s.frames},
      {"tracked", s.tracked},
      {"lost", s.lost},
      {"skipped_corrupt", s.skipped},
      {"dropped", s.dropped},
      {"dropped_share", offered ? double(s.dropped) / double(offered) : 0.0},
      {"relocalisations", s.relocalisation_frames.size()},
      {"relocalisation_frames", s.relocalisation_frames},
      {"loops", loops.size()},
      {"loop_frames", loop_frames},
      {"loop_details", loops},
      {"place_recognition",
       {{"on", slam.placeRecognitionOffReason().empty()},
        {"off_reason", slam.placeRecognitionOffReason()}}},
      {"keyframes", slam.numKeyFrames()},
      {"map_points", slam.numMapPoints()},
      {"keyframes_culled", mapping.keyframes_culled},
      {"points_triangulated", mapping.new_points_triangulated},
      {"bundle_adjustments", mapping.bundle_adjustments},
      {"wall_s", end.wall_s},
      {"cpu_s", processCpuSeconds()},
      {"fps", end.wall_s > 0 ? s.frames / end.wall_s : 0.0},
      {"stage_ms", stages},
      {"latency_ms", {{"mean", latency.mean_ms}, {"p95", latency.p95_ms}, {"max", latency.max_ms}}},
      {"peak_rss_mb", peakRssMb()},
      {"rss_mb", rss_mb_},  // [processed frames, MiB] every 100 frames: the memory curve
      // [processed frames, keyframes in the map, keyframe objects in memory], same samples
      {"keyframes_curve", keyframes_curve_},
      {"heap_mb", heap_mb_},  // [processed frames, MiB malloc'd and not freed], same samples
      {"keyframes_in_memory", KeyFrame::instances()}};
  stats["segmentation_arrivals"] = arrivals_;
  stats["rolling_shutter"] = rollingShutterJson(slam);
  stats["dynamics"] =
      dynamicsJson(dynamics_, end.system.segmenterName(), end.system.segmenterName() != "off");
  if (end.audio) addAudioJson(*end.audio, stats);
  writeJsonFile(out_dir_ / "stats.json", stats);
}

}  // namespace dynanav
