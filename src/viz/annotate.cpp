#include "viz/annotate.hpp"

#include <opencv2/imgproc.hpp>

#include "viz/colours.hpp"

namespace dynanav {
namespace {

void textWithShadow(cv::Mat& image, const std::string& text, cv::Point at, double scale,
                    const cv::Scalar& colour, int thickness = 1) {
  cv::putText(image, text, at + cv::Point(1, 1), cv::FONT_HERSHEY_SIMPLEX, scale,
              cv::Scalar(0, 0, 0), thickness + 2, cv::LINE_AA);
  cv::putText(image, text, at, cv::FONT_HERSHEY_SIMPLEX, scale, colour, thickness, cv::LINE_AA);
}

cv::Scalar priorityColour(FeedbackPriority p) {
  switch (p) {
    case FeedbackPriority::kUrgent:
      return {0, 0, 255};
    case FeedbackPriority::kAdvisory:
      return {0, 200, 255};
    default:
      return {255, 255, 255};
  }
}

}  // namespace

cv::Mat annotateFrame(const cv::Mat& bgr, const Instances& instances, const PinholeCamera& camera,
                      const FrameAnnotation& a) {
  cv::Mat out = drawInstances(bgr, instances, a.statuses);
  // Drawn at the object's centroid as the camera sees it (pinhole; distortion is a few pixels).
  for (const TrackedObject& o : a.objects) {
    if (o.p_camera.z() <= 0.1) continue;
    const Eigen::Vector2d uv = camera.project(o.p_camera);
    const cv::Point centre(int(uv.x()), int(uv.y()));
    const cv::Scalar colour = colourOfId(o.id);
    cv::circle(out, centre, 6, colour, cv::FILLED, cv::LINE_AA);
    cv::circle(out, centre, 7, cv::Scalar(0, 0, 0), 1, cv::LINE_AA);
    if (o.speed_mps > 0.05) {
      // The velocity half a second ahead, projected: where it will be if it keeps going.
      const Vec3 ahead = o.p_camera + 0.5 * (a.T_world_camera.linear().transpose() * o.v_world_mps);
      if (ahead.z() > 0.1) {
        const Eigen::Vector2d tip = camera.project(ahead);
        cv::arrowedLine(out, centre, cv::Point(int(tip.x()), int(tip.y())), colour, 2, cv::LINE_AA,
                        0, 0.25);
      }
    }
    const std::string line1 = cv::format("#%llu %s%s", (unsigned long long)o.id,
                                         o.class_name.c_str(), o.dynamic ? " moving" : "");
    const std::string line2 =
        cv::format("%.1f m/s  %d o'clock  %.1f m", o.speed_mps, o.clock, o.distance_m);
    textWithShadow(out, line1, centre + cv::Point(10, -4), 0.5, colour);
    textWithShadow(out, line2, centre + cv::Point(10, 14), 0.5, cv::Scalar(255, 255, 255));
  }
  // Status line at the top, the message at the bottom (as the wearer would hear it).
  cv::rectangle(out, cv::Rect(0, 0, out.cols, 22), cv::Scalar(0, 0, 0), cv::FILLED);
  textWithShadow(out,
                 cv::format("frame %d  t %.2f s  %s%s  %zu objects", a.index, a.stamp_s,
                            a.state.c_str(), a.keyframe ? "  keyframe" : "", a.objects.size()),
                 {6, 16}, 0.5, cv::Scalar(255, 255, 255));
  if (a.message) {
    cv::rectangle(out, cv::Rect(0, out.rows - 30, out.cols, 30), cv::Scalar(0, 0, 0), cv::FILLED);
    textWithShadow(out, "\"" + a.message->text + "\"", {8, out.rows - 9}, 0.6,
                   priorityColour(a.message->priority), 1);
  }
  return out;
}

}  // namespace dynanav
