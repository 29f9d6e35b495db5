// Closed triangle meshes with known topology, generated for the core tests
// (no files, no VTK): a cube, a UV torus, a subdivided icosahedron and a
// prism over a convex polygon.
#pragma once

#include "MeshSolid.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <map>
#include <vector>

namespace tpctest
{
using tpc::MeshSolid;
using tpc::Vec3;
using Triangles = std::vector<std::array<std::uint32_t, 3>>;

/// Axis-aligned box [lo, hi], outward oriented, 12 triangles.
inline MeshSolid CubeMesh(const Vec3& lo, const Vec3& hi)
{
  std::vector<Vec3> p;
  for (int c = 0; c < 8; ++c)
  {
    p.push_back({ (c & 1) ? hi[0] : lo[0], (c & 2) ? hi[1] : lo[1], (c & 4) ? hi[2] : lo[2] });
  }
  const Triangles t = { { 0, 2, 1 }, { 1, 2, 3 }, { 4, 5, 6 }, { 5, 7, 6 }, { 0, 1, 4 }, { 1, 5, 4 },
    { 2, 6, 3 }, { 3, 6, 7 }, { 0, 4, 2 }, { 2, 4, 6 }, { 1, 3, 5 }, { 3, 7, 5 } };
  return MeshSolid(p, t);
}

/// Torus around the z axis (radii R > r), n x m quads split in triangles.
inline MeshSolid TorusMesh(const Vec3& c, double R, double r, int n, int m)
{
  std::vector<Vec3> p;
  Triangles t;
  for (int i = 0; i < n; ++i)
  {
    const double u = 2 * M_PI * i / n;
    for (int j = 0; j < m; ++j)
    {
      const double v = 2 * M_PI * j / m;
      p.push_back({ c[0] + (R + r * std::cos(v)) * std::cos(u), c[1] + (R + r * std::cos(v)) * std::sin(u),
        c[2] + r * std::sin(v) });
    }
  }
  auto id = [&](int i, int j) { return static_cast<std::uint32_t>((i % n) * m + (j % m)); };
  for (int i = 0; i < n; ++i)
  {
    for (int j = 0; j < m; ++j)
    {
      t.push_back({ id(i, j), id(i + 1, j), id(i + 1, j + 1) });
      t.push_back({ id(i, j), id(i + 1, j + 1), id(i, j + 1) });
    }
  }
  return MeshSolid(p, t);
}

/// Icosahedron subdivided `levels` times, projected on a sphere.
inline MeshSolid SphereMesh(const Vec3& c, double radius, int levels)
{
  const double g = (1 + std::sqrt(5.0)) / 2;
  std::vector<Vec3> p = { { -1, g, 0 }, { 1, g, 0 }, { -1, -g, 0 }, { 1, -g, 0 }, { 0, -1, g }, { 0, 1, g },
    { 0, -1, -g }, { 0, 1, -g }, { g, 0, -1 }, { g, 0, 1 }, { -g, 0, -1 }, { -g, 0, 1 } };
  Triangles t = { { 0, 11, 5 }, { 0, 5, 1 }, { 0, 1, 7 }, { 0, 7, 10 }, { 0, 10, 11 }, { 1, 5, 9 },
    { 5, 11, 4 }, { 11, 10, 2 }, { 10, 7, 6 }, { 7, 1, 8 }, { 3, 9, 4 }, { 3, 4, 2 }, { 3, 2, 6 },
    { 3, 6, 8 }, { 3, 8, 9 }, { 4, 9, 5 }, { 2, 4, 11 }, { 6, 2, 10 }, { 8, 6, 7 }, { 9, 8, 1 } };
  for (int l = 0; l < levels; ++l)
  {
    std::map<std::pair<std::uint32_t, std::uint32_t>, std::uint32_t> mid;
    auto midpoint = [&](std::uint32_t a, std::uint32_t b) {
      const auto key = std::make_pair(std::min(a, b), std::max(a, b));
      const auto it = mid.find(key);
      if (it != mid.end())
      {
        return it->second;
      }
      p.push_back((p[a] + p[b]) * 0.5);
      return mid[key] = static_cast<std::uint32_t>(p.size() - 1);
    };
    Triangles next;
    for (const auto& f : t)
    {
      const std::uint32_t ab = midpoint(f[0], f[1]), bc = midpoint(f[1], f[2]), ca = midpoint(f[2], f[0]);
      next.push_back({ f[0], ab, ca });
      next.push_back({ f[1], bc, ab });
      next.push_back({ f[2], ca, bc });
      next.push_back({ ab, bc, ca });
    }
    t.swap(next);
  }
  for (Vec3& q : p)
  {
    q = c + tpc::Normalized(q) * radius;
  }
  return MeshSolid(p, t);
}

/// A prism along y, y in [y0, y1], over the convex polygon `section` in the
/// (x, z) plane (either orientation), outward oriented: each side quad split
/// by a diagonal (a flat edge), both ends capped by fans. Vertex k of the
/// section is vertex k at y0 and k + section.size() at y1.
inline MeshSolid PrismMesh(const std::vector<std::array<double, 2>>& section, double y0, double y1)
{
  const auto m = static_cast<std::uint32_t>(section.size());
  std::vector<Vec3> p;
  for (const double y : { y0, y1 })
  {
    for (const auto& s : section)
    {
      p.push_back({ s[0], y, s[1] });
    }
  }
  double area = 0.0; // (twice the signed area in (x, z): positive counter-clockwise)
  for (std::uint32_t k = 0; k < m; ++k)
  {
    area += section[k][0] * section[(k + 1) % m][1] - section[(k + 1) % m][0] * section[k][1];
  }
  Triangles t;
  for (std::uint32_t k = 0; k < m; ++k)
  {
    const std::uint32_t a = k, b = (k + 1) % m;
    t.push_back({ a, b + m, b });
    t.push_back({ a, a + m, b + m });
  }
  for (std::uint32_t k = 1; k + 1 < m; ++k)
  {
    t.push_back({ 0, k, k + 1 });
    t.push_back({ m, m + k + 1, m + k });
  }
  if ((area > 0) != (y1 > y0))
  {
    for (auto& tri : t)
    {
      std::swap(tri[1], tri[2]);
    }
  }
  return MeshSolid(p, t);
}
/// `mesh` turned about z by 0.4 and then about x by 0.3: a box's edges cross
/// every lattice plane obliquely.
inline MeshSolid TiltedMesh(const MeshSolid& mesh)
{
  const double c1 = std::cos(0.4), s1 = std::sin(0.4), c2 = std::cos(0.3), s2 = std::sin(0.3);
  std::vector<Vec3> points;
  for (const Vec3& p : mesh.Points())
  {
    const Vec3 q(c1 * p[0] - s1 * p[1], s1 * p[0] + c1 * p[1], p[2]);
    points.push_back({ q[0], c2 * q[1] - s2 * q[2], s2 * q[1] + c2 * q[2] });
  }
  return MeshSolid(points, mesh.Triangles());
}

/// The box holding both meshes (the domain of their Boolean).
inline tpc::Box3 BoundsOfBoth(const MeshSolid& a, const MeshSolid& b)
{
  tpc::Box3 box = a.Bounds();
  for (int axis = 0; axis < 3; ++axis)
  {
    box.lo[axis] = std::min(box.lo[axis], b.Bounds().lo[axis]);
    box.hi[axis] = std::max(box.hi[axis], b.Bounds().hi[axis]);
  }
  return box;
}

/// `mesh` scaled along its axes by `scale`, turned by `angle` about the
/// unit `axis` (Rodrigues' formula) and moved by `shift`: an affine map, so
/// a valid mesh stays closed, manifold and free of self-intersections.
inline MeshSolid AffineMesh(
  const MeshSolid& mesh, const Vec3& scale, const Vec3& axis, double angle, const Vec3& shift)
{
  const double c = std::cos(angle), s = std::sin(angle);
  std::vector<Vec3> points;
  for (const Vec3& p : mesh.Points())
  {
    const Vec3 q(p[0] * scale[0], p[1] * scale[1], p[2] * scale[2]);
    points.push_back(q * c + tpc::Cross(axis, q) * s + axis * (tpc::Dot(axis, q) * (1.0 - c)) + shift);
  }
  return MeshSolid(points, mesh.Triangles());
}
} // namespace tpctest
