#include "sim/rasterizer.hpp"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <opencv2/core/utility.hpp>

namespace dynanav::sim {

namespace {
constexpr int kStripes = 16;  // fixed row partition: the output never depends on thread count
constexpr double kEdgeTolerancePx = 1e-7;

struct ClipVertex {
  Vec3f p;
  Vec2f uv;
  float shade;
};

/// Sutherland–Hodgman against z >= near: a triangle becomes 0, 1 or 2 triangles.
int clipNear(const ClipVertex in[3], ClipVertex out[4]) {
  int n = 0;
  for (int i = 0; i < 3; ++i) {
    const ClipVertex& a = in[i];
    const ClipVertex& b = in[(i + 1) % 3];
    const bool a_in = a.p.z() >= Rasterizer::kNearPlaneM;
    const bool b_in = b.p.z() >= Rasterizer::kNearPlaneM;
    if (a_in) out[n++] = a;
    if (a_in != b_in) {
      const float t = (Rasterizer::kNearPlaneM - a.p.z()) / (b.p.z() - a.p.z());
      out[n++] = {a.p + t * (b.p - a.p), a.uv + t * (b.uv - a.uv),
                  a.shade + t * (b.shade - a.shade)};
    }
  }
  return n;
}
}  // namespace

void Rasterizer::render(const PinholeCamera& camera, const Pose3f& T_camera_world,
                        const std::vector<DrawItem>& items, const TextureSet& textures,
                        RenderBuffers& out, const Lighting& lighting, int row_begin, int row_end) {
  width_ = camera.width;
  height_ = camera.height;
  row_begin_ = std::clamp(row_begin, 0, height_);
  row_end_ = row_end < 0 ? height_ : std::clamp(row_end, row_begin_, height_);
  tris_.clear();
  std::vector<Vec3f> p_camera;
  for (const DrawItem& item : items) {
    const Mesh& mesh = *item.mesh;
    const Pose3f T_camera_mesh = T_camera_world * item.T_world_mesh;
    const bool smooth = mesh.normals.size() == mesh.positions.size();
    p_camera.resize(mesh.positions.size());
    for (size_t i = 0; i < mesh.positions.size(); ++i)
      p_camera[i] = T_camera_mesh * mesh.positions[i];
    for (const Triangle& t : mesh.triangles) {
      const Vec3f p[3] = {p_camera[size_t(t.v[0])], p_camera[size_t(t.v[1])],
                          p_camera[size_t(t.v[2])]};
      if (p[0].z() < kNearPlaneM && p[1].z() < kNearPlaneM && p[2].z() < kNearPlaneM) continue;
      const Vec3f n = (p[1] - p[0]).cross(p[2] - p[0]);
      if (n.dot(p[0]) >= 0.0f) continue;  // back face: its front normal points away from us
      const Vec2f uv[3] = {mesh.uvs[size_t(t.v[0])], mesh.uvs[size_t(t.v[1])],
                           mesh.uvs[size_t(t.v[2])]};
      const float area_m2 = 0.5f * n.norm();
      if (area_m2 < 1e-12f) continue;
      const Vec3f n_unit = n / (2.0f * area_m2);
      // Lambert shading with the normal in the world (room) frame: the lights do not follow us.
      const Vec3f n_world = T_camera_world.linear().transpose() * n_unit;
      const auto lambert = [&](const Vec3f& normal_world) {
        return lighting.ambient +
               lighting.diffuse * std::max(0.0f, normal_world.dot(lighting.towards_light_world));
      };
      const float flat = lambert(n_world);
      float shade[3] = {flat, flat, flat};
      // Smooth parts (bodies) interpolate the light between vertex normals (Gouraud), so a
      // limb's shading turns with its surface instead of showing facets. Zero normals: flat.
      bool smooth_tri = smooth;
      for (int k = 0; k < 3 && smooth_tri; ++k) {
        const Vec3f& n_mesh = mesh.normals[size_t(t.v[size_t(k)])];
        smooth_tri = n_mesh.squaredNorm() > 0.5f;
        if (smooth_tri) shade[k] = lambert(item.T_world_mesh.linear() * n_mesh);
      }
      if (!smooth_tri) shade[0] = shade[1] = shade[2] = flat;
      // Mip level from the footprint: texels per metre on the surface, metres per pixel at
      // depth z on a surface tilted by theta is z / (fx cos theta).
      const float uv_area = 0.5f * std::abs((uv[1] - uv[0]).x() * (uv[2] - uv[0]).y() -
                                            (uv[1] - uv[0]).y() * (uv[2] - uv[0]).x());
      const Vec3f centroid = (p[0] + p[1] + p[2]) / 3.0f;
      const float cos_view = std::abs(n_unit.dot(centroid.normalized()));
      const float texels_per_m = std::sqrt(uv_area / area_m2);
      const float mip_k = texels_per_m / (float(camera.fx) * std::max(cos_view, 0.25f));
      ClipVertex in[3] = {
          {p[0], uv[0], shade[0]}, {p[1], uv[1], shade[1]}, {p[2], uv[2], shade[2]}};
      ClipVertex clipped[4];
      const int count = clipNear(in, clipped);
      for (int k = 1; k + 1 < count; ++k) {
        const Vec3f q[3] = {clipped[0].p, clipped[k].p, clipped[k + 1].p};
        const Vec2f quv[3] = {clipped[0].uv, clipped[k].uv, clipped[k + 1].uv};
        const float qshade[3] = {clipped[0].shade, clipped[k].shade, clipped[k + 1].shade};
        addTriangle(camera, q, quv, t.texture, qshade, smooth_tri, mip_k, item.instance_id);
      }
    }
  }

  inv_z_.create(height_, width_, CV_32F);
  tri_index_.create(height_, width_, CV_32S);
  bary1_.create(height_, width_, CV_32F);
  bary2_.create(height_, width_, CV_32F);
  out.bgr.create(height_, width_, CV_8UC3);
  out.depth_m.create(height_, width_, CV_32F);
  out.instance.create(height_, width_, CV_16U);
  const int rows = row_end_ - row_begin_;
  cv::parallel_for_(cv::Range(0, kStripes), [&](const cv::Range& r) {
    for (int s = r.start; s < r.end; ++s) {
      const int y0 = row_begin_ + rows * s / kStripes, y1 = row_begin_ + rows * (s + 1) / kStripes;
      rasterRows(y0, y1);
      shadeRows(y0, y1, textures, out);
    }
  });
}

void Rasterizer::addTriangle(const PinholeCamera& camera, const Vec3f p[3], const Vec2f uv[3],
                             int texture, const float shade[3], bool smooth, float mip_k,
                             uint16_t instance) {
  double sx[3], sy[3];
  for (int i = 0; i < 3; ++i) {
    sx[i] = camera.fx * p[i].x() / p[i].z() + camera.cx;
    sy[i] = camera.fy * p[i].y() / p[i].z() + camera.cy;
  }
  const double xmin = std::min({sx[0], sx[1], sx[2]}), xmax = std::max({sx[0], sx[1], sx[2]});
  const double ymin = std::min({sy[0], sy[1], sy[2]}), ymax = std::max({sy[0], sy[1], sy[2]});
  if (xmax < 0 || ymax < row_begin_ || xmin > width_ - 1 || ymin > row_end_ - 1) return;
  const double area2 = (sx[1] - sx[0]) * (sy[2] - sy[0]) - (sy[1] - sy[0]) * (sx[2] - sx[0]);
  if (std::abs(area2) < 1e-9) return;
  ScreenTri t;
  // e_i is the barycentric weight of vertex i: the edge opposite i, normalised by the area.
  for (int i = 0; i < 3; ++i) {
    const int j = (i + 1) % 3, k = (i + 2) % 3;
    const double a = (sy[j] - sy[k]) / area2;
    const double b = (sx[k] - sx[j]) / area2;
    t.edge[i][0] = a;
    t.edge[i][1] = b;
    t.edge[i][2] = -(a * sx[j] + b * sy[j]);
    t.inv_z[i] = 1.0f / p[i].z();
    t.uv[i] = uv[i];
  }
  t.xmin = std::max(0, int(std::ceil(xmin - kEdgeTolerancePx)));
  t.xmax = std::min(width_ - 1, int(std::floor(xmax + kEdgeTolerancePx)));
  t.ymin = std::max(0, int(std::ceil(ymin - kEdgeTolerancePx)));
  t.ymax = std::min(height_ - 1, int(std::floor(ymax + kEdgeTolerancePx)));
  if (t.xmin > t.xmax || t.ymin > t.ymax) return;
  t.texture = texture;
  for (int i = 0; i < 3; ++i) t.shade[i] = shade[i];
  t.smooth = smooth;
  t.mip_k = mip_k;
  t.instance = instance;
  tris_.push_back(t);
}

void Rasterizer::rasterRows(int y0, int y1) {
  for (int y = y0; y < y1; ++y) {
    std::fill_n(inv_z_.ptr<float>(y), width_, 0.0f);
    std::fill_n(tri_index_.ptr<int>(y), width_, -1);
  }
  for (size_t ti = 0; ti < tris_.size(); ++ti) {
    const ScreenTri& t = tris_[ti];
    const int ya = std::max(y0, t.ymin), yb = std::min(y1 - 1, t.ymax);
    for (int y = ya; y <= yb; ++y) {
      // The span of x where all three barycentrics are >= 0, solved per edge.
      double lo = t.xmin, hi = t.xmax;
      double row[3];
      bool empty = false;
      for (int i = 0; i < 3; ++i) {
        const double a = t.edge[i][0];
        row[i] = t.edge[i][1] * y + t.edge[i][2];
        if (a > 1e-15)
          lo = std::max(lo, -row[i] / a);
        else if (a < -1e-15)
          hi = std::min(hi, -row[i] / a);
        else if (row[i] < -1e-12)
          empty = true;
      }
      if (empty) continue;
      // Pixels exactly on an edge shared by two triangles belong to both (a z-buffer tie is
      // harmless); without the tolerance rounding could give them to neither and leave cracks.
      const int xa = std::max(t.xmin, int(std::ceil(lo - kEdgeTolerancePx)));
      const int xb = std::min(t.xmax, int(std::floor(hi + kEdgeTolerancePx)));
      if (xa > xb) continue;
      float* iz_row = inv_z_.ptr<float>(y);
      int* id_row = tri_index_.ptr<int>(y);
      float* b1_row = bary1_.ptr<float>(y);
      float* b2_row = bary2_.ptr<float>(y);
      const double a0 = t.edge[0][0], a1 = t.edge[1][0], a2 = t.edge[2][0];
      // 1/z is affine in screen space: one plane equation gives it along the span.
      const double iz_a = a0 * t.inv_z[0] + a1 * t.inv_z[1] + a2 * t.inv_z[2];
      const double iz_c = row[0] * t.inv_z[0] + row[1] * t.inv_z[1] + row[2] * t.inv_z[2];
      for (int x = xa; x <= xb; ++x) {
        const float iz = float(iz_a * x + iz_c);
        if (iz > iz_row[x]) {
          iz_row[x] = iz;
          id_row[x] = int(ti);
          b1_row[x] = float(a1 * x + row[1]);
          b2_row[x] = float(a2 * x + row[2]);
        }
      }
    }
  }
}

void Rasterizer::shadeRows(int y0, int y1, const TextureSet& textures, RenderBuffers& out) const {
  for (int y = y0; y < y1; ++y) {
    const float* iz_row = inv_z_.ptr<float>(y);
    const int* id_row = tri_index_.ptr<int>(y);
    const float* b1_row = bary1_.ptr<float>(y);
    const float* b2_row = bary2_.ptr<float>(y);
    uint8_t* bgr = out.bgr.ptr<uint8_t>(y);
    float* depth = out.depth_m.ptr<float>(y);
    uint16_t* inst = out.instance.ptr<uint16_t>(y);
    for (int x = 0; x < width_; ++x) {
      const int id = id_row[x];
      if (id < 0) {
        bgr[3 * x] = bgr[3 * x + 1] = bgr[3 * x + 2] = 0;
        depth[x] = 0.0f;
        inst[x] = 0;
        continue;
      }
      const ScreenTri& t = tris_[size_t(id)];
      const float z = 1.0f / iz_row[x];
      // Perspective-correct weights: screen barycentrics scaled by 1/z_i, renormalised.
      const float l1 = b1_row[x], l2 = b2_row[x], l0 = 1.0f - l1 - l2;
      const float w0 = l0 * t.inv_z[0] * z, w1 = l1 * t.inv_z[1] * z, w2 = l2 * t.inv_z[2] * z;
      const Vec2f uv = w0 * t.uv[0] + w1 * t.uv[1] + w2 * t.uv[2];
      // floor(log2(texels per pixel)) from the float's exponent bits (= std::ilogb, much cheaper).
      const float footprint = std::max(t.mip_k * z, 1e-6f);
      uint32_t bits;
      std::memcpy(&bits, &footprint, sizeof bits);
      const int level = std::max(0, int((bits >> 23) & 0xFF) - 127);
      float c[3];
      textures[size_t(t.texture)].sample(uv.x(), uv.y(), level, c);
      const float shade =
          t.smooth ? w0 * t.shade[0] + w1 * t.shade[1] + w2 * t.shade[2] : t.shade[0];
      for (int k = 0; k < 3; ++k) bgr[3 * x + k] = cv::saturate_cast<uint8_t>(c[k] * shade);
      depth[x] = z;
      inst[x] = t.instance;
    }
  }
}

}  // namespace dynanav::sim
