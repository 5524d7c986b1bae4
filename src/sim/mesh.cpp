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

void Mesh::addLathe(const std::vector<Vec3f>& profile, int sides, int texture, const Vec2f& uv_span,
                    const Pose3f& T) {
  const int rings = int(profile.size());
  if (rings < 2 || sides < 3) return;
  // A flat-lit mesh gaining smooth parts: its earlier vertices keep their face normal's role
  // through a zero normal, which the rasteriser never sees (meshes are either smooth or flat).
  normals.resize(positions.size(), Vec3f::Zero());
  std::vector<float> v_at(size_t(rings), 0.0f);  // arc length along the profile
  for (int i = 1; i < rings; ++i) {
    const Vec3f d = profile[size_t(i)] - profile[size_t(i - 1)];
    v_at[size_t(i)] = v_at[size_t(i - 1)] + std::hypot(d.x(), d.y());
  }
  const float v_total = std::max(v_at.back(), 1e-6f);
  const auto point = [&](int i, int j) {
    const Vec3f& r = profile[size_t(std::clamp(i, 0, rings - 1))];
    const float a = 2.0f * float(M_PI) * float(j) / float(sides);
    return Vec3f(-r.y() * std::sin(a), r.x(), -r.z() * std::cos(a));
  };
  const int base = int(positions.size());
  for (int i = 0; i < rings; ++i) {
    for (int j = 0; j <= sides; ++j) {  // the seam column is duplicated for its texture u
      // Normal from the grid's neighbours: round the ring x down the profile (outwards).
      const Vec3f along = point(i, j + 1) - point(i, j - 1);
      const Vec3f down = point(i + 1, j) - point(i - 1, j);
      Vec3f n = down.cross(along);
      const bool pole = profile[size_t(i)].y() <= 0.0f && profile[size_t(i)].z() <= 0.0f;
      if (pole || n.squaredNorm() < 1e-12f) n = Vec3f(0, i == 0 ? 1.0f : -1.0f, 0);
      positions.push_back(T * point(i, j));
      normals.push_back((T.linear() * n).normalized());
      uvs.emplace_back(uv_span.x() * float(j) / float(sides),
                       uv_span.y() * v_at[size_t(i)] / v_total);
    }
  }
  const int cols = sides + 1;
  for (int i = 0; i + 1 < rings; ++i) {
    for (int j = 0; j < sides; ++j) {
      const int a = base + i * cols + j, b = a + 1, c = a + cols, d = c + 1;
      // Outward order: with u to the right and v down seen from outside, (a, c, b), (b, c, d)
      // point their normals towards the viewer.
      triangles.push_back({{a, c, b}, texture});
      triangles.push_back({{b, c, d}, texture});
    }
  }
  // Open ends (non-zero radius) are closed with a flat cap facing along the axis.
  for (int end = 0; end < 2; ++end) {
    const int i = end == 0 ? 0 : rings - 1;
    const Vec3f& r = profile[size_t(i)];
    if (r.y() <= 0.0f && r.z() <= 0.0f) continue;
    const int centre = int(positions.size());
    const Vec3f axis_n = T.linear() * Vec3f(0, end == 0 ? 1.0f : -1.0f, 0);
    positions.push_back(T * Vec3f(0, r.x(), 0));
    normals.push_back(axis_n);
    uvs.emplace_back(uv_span.x() * 0.5f, uv_span.y() * v_at[size_t(i)] / v_total);
    for (int j = 0; j < sides; ++j) {
      const int a = base + i * cols + j, b = a + 1;
      const Vec3f n = (positions[size_t(a)] - positions[size_t(centre)])
                          .cross(positions[size_t(b)] - positions[size_t(centre)]);
      if (n.dot(axis_n) > 0)
        triangles.push_back({{centre, a, b}, texture});
      else
        triangles.push_back({{centre, b, a}, texture});
    }
  }
}

void Mesh::append(const Mesh& other, const Pose3f& T_this_other) {
  const int base = int(positions.size());
  for (const Vec3f& p : other.positions) positions.push_back(T_this_other * p);
  if (!other.normals.empty() || !normals.empty()) {
    normals.resize(size_t(base), Vec3f::Zero());
    for (size_t i = 0; i < other.positions.size(); ++i)
      normals.push_back(i < other.normals.size() ? Vec3f(T_this_other.linear() * other.normals[i])
                                                 : Vec3f::Zero());
  }
  uvs.insert(uvs.end(), other.uvs.begin(), other.uvs.end());
  for (Triangle t : other.triangles) {
    for (int& i : t.v) i += base;
    triangles.push_back(t);
  }
}

}  // namespace dynanav::sim
