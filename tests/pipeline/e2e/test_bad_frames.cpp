// Bad-input matrix, part 2 (issue 16): bad frames are skipped and counted (stats.json
// `skipped_corrupt` and a warning naming the file), a run never dies on one frame, a sequence
// with no readable frame says so; an earlier run's files never mix with this run's; log lines
// never land in output files; damaged model files are refused at load.
#include <nlohmann/json.hpp>
#include <opencv2/imgcodecs.hpp>
#include <opencv2/imgproc.hpp>
#include <sstream>

#include "bad_input_support.hpp"
#include "io/camera_yaml.hpp"
#include "io/sequence.hpp"

namespace dynanav {
namespace {

namespace fs = std::filesystem;
using test::runCliTimed;
using test::writeText;

const std::string kQuickRun = " --segmenter none --dynamic off --quiet";

std::vector<std::string> listLines(const fs::path& list) {
  std::vector<std::string> lines;
  std::istringstream in(test::readFile(list));
  for (std::string line; std::getline(in, line);) lines.push_back(line);
  return lines;
}

/// Index of the k-th image line (not a comment) of a TUM list.
size_t imageLine(const std::vector<std::string>& lines, int k) {
  int seen = 0;
  for (size_t i = 0; i < lines.size(); ++i) {
    if (lines[i].empty() || lines[i][0] == '#') continue;
    if (seen++ == k) return i;
  }
  return lines.size();
}

void truncateFile(const fs::path& path, double keep_share) {
  fs::resize_file(path, static_cast<uintmax_t>(fs::file_size(path) * keep_share));
}

TEST(BadFrames, EachKindIsSkippedCountedAndNamed) {
  const fs::path base = test::simulatedSequence("frames", 24);
  const fs::path dir = test::scratchDir("bad_frames");
  const fs::path seq = dir / "seq";
  fs::copy(base, seq, fs::copy_options::recursive);
  const auto pairs = TumSequence::open(seq, IoConfig{}).pairs();
  ASSERT_EQ(pairs.size(), 24u);
  const auto rgb = [&](int i) { return seq / pairs[i].rgb.relative_path; };
  const auto depth = [&](int i) { return seq / pairs[i].depth.relative_path; };
  const cv::Size size = cv::imread(rgb(0).string()).size();

  cv::imwrite(rgb(3).string(), cv::Mat::zeros(size, CV_8UC3));     // all black
  cv::imwrite(depth(5).string(), cv::Mat::zeros(size, CV_16UC1));  // no valid depth
  cv::imwrite(rgb(7).string(), cv::Mat(size, CV_8UC3, cv::Scalar(255, 255, 255)));  // saturated
  truncateFile(rgb(9), 0.5);                                                        // truncated PNG
  writeText(depth(11), "");                                                         // zero bytes
  cv::Mat small;
  cv::resize(cv::imread(rgb(13).string()), small, size / 2);
  cv::imwrite(rgb(13).string(), small);  // wrong size
  // Frames 15 and 16 as JPEG: 15 truncated (libjpeg only warns and fills in grey), 16 intact.
  auto rgb_lines = listLines(seq / "rgb.txt");
  for (int i : {15, 16}) {
    const fs::path jpg = fs::path(rgb(i)).replace_extension(".jpg");
    cv::imwrite(jpg.string(), cv::imread(rgb(i).string()));
    std::string& line = rgb_lines[imageLine(rgb_lines, i)];
    line.replace(line.rfind(".png"), 4, ".jpg");
    if (i == 15) truncateFile(jpg, 0.6);
  }
  // Other formats under a .png name never reach an OpenCV decoder (a DICOM header made GDCM
  // abort the process): frame 18's colour is a BMP, frame 20's depth a DICOM preamble.
  std::vector<unsigned char> bmp;
  ASSERT_TRUE(cv::imencode(".bmp", cv::imread(rgb(18).string()), bmp));
  writeText(rgb(18), std::string(bmp.begin(), bmp.end()));
  writeText(depth(20), std::string(128, '\0') + "DICM" + std::string(64, '\x02'));
  std::string joined;
  for (const auto& l : rgb_lines) joined += l + "\n";
  writeText(seq / "rgb.txt", joined);

  const fs::path out = dir / "out";
  const auto r = runCliTimed("run " + seq.string() + " --out " + out.string() + kQuickRun);
  ASSERT_EQ(r.code, 0) << r.output;
  const auto stats = nlohmann::json::parse(test::readFile(out / "stats.json"));
  EXPECT_EQ(stats["skipped_corrupt"].get<int>(), 9) << r.output;
  EXPECT_EQ(stats["frames"].get<int>(), 24 - 9);
  for (const fs::path& named :
       {rgb(3), depth(5), rgb(7), rgb(9), depth(11), rgb(13), rgb(18), depth(20)})
    EXPECT_NE(r.output.find(named.filename().string()), std::string::npos)
        << "no warning names " << named << ":\n"
        << r.output;
  EXPECT_NE(r.output.find("truncated JPEG"), std::string::npos) << r.output;
  EXPECT_NE(r.output.find("not a PNG or JPEG image"), std::string::npos) << r.output;
  // The intact JPEG was used: its stamp is in the trajectory.
  std::ostringstream stamp;
  stamp.precision(6);
  stamp << std::fixed << pairs[16].rgb.stamp_s;
  EXPECT_NE(test::readFile(out / "trajectory_online.txt").find(stamp.str()), std::string::npos);
}

TEST(BadFrames, NoReadableFrameSaysSo) {
  const fs::path base = test::simulatedSequence("frames", 24);
  const fs::path dir = test::scratchDir("no_frame");
  fs::copy(base, dir / "seq", fs::copy_options::recursive);
  // A camera of another size: every frame is "wrong size".
  PinholeCamera camera = loadCameraYaml(dir / "seq" / "camera.yaml");
  camera.width /= 2;
  camera.cx /= 2;
  saveCameraYaml(dir / "seq" / "camera.yaml", camera);
  const auto r = runCliTimed("run " + (dir / "seq").string() + " --out " + (dir / "out").string() +
                             " --max-frames 5" + kQuickRun);
  EXPECT_BAD_INPUT(r, "no frame could be read");
  EXPECT_EQ(r.output.find("tracking never initialised"), std::string::npos) << r.output;
}

TEST(RunOutputs, EarlierRunsFilesAreReplacedNotMixed) {
  const fs::path seq = test::simulatedSequence("frames", 24);
  const fs::path out = test::scratchDir("stale_outputs");
  for (const char* name :
       {"keyframes.txt", "trajectory_online.txt", "objects.jsonl", "events.jsonl", "stats.json"})
    writeText(out / name, "from an earlier run\n");
  writeText(out / "notes.txt", "mine\n");
  const auto r =
      runCliTimed("run " + seq.string() + " --out " + out.string() + " --max-frames 8" + kQuickRun);
  ASSERT_EQ(r.code, 0) << r.output;
  for (const auto& entry : fs::directory_iterator(out)) {
    if (entry.path().filename() == "notes.txt") continue;  // not ours: left alone
    EXPECT_EQ(test::readFile(entry.path()).find("from an earlier run"), std::string::npos)
        << entry.path();
  }
  EXPECT_FALSE(fs::exists(out / "events.jsonl"));  // this run writes none (no feedback stage yet)
  EXPECT_EQ(test::readFile(out / "notes.txt"), "mine\n");
}

TEST(RunOutputs, ClosedStdoutPutsNoLogLineIntoOutputs) {
  const fs::path seq = test::simulatedSequence("frames", 24);
  const fs::path dir = test::scratchDir("closed_stdout");
  // Stdout closed with stderr kept (logs captured), then both closed.
  for (const std::string redirect : {"2>&1 >&-", ">&- 2>&-"}) {
    const fs::path out = dir / (redirect[0] == '2' ? "a" : "b");
    const auto r = runCliTimed("run " + seq.string() + " --out " + out.string() +
                                   " --max-frames 8 --segmenter none --dynamic off",
                               240, redirect);
    ASSERT_EQ(r.code, 0) << redirect << ": " << r.output;
    for (const char* name : {"trajectory.txt", "trajectory_online.txt", "keyframes.txt"}) {
      std::istringstream in(test::readFile(out / name));
      for (std::string line; std::getline(in, line);) {
        if (line.empty() || line[0] == '#') continue;
        double v[8];
        EXPECT_EQ(std::sscanf(line.c_str(), "%lf %lf %lf %lf %lf %lf %lf %lf", &v[0], &v[1], &v[2],
                              &v[3], &v[4], &v[5], &v[6], &v[7]),
                  8)
            << name << " holds a foreign line: " << line;
      }
    }
    EXPECT_TRUE(nlohmann::json::parse(test::readFile(out / "stats.json")).is_object());
    for (const auto& entry : fs::directory_iterator(out))
      for (const char* level : {"] [info] ", "] [warning] ", "] [error] "})
        EXPECT_EQ(test::readFile(entry.path()).find(level), std::string::npos)
            << entry.path() << " holds a log line";
  }
}

TEST(ModelFiles, TruncatedDetectorWeightsAreRefused) {
  const fs::path models = test::sharedModels();
  if (models.empty()) GTEST_SKIP() << "../shared/models not found: skipped";
  const fs::path seq = test::simulatedSequence("frames", 24);
  const fs::path dir = test::scratchDir("bad_models");
  // A models folder of links to the real files, but with half the detector weights.
  for (const auto& entry : fs::recursive_directory_iterator(models)) {
    const fs::path rel = fs::relative(entry.path(), models);
    if (entry.is_directory()) {
      fs::create_directories(dir / "models" / rel);
    } else if (rel.filename() == "yolo-fastest-1.1-xl.weights") {
      fs::copy_file(entry.path(), dir / "models" / rel);
      truncateFile(dir / "models" / rel, 0.5);
    } else {
      fs::create_symlink(entry.path(), dir / "models" / rel);
    }
  }
  const auto r =
      runCliTimed("run " + seq.string() + " --out " + (dir / "out").string() +
                  " --max-frames 3 --segmenter dnn --models " + (dir / "models").string());
  EXPECT_BAD_INPUT(r, "yolo-fastest-1.1-xl.weights");
  EXPECT_NE(r.output.find("SHA-256"), std::string::npos) << r.output;
}

}  // namespace
}  // namespace dynanav
