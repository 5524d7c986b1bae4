#pragma once
// Triangle meshes for the rasteriser. Each vertex carries its texture coordinate in texels of
// its texture's level 0. Front faces: (p1 - p0) x (p2 - p0) points towards a viewer who sees them.
#include <Eigen/Geometry>
#include <array>
#include <cstdint>
#include <vector>

namespace dynanav::sim {

using Vec3f = Eigen::Vector3f;
using Vec2f = Eigen::Vector2f;
using Pose3f = Eigen::Isometry3f;

struct Triangle {
  std::array<int, 3> v{};
  int texture = 0;
};

/// Six zero texture offsets. Not `{}`: an Eigen vector's default constructor leaves it
/// uninitialised, so `{}` gave boxes garbage texture coordinates (found under ASan + UBSan).
inline std::array<Vec2f, 6> noUvOffsets() {
  std::array<Vec2f, 6> offsets;
  offsets.fill(Vec2f::Zero());
  return offsets;
}

struct Mesh {
  std::vector<Vec3f> positions;
  std::vector<Vec2f> uvs;  ///< one per position
  std::vector<Triangle> triangles;
  /// Optional unit normals, one per position: when present the rasteriser interpolates the
  /// lighting across each triangle (smooth bodies); when empty every triangle is lit flat.
  std::vector<Vec3f> normals;

  /// A textured rectangle seen from the side where `axis_u` points right and `axis_v` points
  /// down (so its outward normal is axis_v x axis_u). Texture coordinates run from `uv_origin`
  /// by `texels_per_m` along both axes. Split into tiles of at most `max_tile_m`, so per-triangle
  /// quantities (mip level, lighting) stay local and near-plane clipping stays cheap.
  void addQuad(const Vec3f& origin, const Vec3f& axis_u, const Vec3f& axis_v, int texture,
               float texels_per_m, const Vec2f& uv_origin = Vec2f::Zero(), float max_tile_m = 1.0f);
  /// Like addQuad, with the whole texture stretched over the rectangle exactly once.
  void addQuadFitted(const Vec3f& origin, const Vec3f& axis_u, const Vec3f& axis_v, int texture,
                     const Vec2f& texture_size);

  /// An axis-aligned box (centre and full size, local frame, y up) facing outwards. `textures`
  /// gives +x, -x, +y, -y, +z, -z faces; each face starts at its own texture offset so the
  /// same texture on several faces does not repeat visibly.
  void addBox(const Vec3f& centre, const Vec3f& size, const std::array<int, 6>& textures,
              float texels_per_m, const std::array<Vec2f, 6>& uv_offsets = noUvOffsets());
  void addBox(const Vec3f& centre, const Vec3f& size, int texture, float texels_per_m,
              float uv_offset = 0.0f);
  /// A vertical n-sided prism (cylinder stand-in) with caps, base centre at `base`.
  void addPrism(const Vec3f& base, float radius, float height, int sides, int texture,
                float texels_per_m);

  /// A surface of revolution with elliptic cross-sections (a limb, a torso, a head), placed by
  /// T_mesh_lathe. The lathe's axis is its local y; `profile` lists (y, radius_x, radius_z) from
  /// top to bottom, a zero radius closes the end in a point. Texture u runs once round (from the
  /// back, -z, through -x, the front +z, to +x: to the right seen from outside), v from the
  /// first ring to the last: `uv_span` texels in all. Smooth normals: the mesh gets `normals`.
  void addLathe(const std::vector<Vec3f>& profile, int sides, int texture, const Vec2f& uv_span,
                const Pose3f& T_mesh_lathe = Pose3f::Identity());

  /// Appends another mesh transformed by T_this_other.
  void append(const Mesh& other, const Pose3f& T_this_other);
};

/// One mesh placed in the world for one frame. instance_id 0 = static background.
struct DrawItem {
  const Mesh* mesh = nullptr;
  Pose3f T_world_mesh = Pose3f::Identity();
  uint16_t instance_id = 0;
};

}  // namespace dynanav::sim
