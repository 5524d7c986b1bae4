#include "pipeline/report_sink.hpp"

#include <spdlog/spdlog.h>

#include <fstream>
#include <sstream>

#include "core/error.hpp"
#include "io/json_io.hpp"
#include "pipeline/system.hpp"
#include "slam/slam_system.hpp"

namespace dynanav {
namespace {

std::string fileBytes(const std::filesystem::path& path) {
  std::ifstream in(path, std::ios::binary);
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

ReportAccuracy accuracy(const std::vector<StampedPose>& gt, const std::vector<StampedPose>& est) {
  ReportAccuracy a;
  a.ate = computeAte(gt, est);
  try {
    a.rpe = computeRpe(gt, est);
  } catch (const InputError&) {
  }
  std::vector<double> gt_stamps, est_stamps;
  for (const StampedPose& p : gt) gt_stamps.push_back(p.stamp_s);
  for (const StampedPose& p : est) est_stamps.push_back(p.stamp_s);
  PlotSeries g{"ground truth", {}, {}, 3}, e{"estimate (aligned)", {}, {}, 1, true};
  a.ate_over_time = {"translation error", {}, {}, 1};
  const double t0 = est.empty() ? 0.0 : est.front().stamp_s;
  for (const auto& [i, j] : associateStamps(est_stamps, gt_stamps, 0.02)) {
    const Vec3 p_est = a.ate.T_gt_est * est[i].T_world_camera.translation();
    const Vec3 p_gt = gt[j].T_world_camera.translation();
    g.x.push_back(p_gt.x()), g.y.push_back(p_gt.z());
    e.x.push_back(p_est.x()), e.y.push_back(p_est.z());
    a.ate_over_time.x.push_back(est[i].stamp_s - t0);
    a.ate_over_time.y.push_back((p_est - p_gt).norm());
  }
  a.trajectory_xz = {g, e};
  return a;
}

}  // namespace

ReportSink::ReportSink(std::filesystem::path out_dir, std::filesystem::path sequence_dir)
    : out_dir_(std::move(out_dir)), sequence_dir_(std::move(sequence_dir)) {}

void ReportSink::consume(const RgbdFrame&, const FrameResult& result) {
  if (first_stamp_s_ < 0) first_stamp_s_ = result.stamp_s;
  last_stamp_s_ = result.stamp_s;
  for (const TrackedObject& o : result.objects) {
    PlotSeries& s = speeds_[o.id];
    if (s.name.empty()) s = {"#" + std::to_string(o.id) + " " + o.class_name, {}, {}, o.id};
    s.x.push_back(result.stamp_s - first_stamp_s_);
    s.y.push_back(o.speed_mps);
  }
  events_.insert(events_.end(), result.events.begin(), result.events.end());
}

void ReportSink::finish(const RunEnd& end) {
  ReportData d;
  d.sequence = sequence_dir_.string();
  const auto stats_path = out_dir_ / "stats.json";
  if (std::filesystem::exists(stats_path)) d.stats = readJsonFile(stats_path);
  const auto gt_path = sequence_dir_ / "groundtruth.txt";
  if (std::filesystem::exists(gt_path)) {
    try {
      d.accuracy = accuracy(readTrajectory(gt_path), end.system.slam().refinedTrajectory());
    } catch (const InputError& e) {
      d.accuracy_note = std::string("no accuracy figures: ") + e.what();
    }
  } else {
    d.accuracy_note = "no groundtruth.txt in the sequence folder: no accuracy figures";
  }
  for (auto& [id, series] : speeds_) d.speeds.push_back(std::move(series));
  d.events = events_;
  d.first_stamp_s = first_stamp_s_ < 0 ? 0.0 : first_stamp_s_;
  d.last_stamp_s = last_stamp_s_;
  if (std::filesystem::exists(out_dir_ / "topview.png"))
    d.topview_png = fileBytes(out_dir_ / "topview.png");
  for (const auto& entry : std::filesystem::directory_iterator(out_dir_))
    if (entry.is_regular_file()) d.outputs.push_back(entry.path().filename().string());
  d.outputs.push_back("report.html");
  std::sort(d.outputs.begin(), d.outputs.end());
  const auto path = out_dir_ / "report.html";
  std::ofstream out(path);
  out << reportHtml(d);
  if (!out) throw InputError(path.string(), "cannot write");
  spdlog::info("report: {}", path.string());
}

}  // namespace dynanav
