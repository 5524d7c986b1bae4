// Writing a simulated sequence in TUM layout; PNG encoding of frame i overlaps rendering of i+1.
#include <chrono>
#include <fstream>
#include <future>
#include <opencv2/imgcodecs.hpp>

#include "core/error.hpp"
#include "io/camera_yaml.hpp"
#include "io/json_io.hpp"
#include "io/sequence.hpp"
#include "io/trajectory.hpp"
#include "sim/simulator.hpp"

namespace dynanav::sim {

namespace fs = std::filesystem;

namespace {
std::ofstream listFile(const fs::path& path, const std::string& what, const SimOptions& o) {
  std::ofstream out(path);
  if (!out) throw InputError(path.string(), "cannot write");
  // The three comment lines of TUM's list files.
  out << "# " << what << "\n# file: 'dynanav simulate --scenario " << o.scenario << " --seed "
      << o.seed << "'\n# timestamp filename\n";
  return out;
}

void writePng(const fs::path& path, const cv::Mat& image) {
  // OpenCV's PNG defaults are its fast path (SUB filter, zlib level 1, RLE); asking for a
  // compression level makes it try every PNG filter, three times slower (bench_sim BM_EncodePng).
  if (!cv::imwrite(path.string(), image)) throw InputError(path.string(), "cannot write image");
}
}  // namespace

WriteStats writeSequence(Simulator& sim, const fs::path& out_dir,
                         const std::function<void(int)>& progress) {
  const auto start = std::chrono::steady_clock::now();
  for (const char* sub : {"rgb", "depth", "masks"}) fs::create_directories(out_dir / sub);
  saveCameraYaml(out_dir / "camera.yaml", sim.camera());
  writeJsonFile(out_dir / "masks.json", sim.masksJson());
  std::ofstream rgb_list = listFile(out_dir / "rgb.txt", "color images", sim.options());
  std::ofstream depth_list = listFile(out_dir / "depth.txt", "depth maps", sim.options());
  TrajectoryWriter groundtruth(out_dir / "groundtruth.txt");
  JsonLinesWriter objects(out_dir / "objects_gt.jsonl");
  const double depth_factor = sim.camera().depth_factor;

  auto write = [&](const SimFrame& f) {
    const std::string name = Simulator::stampName(f.stamp_s) + ".png";
    writePng(out_dir / "rgb" / name, f.bgr);
    writeDepthPng(out_dir / "depth" / name, f.depth_m, depth_factor);
    writePng(out_dir / "masks" / name, f.instance);
    rgb_list << Simulator::stampName(f.stamp_s) << " rgb/" << name << "\n" << std::flush;
    depth_list << Simulator::stampName(f.stamp_s) << " depth/" << name << "\n" << std::flush;
    if (!rgb_list || !depth_list)
      throw InputError((out_dir / "rgb.txt").string(),
                       "writing the image lists failed (disk full?)");
    groundtruth.write({f.stamp_s, f.T_world_camera});
    objects.write(f.objects);
  };
  std::future<void> pending;
  for (int i = 0; i < sim.frameCount(); ++i) {
    SimFrame frame = sim.render(i);
    if (pending.valid()) pending.get();  // rethrows a write error
    pending = std::async(std::launch::async, [&write, f = std::move(frame)] { write(f); });
    if (progress) progress(i);
  }
  if (pending.valid()) pending.get();
  groundtruth.close();
  WriteStats stats;
  stats.frames = sim.frameCount();
  stats.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return stats;
}

}  // namespace dynanav::sim
