#include "CreaseSplit.h"

#include "MeshEdges.h"
#include "UnionFind.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace tpc
{
namespace
{
constexpr std::uint32_t Unset = std::numeric_limits<std::uint32_t>::max();

/// The interior angle of triangle t at its corner k (the weight of t's normal
/// in the point's: a wedge's normal then does not depend on how finely the
/// wedge is triangulated).
double CornerAngle(const TriangleMesh& mesh, const Triangle& t, int k)
{
  const Vec3& p = mesh.Points[t[k]];
  const Vec3 a = mesh.Points[t[(k + 1) % 3]] - p;
  const Vec3 b = mesh.Points[t[(k + 2) % 3]] - p;
  return std::atan2(Norm(Cross(a, b)), Dot(a, b));
}

/// Joins, across every edge of two triangles that is not a crease, the
/// corners of the two triangles at each of the edge's points: what remains
/// apart around a point are its wedges.
void JoinCornersAcrossSmoothEdges(
  const TriangleMesh& mesh, const std::vector<Vec3>& unitNormals, double creaseCosine, UnionFind& corners)
{
  std::vector<EdgeUse> uses;
  BuildEdgeTable(mesh.Triangles.data(), mesh.Triangles.size(), uses);
  ForEachEdge(uses, [&](std::size_t first, std::size_t count) {
    if (count != 2)
    {
      return;
    }
    const EdgeUse& u = uses[first];
    const EdgeUse& w = uses[first + 1];
    const Vec3& nu = unitNormals[u.Triangle];
    const Vec3& nw = unitNormals[w.Triangle];
    // A degenerate triangle has no normal to differ by: it joins.
    const bool degenerate = Dot(nu, nu) == 0.0 || Dot(nw, nw) == 0.0;
    if (!degenerate && Dot(nu, nw) <= creaseCosine)
    {
      return;
    }
    for (const int du : { 0, 1 })
    {
      const int cu = (u.Corner + du) % 3;
      const std::uint32_t point = mesh.Triangles[u.Triangle][cu];
      for (int cw = 0; cw < 3; ++cw)
      {
        if (mesh.Triangles[w.Triangle][cw] == point)
        {
          corners.Join(3 * u.Triangle + cu, 3 * w.Triangle + cw);
        }
      }
    }
  });
}
} // namespace

void SplitAtCreases(TriangleMesh& mesh, double creaseAngleDegrees, std::vector<std::uint32_t>& surfacePoint)
{
  const std::size_t triangleCount = mesh.Triangles.size();
  const std::size_t pointCount = mesh.Points.size();
  std::vector<Vec3> unitNormals(triangleCount);
  for (std::size_t t = 0; t < triangleCount; ++t)
  {
    const Triangle& tri = mesh.Triangles[t];
    const Vec3 n = Cross(mesh.Points[tri[1]] - mesh.Points[tri[0]], mesh.Points[tri[2]] - mesh.Points[tri[0]]);
    const double length = Norm(n);
    unitNormals[t] = length > 0.0 ? n * (1.0 / length) : Vec3();
  }
  UnionFind corners(3 * triangleCount);
  JoinCornersAcrossSmoothEdges(mesh, unitNormals, std::cos(creaseAngleDegrees * std::acos(-1.0) / 180.0), corners);

  // Each wedge (a set of joined corners) becomes a point: the point's first
  // wedge keeps its id, later ones are appended.
  surfacePoint.resize(pointCount);
  for (std::size_t v = 0; v < pointCount; ++v)
  {
    surfacePoint[v] = static_cast<std::uint32_t>(v);
  }
  std::vector<std::uint32_t> wedgePoint(3 * triangleCount, Unset);
  std::vector<Vec3> wedgeNormal(3 * triangleCount);
  std::vector<bool> pointSeen(pointCount, false), pointSplit(pointCount, false);
  for (std::size_t t = 0; t < triangleCount; ++t)
  {
    Triangle& tri = mesh.Triangles[t];
    const Triangle original = tri;
    for (int k = 0; k < 3; ++k)
    {
      const std::uint32_t point = original[k];
      const std::uint32_t wedge = corners.Find(static_cast<std::uint32_t>(3 * t + k));
      wedgeNormal[wedge] += unitNormals[t] * CornerAngle(mesh, original, k);
      if (wedgePoint[wedge] == Unset)
      {
        if (!pointSeen[point])
        {
          pointSeen[point] = true;
          wedgePoint[wedge] = point;
        }
        else
        {
          pointSplit[point] = true;
          wedgePoint[wedge] = static_cast<std::uint32_t>(surfacePoint.size());
          surfacePoint.push_back(point);
        }
      }
      tri[k] = wedgePoint[wedge];
    }
  }

  // The copies: the original's position, their wedge's normal (the original
  // too once it is split; an unsplit point keeps its normal).
  const std::size_t splitCount = surfacePoint.size();
  ReleasableArray<Vec3> points, normals;
  points.resize(splitCount);
  normals.resize(splitCount);
  std::copy(mesh.Points.begin(), mesh.Points.end(), points.begin());
  std::copy(mesh.Normals.begin(), mesh.Normals.end(), normals.begin());
  for (std::size_t c = 0; c < 3 * triangleCount; ++c)
  {
    const std::uint32_t wedge = corners.Find(static_cast<std::uint32_t>(c));
    const std::uint32_t point = wedgePoint[wedge];
    if (wedge == c && pointSplit[surfacePoint[point]])
    {
      points[point] = mesh.Points[surfacePoint[point]];
      // (A wedge of degenerate triangles only has no normal of its own: it
      // keeps the point's.)
      const bool none = Dot(wedgeNormal[wedge], wedgeNormal[wedge]) == 0.0;
      normals[point] = none ? mesh.Normals[surfacePoint[point]] : Normalized(wedgeNormal[wedge]);
    }
  }
  mesh.Points = std::move(points);
  mesh.Normals = std::move(normals);
}

} // namespace tpc
