#include "PolygonTriangulation.h"

#include "ExactPredicates.h"

#include <array>
#include <cmath>

namespace tpc
{
namespace
{
/// Twice the polygon's vector area (Newell): only chooses the plane to
/// project on and the projection's orientation, so rounding in it cannot
/// make a test wrong - at worst the ears are not found and the polygon is
/// fanned.
Vec3 NewellNormal(const std::vector<Vec3>& points, const std::uint32_t* corners, std::size_t n)
{
  Vec3 normal{ 0.0, 0.0, 0.0 };
  for (std::size_t i = 0; i < n; ++i)
  {
    const Vec3& a = points[corners[i]];
    const Vec3& b = points[corners[(i + 1) % n]];
    normal[0] += (a[1] - b[1]) * (a[2] + b[2]);
    normal[1] += (a[2] - b[2]) * (a[0] + b[0]);
    normal[2] += (a[0] - b[0]) * (a[1] + b[1]);
  }
  return normal;
}

/// The remaining polygon as a ring of corners, in the projection where it
/// turns counter-clockwise.
class EarClipping
{
public:
  EarClipping(const std::vector<Vec3>& points, const std::uint32_t* corners, std::size_t n, int u, int v)
    : Corners(corners)
    , Projected(n)
    , Next(n)
    , Previous(n)
  {
    for (std::size_t i = 0; i < n; ++i)
    {
      const Vec3& p = points[corners[i]];
      this->Projected[i] = { p[u], p[v] };
      this->Next[i] = (i + 1) % n;
      this->Previous[i] = (i + n - 1) % n;
    }
  }

  /// Appends the ears' triangles; false (with `triangles` partly appended)
  /// when the ring has no ear left.
  bool Clip(std::vector<Triangle>& triangles)
  {
    std::size_t remaining = this->Projected.size();
    std::size_t corner = 0;
    std::size_t triedSinceLastEar = 0;
    while (remaining > 3)
    {
      if (this->IsEar(corner))
      {
        this->Emit(corner, triangles);
        const std::size_t previous = this->Previous[corner];
        this->Next[previous] = this->Next[corner];
        this->Previous[this->Next[corner]] = previous;
        corner = previous; // (its turn may have changed)
        --remaining;
        triedSinceLastEar = 0;
      }
      else if (++triedSinceLastEar > remaining)
      {
        return false;
      }
      else
      {
        corner = this->Next[corner];
      }
    }
    if (this->Turn(this->Previous[corner], corner, this->Next[corner]) <= 0)
    {
      return false;
    }
    this->Emit(corner, triangles);
    return true;
  }

private:
  int Turn(std::size_t a, std::size_t b, std::size_t c) const
  {
    const auto &pa = this->Projected[a], &pb = this->Projected[b], &pc = this->Projected[c];
    return Orient2D(pa[0], pa[1], pb[0], pb[1], pc[0], pc[1]);
  }

  /// Strictly convex, and no other corner in its closed triangle (corners at
  /// the position of one of its own excepted).
  bool IsEar(std::size_t c) const
  {
    const std::size_t p = this->Previous[c], n = this->Next[c];
    if (this->Turn(p, c, n) <= 0)
    {
      return false;
    }
    for (std::size_t j = this->Next[n]; j != p; j = this->Next[j])
    {
      const auto& q = this->Projected[j];
      if (q == this->Projected[p] || q == this->Projected[c] || q == this->Projected[n])
      {
        continue;
      }
      if (this->Turn(p, c, j) >= 0 && this->Turn(c, n, j) >= 0 && this->Turn(n, p, j) >= 0)
      {
        return false;
      }
    }
    return true;
  }

  void Emit(std::size_t c, std::vector<Triangle>& triangles) const
  {
    triangles.push_back(
      { this->Corners[this->Previous[c]], this->Corners[c], this->Corners[this->Next[c]] });
  }

  const std::uint32_t* Corners;
  std::vector<std::array<double, 2>> Projected;
  std::vector<std::size_t> Next, Previous;
};

void Fan(const std::uint32_t* corners, std::size_t n, std::vector<Triangle>& triangles)
{
  for (std::size_t i = 1; i + 1 < n; ++i)
  {
    triangles.push_back({ corners[0], corners[i], corners[i + 1] });
  }
}
} // namespace

PolygonTriangulation TriangulatePolygon(
  const std::vector<Vec3>& points, const std::uint32_t* corners, std::size_t n, std::vector<Triangle>& triangles)
{
  if (n == 3)
  {
    triangles.push_back({ corners[0], corners[1], corners[2] });
    return PolygonTriangulation::Ears;
  }
  const Vec3 normal = NewellNormal(points, corners, n);
  int k = 0;
  for (int a = 1; a < 3; ++a)
  {
    k = std::abs(normal[a]) > std::abs(normal[k]) ? a : k;
  }
  if (normal[k] != 0.0)
  {
    // Dropping coordinate k keeps (k + 1, k + 2), a cyclic order, in which
    // the polygon turns counter-clockwise when normal[k] > 0.
    const int u = normal[k] > 0.0 ? (k + 1) % 3 : (k + 2) % 3;
    const int v = normal[k] > 0.0 ? (k + 2) % 3 : (k + 1) % 3;
    const std::size_t before = triangles.size();
    if (EarClipping(points, corners, n, u, v).Clip(triangles))
    {
      return PolygonTriangulation::Ears;
    }
    triangles.resize(before);
  }
  Fan(corners, n, triangles);
  return PolygonTriangulation::Fan;
}

} // namespace tpc
