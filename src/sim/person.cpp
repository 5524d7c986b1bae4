#include "sim/person.hpp"

#include <cmath>

#include "sim/body_textures.hpp"

namespace dynanav::sim {

namespace {
// Joint heights and segment lengths (m) for a 1.75 m adult; every person is scaled by a random
// factor. Profiles are (y, radius_x, radius_z) from top to bottom (Mesh::addLathe).
constexpr float kHipY = 0.93f, kHipX = 0.09f, kShoulderY = 1.42f, kShoulderX = 0.19f;
constexpr float kThigh = 0.43f, kShin = 0.42f, kUpperArm = 0.29f, kForearm = 0.25f;
constexpr float kHeadCentreY = 1.665f;
constexpr int kSides = 16;

using Profile = std::vector<Vec3f>;

Profile scaled(Profile p, float s) {
  for (Vec3f& v : p) v *= s;
  return p;
}
float circumference(const Profile& p) {
  float r = 0.0f;
  for (const Vec3f& v : p) r = std::max(r, 0.5f * (v.y() + v.z()));
  return 2.0f * float(M_PI) * r;
}
float length(const Profile& p) {
  return p.front().x() - p.back().x();
}

/// Adds a lathe whose texture keeps `tpm` texels per metre (clothing, skin).
void addPart(Mesh& m, const Profile& p, int texture, float tpm,
             const Pose3f& T = Pose3f::Identity()) {
  m.addLathe(p, kSides, texture, Vec2f(circumference(p) * tpm, length(p) * tpm), T);
}

/// An ellipsoidal head: radii (x, y, z) round `centre_y`, the jaw narrowing below the middle.
Profile headProfile(float rx, float ry, float rz, int rings) {
  Profile p;
  for (int i = 0; i <= rings; ++i) {
    const float theta = float(M_PI) * float(i) / float(rings);
    const float below = std::max(0.0f, -std::cos(theta));
    const float jaw = 1.0f - 0.22f * below * below;
    p.emplace_back(ry * std::cos(theta), rx * std::sin(theta) * jaw,
                   rz * std::sin(theta) * (1.0f - 0.1f * below));
  }
  return p;
}

Pose3f rotX(float angle) {
  Pose3f T = Pose3f::Identity();
  T.linear() = Eigen::AngleAxisf(angle, Vec3f::UnitX()).toRotationMatrix();
  return T;
}
Pose3f rotZ(float angle) {
  Pose3f T = Pose3f::Identity();
  T.linear() = Eigen::AngleAxisf(angle, Vec3f::UnitZ()).toRotationMatrix();
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
  const float s = float(scale_);
  const BodyColours colours = randomBodyColours(rng);
  const auto tex = [&](const cv::Mat& img) { return world.addTexture(img); };
  const int tpm_i = int(tpm);
  const int shirt =
      tex(garmentTexture({tpm_i, tpm_i * 3 / 4}, colours.shirt, colours.shirt_pattern, rng));
  const int trousers = tex(garmentTexture({tpm_i, tpm_i}, colours.trousers, 3, rng));
  const int shoes = tex(garmentTexture({64, 64}, colours.shoes, 0, rng));
  const int skin = tex(skinTexture({tpm_i / 2, tpm_i / 2}, colours, rng));
  // The face gets a finer texture than clothing: it is what detectors look at first.
  const int face = tex(faceTexture({480, 256}, colours, rng));

  auto& body = parts_[kBody] = std::make_unique<Mesh>();
  body->addLathe(scaled(headProfile(0.078f, 0.115f, 0.097f, 14), s), kSides, face, Vec2f(480, 256),
                 translate(Vec3f(0, kHeadCentreY * s, 0.005f * s)));
  addPart(*body, scaled({{1.61f, 0.05f, 0.05f}, {1.47f, 0.058f, 0.056f}}, s), skin, tpm,
          translate(Vec3f(0, 0, -0.01f * s)));
  addPart(*body,
          // Shoulders slope down from the collar, as people's do; a square top reads as a box.
          scaled({{1.53f, 0.055f, 0.05f},
                  {1.515f, 0.09f, 0.07f},
                  {1.49f, 0.14f, 0.09f},
                  {1.455f, 0.175f, 0.105f},
                  {1.40f, 0.188f, 0.115f},
                  {1.25f, 0.172f, 0.12f},
                  {1.10f, 0.157f, 0.105f},
                  {0.99f, 0.163f, 0.103f},
                  {0.96f, 0.166f, 0.104f}},
                 s),
          shirt, tpm);
  addPart(*body,
          scaled({{1.0f, 0.161f, 0.101f},
                  {0.90f, 0.172f, 0.106f},
                  {0.82f, 0.15f, 0.096f},
                  {0.77f, 0.04f, 0.04f}},
                 s),
          trousers, tpm);

  for (int side = 0; side < 2; ++side) {
    const Profile upper = scaled({{0.05f, 0.0f, 0.0f},
                                  {0.035f, 0.045f, 0.047f},
                                  {0.0f, 0.056f, 0.057f},
                                  {-0.12f, 0.05f, 0.052f},
                                  {-0.27f, 0.04f, 0.043f},
                                  {-0.31f, 0.033f, 0.035f}},
                                 s);
    auto& arm = parts_[side == 0 ? kUpperArmL : kUpperArmR] = std::make_unique<Mesh>();
    if (colours.long_sleeves) {
      addPart(*arm, upper, shirt, tpm);
    } else {
      addPart(*arm, upper, skin, tpm);
      // A short sleeve over the top of the arm, a little wider than the skin below it.
      addPart(*arm,
              scaled({{0.05f, 0.0f, 0.0f},
                      {0.036f, 0.052f, 0.054f},
                      {0.0f, 0.064f, 0.065f},
                      {-0.15f, 0.058f, 0.06f}},
                     s),
              shirt, tpm);
    }
    auto& fore = parts_[side == 0 ? kForearmL : kForearmR] = std::make_unique<Mesh>();
    addPart(*fore,
            scaled({{0.025f, 0.036f, 0.038f},
                    {-0.07f, 0.042f, 0.043f},
                    {-0.23f, 0.03f, 0.026f},
                    {-0.26f, 0.028f, 0.024f}},
                   s),
            colours.long_sleeves ? shirt : skin, tpm);
    // The hand hangs palm inwards: thin across (x), wide front to back (z).
    addPart(*fore,
            scaled({{-0.235f, 0.016f, 0.026f},
                    {-0.28f, 0.02f, 0.044f},
                    {-0.36f, 0.018f, 0.043f},
                    {-0.41f, 0.013f, 0.028f},
                    {-0.43f, 0.0f, 0.0f}},
                   s),
            skin, tpm);
    auto& thigh = parts_[side == 0 ? kThighL : kThighR] = std::make_unique<Mesh>();
    addPart(*thigh,
            scaled({{0.04f, 0.06f, 0.065f},
                    {0.0f, 0.083f, 0.088f},
                    {-0.2f, 0.072f, 0.076f},
                    {-0.41f, 0.056f, 0.058f},
                    {-0.45f, 0.05f, 0.052f}},
                   s),
            trousers, tpm);
    auto& shin = parts_[side == 0 ? kShinL : kShinR] = std::make_unique<Mesh>();
    addPart(*shin,
            scaled({{0.02f, 0.054f, 0.056f},
                    {-0.12f, 0.055f, 0.06f},
                    {-0.36f, 0.042f, 0.044f},
                    {-0.42f, 0.04f, 0.042f}},
                   s),
            trousers, tpm);
    // The foot: a lathe along the walking direction (lathe y -> body +z), its sole on the floor.
    auto& foot = parts_[side == 0 ? kFootL : kFootR] = std::make_unique<Mesh>();
    addPart(*foot,
            scaled({{0.2f, 0.0f, 0.0f},
                    {0.19f, 0.03f, 0.025f},
                    {0.15f, 0.047f, 0.036f},
                    {0.03f, 0.048f, 0.042f},
                    {-0.05f, 0.04f, 0.04f},
                    {-0.07f, 0.0f, 0.0f}},
                   s),
            shoes, tpm, translate(Vec3f(0, -0.04f * s, 0)) * rotX(float(M_PI) / 2.0f));
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
  // phase, arms swing against the legs with the elbow bending as the arm comes forward.
  // rotX(-a) swings a hanging limb forward by a.
  const double phase = 2.0 * M_PI * pose.distance_m / (1.3 * scale_);
  const float w = float(pose.walking);
  const float hip = 0.44f * w * float(std::sin(phase));
  const float knee_l = 0.6f * w * float(std::max(0.0, std::sin(phase + 1.2)));
  const float knee_r = 0.6f * w * float(std::max(0.0, std::sin(phase + 1.2 + M_PI)));
  const float arm =
      pose.pushing ? 0.85f : 0.4f * w * float(std::sin(phase));  // pushing: hands at ~1 m

  add(kBody, Pose3f::Identity());
  for (int side = 0; side < 2; ++side) {
    const float sign = side == 0 ? 1.0f : -1.0f;  // left leg forward when sin(phase) > 0
    const Pose3f hip_joint = translate(Vec3f(sign * kHipX * s, kHipY * s, 0)) * rotX(-sign * hip);
    add(side == 0 ? kThighL : kThighR, hip_joint);
    const Pose3f knee_joint =
        hip_joint * translate(Vec3f(0, -kThigh * s, 0)) * rotX(side == 0 ? knee_l : knee_r);
    add(side == 0 ? kShinL : kShinR, knee_joint);
    add(side == 0 ? kFootL : kFootR, knee_joint * translate(Vec3f(0, -kShin * s, 0)));
    const float swing = pose.pushing ? arm : -sign * arm;  // arms swing against the legs
    // Arms hang a little away from the body (abduction) so the hands clear the hips.
    const Pose3f shoulder = translate(Vec3f(sign * kShoulderX * s, kShoulderY * s, 0)) *
                            rotZ(sign * 0.11f) * rotX(-swing);
    add(side == 0 ? kUpperArmL : kUpperArmR, shoulder);
    const float elbow = pose.pushing ? 0.2f : 0.15f + 0.35f * std::max(0.0f, swing);
    add(side == 0 ? kForearmL : kForearmR,
        shoulder * translate(Vec3f(0, -kUpperArm * s, 0)) * rotX(-elbow));
  }
}

}  // namespace dynanav::sim
