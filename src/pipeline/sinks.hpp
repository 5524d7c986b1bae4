#pragma once
// Writers are consumers of FrameResult (DESIGN.md §1, sinks): registered once, each gets every
// processed frame in order, then the end of the run once the map is final.
#include <array>
#include <filesystem>
#include <memory>
#include <string>
#include <vector>

#include "assist/audio_feedback.hpp"
#include "core/frame.hpp"
#include "io/trajectory.hpp"
#include "pipeline/frame_result.hpp"

namespace dynanav {

class System;

/// What a whole run did, from the results it produced.
struct RunSummary {
  int frames = 0;  ///< processed
  int tracked = 0;
  int lost = 0;
  int skipped = 0;             ///< unreadable frames (the source's count)
  std::string source_failure;  ///< why the frames stopped early (a camera that failed), or ""
  size_t dropped = 0;          ///< real time: frames dropped because the system was behind
  bool initialised = false;
  int interrupted_by_signal =
      0;  ///< SIGINT/SIGTERM/SIGHUP ended the run early (0 = ran to the end)
  std::vector<int> relocalisation_frames;  ///< input frames on which tracking came back (issue 4)
  void add(const FrameResult& result);
};

/// The end of a run, as sinks see it (after System::finish()).
struct RunEnd {
  const System& system;
  const RunSummary& summary;
  double wall_s = 0.0;
  std::string mode;                           ///< "deterministic", "realtime" or "realtime-unpaced"
  const AudioFeedbackStats* audio = nullptr;  ///< issue 14: with --audio
};

class FrameSink {
 public:
  virtual ~FrameSink() = default;
  virtual void consume(const RgbdFrame& frame, const FrameResult& result) = 0;
  virtual void finish(const RunEnd& end) = 0;
};

/// OUT/trajectory.txt as the run goes (flushed per line, so an interrupted run keeps it); at the
/// end keyframes.txt, trajectory_online.txt (poses as tracked) and trajectory.txt re-anchored
/// on the optimised keyframes, as ORB-SLAM2 saves its trajectory.
class TrajectorySink final : public FrameSink {
 public:
  explicit TrajectorySink(std::filesystem::path out_dir);
  void consume(const RgbdFrame& frame, const FrameResult& result) override;
  void finish(const RunEnd& end) override;

 private:
  std::filesystem::path out_dir_;
  std::unique_ptr<TrajectoryWriter> online_;
};

/// OUT/stats.json at the end: counts, timings per stage, latency, dynamics per frame.
class StatsSink final : public FrameSink {
 public:
  explicit StatsSink(std::filesystem::path out_dir) : out_dir_(std::move(out_dir)) {}
  void consume(const RgbdFrame& frame, const FrameResult& result) override;
  void finish(const RunEnd& end) override;

 private:
  std::filesystem::path out_dir_;
  std::vector<double> latency_ms_;
  std::vector<FrameDynamics> dynamics_;
  /// [segmented frame, frame its result was first used on]: replayable with
  /// perception.replay_arrivals.
  std::vector<std::pair<int, int>> arrivals_;
  std::vector<std::pair<int, double>>
      rss_mb_;  // (processed frames, resident MiB), every 100 frames
  // (processed frames, keyframes in the map, KeyFrame objects in memory), sampled with rss_mb_:
  // the second exceeds the first by the culled keyframes still held.
  std::vector<std::array<int64_t, 3>> keyframes_curve_;
  std::vector<std::pair<int, double>> heap_mb_;  // (processed frames, live heap MiB), same samples
};

/// A progress bar on stderr.
class ProgressSink final : public FrameSink {
 public:
  explicit ProgressSink(size_t expected) : expected_(expected) {}
  void consume(const RgbdFrame& frame, const FrameResult& result) override;
  void finish(const RunEnd& end) override;

 private:
  size_t expected_;
  size_t done_ = 0;
  int lost_ = 0;
};

}  // namespace dynanav
