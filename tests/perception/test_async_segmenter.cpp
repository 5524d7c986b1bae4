// The real-time segmenter thread: results arrive asynchronously and are carried to each frame.
#include <gtest/gtest.h>

#include <chrono>
#include <opencv2/imgproc.hpp>
#include <thread>

#include "core/error.hpp"
#include "perception/async_segmenter.hpp"

using namespace dynanav;

namespace {

constexpr int kShiftPx = 2;  // the scene moves right by 2 px per frame

RgbdFrame frameAt(int index, const cv::Mat& texture) {
  RgbdFrame f;
  f.index = index;
  cv::warpAffine(texture, f.bgr, cv::Matx23d(1, 0, kShiftPx * index, 0, 1, 0), texture.size(),
                 cv::INTER_NEAREST, cv::BORDER_REFLECT);
  return f;
}

cv::Rect truthAt(int index) {
  return {60 + kShiftPx * index, 50, 40, 60};
}

/// Labels the true square of the frame it is given (the scene's ground truth).
struct TruthSegmenter final : Segmenter {
  bool fail = false;
  Instances segment(const RgbdFrame& f) override {
    if (fail) throw InputError("fake", "segmenter failed");
    Instances out = Instances::none(f.bgr.size());
    out.labels(truthAt(f.index)).setTo(1);
    out.items = {{1, "person", 1.f, truthAt(f.index), "file", {}}};
    return out;
  }
  std::string name() const override { return "truth"; }
};

/// Waits (test only) until `done()` or 5 s pass.
template <class F>
bool waitFor(F&& done) {
  const auto until = std::chrono::steady_clock::now() + std::chrono::seconds(5);
  for (;;) {
    if (done()) return true;
    if (std::chrono::steady_clock::now() > until) return false;
    std::this_thread::yield();
  }
}

cv::Mat texture() {
  cv::Mat t(160, 240, CV_8UC3);
  cv::RNG rng(11);
  rng.fill(t, cv::RNG::UNIFORM, 0, 255);
  cv::GaussianBlur(t, t, cv::Size(0, 0), 2.0);
  return t;
}

TEST(AsyncSegmenter, CarriesTheNewestResultToEveryFrame) {
  const cv::Mat tex = texture();
  AsyncSegmenter segmenter(std::make_unique<TruthSegmenter>(), PerceptionConfig{});
  EXPECT_EQ(segmenter.name(), "truth/async");
  // The first frame is segmented at once (the map is initialised from it), the rest by the worker.
  const Instances first = segmenter.segment(frameAt(0, tex));
  ASSERT_EQ(first.items.size(), 1u);
  EXPECT_EQ(first.items[0].box, truthAt(0));
  EXPECT_EQ(segmenter.finished(), 0);
  EXPECT_EQ(segmenter.segment(frameAt(1, tex)).items.size(), 1u);  // frame 0 carried by flow
  ASSERT_TRUE(waitFor([&] { return segmenter.finished() >= 1; }));
  for (int i = 2; i < 15; ++i) {
    const Instances out = segmenter.segment(frameAt(i, tex));
    ASSERT_EQ(out.items.size(), 1u) << "frame " << i;
    const cv::Rect box = out.items[0].box, truth = truthAt(i);
    EXPECT_LE(std::abs(box.x - truth.x), 3) << "frame " << i;
    EXPECT_LE(std::abs(box.width - truth.width), 4) << "frame " << i;
  }
  EXPECT_GE(segmenter.finished(), 1);
  EXPECT_LE(segmenter.finished(), 15);
}

TEST(AsyncSegmenter, RethrowsTheWorkersError) {
  auto inner = std::make_unique<TruthSegmenter>();
  inner->fail = true;
  AsyncSegmenter segmenter(std::move(inner), PerceptionConfig{});
  const cv::Mat tex = texture();
  bool thrown = waitFor([&] {
    try {
      (void)segmenter.segment(frameAt(0, tex));
    } catch (const InputError&) {
      return true;
    }
    return false;
  });
  EXPECT_TRUE(thrown);
}

}  // namespace
