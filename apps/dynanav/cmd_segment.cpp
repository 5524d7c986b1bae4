// dynanav segment SEQ_DIR --out DIR: label PNGs, masks.json, an overlay video and stats.json.
#include <spdlog/spdlog.h>

#include <opencv2/core/utility.hpp>
#include <optional>

#include "apps/dynanav/commands.hpp"
#include "core/config.hpp"
#include "core/error.hpp"
#include "perception/segment_run.hpp"
#include "viz/instance_drawing.hpp"
#include "viz/video_writer.hpp"

namespace dynanav::cli {

void registerSegment(CLI::App& root, Action& chosen) {
  auto* sub =
      root.add_subcommand("segment", "segment people and objects: label PNGs + overlay video");
  struct Args {
    std::string sequence, out, config, segmenter = "auto", models;
    int segment_every = 1, max_frames = -1;
    bool no_video = false, contact_sheets = false;
  };
  auto args = std::make_shared<Args>();
  sub->add_option("SEQ_DIR", args->sequence, "sequence folder (TUM layout)")->required();
  sub->add_option("--out", args->out, "output folder")->required();
  sub->add_option("--config", args->config, "YAML config (perception and io sections apply)");
  sub->add_option("--segmenter", args->segmenter, "auto | dnn | hog | masks | none")
      ->check(CLI::IsMember({"auto", "dnn", "hog", "masks", "none"}));
  sub->add_option("--models", args->models,
                  "folder with the model files (default: $DYNANAV_MODELS, ../shared/models)");
  sub->add_option("--segment-every", args->segment_every,
                  "segment every k-th frame, propagate masks between")
      ->check(CLI::PositiveNumber);
  sub->add_option("--max-frames", args->max_frames, "stop after N frames")
      ->check(finiteRange(0, 2147483647));
  sub->add_flag("--no-video", args->no_video, "skip the overlay video");
  sub->add_flag("--contact-sheets", args->contact_sheets,
                "also write OUT/contact/sheet_NNN.png (48 overlays each)");
  sub->callback([&chosen, args] {
    chosen = [args] {
      const Config config = args->config.empty() ? Config{} : Config::load(args->config);
      SegmentRunOptions options;
      options.sequence_dir = args->sequence;
      options.out_dir = args->out;
      options.request.name = args->segmenter;
      options.request.segment_every = args->segment_every;
      options.perception = config.perception;
      if (!args->models.empty()) options.perception.models_dir = args->models;
      options.io = config.io;
      options.max_frames = args->max_frames;
      // The overlay video (OUT/overlay.mp4, H.264; else .avi, MJPG) and contact sheets: viz/.
      std::optional<VideoOutput> video;
      if (!args->no_video)
        video.emplace(options.out_dir, "overlay", 30.0,
                      videoEncoderOptions(config.outputs.video_encoder_options));
      std::optional<ContactSheets> sheets;
      if (args->contact_sheets) sheets.emplace((options.out_dir / "contact").string());
      if (video || sheets)
        options.on_frame = [&video, &sheets](const RgbdFrame& frame, const Instances& instances) {
          const cv::Mat overlay = drawInstances(frame.bgr, instances);
          if (sheets) sheets->add(overlay, frame.index);
          if (video) video->write(overlay);
        };
      if (options.perception.threads > 0) cv::setNumThreads(options.perception.threads);
      const SegmentRunSummary s = runSegmentation(options);
      if (video) video->close();
      if (sheets) sheets->flush();
      const std::string video_note =
          video && !video->path().empty()
              ? ", video " + video->path().string() + " (" + video->fourcc() + ")"
              : "";
      spdlog::info("segment: {} frames with {} ({} skipped), a person in {}; masks in {}{}",
                   s.frames, s.segmenter, s.skipped, s.frames_with_person,
                   (options.out_dir / "masks").string(), video_note);
      return kExitOk;
    };
  });
}

}  // namespace dynanav::cli
