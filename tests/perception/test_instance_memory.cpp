// Instance memory: an instance the segmenter loses for a frame is carried by flow for at most
// mask_memory_frames frames; fresh instances always win.
#include <gtest/gtest.h>

#include <deque>

#include "perception/instance_memory.hpp"
#include "perception/segmenter.hpp"
#include "synthetic_scene.hpp"

using namespace dynanav;

namespace {

constexpr int kShiftPx = 3;  // the scene moves right by this much per frame
const cv::Size kSize(320, 240);
const cv::Rect kSquare(100, 80, 60, 60);  // the person at frame 0, 1.5 m in front of a 3 m wall

RgbdFrame frameAt(int index, const cv::Mat& tex) {
  RgbdFrame f;
  f.index = index;
  f.bgr = test::shifted(tex, kShiftPx * index, 0);
  f.depth_m = cv::Mat(kSize, CV_32F, cv::Scalar(3.0f));
  f.depth_m(kSquare + cv::Point(kShiftPx * index, 0)).setTo(1.5f);
  return f;
}

Instances personAt(int index, uint16_t id = 1) {
  const cv::Rect box = kSquare + cv::Point(kShiftPx * index, 0);
  Instances out = Instances::none(kSize);
  out.labels(box).setTo(id);
  out.items = {{id, "person", 1.f, box, "file", {}}};
  return out;
}

/// Plays back a script: per call, the person or nothing.
struct Scripted final : Segmenter {
  std::deque<bool> person_seen;
  int calls = 0;
  explicit Scripted(std::deque<bool> script) : person_seen(std::move(script)) {}
  Instances segment(const RgbdFrame& f) override {
    const bool seen = person_seen.empty() ? true : person_seen.front();
    if (!person_seen.empty()) person_seen.pop_front();
    ++calls;
    return seen ? personAt(f.index) : Instances::none(f.bgr.size());
  }
  std::string name() const override { return "scripted"; }
};

TEST(InstanceMemory, ALostPersonIsCarriedForAtMostTheMemoryFrames) {
  const cv::Mat tex = test::texture(kSize, 7);
  // Seen in frames 0-1, lost in 2-6.
  RememberingSegmenter memory(
      std::make_unique<Scripted>(std::deque<bool>{true, true, false, false, false, false, false}),
      3, PerceptionConfig{});
  EXPECT_EQ(memory.name(), "scripted");
  for (int i = 0; i < 7; ++i) {
    const Instances out = memory.segment(frameAt(i, tex));
    if (i < 2) {
      ASSERT_EQ(out.items.size(), 1u);
      EXPECT_EQ(out.items[0].mask_source, "file");
    } else if (i < 5) {  // carried in frames 2, 3, 4
      ASSERT_EQ(out.items.size(), 1u) << "frame " << i;
      EXPECT_EQ(out.items[0].mask_source, "memory");
      EXPECT_EQ(out.items[0].id, 1);
      const cv::Rect truth = kSquare + cv::Point(kShiftPx * i, 0);
      EXPECT_NEAR(out.items[0].box.x, truth.x, 2) << "frame " << i;
      EXPECT_GT(cv::countNonZero(out.mask(1)(truth)), 0.9 * truth.area()) << "frame " << i;
    } else {
      EXPECT_TRUE(out.items.empty()) << "frame " << i << ": carried longer than 3 frames";
    }
  }
  EXPECT_EQ(memory.carriedCount(), 3);
}

TEST(InstanceMemory, ASegmentedInstanceIsNeverOverwritten) {
  const cv::Mat tex = test::texture(kSize, 9);
  // Frame 0: a person and a chair; frame 1: the segmenter misses the person but finds the chair
  // again and a new bag where the person stands.
  struct TwoThenOne final : Segmenter {
    int call = 0;
    Instances segment(const RgbdFrame& f) override {
      Instances out = call++ == 0 ? personAt(f.index) : Instances::none(f.bgr.size());
      const cv::Rect chair(200, 150, 40, 40), bag(110, 80, 40, 40);
      out.labels(chair).setTo(2);
      out.items.push_back({2, "chair", 1.f, chair, "depth", {}});
      if (call == 2) {
        out.labels(bag).setTo(3);
        out.items.push_back({3, "handbag", 1.f, bag, "depth", {}});
      }
      return out;
    }
    std::string name() const override { return "two"; }
  };
  RememberingSegmenter memory(std::make_unique<TwoThenOne>(), 3, PerceptionConfig{});
  (void)memory.segment(frameAt(0, tex));
  const Instances out = memory.segment(frameAt(1, tex));
  ASSERT_EQ(out.items.size(), 3u);
  const Instance* person = out.find(1);
  ASSERT_NE(person, nullptr);
  EXPECT_EQ(person->mask_source, "memory");
  EXPECT_EQ(out.find(2)->mask_source, "depth");  // the chair was seen again: not carried
  EXPECT_EQ(out.area(3), 40 * 40);               // the fresh bag keeps all of its pixels
  EXPECT_GT(out.area(1), 0.5 * kSquare.area());
}

TEST(InstanceMemory, ASeenInstanceIsNotDuplicated) {
  const cv::Mat tex = test::texture(kSize, 11);
  RememberingSegmenter memory(std::make_unique<Scripted>(std::deque<bool>{}), 3,
                              PerceptionConfig{});
  for (int i = 0; i < 4; ++i) {
    const Instances out = memory.segment(frameAt(i, tex));
    ASSERT_EQ(out.items.size(), 1u);
    EXPECT_EQ(out.items[0].mask_source, "file");
  }
  EXPECT_EQ(memory.carriedCount(), 0);
}

TEST(InstanceMemory, CounterpartNeedsTheSameClassAndAnOverlappingBox) {
  Instance old{1, "person", 1.f, cv::Rect(0, 0, 50, 100), "file", {}};
  Instances fresh = Instances::none(kSize);
  fresh.items = {{4, "chair", 1.f, cv::Rect(0, 0, 50, 100), "depth", {}}};
  EXPECT_FALSE(hasCounterpart(old, fresh, 0.1));  // another class at the same place
  fresh.items.push_back({5, "person", 1.f, cv::Rect(200, 0, 50, 100), "selfie", {}});
  EXPECT_FALSE(hasCounterpart(old, fresh, 0.1));  // another person elsewhere
  fresh.items.push_back({6, "person", 1.f, cv::Rect(10, 5, 50, 100), "selfie", {}});
  EXPECT_TRUE(hasCounterpart(old, fresh, 0.1));
}

}  // namespace
