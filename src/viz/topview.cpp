#include "viz/topview.hpp"

#include <opencv2/imgproc.hpp>

#include "viz/colours.hpp"

namespace dynanav {

cv::Mat drawTopView(const OccupancyGrid& grid, const std::vector<Vec3>& wearer_path_world,
                    const std::map<uint64_t, ObjectPath>& objects, int scale_px) {
  cv::Mat grey = grid.image(), out;
  cv::resize(grey, grey, grey.size() * scale_px, 0, 0, cv::INTER_NEAREST);
  cv::cvtColor(grey, out, cv::COLOR_GRAY2BGR);
  auto pixel = [&](const Vec3& p) {
    const cv::Point2f c = grid.pixel(p);
    return cv::Point(int(c.x * float(scale_px)), int(c.y * float(scale_px)));
  };
  auto polyline = [&](const std::vector<Vec3>& path, const cv::Scalar& colour, int thickness) {
    std::vector<cv::Point> points;
    for (const Vec3& p : path) points.push_back(pixel(p));
    if (points.size() >= 2) cv::polylines(out, points, false, colour, thickness, cv::LINE_AA);
    return points;
  };
  for (const auto& [id, path] : objects) {
    const cv::Scalar colour = colourOfId(id);
    const auto points = polyline(path.p_world, colour, 2);
    if (points.empty()) continue;
    cv::circle(out, points.back(), 5, colour, cv::FILLED, cv::LINE_AA);
    // Appended rather than "#" + ...: GCC 12 warns falsely on that form (-Wrestrict, its bug
    // 105651) in optimised builds.
    std::string label = "#";
    label += std::to_string(id);
    label += ' ';
    label += path.class_name;
    cv::putText(out, label, points.back() + cv::Point(6, -6), cv::FONT_HERSHEY_SIMPLEX, 0.45,
                cv::Scalar(0, 0, 0), 1, cv::LINE_AA);
  }
  const auto wearer = polyline(wearer_path_world, cv::Scalar(255, 80, 0), 3);
  if (!wearer.empty()) {
    cv::circle(out, wearer.front(), 6, cv::Scalar(0, 160, 0), cv::FILLED, cv::LINE_AA);
    cv::circle(out, wearer.back(), 6, cv::Scalar(0, 0, 200), cv::FILLED, cv::LINE_AA);
  }
  // Legend and scale bar (1 m).
  const int bar = int(1.0 / grid.cell_m * scale_px);
  cv::line(out, {10, out.rows - 12}, {10 + bar, out.rows - 12}, cv::Scalar(0, 0, 0), 3);
  cv::putText(out, "1 m", {14 + bar, out.rows - 8}, cv::FONT_HERSHEY_SIMPLEX, 0.45,
              cv::Scalar(0, 0, 0), 1, cv::LINE_AA);
  cv::putText(out, "wearer (blue): start green, end red; objects: one colour per id", {10, 18},
              cv::FONT_HERSHEY_SIMPLEX, 0.45, cv::Scalar(0, 0, 0), 1, cv::LINE_AA);
  return out;
}

}  // namespace dynanav
