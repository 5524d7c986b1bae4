// dynanav vocabulary train|info: our own ORB bag-of-words vocabulary (docs/orb_vocabulary.md).
#include <fmt/format.h>
#include <spdlog/spdlog.h>

#include <chrono>
#include <filesystem>
#include <iostream>

#include "apps/dynanav/commands.hpp"
#include "core/error.hpp"
#include "slam/orb_extractor.hpp"
#include "slam/vocabulary/training_images.hpp"
#include "slam/vocabulary/vocabulary.hpp"

namespace dynanav::cli {
namespace {

struct TrainOptions {
  std::vector<std::string> inputs;
  std::string out;
  int branching = 10;
  int levels = 6;
  int max_images = 0;
  int video_step = 10;
  int features = 1000;
  uint64_t seed = 1;
};

std::string joined(const std::vector<std::string>& items) {
  std::string s;
  for (const auto& item : items) s += (s.empty() ? "" : " ") + item;
  return s;
}

int runTrain(const TrainOptions& opt) {
  if (opt.branching < 2 || opt.branching > 64) throw InputError("--k", "must be in 2..64");
  if (opt.levels < 1 || opt.levels > 8) throw InputError("--levels", "must be in 1..8");
  if (opt.features < 1) throw InputError("--features", "must be positive");
  const auto start = std::chrono::steady_clock::now();
  const auto images = thinEvenly(listTrainingImages(opt.inputs, opt.video_step), opt.max_images);
  if (images.empty()) throw InputError(joined(opt.inputs), "no images or video frames found");

  OrbConfig orb;
  orb.n_features = opt.features;
  OrbExtractor extractor(orb);
  std::vector<cv::Mat> descriptors;
  std::vector<cv::KeyPoint> keypoints;
  size_t video_frames = 0;
  forEachTrainingImage(images, [&](const cv::Mat& gray, const TrainingImage& item) {
    cv::Mat d;
    extractor.extract(gray, keypoints, d);
    if (d.rows == 0) return;
    descriptors.push_back(d);
    video_frames += item.frame >= 0 ? 1 : 0;
  });
  if (descriptors.empty()) throw InputError(joined(opt.inputs), "no ORB features in any image");
  const auto extracted = std::chrono::steady_clock::now();

  VocabularyTrainOptions train;
  train.branching = opt.branching;
  train.levels = opt.levels;
  train.seed = opt.seed;
  train.source = fmt::format("{} images ({} video frames, every {}th) from: {}", descriptors.size(),
                             video_frames, opt.video_step, joined(opt.inputs));
  const Vocabulary vocabulary = Vocabulary::train(descriptors, train);
  const auto trained = std::chrono::steady_clock::now();
  if (const auto parent = std::filesystem::path(opt.out).parent_path(); !parent.empty())
    std::filesystem::create_directories(parent);
  vocabulary.save(opt.out);

  const auto seconds = [](auto a, auto b) { return std::chrono::duration<double>(b - a).count(); };
  std::cout << fmt::format(
      "vocabulary {}: k={} L={} words={} from {} images, {} descriptors; ORB {:.1f} s, "
      "k-means {:.1f} s\n",
      opt.out, opt.branching, opt.levels, vocabulary.words(), descriptors.size(),
      vocabulary.info().training_descriptors, seconds(start, extracted),
      seconds(extracted, trained));
  return kExitOk;
}

int runInfo(const std::string& path) {
  const Vocabulary v = Vocabulary::load(path);
  const auto& info = v.info();
  std::cout << fmt::format(
      "file: {}\nsize_bytes: {}\nk: {}\nlevels: {}\nwords: {}\nnodes: {}\ntraining_images: {}\n"
      "training_descriptors: {}\nseed: {}\nsource: {}\n",
      path, std::filesystem::file_size(path), info.branching, info.levels, v.words(), v.nodes(),
      info.training_images, info.training_descriptors, info.seed, info.source);
  return kExitOk;
}

}  // namespace

void registerVocabulary(CLI::App& root, Action& chosen) {
  auto* sub = root.add_subcommand("vocabulary", "train or inspect an ORB bag-of-words vocabulary");
  sub->require_subcommand(1);

  static TrainOptions train;
  auto* t = sub->add_subcommand("train", "train a vocabulary on images, folders and videos");
  t->add_option("inputs", train.inputs, "image files, folders (searched recursively), videos")
      ->required();
  t->add_option("--out", train.out, "vocabulary file to write")->required();
  t->add_option("--k", train.branching, "branching factor")->capture_default_str();
  t->add_option("--levels", train.levels, "tree depth L (at most k^L words)")
      ->capture_default_str();
  t->add_option("--max-images", train.max_images, "use at most N images, evenly spaced (0 = all)")
      ->check(finiteRange(0, 1e9))
      ->capture_default_str();
  t->add_option("--video-step", train.video_step, "use every Nth video frame")
      ->check(finiteRange(1, 1e6))
      ->capture_default_str();
  t->add_option("--features", train.features, "ORB features per image")
      ->check(finiteRange(1, 100000))
      ->capture_default_str();
  t->add_option("--seed", train.seed, "k-means++ seed")->capture_default_str();
  t->callback([&chosen] { chosen = [] { return runTrain(train); }; });

  static std::string info_path;
  auto* i = sub->add_subcommand("info", "print what a vocabulary file holds");
  i->add_option("file", info_path, "vocabulary file")->required();
  i->callback([&chosen] { chosen = [] { return runInfo(info_path); }; });
}

}  // namespace dynanav::cli
