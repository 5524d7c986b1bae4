#include "sim/mesh.hpp"

#include <algorithm>
#include <cmath>

namespace dynanav::sim {

namespace {
void addRect(Mesh& m, const Vec3f& o, const Vec3f& du, const Vec3f& dv, const Vec2f& uv_o,
             const Vec2f& uv_du, const Vec2f& uv_dv, int texture) {
  const int base = int(m.positions.size());
  m.positions.insert(m.positions.end(), {o, o + du, o + du + dv, o + dv});
  m.uvs.insert(m.uvs.end(), {uv_o, uv_o + uv_du, uv_o + uv_du + uv_dv, uv_o + uv_dv});
  // Outward normal is dv x du; (p1-p0) x (p2-p0) = du x (du + dv) = du x dv points inwards, so
  // the front-facing order is 0, 2, 1 and 0, 3, 2.
  m.triangles.push_back({{base, base + 2, base + 1}, texture});
  m.triangles.push_back({{base, base + 3, base + 2}, texture});
}
}  // namespace

void Mesh::addQuad(const Vec3f& origin, const Vec3f& axis_u, const Vec3f& axis_v, int texture,
                   float texels_per_m, const Vec2f& uv_origin, float max_tile_m) {
  const float len_u = axis_u.norm(), len_v = axis_v.norm();
  const int nu = std::max(1, int(std::ceil(len_u / max_tile_m)));
  const int nv = std::max(1, int(std::ceil(len_v / max_tile_m)));
  const Vec3f du = axis_u / float(nu), dv = axis_v / float(nv);
  const Vec2f uv_du(len_u / float(nu) * texels_per_m, 0.0f);
  const Vec2f uv_dv(0.0f, len_v / float(nv) * texels_per_m);
  for (int j = 0; j < nv; ++j)
    for (int i = 0; i < nu; ++i)
      addRect(*this, origin + float(i) * du + float(j) * dv, du, dv,
              uv_origin + float(i) * uv_du + float(j) * uv_dv, uv_du, uv_dv, texture);
}

void Mesh::addQuadFitted(const Vec3f& origin, const Vec3f& axis_u, const Vec3f& axis_v, int texture,
                         const Vec2f& texture_size) {
  addRect(*this, origin, axis_u, axis_v, Vec2f::Zero(), Vec2f(texture_size.x(), 0.0f),
          Vec2f(0.0f, texture_size.y()), texture);
}

void Mesh::addBox(const Vec3f& c, const Vec3f& size, const std::array<int, 6>& textures,
                  float texels_per_m, const std::array<Vec2f, 6>& uv_offsets) {
  const Vec3f h = size / 2.0f;
  const Vec3f X = Vec3f::UnitX(), Y = Vec3f::UnitY(), Z = Vec3f::UnitZ();
  // For each face: the corner seen top-left from outside, the right and down axes.
  // Vertical faces keep "down" = -y so that texture rows run downwards as in an image.
  struct Face {
    Vec3f origin, u, v;
  };
  const std::array<Face, 6> faces{{
      {c + Vec3f(h.x(), h.y(), h.z()), -Z * size.z(), -Y * size.y()},   // +x
      {c + Vec3f(-h.x(), h.y(), -h.z()), Z * size.z(), -Y * size.y()},  // -x
      {c + Vec3f(-h.x(), h.y(), -h.z()), X * size.x(), Z * size.z()},   // +y (top)
      {c + Vec3f(-h.x(), -h.y(), h.z()), X * size.x(), -Z * size.z()},  // -y (bottom)
      {c + Vec3f(-h.x(), h.y(), h.z()), X * size.x(), -Y * size.y()},   // +z
      {c + Vec3f(h.x(), h.y(), -h.z()), -X * size.x(), -Y * size.y()},  // -z
  }};
  for (size_t f = 0; f < 6; ++f)
    addQuad(faces[f].origin, faces[f].u, faces[f].v, textures[f], texels_per_m, uv_offsets[f]);
}

void Mesh::addBox(const Vec3f& centre, const Vec3f& size, int texture, float texels_per_m,
                  float uv_offset) {
  std::array<Vec2f, 6> offsets;
  for (size_t f = 0; f < 6; ++f)
    offsets[f] = Vec2f(uv_offset + 137.0f * float(f), 0.5f * uv_offset + 71.0f * float(f));
  addBox(centre, size, {texture, texture, texture, texture, texture, texture}, texels_per_m,
         offsets);
}

void Mesh::addPrism(const Vec3f& base, float radius, float height, int sides, int texture,
                    float texels_per_m) {
  const float step = 2.0f * float(M_PI) / float(sides);
  const float side_len = 2.0f * radius * std::sin(step / 2.0f);
  for (int i = 0; i < sides; ++i) {
    const float a0 = float(i) * step, a1 = a0 + step;
    // From angle a0 to a1 runs to the right for a viewer outside (outward = -y x (p1 - p0)).
    const Vec3f p0 = base + Vec3f(radius * std::sin(a0), height, radius * std::cos(a0));
    const Vec3f p1 = base + Vec3f(radius * std::sin(a1), height, radius * std::cos(a1));
    addQuad(p0, p1 - p0, Vec3f(0, -height, 0), texture, texels_per_m,
            Vec2f(float(i) * side_len * texels_per_m, 0.0f));
  }
  // Caps as triangle fans (outward: +y on top, -y below).
  for (int cap = 0; cap < 2; ++cap) {
    const float y = cap == 0 ? height : 0.0f;
    const int centre = int(positions.size());
    positions.push_back(base + Vec3f(0, y, 0));
    uvs.push_back(Vec2f(radius, radius) * texels_per_m);
    for (int i = 0; i <= sides; ++i) {
      const float a = float(i) * step;
      positions.push_back(base + Vec3f(radius * std::sin(a), y, radius * std::cos(a)));
      uvs.push_back(Vec2f(radius + radius * std::sin(a), radius + radius * std::cos(a)) *
                    texels_per_m);
    }
    for (int i = 0; i < sides; ++i) {
      const int a = centre + 1 + i, b = centre + 2 + i;
      // Angles grow counter-clockwise seen from below (+x towards +z): check with the normal.
      const Vec3f n = (positions[size_t(a)] - positions[size_t(centre)])
                          .cross(positions[size_t(b)] - positions[size_t(centre)]);
      const bool up = n.y() > 0;
      if (up == (cap == 0))
        triangles.push_back({{centre, a, b}, texture});
      else
        triangles.push_back({{centre, b, a}, texture});
    }
  }
}

void Mesh::append(const Mesh& other, const Pose3f& T_this_other) {
  const int base = int(positions.size());
  for (const Vec3f& p : other.positions) positions.push_back(T_this_other * p);
  uvs.insert(uvs.end(), other.uvs.begin(), other.uvs.end());
  for (Triangle t : other.triangles) {
    for (int& i : t.v) i += base;
    triangles.push_back(t);
  }
}

}  // namespace dynanav::sim
