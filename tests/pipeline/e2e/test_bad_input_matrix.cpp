// Bad-input matrix, part 1 (issue 16): every CLI option that takes a value, the config and
// camera files, and filesystem errors. Each case: exit 2 with a message naming the file, key or
// option; never a crash (a signal), a hang (the time limit) or exit 1 ("internal error").
#include <filesystem>
#include <string>
#include <utility>
#include <vector>

#include "bad_input_support.hpp"

namespace dynanav {
namespace {

namespace fs = std::filesystem;
using test::runCliTimed;
using test::writeText;

struct Case {
  std::string args;   ///< after `dynanav`
  std::string token;  ///< the message must contain it
};

void expectAll(const std::vector<Case>& cases) {
  for (const Case& c : cases) {
    SCOPED_TRACE("dynanav " + c.args);
    EXPECT_BAD_INPUT(runCliTimed(c.args), c.token);
  }
}

TEST(BadInputMatrix, RunOptions) {
  const fs::path seq = test::simulatedSequence("matrix", 6);
  const fs::path dir = test::scratchDir("matrix_run");
  const std::string out = " --out " + (dir / "out").string();
  const std::string run = "run " + seq.string() + out;
  writeText(dir / "a_file", "x");
  expectAll({
      {"run /nonexistent/seq" + out, "/nonexistent/seq"},
      {"run " + seq.string() + " --out " + (dir / "a_file").string(), "a_file"},
      {"run " + seq.string() + " --out " + (dir / "a_file" / "sub").string(), "a_file"},
      {"run " + seq.string() + " --out /proc/version/out", "/proc/version"},
      {run + " --config /nonexistent/c.yaml", "/nonexistent/c.yaml"},
      {run + " --dynamic maybe", "--dynamic"},
      {run + " --segmenter magic", "--segmenter"},
      {run + " --segmenter dnn --models /nonexistent/models", "/nonexistent/models"},
      {run + " --segment-every 0", "--segment-every"},
      {run + " --segment-every -1", "--segment-every"},
      {run + " --segment-every nan", "--segment-every"},
      {run + " --segment-every 99999999999999", "--segment-every"},
      {run + " --max-frames -1", "--max-frames"},
      {run + " --max-frames lots", "--max-frames"},
      {run + " --blackout 5:2", "--blackout"},
      {run + " --blackout 99999999999:99999999999", "--blackout"},
      {run + " --blackout x", "--blackout"},
      {run + " --deterministic --realtime", "--deterministic"},
      {run + " --unpaced", "--unpaced"},
      {run + " --camera /nonexistent/cam.yaml", "/nonexistent/cam.yaml"},
      {run + " --camera " + (dir / "a_file").string(), "a_file"},
      {"run " + (dir / "missing.oni").string() + out, "missing.oni"},
      {"run openni:// --passes 3" + out, "--passes"},
  });
}

TEST(BadInputMatrix, ConfigValuesOutOfRange) {
  const fs::path seq = test::simulatedSequence("matrix", 6);
  const fs::path dir = test::scratchDir("matrix_config");
  const std::vector<std::pair<std::string, std::string>> bad = {
      {"orb:\n  n_features: 0\n", "n_features"},
      {"orb:\n  n_features: 2000000000\n", "n_features"},
      {"orb:\n  n_features: 99999999999999\n", "n_features"},
      {"orb:\n  scale_factor: 1.0\n", "scale_factor"},
      {"orb:\n  scale_factor: .nan\n", "scale_factor"},
      {"orb:\n  n_levels: 0\n", "n_levels"},
      {"tracking:\n  depth_max_m: .inf\n", "depth_max_m"},
      {"tracking:\n  pose_iterations: 0\n", "pose_iterations"},
      {"mapping:\n  queue_capacity: -4\n", "queue_capacity"},
      {"loop:\n  direct_index_depth: 0\n", "direct_index_depth"},
      {"perception:\n  flow_scale: 0\n", "flow_scale"},
      {"dynamics:\n  sample_step_px: 0\n", "sample_step_px"},
      {"run:\n  segment_every: 0\n", "segment_every"},
      {"run:\n  queue_frames: 0\n", "queue_frames"},
      {"io:\n  max_association_dt_s: -.inf\n", "max_association_dt_s"},
      {"orb: [1, 2\n", "bad.yaml"},
  };
  for (const auto& [yaml, key] : bad) {
    writeText(dir / "bad.yaml", yaml);
    SCOPED_TRACE(yaml);
    const auto r = runCliTimed("run " + seq.string() + " --out " + (dir / "out").string() +
                               " --config " + (dir / "bad.yaml").string());
    EXPECT_BAD_INPUT(r, key);
    EXPECT_NE(r.output.find("bad.yaml"), std::string::npos) << r.output;
  }
}

TEST(BadInputMatrix, CameraYaml) {
  const fs::path seq = test::simulatedSequence("matrix", 6);
  const std::string good = test::readFile(seq / "camera.yaml");
  const fs::path dir = test::scratchDir("matrix_camera");
  fs::copy(seq, dir / "seq", fs::copy_options::recursive);
  const std::vector<std::pair<std::string, std::string>> bad = {
      {"width: 640\nheight: 480\nfx: .nan\nfy: 525\ncx: 319.5\ncy: 239.5\n", "'fx'"},
      {"width: 640\nheight: 480\nfx: 525\nfy: .inf\ncx: 319.5\ncy: 239.5\n", "'fy'"},
      {"width: 640\nheight: 480\nfx: 525\nfy: 525\ncx: 319.5\ncy: 239.5\n"
       "distortion: [0, .nan, 0, 0, 0]\n",
       "'distortion'"},
      {"width: 640\nheight: 480\nfx: 525\nfy: 525\ncx: 319.5\ncy: 239.5\nfxx: 1\n", "'fxx'"},
      {"width: 0\nheight: 480\nfx: 525\nfy: 525\ncx: 319.5\ncy: 239.5\n", "'width'"},
      {"width: 640.5\nheight: 480\nfx: 525\nfy: 525\ncx: 319.5\ncy: 239.5\n", "'width'"},
      {"width: 640\nheight: 480\nfx: 525\nfy: 525\ncx: 9000\ncy: 239.5\n", "'cx'"},
      {"width: 640\nheight: 480\nfx: 525\nfy: 525\ncx: 319.5\ncy: 239.5\ndepth_factor: 0\n",
       "'depth_factor'"},
      {"width: 640\nheight: 480\nfx: 525\nfy: 525\ncx: 319.5\n", "'cy'"},
      {"[1, 2, 3]\n", "camera.yaml"},
  };
  for (const auto& [yaml, key] : bad) {
    writeText(dir / "seq" / "camera.yaml", yaml);
    SCOPED_TRACE(yaml);
    const auto r =
        runCliTimed("run " + (dir / "seq").string() + " --out " + (dir / "out").string());
    EXPECT_BAD_INPUT(r, key);
    EXPECT_NE(r.output.find("camera.yaml"), std::string::npos) << r.output;
  }
  writeText(dir / "seq" / "camera.yaml", good);
}

TEST(BadInputMatrix, FilesystemErrorsInEverySubcommand) {
  const fs::path dir = test::scratchDir("matrix_fs");
  fs::create_symlink(dir / "loop_a", dir / "loop_b");
  fs::create_symlink(dir / "loop_b", dir / "loop_a");
  writeText(dir / "a_file", "x");
  const std::string loop = (dir / "loop_a").string();
  const std::string file = (dir / "a_file").string();
  expectAll({
      {"run " + loop + " --out " + (dir / "o1").string(), "loop_a"},
      {"eval --gt " + loop + " --est " + loop, "loop_a"},
      {"simulate --scenario static-room --frames 2 --out " + file, "a_file"},
      {"simulate --scenario static-room --frames 2 --out " + loop, "loop_a"},
      {"segment " + loop + " --out " + (dir / "o2").string(), "loop_a"},
      {"vocabulary info " + loop, "loop_a"},
      {"vocabulary train " + loop + " --out " + (dir / "v.dnvoc").string(), "loop_a"},
  });
}

TEST(BadInputMatrix, OtherSubcommandOptions) {
  const fs::path seq = test::simulatedSequence("matrix", 6);
  const fs::path dir = test::scratchDir("matrix_other");
  const std::string gt = (seq / "groundtruth.txt").string();
  writeText(dir / "bad_traj.txt", "1.0 0 0 0 0 0 0 1\n0.5 0 0 0 0 0 0 1\n");
  writeText(dir / "nan_traj.txt", "1.0 nan 0 0 0 0 0 1\n");
  writeText(dir / "short.dnvoc", "DNVOC");
  const std::string eval = "eval --gt " + gt + " --est " + gt;
  expectAll({
      {"eval --gt /nonexistent/gt.txt --est " + gt, "/nonexistent/gt.txt"},
      {"eval --gt " + gt + " --est " + (dir / "bad_traj.txt").string(), "bad_traj.txt"},
      {"eval --gt " + gt + " --est " + (dir / "nan_traj.txt").string(), "nan_traj.txt"},
      {eval + " --sequence /nonexistent/seq", "/nonexistent/seq"},
      {eval + " --max-dt nan", "--max-dt"},
      {eval + " --max-dt 0", "--max-dt"},
      {eval + " --stats /nonexistent/stats.json --sequence " + seq.string(), "stats.json"},
      {eval + " --min-visible-px -1", "--min-visible-px"},
      {"simulate --scenario bogus --out " + (dir / "s").string(), "bogus"},
      {"simulate --scenario static-room --frames -1 --out " + (dir / "s").string(), "--frames"},
      {"simulate --scenario static-room --seed abc --out " + (dir / "s").string(), "--seed"},
      {"simulate --scenario static-room --fps nan --out " + (dir / "s").string(), "--fps"},
      {"simulate --scenario static-room --fps 0 --out " + (dir / "s").string(), "--fps"},
      {"segment /nonexistent/seq --out " + (dir / "g").string(), "/nonexistent/seq"},
      {"segment " + seq.string() + " --out " + (dir / "g").string() + " --segmenter x",
       "--segmenter"},
      {"segment " + seq.string() + " --out " + (dir / "g").string() + " --segment-every 0",
       "--segment-every"},
      {"segment " + seq.string() + " --out " + (dir / "g").string() + " --max-frames -2",
       "--max-frames"},
      {"segment " + seq.string() + " --out " + (dir / "g").string() +
           " --config /nonexistent/c.yaml",
       "/nonexistent/c.yaml"},
      {"segment " + seq.string() + " --out " + (dir / "g").string() +
           " --segmenter dnn --models /nonexistent/models",
       "/nonexistent/models"},
      {"vocabulary info /nonexistent/v.dnvoc", "/nonexistent/v.dnvoc"},
      {"vocabulary info " + (dir / "short.dnvoc").string(), "short.dnvoc"},
      {"vocabulary info /dev/zero", "/dev/zero"},  // was read for ever
      {"vocabulary train /nonexistent/images --out " + (dir / "v").string(), "/nonexistent/images"},
      {"vocabulary train " + (seq / "rgb").string() + " --out " + (dir / "v").string() + " --k 1",
       "--k"},
      {"vocabulary train " + (seq / "rgb").string() + " --out " + (dir / "v").string() +
           " --levels 0",
       "--levels"},
      {"vocabulary train " + (seq / "rgb").string() + " --out " + (dir / "v").string() +
           " --features 0",
       "--features"},
      {"vocabulary train " + (seq / "rgb").string() + " --out " + (dir / "v").string() +
           " --video-step 0",
       "--video-step"},
      {"vocabulary train " + (seq / "rgb").string() + " --out " + (dir / "v").string() +
           " --max-images -1",
       "--max-images"},
      {"vocabulary train " + (seq / "rgb").string() + " --out " + (dir / "v").string() +
           " --seed x",
       "--seed"},
  });
}

}  // namespace
}  // namespace dynanav
