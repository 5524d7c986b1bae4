#pragma once
// A CPU z-buffer rasteriser for textured triangle meshes: the simulator's "camera".
// Two passes: visibility (per pixel: nearest triangle, its screen-space barycentrics and 1/z),
// then shading once per visible pixel (perspective-correct texture coordinates, mip level from
// the pixel's footprint, Lambert lighting: flat, or between vertex normals). Pixel (u, v) is
// sampled at its centre, which sits at integer coordinates in the pinhole model used throughout (cx
// = 319.5 for 640 columns).
#include <opencv2/core.hpp>
#include <vector>

#include "core/camera.hpp"
#include "sim/mesh.hpp"
#include "sim/texture.hpp"

namespace dynanav::sim {

/// What the virtual camera sees, before any sensor model.
struct RenderBuffers {
  cv::Mat bgr;       ///< CV_8UC3
  cv::Mat depth_m;   ///< CV_32F, camera z of the visible surface (m); 0 where nothing is hit
  cv::Mat instance;  ///< CV_16U, DrawItem::instance_id of the visible surface
};

struct Lighting {
  Vec3f towards_light_world = Vec3f(0.35f, 0.85f, 0.4f).normalized();  ///< room frame, y up
  float ambient = 0.55f;
  float diffuse = 0.45f;
};

class Rasterizer {
 public:
  static constexpr float kNearPlaneM = 0.05f;

  /// Renders the items seen from T_camera_world (camera x right, y down, z forward) into the
  /// rows [row_begin, row_end) of `out` (row_end < 0: to the bottom); other rows of an `out` of
  /// the right size are left as they are, so a rolling shutter can compose bands of rows seen
  /// from different poses.
  void render(const PinholeCamera& camera, const Pose3f& T_camera_world,
              const std::vector<DrawItem>& items, const TextureSet& textures, RenderBuffers& out,
              const Lighting& lighting = {}, int row_begin = 0, int row_end = -1);

  /// Screen-space triangle after clipping: plane equations in pixel coordinates.
  struct ScreenTri {
    double edge[3][3];  ///< e_i(x, y) = a x + b y + c, all >= 0 inside; e_1, e_2 = barycentrics
    float inv_z[3];
    Vec2f uv[3];
    int ymin, ymax, xmin, xmax;
    int texture;
    float shade[3];  ///< light factor per vertex (all equal for flat-lit triangles)
    bool smooth;     ///< interpolate shade (Gouraud) rather than use shade[0]
    float mip_k;     ///< texels per pixel = mip_k * z
    uint16_t instance;
  };

 private:
  void addTriangle(const PinholeCamera& camera, const Vec3f p_camera[3], const Vec2f uv[3],
                   int texture, const float shade[3], bool smooth, float mip_k, uint16_t instance);
  void rasterRows(int y0, int y1);
  void shadeRows(int y0, int y1, const TextureSet& textures, RenderBuffers& out) const;

  std::vector<ScreenTri> tris_;
  cv::Mat inv_z_, tri_index_, bary1_, bary2_;  // visibility buffers
  int width_ = 0, height_ = 0;
  int row_begin_ = 0, row_end_ = 0;  // the band being rendered
};

}  // namespace dynanav::sim
