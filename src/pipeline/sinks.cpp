#include "pipeline/sinks.hpp"

#include <cstdio>

#include "core/error.hpp"
#include "pipeline/system.hpp"
#include "slam/slam_system.hpp"

namespace dynanav {

void RunSummary::add(const FrameResult& result) {
  ++frames;
  if (result.tracked)
    ++tracked;
  else if (result.state == TrackingState::kLost)
    ++lost;
  if (result.recovered) relocalisation_frames.push_back(result.index);
}

TrajectorySink::TrajectorySink(std::filesystem::path out_dir)
    : out_dir_(std::move(out_dir)),
      online_(std::make_unique<TrajectoryWriter>(out_dir_ / "trajectory.txt")) {}

void TrajectorySink::consume(const RgbdFrame&, const FrameResult& result) {
  if (result.tracked) online_->write({result.stamp_s, result.T_world_camera});
}

void TrajectorySink::finish(const RunEnd& end) {
  const SlamSystem& slam = end.system.slam();
  writeTrajectory(out_dir_ / "keyframes.txt", slam.keyframePoses());
  // The run is complete: keep the poses as tracked, and replace trajectory.txt by every frame
  // re-anchored on its (since optimised) reference keyframe.
  online_->close();
  online_.reset();
  std::error_code ec;
  std::filesystem::copy_file(out_dir_ / "trajectory.txt", out_dir_ / "trajectory_online.txt",
                             std::filesystem::copy_options::overwrite_existing, ec);
  if (ec)
    throw InputError((out_dir_ / "trajectory_online.txt").string(),
                     "cannot write: " + ec.message());
  writeTrajectory(out_dir_ / "trajectory.txt", slam.refinedTrajectory());
}

void ProgressSink::consume(const RgbdFrame& frame, const FrameResult& result) {
  ++done_;
  if (result.state == TrackingState::kLost) ++lost_;
  const size_t position = static_cast<size_t>(frame.index) + 1;
  if (position % 5 != 0 && position != expected_) return;
  const int width = 40;
  const int filled =
      expected_ ? static_cast<int>(width * std::min(position, expected_) / expected_) : width;
  std::fprintf(stderr, "\r[%.*s%*s] %zu/%zu frames, %d lost", filled,
               "########################################", width - filled, "", position, expected_,
               lost_);
  std::fflush(stderr);
}

void ProgressSink::finish(const RunEnd&) {
  std::fprintf(stderr, "\n");
}

}  // namespace dynanav
