#include "CertifiedError.h"

#include <algorithm>
#include <cmath>

namespace tpc
{
namespace
{
/// The chord term of the edge ab if it lies in a face of the cell (the larger
/// one for an edge on two faces), 0 otherwise.
double EdgeChordError(const QuadricCellError& bound, const Vec3& a, const Vec3& b)
{
  double error = 0.0;
  for (int face = 0; face < 6; ++face)
  {
    const double plane = (face % 2 ? bound.Cell.hi : bound.Cell.lo)[face / 2];
    if (a[face / 2] == plane && b[face / 2] == plane)
    {
      error = std::max(error, ChordError(bound, face, a, b));
    }
  }
  return error;
}

/// The cell's triangles with their vertices' positions.
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
} // namespace

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

HausdorffEstimate CertifiedMeshCellError(const std::vector<ConvexPolygon>& surface, const CellPatches& patches,
  const TriangleMesh& mesh, double slack, double enough, double giveUp, std::size_t budget)
{
  return CertifiedMeshPatchError(surface, PatchTriangles(patches, mesh), slack, enough, giveUp, budget);
}

} // namespace tpc
