#include "pipeline/run_sequence.hpp"

#include <spdlog/spdlog.h>

#include <sys/resource.h>

#include <chrono>
#include <cstdio>
#include <fstream>
#include <future>
#include <memory>

#include "core/error.hpp"
#include "core/timer.hpp"
#include "io/json_io.hpp"
#include "io/sequence.hpp"
#include "io/trajectory.hpp"
#include "pipeline/system.hpp"
#include "slam/loop_closer.hpp"

namespace dynanav {
namespace {

void drawProgress(size_t done, size_t total, int lost) {
  const int width = 40;
  const int filled = total ? static_cast<int>(width * done / total) : width;
  std::fprintf(stderr, "\r[%.*s%*s] %zu/%zu frames, %d lost", filled,
               "########################################", width - filled, "", done, total, lost);
  std::fflush(stderr);
}

RgbdFrame blackFrame(const RgbdFrame& like, const PinholeCamera& camera) {
  RgbdFrame f = like;
  const cv::Size size = like.bgr.empty() ? cv::Size(camera.width, camera.height) : like.bgr.size();
  f.bgr = cv::Mat::zeros(size, CV_8UC3);
  f.depth_m = cv::Mat::zeros(size, CV_32F);
  return f;
}

/// CPU seconds (user + system, all threads) this process has used: a steadier throughput
/// measure than wall time on a shared machine.
double processCpuSeconds() {
  rusage usage{};
  getrusage(RUSAGE_SELF, &usage);
  return static_cast<double>(usage.ru_utime.tv_sec + usage.ru_stime.tv_sec) +
         1e-6 * static_cast<double>(usage.ru_utime.tv_usec + usage.ru_stime.tv_usec);
}

nlohmann::json statsJson(const RunSummary& s, const System& system, double wall_s) {
  nlohmann::json stages = nlohmann::json::object();
  for (const auto& [stage, t] : system.timers().summary()) {
    if (stage == "frame") continue;
    stages[stage] = {{"mean", t.mean_ms}, {"p95", t.p95_ms}, {"count", t.count}};
  }
  const auto all = system.timers().summary();
  const auto frame_it = all.find("frame");
  const TimingSummary latency = frame_it != all.end() ? frame_it->second : TimingSummary{};
  const auto mapping = system.mappingStats();
  // Issue 4: loops with the frames that closed them (frame = the System's frame counter, which is
  // the input index unless corrupt frames were skipped).
  nlohmann::json loops = nlohmann::json::array();
  nlohmann::json loop_frames = nlohmann::json::array();
  for (const LoopEvent& e : system.loops()) {
    loop_frames.push_back(e.frame_id);
    loops.push_back({{"frame", e.frame_id}, {"t", e.stamp_s}, {"loop_frame", e.loop_frame_id},
                     {"keyframe", e.keyframe_id}, {"loop_keyframe", e.loop_keyframe_id}, {"matches", e.matches},
                     {"correction_m", e.correction_m}});
  }
  return {{"frames", s.frames},
          {"tracked", s.tracked},
          {"lost", s.lost},
          {"skipped_corrupt", s.skipped},
          {"dropped", 0},
          {"relocalisations", s.relocalisation_frames.size()},
          {"relocalisation_frames", s.relocalisation_frames},
          {"loops", loops.size()},
          {"loop_frames", loop_frames},
          {"loop_details", loops},
          {"keyframes", system.numKeyFrames()},
          {"map_points", system.numMapPoints()},
          {"keyframes_culled", mapping.keyframes_culled},
          {"points_triangulated", mapping.new_points_triangulated},
          {"bundle_adjustments", mapping.bundle_adjustments},
          {"wall_s", wall_s},
          {"cpu_s", processCpuSeconds()},
          {"fps", wall_s > 0 ? s.frames / wall_s : 0.0},
          {"stage_ms", stages},
          {"latency_ms", {{"mean", latency.mean_ms}, {"p95", latency.p95_ms}, {"max", latency.max_ms}}},
          {"peak_rss_mb", peakRssMb()}};
}

}  // namespace

RunSummary runSequence(const RunOptions& options) {
  const TumSequence sequence = TumSequence::open(options.sequence_dir, options.config.io, options.fallback_camera);
  std::error_code ec;
  std::filesystem::create_directories(options.out_dir, ec);
  if (ec) throw InputError(options.out_dir.string(), "cannot create output folder: " + ec.message());
  {
    std::ofstream config_out(options.out_dir / "config_used.yaml");
    config_out << options.config.toYaml();
  }
  spdlog::info("sequence {}: {} frames, camera {} (from {})", sequence.dir().string(), sequence.size(),
               sequence.camera().name, sequence.cameraSource());

  System system(options.config, sequence.camera(), options.sequence_dir);
  auto trajectory = std::make_unique<TrajectoryWriter>(options.out_dir / "trajectory.txt");
  RunSummary summary;
  size_t total = sequence.size();
  if (options.max_frames > 0) total = std::min<size_t>(total, options.max_frames);
  const auto start = std::chrono::steady_clock::now();
  // Decoding the next frame's images overlaps with processing this one. Loading is a pure
  // function of the files, so this does not affect determinism.
  auto load = [&sequence](size_t i) { return sequence.load(i); };
  std::future<RgbdFrame> next;
  if (total > 0) next = std::async(std::launch::async, load, 0);
  for (size_t i = 0; i < total; ++i) {
    RgbdFrame frame;
    try {
      frame = next.get();
    } catch (const InputError& e) {
      ++summary.skipped;
      spdlog::warn("frame {} skipped: {}", i, e.what());
      if (i + 1 < total) next = std::async(std::launch::async, load, i + 1);
      continue;
    }
    if (i + 1 < total) next = std::async(std::launch::async, load, i + 1);
    const int index = static_cast<int>(i);
    if (options.blackout && index >= options.blackout->first && index <= options.blackout->second)
      frame = blackFrame(frame, sequence.camera());
    const FrameResult result = system.process(frame);
    ++summary.frames;
    if (result.tracked) {
      ++summary.tracked;
      trajectory->write({result.stamp_s, result.T_world_camera});
    } else if (result.state == TrackingState::kLost) {
      ++summary.lost;
    }
    if (result.recovered) {
      spdlog::info("frame {}: tracking recovered", i);
      summary.relocalisation_frames.push_back(index);
    }
    if (options.progress && (i % 5 == 0 || i + 1 == total)) drawProgress(i + 1, total, summary.lost);
  }
  system.finish();
  const double wall_s = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  if (options.progress) std::fprintf(stderr, "\n");
  summary.initialised = system.numKeyFrames() > 0;
  writeTrajectory(options.out_dir / "keyframes.txt", system.keyframePoses());
  // The run is complete: keep the poses as tracked, and replace trajectory.txt by every frame
  // re-anchored on its (since optimised) reference keyframe, as ORB-SLAM2 saves its trajectory.
  trajectory.reset();
  std::filesystem::copy_file(options.out_dir / "trajectory.txt", options.out_dir / "trajectory_online.txt",
                             std::filesystem::copy_options::overwrite_existing, ec);
  writeTrajectory(options.out_dir / "trajectory.txt", system.refinedTrajectory());
  nlohmann::json stats = statsJson(summary, system, wall_s);
  stats["dynamics"] = system.dynamicsSummary();  // issue 7
  writeJsonFile(options.out_dir / "stats.json", stats);
  spdlog::info("{} frames: {} tracked, {} lost, {} skipped; {} keyframes, {} map points; {:.1f} frames/s",
               summary.frames, summary.tracked, summary.lost, summary.skipped, system.numKeyFrames(),
               system.numMapPoints(), wall_s > 0 ? summary.frames / wall_s : 0.0);
  return summary;
}

}  // namespace dynanav
