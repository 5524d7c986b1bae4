#pragma once
// report.html (issue 15): one self-contained page about a run — no network, no external file:
// styles inline, charts as inline SVG, the top view as a data: URI. Sections: summary, accuracy
// (ATE/RPE and plots, when the sequence has ground truth), per-stage timing (from stats.json),
// speed over time per track, the message timeline.
#include <nlohmann/json.hpp>
#include <optional>
#include <string>
#include <vector>

#include "core/feedback_event.hpp"
#include "eval/trajectory_metrics.hpp"
#include "viz/svg_plot.hpp"

namespace dynanav {

struct ReportAccuracy {
  AteResult ate;
  std::optional<RpeResult> rpe;
  std::vector<PlotSeries> trajectory_xz;  ///< ground truth and the aligned estimate, top view
  PlotSeries ate_over_time;               ///< per matched pose: time (s), error (m)
};

struct ReportData {
  std::string sequence;
  nlohmann::json stats;  ///< OUT/stats.json as the run wrote it
  std::optional<ReportAccuracy> accuracy;
  std::string accuracy_note;          ///< why there is none (no ground truth, too few poses)
  std::vector<PlotSeries> speeds;     ///< one per track: time (s), speed (m/s)
  std::vector<FeedbackEvent> events;  ///< in time order
  double first_stamp_s = 0.0;         ///< times are shown relative to it
  double last_stamp_s = 0.0;
  std::string topview_png;           ///< raw PNG bytes (empty: none)
  std::vector<std::string> outputs;  ///< files written next to the report
};

std::string reportHtml(const ReportData& data);

/// RFC 4648 base64 (for data: URIs).
std::string base64(const std::string& bytes);

}  // namespace dynanav
