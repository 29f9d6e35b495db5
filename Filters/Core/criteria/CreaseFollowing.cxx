#include "CreaseFollowing.h"

#include "ConvexPolygons.h"
#include "CreaseCrossing.h"
#include "MeshSolid.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <tuple>

namespace tpc
{
namespace
{
/// One use of a mesh edge by a listed triangle.
struct EdgeOfTriangle
{
  std::uint32_t Low = 0, High = 0, Triangle = 0;
  bool operator<(const EdgeOfTriangle& o) const
  {
    return std::tie(this->Low, this->High, this->Triangle) < std::tie(o.Low, o.High, o.Triangle);
  }
};

bool SamePoint(const Vec3& a, const Vec3& b)
{
  return a[0] == b[0] && a[1] == b[1] && a[2] == b[2];
}

Vec3 UnitNormal(const std::array<Vec3, 3>& t)
{
  return Normalized(Cross(t[1] - t[0], t[2] - t[0]));
}

/// The patch's edges where two of its triangles meet at CreaseAngleDegrees
/// or more.
std::vector<CreaseSegment> PatchCreases(const std::vector<std::array<Vec3, 3>>& patch)
{
  const double cosine = std::cos(CreaseAngleDegrees * M_PI / 180.0);
  std::vector<CreaseSegment> creases;
  for (std::size_t i = 0; i < patch.size(); ++i)
  {
    for (std::size_t j = i + 1; j < patch.size(); ++j)
    {
      for (int k = 0; k < 3; ++k)
      {
        const Vec3 &a = patch[i][k], &b = patch[i][(k + 1) % 3];
        for (int l = 0; l < 3; ++l)
        {
          // (A consistently oriented patch walks a shared edge both ways.)
          if (SamePoint(patch[j][l], b) && SamePoint(patch[j][(l + 1) % 3], a) &&
            !(Dot(UnitNormal(patch[i]), UnitNormal(patch[j])) > cosine))
          {
            creases.push_back({ a, b });
          }
        }
      }
    }
  }
  return creases;
}
} // namespace

std::vector<CreaseSegment> CreasesInCell(const CsgLeaf& leaf, const PrimitiveSet& primitives, const Box3& cell)
{
  const MeshSolid& mesh = primitives.Meshes[leaf.Primitive];
  const double cosine = std::cos(FollowedCreaseDegrees * M_PI / 180.0);
  // The listed triangles' edges that bend that much (each use; the mesh
  // knows each edge's other triangle), then those used by two listed
  // triangles: both meet the cell where the edge does.
  std::vector<EdgeOfTriangle> uses;
  const auto gather = [&](std::uint32_t t) {
    const auto& ids = mesh.Triangles()[t];
    for (int k = 0; k < 3; ++k)
    {
      const std::uint32_t other = mesh.Across(t, k);
      if (other != MeshSolid::NoTriangle && !(Dot(mesh.Normal(t), mesh.Normal(other)) > cosine))
      {
        const std::uint32_t a = ids[k], b = ids[(k + 1) % 3];
        uses.push_back({ std::min(a, b), std::max(a, b), t });
      }
    }
  };
  if (leaf.Triangles)
  {
    std::for_each(leaf.Triangles->begin(), leaf.Triangles->end(), gather);
  }
  else
  {
    for (std::uint32_t t = 0; t < mesh.TriangleCount(); ++t)
    {
      gather(t);
    }
  }
  std::sort(uses.begin(), uses.end());
  std::vector<CreaseSegment> creases;
  for (std::size_t i = 0; i + 1 < uses.size(); ++i)
  {
    const EdgeOfTriangle &p = uses[i], &q = uses[i + 1];
    CreaseSegment clipped{ mesh.Points()[p.Low], mesh.Points()[p.High] };
    if (p.Low == q.Low && p.High == q.High && ClipSegment(clipped.A, clipped.B, cell))
    {
      creases.push_back(clipped);
    }
  }
  return creases;
}

bool CreasesFollowed(
  const std::vector<CreaseSegment>& creases, const std::vector<std::array<Vec3, 3>>& patch, double reach)
{
  if (creases.empty())
  {
    return true;
  }
  const std::vector<CreaseSegment> drawn = PatchCreases(patch);
  const double spacing = reach / 8.0;
  for (const CreaseSegment& crease : creases)
  {
    const double length = Norm(crease.B - crease.A);
    const std::size_t steps = static_cast<std::size_t>(std::ceil(length / spacing));
    for (std::size_t i = 0; i <= steps; ++i)
    {
      const Vec3 p = steps ? crease.A + (crease.B - crease.A) * (static_cast<double>(i) / steps) : crease.A;
      double nearest = HUGE_VAL;
      for (const CreaseSegment& d : drawn)
      {
        nearest = std::min(nearest, SegmentDistance(p, d.A, d.B));
      }
      if (!(nearest <= reach - 0.5 * spacing))
      {
        return false;
      }
    }
  }
  return true;
}

} // namespace tpc
