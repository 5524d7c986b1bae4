#pragma once
// `--report` (issue 15): OUT/report.html at the end of the run (viz/report_html): accuracy
// against SEQ_DIR/groundtruth.txt when present (eval/), timing from OUT/stats.json (so it must
// finish after StatsSink), speed per track, the messages. Embeds OUT/topview.png when written.
#include <filesystem>
#include <map>
#include <vector>

#include "pipeline/sinks.hpp"
#include "viz/report_html.hpp"

namespace dynanav {

class ReportSink final : public FrameSink {
 public:
  ReportSink(std::filesystem::path out_dir, std::filesystem::path sequence_dir);
  void consume(const RgbdFrame& frame, const FrameResult& result) override;
  void finish(const RunEnd& end) override;

 private:
  std::filesystem::path out_dir_, sequence_dir_;
  double first_stamp_s_ = -1.0, last_stamp_s_ = 0.0;
  std::map<uint64_t, PlotSeries> speeds_;
  std::vector<FeedbackEvent> events_;
};

}  // namespace dynanav
