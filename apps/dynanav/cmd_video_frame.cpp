// dynanav video-frame VIDEO --frame N --out PNG: one frame of a video (e.g. OUT/annotated.mp4)
// as an image, through OpenCV's reader, for documentation (issue 15).
#include <spdlog/spdlog.h>

#include <opencv2/imgcodecs.hpp>
#include <opencv2/videoio.hpp>

#include "apps/dynanav/commands.hpp"
#include "core/error.hpp"

namespace dynanav::cli {

void registerVideoFrame(CLI::App& root, Action& chosen) {
  auto* sub = root.add_subcommand("video-frame", "write one frame of a video as an image");
  struct Args {
    std::string video, out;
    int frame = 0;
  };
  auto args = std::make_shared<Args>();
  sub->add_option("VIDEO", args->video, "video file (annotated.mp4, overlay.mp4, ...)")->required();
  sub->add_option("--frame", args->frame, "0-based frame index")->check(CLI::NonNegativeNumber);
  sub->add_option("--out", args->out, "output image (.png or .jpg)")->required();
  sub->callback([&chosen, args] {
    chosen = [args] {
      cv::VideoCapture video(args->video);
      if (!video.isOpened()) throw InputError(args->video, "cannot open video");
      cv::Mat image;
      for (int i = 0; i <= args->frame; ++i)
        if (!video.read(image))
          throw InputError(args->video, "has only " + std::to_string(i) + " frames");
      if (!cv::imwrite(args->out, image, {cv::IMWRITE_JPEG_QUALITY, 85}))
        throw InputError(args->out, "cannot write image");
      spdlog::info("video-frame: frame {} of {} -> {}", args->frame, args->video, args->out);
      return kExitOk;
    };
  });
}

}  // namespace dynanav::cli
