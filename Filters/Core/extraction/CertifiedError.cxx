#include "CertifiedError.h"

#include <algorithm>
#include <cmath>

namespace tpc
{
std::vector<SourceTriangle> PatchTriangles(const CellPatches& patches, const TriangleMesh& mesh)
{
  const auto position = [&](std::uint32_t v) -> const Vec3& {
    return (v & CellPatches::LocalFlag) ? patches.Apexes[v & ~CellPatches::LocalFlag] : mesh.Points[v];
  };
  std::vector<SourceTriangle> triangles;
  for (const Triangle& t : patches.Triangles)
  {
    triangles.push_back({ position(t[0]), position(t[1]), position(t[2]) });
  }
  return triangles;
}

double CertifiedPatchError(const QuadricCellError& bound, const CellPatches& patches, const TriangleMesh& mesh)
{
  double error = 0.0;
  for (const SourceTriangle& t : PatchTriangles(patches, mesh))
  {
    const Vec3 &a = t[0], &b = t[1], &c = t[2];
    error = std::max({ error, TriangleError(bound, a, b, c), EdgeChordError(bound, a, b), EdgeChordError(bound, b, c),
      EdgeChordError(bound, c, a) });
  }
  return error <= bound.Margin ? error : HUGE_VAL;
}

HausdorffEstimate CertifiedMeshCellError(const PolygonSet& surface, const CellPatches& patches,
  const TriangleMesh& mesh, double slack, double enough, double giveUp, std::size_t budget)
{
  return CertifiedMeshPatchError(surface, PatchTriangles(patches, mesh), slack, enough, giveUp, budget);
}

} // namespace tpc
