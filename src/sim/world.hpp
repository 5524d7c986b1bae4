#pragma once
// The static world: rooms (floor, ceiling, walls with doorways) and furniture, all in one mesh in
// the room frame (x, z on the floor, y up, metres), with their textures.
#include <vector>

#include "sim/mesh.hpp"
#include "sim/path.hpp"
#include "sim/patterns.hpp"
#include "sim/texture.hpp"

namespace dynanav::sim {

struct World {
  TextureSet textures;
  Mesh static_mesh;
  int addTexture(const cv::Mat& bgr) {
    textures.emplace_back(bgr);
    return int(textures.size()) - 1;
  }
};

/// A doorway in one wall, between two coordinates along that wall (x for the south and north
/// walls, z for the west and east walls).
struct Doorway {
  enum Side { kSouth, kNorth, kWest, kEast } side = kSouth;
  double from = 0.0, to = 1.0;
  double height_m = 2.1;
  bool jambs = true;  ///< draw the wall's thickness (only one of two rooms sharing a wall should)
};

/// Places rooms and furniture; every surface gets its own texture, drawn from the scene's Rng.
class WorldBuilder {
 public:
  WorldBuilder(World& world, Rng& rng, const PhotoLibrary& photos, float texels_per_m = 200.0f)
      : world_(world), rng_(rng), photos_(photos), tpm_(texels_per_m) {}

  /// An axis-aligned room [min, max] on the floor, `height_m` tall, walls decorated.
  void room(const Vec2& min, const Vec2& max, double height_m,
            const std::vector<Doorway>& doorways = {});
  // Furniture stands on the floor at `at`, its front facing `yaw_rad` ((sin, cos) in (x, z)).
  void desk(const Vec2& at, double yaw_rad);
  void chair(const Vec2& at, double yaw_rad);
  void shelf(const Vec2& at, double yaw_rad, double width_m = 1.0);
  void cabinet(const Vec2& at, double yaw_rad);
  /// A cubicle partition (pinboard on both sides), `width_m` long, 1.3 m high.
  void partition(const Vec2& at, double yaw_rad, double width_m);
  /// A square pillar from floor to a 2.8 m ceiling, covered in notices.
  void pillar(const Vec2& at, double side_m);
  void plant(const Vec2& at);
  void bin(const Vec2& at);
  /// A closed door against a wall (front facing `yaw_rad`, i.e. into the room).
  void closedDoor(const Vec2& at, double yaw_rad);
  /// A door leaf standing open at `at` (hinge), swung to face `yaw_rad`.
  void openDoor(const Vec2& hinge, double yaw_rad);

  [[nodiscard]] int texture(const cv::Mat& bgr) { return world_.addTexture(bgr); }
  [[nodiscard]] Rng& rng() { return rng_; }
  [[nodiscard]] float texelsPerMetre() const { return tpm_; }
  [[nodiscard]] const PhotoLibrary& photos() const { return photos_; }

 private:
  cv::Size texels(double w_m, double h_m) const;
  struct Opening {
    double s0, s1, height_m;
    bool jambs;
  };
  void wall(const Vec2& a, const Vec2& b, double height_m, std::vector<Opening> openings);
  void place(const Mesh& local, const Vec2& at, double yaw_rad);
  World& world_;
  Rng& rng_;
  const PhotoLibrary& photos_;
  float tpm_;
};

}  // namespace dynanav::sim
