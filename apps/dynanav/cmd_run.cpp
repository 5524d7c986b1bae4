// dynanav run: the whole pipeline over a TUM-layout sequence (DESIGN.md §2). Thin: parses the
// flags into RunOptions and calls runSequence().
#include <spdlog/cfg/env.h>
#include <spdlog/spdlog.h>
#include <unistd.h>

#include <regex>

#include "apps/dynanav/commands.hpp"
#include "core/error.hpp"
#include "core/interrupt.hpp"
#include "io/camera_yaml.hpp"
#include "pipeline/run_sequence.hpp"

namespace dynanav::cli {
namespace {

struct RunFlags {
  std::string sequence_dir;
  std::string out_dir;
  std::string config_path;
  std::string camera_path;  // --camera: intrinsics of a device, or of a folder without its own
  std::string dynamic;
  std::string blackout;
  std::string segmenter;  // issue 7 (dynamics): segmenter, models and segmentation rate
  std::string models;
  int segment_every = 0;
  bool deterministic = false;
  bool realtime = false;
  bool unpaced = false;
  int passes = 1;
  int max_frames = 0;
  bool quiet = false;
  bool map = false, video = false, report = false, all_outputs = false;  // issue 15
  std::string audio;     // issue 14: "file" (--audio) or "live"
  std::string language;  // issue 14
};

int runCommand(const RunFlags& flags) {
  RunOptions options;
  options.sequence_dir = flags.sequence_dir;
  options.out_dir = flags.out_dir;
  if (!flags.config_path.empty()) options.config = Config::load(flags.config_path);
  if (!flags.camera_path.empty()) {
    options.fallback_camera = loadCameraYaml(flags.camera_path);
    options.camera_origin = flags.camera_path;
  }
  if (!flags.dynamic.empty()) options.config.run.dynamic = flags.dynamic == "on";
  if (!flags.segmenter.empty()) options.config.run.segmenter = flags.segmenter;  // issue 7
  if (!flags.models.empty()) options.config.perception.models_dir = flags.models;
  if (!flags.language.empty()) options.config.assist.language = flags.language;  // issue 14
  if (flags.segment_every < 0) throw InputError("--segment-every", "must be >= 1");
  if (flags.segment_every > 0) options.config.run.segment_every = flags.segment_every;
  if (flags.deterministic && flags.realtime)
    throw InputError("--deterministic", "excludes --realtime");
  if (flags.deterministic) {
    options.config.run.deterministic = true;
    options.config.run.realtime = false;
  }
  if (flags.unpaced && !flags.realtime) throw InputError("--unpaced", "only goes with --realtime");
  if (flags.realtime) {
    options.config.run.deterministic = false;
    options.config.run.realtime = true;
    if (flags.unpaced) options.config.run.paced = false;
  }
  // A config file may ask for real time; deterministic mode means one thread, so both agree.
  if (options.config.run.realtime && !flags.deterministic) options.config.run.deterministic = false;
  if (flags.passes < 1)
    throw InputError("--passes", "must be at least 1, got " + std::to_string(flags.passes));
  options.passes = flags.passes;
  if (flags.max_frames < 0) throw InputError("--max-frames", "must be >= 0");
  if (flags.max_frames > 0) options.config.run.max_frames = flags.max_frames;
  options.max_frames = options.config.run.max_frames;
  options.config.validate(flags.config_path.empty() ? "command line"
                                                    : flags.config_path + " with the flags");
  if (!flags.blackout.empty()) {
    std::smatch m;
    // At most 9 digits each, so stoi cannot overflow.
    const std::regex pattern(R"((\d{1,9}):(\d{1,9}))");
    if (!std::regex_match(flags.blackout, m, pattern) || std::stoi(m[1]) > std::stoi(m[2]))
      throw InputError("--blackout",
                       "expects A:B with 0 <= A <= B < 1e9, got '" + flags.blackout + "'");
    options.blackout = std::make_pair(std::stoi(m[1]), std::stoi(m[2]));
  }
  options.config.outputs.map |= flags.map || flags.all_outputs;
  options.config.outputs.video |= flags.video || flags.all_outputs;
  options.config.outputs.report |= flags.report || flags.all_outputs;
  if (!flags.audio.empty()) options.config.audio.output = flags.audio;  // issue 14
  spdlog::cfg::load_env_levels();  // SPDLOG_LEVEL=debug shows per-frame tracking details
  if (flags.quiet) spdlog::set_level(spdlog::level::warn);
  options.progress = !flags.quiet && isatty(STDERR_FILENO);
  installInterruptHandlers();
  const RunSummary summary = runSequence(options);
  if (summary.interrupted_by_signal)
    return 128 + summary.interrupted_by_signal;  // 130 SIGINT, 143 SIGTERM
  if (!summary.source_failure.empty())
    throw InputError("", summary.source_failure + " (the outputs hold the " +
                             std::to_string(summary.frames) + " frames processed before)");
  if (summary.frames == 0)
    throw InputError(flags.sequence_dir, "no frame could be read: all " +
                                             std::to_string(summary.skipped) +
                                             " frames were skipped (see the warnings above)");
  if (!summary.initialised) {
    spdlog::error(
        "tracking never initialised: no frame had enough keypoints with valid depth ({} frames "
        "processed, {} skipped as unreadable)",
        summary.frames, summary.skipped);
    return kExitNotInitialised;
  }
  return kExitOk;
}

}  // namespace

void registerRun(CLI::App& root, Action& chosen) {
  auto flags = std::make_shared<RunFlags>();
  auto* sub = root.add_subcommand(
      "run", "Track a TUM-layout RGB-D sequence; write trajectory, keyframes, stats");
  sub->add_option("SEQ_DIR", flags->sequence_dir,
                  "sequence folder (rgb.txt, depth.txt, rgb/, depth/), openni://[URI] (a live "
                  "OpenNI2 camera; openni:// = any) or FILE.oni (a recording)")
      ->required();
  sub->add_option("--out", flags->out_dir, "output folder")->required();
  sub->add_option("--config", flags->config_path, "YAML config (unknown keys are errors)");
  sub->add_option("--camera", flags->camera_path,
                  "camera.yaml with the intrinsics of an openni:// or .oni input (default: "
                  "camera.yaml beside the .oni, else the device's field of view) or of a folder "
                  "that has none");
  sub->add_option("--dynamic", flags->dynamic,
                  "on|off: handle moving objects (off = plain SLAM baseline)")
      ->check(CLI::IsMember({"on", "off"}));
  sub->add_option("--segmenter", flags->segmenter,
                  "auto|dnn|hog|masks|none: how people and objects are found")
      ->check(CLI::IsMember({"auto", "dnn", "hog", "masks", "none"}));
  sub->add_option("--models", flags->models,
                  "folder with the model files (default: $DYNANAV_MODELS, ../shared/models)");
  sub->add_option("--segment-every", flags->segment_every,
                  "segment every k-th frame, propagate masks between")
      ->check(finiteRange(1, 1000));
  sub->add_flag("--deterministic", flags->deterministic,
                "single thread, local mapping inline: identical results run to run (default)");
  sub->add_flag("--realtime", flags->realtime,
                "real time: frames at the camera's pace (dropped when behind), segmentation, local "
                "mapping and loop "
                "closing in their own threads");
  sub->add_flag("--unpaced", flags->unpaced,
                "with --realtime: frames as fast as they are processed, none dropped");
  sub->add_option("--max-frames", flags->max_frames, "process at most N frames (0 = all)")
      ->check(finiteRange(0, 2147483647));
  sub->add_option("--passes", flags->passes,
                  "play the sequence N times, alternately forward and backward so the camera "
                  "path stays continuous, time running on (a long-run test)")
      ->check(finiteRange(1, 1000000));
  sub->add_option("--blackout", flags->blackout,
                  "A:B replace frames A..B (0-based, inclusive) by black images and no depth");
  sub->add_option("--language", flags->language, "en|de: language of the spoken messages")
      ->check(CLI::IsMember({"en", "de"}));
  sub->add_flag("--quiet", flags->quiet, "only warnings and errors, no progress bar");
  sub->add_flag("--map", flags->map,
                "write the static map: map.ply, map.bt, occupancy.png, topview.png, map_info.json");
  sub->add_flag("--video", flags->video, "write annotated.mp4 (masks, objects, messages)");
  sub->add_flag("--report", flags->report,
                "write report.html (accuracy, timing, speeds, messages)");
  sub->add_flag("--all-outputs", flags->all_outputs, "--map --video --report");
  sub->add_option("--audio", flags->audio,
                  "write feedback.wav (earcons + speech, 48 kHz stereo); --audio live also plays "
                  "it on the default sound device (needs --realtime)")
      ->expected(0, 1)
      ->default_str("file")
      ->check(CLI::IsMember({"file", "live"}));
  sub->callback([&chosen, flags] { chosen = [flags] { return runCommand(*flags); }; });
}

}  // namespace dynanav::cli
