#pragma once
// `--map` (issue 15): keeps every keyframe's colour, depth and static mask as the run goes (and a
// frame every map_frame_interval_s between keyframes), and at the end places them with the
// optimised keyframe poses to write the static map (mapping/:
// map.ply, map.bt, occupancy.png, map_info.json) and the top view (viz/: topview.png).
#include <filesystem>
#include <map>
#include <vector>

#include "core/camera.hpp"
#include "core/config/outputs.hpp"
#include "mapping/map_keyframe.hpp"
#include "pipeline/sinks.hpp"
#include "viz/topview.hpp"

namespace dynanav {

/// Ids of the instances removed from maps: people (prior dynamic) and whatever moved.
std::vector<uint16_t> dynamicInstanceIds(const FrameResult& result);

class MapSink final : public FrameSink {
 public:
  MapSink(std::filesystem::path out_dir, const OutputsConfig& config, const PinholeCamera& camera);
  void consume(const RgbdFrame& frame, const FrameResult& result) override;
  void finish(const RunEnd& end) override;

 private:
  std::filesystem::path out_dir_;
  OutputsConfig config_;
  PinholeCamera camera_;
  std::vector<MapKeyframe> keyframes_;
  std::map<uint64_t, ObjectPath> object_paths_;
};

}  // namespace dynanav
