#include "slam/loop_closer.hpp"

#include <spdlog/spdlog.h>

#include "core/heap.hpp"
#include "slam/global_ba.hpp"
#include "slam/loop_correction.hpp"

namespace dynanav {

LoopCloser::LoopCloser(Map& map, PlaceIndex& places, const LoopConfig& config,
                       int covisibility_min_weight, bool threaded)
    : map_(map),
      places_(places),
      config_(config),
      covisibility_min_weight_(covisibility_min_weight),
      threaded_(threaded),
      detector_(config) {}

LoopCloser::~LoopCloser() {
  finish();
}

void LoopCloser::finish() {
  if (global_ba_thread_.joinable()) global_ba_thread_.join();
}

std::vector<LoopEvent> LoopCloser::loops() const {
  std::unique_lock lock(events_mutex_);
  return events_;
}

void LoopCloser::process(const KeyFramePtr& keyframe) {
  {
    std::unique_lock lock(map_.mutex());
    if (keyframe->bad) return;
    places_.eraseCulled(map_);
    places_.computeBow(*keyframe);
    std::vector<KeyFrame*> candidates;
    const bool due =
        map_.numKeyFrames() >= static_cast<size_t>(config_.loop_min_keyframes) &&
        (events_.empty() || keyframe->id >= last_loop_keyframe_ + config_.loop_min_keyframes);
    if (config_.loop_closing && due && !global_ba_running_)
      candidates = detector_.detect(*keyframe, places_, map_);
    places_.add(*keyframe);
    if (candidates.empty()) return;
    const auto verified = verifyLoop(*keyframe, candidates, config_);
    if (!verified) return;
    LoopEvent event;
    event.keyframe_id = keyframe->id;
    event.frame_id = keyframe->frame_id;
    event.stamp_s = keyframe->stamp_s;
    event.loop_keyframe_id = verified->loop->id;
    event.loop_frame_id = verified->loop->frame_id;
    event.matches = static_cast<int>(verified->matches.size());
    event.correction_m =
        (verified->T_camera_world_corrected.inverse().translation() - keyframe->center()).norm();
    const LoopCorrectionSummary summary =
        correctLoop(map_, *keyframe, *verified, config_, covisibility_min_weight_);
    spdlog::info(
        "loop closed: keyframe {} (frame {}) with keyframe {} (frame {}), {} matches, moved {:.3f} "
        "m; "
        "window {} keyframes, {} points fused, essential graph {} edges, cost {:.4g} -> {:.4g}",
        event.keyframe_id, event.frame_id, event.loop_keyframe_id, event.loop_frame_id,
        event.matches, event.correction_m, summary.window_keyframes, summary.points_fused,
        summary.graph_edges, summary.graph_initial_cost, summary.graph_final_cost);
    detector_.reset();
    last_loop_keyframe_ = keyframe->id;
    std::unique_lock events_lock(events_mutex_);
    events_.push_back(event);
  }
  if (!config_.global_ba) return;
  if (!threaded_) {
    globalBundleAdjustment();
    return;
  }
  finish();  // at most one global BA at a time
  global_ba_running_ = true;
  global_ba_thread_ = std::thread([this] { globalBundleAdjustment(); });
}

void LoopCloser::globalBundleAdjustment() {
  global_ba_running_ = true;
  BaOptions options;
  options.iterations_first = config_.global_ba_iterations;
  options.iterations_second = config_.global_ba_iterations;
  const GlobalBaRun run = runGlobalBa(map_, options);
  ++global_bas_;
  spdlog::info("global BA: {} keyframes, {} points, rms {:.3f} -> {:.3f} px", run.keyframes,
               run.points, run.result.initial_rms_px, run.result.final_rms_px);
  // The whole map's problem is a run's largest transient (20-40 MiB on the Bonn window's map):
  // its pages go back at once rather than at the mapping thread's next periodic release.
  releaseFreeHeapPages();
  global_ba_running_ = false;
}

}  // namespace dynanav
