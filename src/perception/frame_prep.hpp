#pragma once
// The per-frame preparation step (DESIGN.md §1, "FramePrep"): the images several stages need,
// computed once per frame and shared — the grey image (ORB extraction), its half-size copy
// (scene flow, object point tracking) and the dense optical flow from the previous frame to
// this one (object point tracking; DIS, Kroeger et al. ECCV 2016, OpenCV's ultrafast preset).
#include <opencv2/core.hpp>
#include <opencv2/video/tracking.hpp>

#include "core/frame.hpp"

namespace dynanav {

struct PreparedFrame {
  cv::Mat grey;       ///< CV_8U, full size
  cv::Mat grey_half;  ///< CV_8U, half size (INTER_AREA); empty unless asked for
  /// CV_32FC2 at half size: for each pixel of the previous frame's grey_half, where it went in
  /// this one (half-size pixels). Empty on the first frame, after a size change, or unless asked.
  cv::Mat flow_half;
};

/// Full-image pixels one DIS patch of `patch_px` spans at pyramid level `finest_scale` of an
/// image scaled by `image_scale`: the flow at a pixel is made from image content up to this far
/// away (DIS blends the overlapping patches).
int disPatchFootprintPx(int patch_px, int finest_scale, double image_scale);

/// DIS's patch side in FramePrep's shared flow (the ultrafast preset's), on half-size images.
inline constexpr int kSharedFlowPatchPx = 8;
/// The shared flow's footprint (disPatchFootprintPx) at its finest level `finest_scale`.
inline int sharedFlowFootprintPx(int finest_scale) {
  return disPatchFootprintPx(kSharedFlowPatchPx, finest_scale, 0.5);
}

/// Prepares frames in sequence order, remembering the previous one for the flow.
class FramePrep {
 public:
  struct Needs {
    bool half = false;  ///< grey_half
    bool flow = false;  ///< flow_half (implies half)
    /// DIS's finest pyramid level (the ultrafast preset's is 2): its 8 px patches there cover
    /// 2^(level+1) * 8 px of the full image, and a finer level follows a narrow object better.
    int flow_finest_scale = 2;
    /// Variational refinement iterations after DIS's patch search (the preset's: 0): a smooth
    /// field that keeps the image's brightness constant, which fills in the patch search's
    /// shortfall on low-texture surfaces (smooth clothes) at a cost per pixel.
    int flow_refinement_iterations = 0;
  };
  explicit FramePrep(Needs needs) : needs_(needs) {}
  PreparedFrame prepare(const RgbdFrame& frame);

 private:
  Needs needs_;
  cv::Mat previous_half_;
  cv::Ptr<cv::DISOpticalFlow> dis_;
};

}  // namespace dynanav
