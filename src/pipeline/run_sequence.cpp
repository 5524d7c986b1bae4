#include "pipeline/run_sequence.hpp"

#include <spdlog/spdlog.h>

#include <opencv2/core/utility.hpp>

#include <chrono>
#include <fstream>
#include <memory>
#include <optional>

#include "core/error.hpp"
#include "core/interrupt.hpp"
#include "io/json_io.hpp"
#include "pipeline/audio_stage.hpp"
#include "pipeline/events_sink.hpp"
#include "pipeline/frame_source.hpp"
#include "pipeline/map_sink.hpp"
#include "pipeline/objects_sink.hpp"
#include "pipeline/open_source.hpp"
#include "pipeline/realtime_runner.hpp"
#include "pipeline/report_sink.hpp"
#include "pipeline/run_outputs.hpp"
#include "pipeline/system.hpp"
#include "pipeline/video_sink.hpp"
#include "slam/slam_system.hpp"

namespace dynanav {
namespace {

/// Deterministic mode: every frame in order on this thread.
void runInOrder(FrameSource& source, System& system, const std::vector<FrameSink*>& sinks,
                RunSummary& summary, const BeforeSinks& before_sinks) {
  for (auto frame = source.next(); frame && !interruptRequested(); frame = source.next()) {
    const auto arrival = std::chrono::steady_clock::now();
    FrameResult result = system.process(*frame);
    result.latency_ms = msSince(arrival);
    if (before_sinks) before_sinks(result);
    summary.add(result);
    for (FrameSink* sink : sinks) sink->consume(*frame, result);
  }
}

std::string modeName(const RunConfig& run) {
  if (!run.realtime) return "deterministic";
  return run.paced ? "realtime" : "realtime-unpaced";
}

}  // namespace

RunSummary runSequence(const RunOptions& options) {
  const std::unique_ptr<FrameSource> source_owner = openFrameSource(
      {options.sequence_dir.string(), options.config.io, options.fallback_camera,
       options.camera_origin, options.blackout, options.max_frames, options.passes});
  FrameSource& source = *source_owner;
  std::error_code ec;
  std::filesystem::create_directories(options.out_dir, ec);
  if (ec)
    throw InputError(options.out_dir.string(), "cannot create output folder: " + ec.message());
  if (const int removed = removeEarlierRunOutputs(options.out_dir); removed > 0)
    spdlog::info("{}: replaced {} files of an earlier run", options.out_dir.string(), removed);
  writeTextFile(options.out_dir / "config_used.yaml", options.config.toYaml());
  spdlog::info("input {}: {} frames, camera {} (from {})", source.describe(), source.expected(),
               source.camera().name, source.cameraSource());

  const RunConfig& run = options.config.run;
  // Real time: our threads are the parallelism (segmenter, tracking, mapping); OpenCV's pool
  // threads would compete with tracking at its priority. Deterministic mode keeps OpenCV's default.
  if (run.realtime && run.realtime_opencv_threads > 0)
    cv::setNumThreads(run.realtime_opencv_threads);
  // Issue 14: the audio stage stamps each message's start before the writers see it; set up
  // first, so a missing voice or sound device fails before the run; the voice speaks the
  // messages' language (assist.language).
  std::optional<AudioStage> audio;
  if (options.config.audio.output != "none")
    audio.emplace(options.config, options.out_dir, options.config.assist.language);
  System system(options.config, source.camera(), options.sequence_dir);
  TrajectorySink trajectory(options.out_dir);
  StatsSink stats(options.out_dir);
  ObjectsSink objects(options.out_dir);
  ProgressSink progress(source.expected());
  std::vector<FrameSink*> sinks = {&trajectory, &stats, &objects};
  // Issue 14: the messages, whenever object tracking (and so the feedback stage) is on.
  std::optional<EventsSink> events_sink;
  const Config& config = options.config;
  if (config.run.dynamic && config.objects.enabled && config.assist.enabled)
    sinks.push_back(&events_sink.emplace(options.out_dir));
  // Issue 15: optional products; the report comes last (it reads stats.json and topview.png).
  const OutputsConfig& outputs = options.config.outputs;
  std::optional<MapSink> map_sink;
  std::optional<VideoSink> video_sink;
  std::optional<ReportSink> report_sink;
  if (outputs.map) sinks.push_back(&map_sink.emplace(options.out_dir, outputs, source.camera()));
  if (outputs.video)
    sinks.push_back(
        &video_sink.emplace(options.out_dir, source.camera(), outputs.video_encoder_options));
  if (outputs.report) sinks.push_back(&report_sink.emplace(options.out_dir, options.sequence_dir));
  if (options.progress) sinks.push_back(&progress);

  BeforeSinks before_sinks;
  if (audio) before_sinks = [&audio](FrameResult& result) { audio->process(result); };

  RunSummary summary;
  const auto start = std::chrono::steady_clock::now();
  if (audio) audio->start(start);
  if (run.realtime)
    runRealtime(source, [&system](const RgbdFrame& f) { return system.process(f); }, sinks, summary,
                {run.paced, size_t(std::max(1, run.queue_frames)), start, before_sinks});
  else
    runInOrder(source, system, sinks, summary, before_sinks);
  std::optional<AudioFeedbackStats> audio_stats;
  if (audio) audio_stats = audio->finish(interruptRequested());
  system.finish();
  const double wall_s =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  summary.skipped = source.skipped();
  summary.source_failure = source.failure();
  summary.interrupted_by_signal = interruptSignal();
  if (summary.interrupted_by_signal)
    spdlog::warn("interrupted by signal {} after {} frames: writing what the run has",
                 summary.interrupted_by_signal, summary.frames);
  summary.initialised = system.slam().numKeyFrames() > 0;
  const RunEnd end{system, summary, wall_s, modeName(run), audio_stats ? &*audio_stats : nullptr};
  for (FrameSink* sink : sinks) sink->finish(end);
  spdlog::info(
      "{} frames: {} tracked, {} lost, {} skipped, {} dropped; {} keyframes, {} map points; {:.1f} "
      "frames/s",
      summary.frames, summary.tracked, summary.lost, summary.skipped, summary.dropped,
      system.slam().numKeyFrames(), system.slam().numMapPoints(),
      wall_s > 0 ? summary.frames / wall_s : 0.0);
  return summary;
}

}  // namespace dynanav
