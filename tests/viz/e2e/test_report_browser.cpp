// report.html in a real browser (issue 15): headless Chromium loads the page with every network
// request refused, runs its inline script and dumps the DOM; the plots and the message list must
// be there, and no element may reference anything but inline data.
#include <gtest/gtest.h>

#include <cstdio>

#include "support/test_support.hpp"

namespace fs = std::filesystem;
using dynanav::test::readFile;
using dynanav::test::runCli;
using dynanav::test::scratchDir;

namespace dynanav {
namespace {

/// Runs a shell command, returning its exit status and stdout.
int shell(const std::string& command, std::string& out) {
  FILE* pipe = popen(command.c_str(), "r");
  if (!pipe) return -1;
  char buffer[4096];
  for (size_t n; (n = fread(buffer, 1, sizeof buffer, pipe)) > 0;) out.append(buffer, n);
  return pclose(pipe);
}

std::string chromium() {
  for (const char* name : {"chromium", "chromium-browser", "google-chrome"}) {
    std::string out;
    if (shell(std::string("command -v ") + name + " 2>/dev/null", out) == 0 && !out.empty())
      return name;
  }
  return "";
}

TEST(ReportBrowser, ChromiumRendersPlotsAndMessagesWithoutNetwork) {
  const std::string browser = chromium();
  if (browser.empty())
    GTEST_SKIP() << "no chromium on PATH (scripts/setup.sh installs it): skipped";
  const fs::path dir = scratchDir("report_browser");
  std::string log;
  ASSERT_EQ(runCli("simulate --scenario office --frames 90 --out " + (dir / "seq").string(), &log),
            0)
      << log;
  ASSERT_EQ(runCli("run " + (dir / "seq").string() + " --out " + (dir / "out").string() +
                       " --segmenter masks --all-outputs --quiet",
                   &log),
            0)
      << log;
  const fs::path report = dir / "out" / "report.html";
  ASSERT_TRUE(fs::is_regular_file(report));
  // --no-sandbox: CI runs as root; the resolver rule makes any host lookup fail, so a page that
  // needed the network would show it.
  std::string dom;
  const int status =
      shell("timeout 60 " + browser +
                " --headless --no-sandbox --disable-gpu --no-first-run --disable-extensions "
                "--host-resolver-rules='MAP * ~NOTFOUND' --user-data-dir=" +
                (dir / "profile").string() + " --dump-dom file://" + fs::absolute(report).string() +
                " 2>" + (dir / "chromium.log").string(),
            dom);
  if (status != 0 || dom.find("<body") == std::string::npos)
    GTEST_SKIP() << "chromium could not start here (status " << status
                 << "): " << readFile(dir / "chromium.log").substr(0, 400);
  // The inline script ran in the browser and counted what it found.
  // (std::regex recurses per character and overflows the stack on the inline image: plain finds.)
  const size_t plots = dom.find("data-plots=\"");
  ASSERT_NE(plots, std::string::npos) << dom.substr(0, 500);
  EXPECT_GE(std::stoi(dom.substr(plots + 12)), 5);  // trajectory, ATE, timing, speeds, timeline
  for (const char* id : {"plot-trajectory", "plot-ate", "plot-timing", "plot-speeds",
                         "plot-timeline", "message-list"})
    EXPECT_NE(dom.find(std::string("id=\"") + id + "\""), std::string::npos) << id;
  EXPECT_NE(dom.find("<polyline"), std::string::npos);
  // Nothing outside the page: every src/href is inline data or a fragment, no <link>, no url().
  int references = 0;
  for (const std::string attribute : {" src=\"", " href=\""})
    for (size_t at = dom.find(attribute); at != std::string::npos;
         at = dom.find(attribute, at + 1)) {
      const std::string target = dom.substr(at + attribute.size(), 16);
      EXPECT_TRUE(target.rfind("data:", 0) == 0 || target.rfind("#", 0) == 0) << target;
      ++references;
    }
  EXPECT_GE(references, 1);  // the top view, inline
  EXPECT_EQ(dom.find("<link"), std::string::npos);
  EXPECT_EQ(dom.find("url("), std::string::npos);
}

}  // namespace
}  // namespace dynanav
