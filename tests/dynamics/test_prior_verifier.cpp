#include <gtest/gtest.h>

#include <algorithm>
#include <opencv2/imgproc.hpp>

#include "dynamics/prior_verifier.hpp"

using namespace dynanav;

namespace {
constexpr int kWidth = 640, kHeight = 480;
constexpr uint16_t kChair = 1, kPerson = 2;
const cv::Rect kChairBox(200, 150, 80, 150);
const cv::Rect kPersonBox(420, 100, 60, 250);

PinholeCamera camera() {
  PinholeCamera c;
  c.width = kWidth;
  c.height = kHeight;
  c.fx = c.fy = 525;
  c.cx = 320;
  c.cy = 240;
  return c;
}

cv::Mat texture(int seed) {
  cv::Mat t(kHeight, kWidth, CV_8U);
  cv::theRNG().state = uint64_t(seed);
  cv::randu(t, 0, 255);
  cv::GaussianBlur(t, t, cv::Size(7, 7), 2.0);
  return t;
}

cv::Mat shifted(const cv::Mat& image, double dx_px, int interpolation) {
  const cv::Mat A = (cv::Mat_<double>(2, 3) << 1, 0, dx_px, 0, 1, 0);
  cv::Mat out;
  cv::warpAffine(image, out, A, image.size(), interpolation, cv::BORDER_REFLECT);
  return out;
}

/// One frame: grey image, the labels of a chair and a person, depth 2 m everywhere.
struct Scene {
  cv::Mat grey;
  Instances instances;
};

Instances labelled(double chair_dx_px, double person_dx_px) {
  Instances inst;
  inst.labels = cv::Mat(kHeight, kWidth, CV_16U, cv::Scalar(0));
  inst.labels(kChairBox + cv::Point(int(chair_dx_px), 0)).setTo(kChair);
  inst.labels(kPersonBox + cv::Point(int(person_dx_px), 0)).setTo(kPerson);
  for (const auto& [id, name] : {std::pair{kChair, "chair"}, std::pair{kPerson, "person"}}) {
    Instance& instance = inst.items.emplace_back();
    instance.id = id;
    instance.class_name = name;
  }
  return inst;
}

/// Runs the verifier over `frames` (the pose says the camera never moved) and returns whether
/// the chair was found moving in any frame with a verdict.
bool chairFoundMoving(const std::vector<Scene>& frames, const DynamicsConfig& config) {
  PriorVerifier verifier(config);
  const cv::Mat depth(kHeight, kWidth, CV_32F, cv::Scalar(2.f));
  const PinholeCamera cam = camera();
  const SE3 pose = SE3::Identity();
  bool moving = false;
  for (const Scene& f : frames) {
    cv::Mat grey_half;
    cv::resize(f.grey, grey_half, cv::Size(), 0.5, 0.5, cv::INTER_AREA);
    const PriorVerdicts v = verifier.verify({grey_half, depth, f.instances, pose, true, cam}, {});
    moving = moving || std::count(v.moving_ids.begin(), v.moving_ids.end(), kChair) > 0;
  }
  return moving;
}
}  // namespace

TEST(PriorVerifier, AChairWhoseSurroundingsShowTheSameFlowIsNotFoundMoving) {
  // The whole image slides 4 px per frame while the pose says the camera stood still (a pose or
  // a flow off by 12 px over the verifier's 3 frames: 4.6 cm at 2 m). Against the camera's
  // motion alone the chair moves; against its surroundings it does not.
  const cv::Mat t = texture(1);
  std::vector<Scene> frames;
  for (int k = 0; k < 6; ++k)
    frames.push_back({shifted(t, 4.0 * k, cv::INTER_LINEAR), labelled(4.0 * k, 4.0 * k)});
  DynamicsConfig config;
  EXPECT_FALSE(chairFoundMoving(frames, config));
  config.scene_flow_reference_px = 0;
  EXPECT_TRUE(chairFoundMoving(frames, config));
}

TEST(PriorVerifier, AChairPushedPastStillSurroundingsIsFoundMoving) {
  // The chair alone slides 4 px per frame (1.4 cm at 2 m, 0.4 m/s at 30 frames/s) over a still
  // background.
  const cv::Mat background = texture(2), chair = texture(3);
  std::vector<Scene> frames;
  for (int k = 0; k < 6; ++k) {
    cv::Mat grey = background.clone();
    const cv::Mat moved = shifted(chair, 4.0 * k, cv::INTER_LINEAR);
    const cv::Rect box = kChairBox + cv::Point(4 * k, 0);
    moved(box).copyTo(grey(box));
    frames.push_back({grey, labelled(4.0 * k, 0.0)});
  }
  EXPECT_TRUE(chairFoundMoving(frames, DynamicsConfig{}));
}

TEST(PriorVerifier, APersonsMaskGrownOverAnOccluderReadsOnlyTheBodysFlow) {
  // A person 4 m away walks straight at the camera at 0.35 m/s (the image barely moves: 3.5 cm
  // nearer over the verifier's 3 frames), and the mask is grown over a static pillar 2 m away
  // beside it, almost as wide as the body. All points together move 1.8 cm on average, under the
  // 2 cm a still object may move: "verified static". The body's points alone move 3.5 cm.
  const cv::Mat grey = texture(4);
  const cv::Rect body(400, 100, 40, 250), pillar(440, 100, 36, 250);
  Instances instances;
  instances.labels = cv::Mat(kHeight, kWidth, CV_16U, cv::Scalar(0));
  instances.labels(body | pillar).setTo(kPerson);
  Instance& person = instances.items.emplace_back();
  person.id = kPerson;
  person.class_name = "person";
  cv::Mat grey_half;
  cv::resize(grey, grey_half, cv::Size(), 0.5, 0.5, cv::INTER_AREA);
  const PinholeCamera cam = camera();
  const SE3 pose = SE3::Identity();
  const auto verifiedStatic = [&](const DynamicsConfig& config) {
    PriorVerifier verifier(config);
    bool held = false;
    for (int k = 0; k < 6; ++k) {
      cv::Mat depth(kHeight, kWidth, CV_32F, cv::Scalar(6.f));
      depth(pillar).setTo(2.f);
      depth(body).setTo(4.f - 0.35f / 30.f * float(k));
      const PriorVerdicts v = verifier.verify({grey_half, depth, instances, pose, true, cam}, {});
      // From frame 3 on the verifier compares frames 3 apart (before, fewer: 1.2 cm a frame).
      if (k >= 3) held = held || std::count(v.static_ids.begin(), v.static_ids.end(), kPerson) > 0;
    }
    return held;
  };
  DynamicsConfig config;
  EXPECT_FALSE(verifiedStatic(config));
  config.scene_flow_prior_depth_band_m = 0;
  EXPECT_TRUE(verifiedStatic(config));
}
