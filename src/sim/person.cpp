#include "sim/person.hpp"

#include <cmath>

namespace dynanav::sim {

namespace {
// Body proportions (m) for a 1.75 m adult; every person is scaled by a random factor.
constexpr float kHipY = 0.88f, kShoulderY = 1.45f;
constexpr float kThigh = 0.45f, kShin = 0.43f, kUpperArm = 0.30f, kForearm = 0.28f;

/// A box hanging below its joint (the mesh origin), so rotating the mesh swings the limb.
std::unique_ptr<Mesh> limb(float length, float width, float depth, int texture, float tpm,
                           float offset) {
  auto m = std::make_unique<Mesh>();
  m->addBox(Vec3f(0, -length / 2, 0), Vec3f(width, length, depth), texture, tpm, offset);
  return m;
}

Pose3f rotX(float angle) {
  Pose3f T = Pose3f::Identity();
  T.linear() = Eigen::AngleAxisf(angle, Vec3f::UnitX()).toRotationMatrix();
  return T;
}
Pose3f translate(const Vec3f& t) {
  Pose3f T = Pose3f::Identity();
  T.translation() = t;
  return T;
}
}  // namespace

Person::Person(World& world, Rng& rng, float tpm) {
  scale_ = rng.uniform(0.9, 1.08);
  const auto tex = [&](const cv::Mat& img) { return world.addTexture(img); };
  const cv::Size cloth(int(1.2f * tpm), int(1.2f * tpm));
  const int shirt = tex(fabric(cloth, rng));
  const int trousers = tex(fabric(cloth, rng));
  const int shoes = tex(plaster(cv::Size(64, 64), rng));
  const int head = tex(headTexture(cv::Size(int(0.66f * tpm), int(0.23f * tpm)), rng));
  const int hair = tex(plaster(cv::Size(64, 64), rng));
  const float s = float(scale_);
  parts_[kTorso] = std::make_unique<Mesh>();
  parts_[kTorso]->addBox(Vec3f(0, 0, 0), Vec3f(0.40f, 0.62f, 0.23f) * s, shirt, tpm);
  // Head: the face texture's middle third lands on the front (+z) face.
  parts_[kHead] = std::make_unique<Mesh>();
  const float hw = 0.19f * s, hh = 0.23f * s;
  const Vec2f third(0.22f * tpm, 0.0f);
  parts_[kHead]->addBox(
      Vec3f(0, 0, 0), Vec3f(hw, hh, 0.21f * s), {head, head, hair, hair, head, head}, tpm,
      {Vec2f(0, 0), Vec2f(0, 0), Vec2f(0, 0), Vec2f(0, 0), third, Vec2f(0.44f * tpm, 0)});
  parts_[kUpperArmL] = limb(kUpperArm * s, 0.09f * s, 0.10f * s, shirt, tpm, 11.0f);
  parts_[kUpperArmR] = limb(kUpperArm * s, 0.09f * s, 0.10f * s, shirt, tpm, 53.0f);
  parts_[kForearmL] = limb(kForearm * s, 0.075f * s, 0.085f * s, head, tpm, 0.0f);
  parts_[kForearmR] = limb(kForearm * s, 0.075f * s, 0.085f * s, head, tpm, 0.0f);
  parts_[kThighL] = limb(kThigh * s, 0.15f * s, 0.16f * s, trousers, tpm, 7.0f);
  parts_[kThighR] = limb(kThigh * s, 0.15f * s, 0.16f * s, trousers, tpm, 91.0f);
  parts_[kShinL] = limb(kShin * s, 0.12f * s, 0.13f * s, trousers, tpm, 33.0f);
  parts_[kShinR] = limb(kShin * s, 0.12f * s, 0.13f * s, trousers, tpm, 71.0f);
  for (Part foot : {kFootL, kFootR}) {
    parts_[foot] = std::make_unique<Mesh>();
    parts_[foot]->addBox(Vec3f(0, -0.035f * s, 0.05f * s), Vec3f(0.10f, 0.07f, 0.25f) * s, shoes,
                         tpm);
  }
}

void Person::draw(const BodyPose& pose, uint16_t id, std::vector<DrawItem>& out) const {
  const float s = float(scale_);
  Pose3f T_room_body = Pose3f::Identity();
  T_room_body.linear() =
      Eigen::AngleAxisf(float(pose.heading_rad), Vec3f::UnitY()).toRotationMatrix();
  T_room_body.translation() = Vec3f(float(pose.position.x()), 0.0f, float(pose.position.y()));
  const auto add = [&](Part p, const Pose3f& T_body_part) {
    out.push_back({parts_[p].get(), T_room_body * T_body_part, id});
  };

  // Gait: one stride (two steps) per ~1.3 m; hips swing +-25 deg, knees bend in the swing
  // phase, arms swing against the legs. rotX(-a) swings a hanging limb forward by a.
  const double phase = 2.0 * M_PI * pose.distance_m / (1.3 * scale_);
  const float w = float(pose.walking);
  const float hip = 0.44f * w * float(std::sin(phase));
  const float knee_l = 0.6f * w * float(std::max(0.0, std::sin(phase + 1.2)));
  const float knee_r = 0.6f * w * float(std::max(0.0, std::sin(phase + 1.2 + M_PI)));
  const float arm =
      pose.pushing ? 0.85f : 0.35f * w * float(std::sin(phase));  // pushing: hands at ~1 m
  const float elbow = pose.pushing ? 0.2f : 0.25f;

  add(kTorso, translate(Vec3f(0, float(torsoCentreHeight()), 0)));
  add(kHead, translate(Vec3f(0, (kShoulderY + 0.07f + 0.115f) * s, 0)));
  for (int side = 0; side < 2; ++side) {
    const float sign = side == 0 ? 1.0f : -1.0f;  // left leg forward when sin(phase) > 0
    const Pose3f hip_joint = translate(Vec3f(sign * 0.1f * s, kHipY * s, 0)) * rotX(-sign * hip);
    add(side == 0 ? kThighL : kThighR, hip_joint);
    const Pose3f knee_joint =
        hip_joint * translate(Vec3f(0, -kThigh * s, 0)) * rotX(side == 0 ? knee_l : knee_r);
    add(side == 0 ? kShinL : kShinR, knee_joint);
    add(side == 0 ? kFootL : kFootR, knee_joint * translate(Vec3f(0, -kShin * s, 0)));
    const float swing = pose.pushing ? arm : -sign * arm;  // arms swing against the legs
    const Pose3f shoulder = translate(Vec3f(sign * 0.245f * s, kShoulderY * s, 0)) * rotX(-swing);
    add(side == 0 ? kUpperArmL : kUpperArmR, shoulder);
    add(side == 0 ? kForearmL : kForearmR,
        shoulder * translate(Vec3f(0, -kUpperArm * s, 0)) * rotX(-elbow));
  }
}

}  // namespace dynanav::sim
