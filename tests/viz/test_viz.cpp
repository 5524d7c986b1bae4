// Unit tests of viz (issue 15): charts, the report page, drawing (video encoder:
// test_h264_file.cpp).
#include <gtest/gtest.h>

#include <opencv2/imgproc.hpp>
#include <regex>

#include "support/test_support.hpp"
#include "viz/annotate.hpp"
#include "viz/report_html.hpp"
#include "viz/svg_plot.hpp"
#include "viz/topview.hpp"

namespace dynanav {
namespace {

TEST(SvgPlot, OnePolylinePerSeriesWithItsPointsInsideTheFrame) {
  const std::string svg = svgLinePlot({"p", "title <&>", "x", "y", 400, 200},
                                      {{"a", {0, 1, 2}, {0, 1, 4}, 1}, {"b", {0, 2}, {1, 1}, 2}});
  EXPECT_NE(svg.find("title &lt;&amp;&gt;"), std::string::npos);
  const std::regex polyline("<polyline[^>]*points=\"([^\"]*)\"");
  int lines = 0;
  for (auto it = std::sregex_iterator(svg.begin(), svg.end(), polyline);
       it != std::sregex_iterator(); ++it, ++lines) {
    std::istringstream points((*it)[1].str());
    double x, y;
    char comma;
    while (points >> x >> comma >> y) {
      EXPECT_TRUE(x >= 0 && x <= 400 && y >= 0 && y <= 200) << x << "," << y;
    }
  }
  EXPECT_EQ(lines, 2);
}

TEST(Base64, KnownAnswers) {
  EXPECT_EQ(base64(""), "");
  EXPECT_EQ(base64("f"), "Zg==");
  EXPECT_EQ(base64("fo"), "Zm8=");
  EXPECT_EQ(base64("foobar"), "Zm9vYmFy");
}

TEST(ReportHtml, SelfContainedWithPlotsAndMessages) {
  ReportData d;
  d.sequence = "seq";
  d.stats = {{"frames", 10}, {"stage_ms", {{"tracking", {{"mean", 3.0}, {"count", 10}}}}}};
  d.speeds = {{"#1 person", {0, 1}, {0.5, 1.2}, 1}};
  FeedbackEvent e;
  e.stamp_s = 1.0;
  e.text = "person <ahead>";
  e.kind = "approaching";
  d.events = {e};
  d.accuracy_note = "no ground truth";
  d.topview_png = "\x89PNG";
  const std::string html = reportHtml(d);
  EXPECT_NE(html.find("id=\"plot-timing\""), std::string::npos);
  EXPECT_NE(html.find("id=\"plot-speeds\""), std::string::npos);
  EXPECT_NE(html.find("person &lt;ahead&gt;"), std::string::npos);
  EXPECT_NE(html.find("src=\"data:image/png;base64,"), std::string::npos);
  EXPECT_EQ(html.find("http://"), std::string::npos);
  EXPECT_EQ(html.find("https://"), std::string::npos);
}

TEST(Annotate, DrawsObjectsAndTheMessage) {
  const cv::Mat bgr(240, 320, CV_8UC3, cv::Scalar(0, 0, 0));
  PinholeCamera camera;
  camera.width = 320, camera.height = 240, camera.fx = camera.fy = 260, camera.cx = 160,
  camera.cy = 120;
  FrameAnnotation a;
  TrackedObject o;
  o.id = 3;
  o.p_camera = Vec3(0, 0, 2);
  o.v_world_mps = Vec3(1, 0, 0);
  o.speed_mps = 1.0;
  a.objects = {o};
  FeedbackEvent m;
  m.text = "stop";
  a.message = m;
  const cv::Mat out = annotateFrame(bgr, Instances::none(bgr.size()), camera, a);
  cv::Mat grey;
  cv::cvtColor(out, grey, cv::COLOR_BGR2GRAY);
  EXPECT_GT(cv::countNonZero(grey(cv::Rect(150, 100, 80, 40))), 20);  // the object's marker
  EXPECT_GT(cv::countNonZero(grey(cv::Rect(0, 215, 100, 25))), 20);   // the message
}

TEST(TopView, PathsAreDrawnOverTheGrid) {
  OccupancyGrid grid;
  grid.cells = cv::Mat(40, 40, CV_8U, cv::Scalar(OccupancyGrid::kFree));
  grid.cell_m = 0.1;
  grid.right0_m = -2, grid.forward0_m = 4;
  const cv::Mat out = drawTopView(grid, {Vec3(0, 0, 0), Vec3(0, 0, 3)}, {}, 4);
  ASSERT_EQ(out.size(), cv::Size(160, 160));
  // The wearer's path (blue) runs up the middle column.
  const cv::Vec3b mid = out.at<cv::Vec3b>(80, 80);
  EXPECT_GT(mid[0], 200);
  EXPECT_LT(mid[2], 100);
}

}  // namespace
}  // namespace dynanav
