#pragma once
// One frame of annotated.mp4 (issue 15): instance masks with their verdicts, tracked objects
// (id, class, speed, clock direction, distance, a velocity arrow), the current message to the
// wearer and a status line. Inputs are plain data, so it draws whatever the run produced.
#include <opencv2/core.hpp>
#include <optional>
#include <string>
#include <vector>

#include "core/camera.hpp"
#include "core/feedback_event.hpp"
#include "core/se3.hpp"
#include "core/tracked_object.hpp"
#include "viz/instance_drawing.hpp"

namespace dynanav {

struct FrameAnnotation {
  int index = 0;
  double stamp_s = 0.0;
  std::string state;  ///< tracking state ("ok", "lost", ...)
  bool keyframe = false;
  SE3 T_world_camera = SE3::Identity();  ///< turns objects' world velocity into the image
  std::vector<InstanceStatus> statuses;
  std::vector<TrackedObject> objects;
  std::optional<FeedbackEvent> message;  ///< the latest message still shown, if any
};

cv::Mat annotateFrame(const cv::Mat& bgr, const Instances& instances, const PinholeCamera& camera,
                      const FrameAnnotation& annotation);

}  // namespace dynanav
