#include "CertifiedError.h"

#include "ExactCellCriterion.h"
#include "MeshBooleanCellError.h"
#include "SlabBound.h"

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

bool SurfaceOfCell(
  const AdaptiveOctree& tree, std::uint32_t n, const PrimitiveSet& prims, bool creases, CellSurface& surface)
{
  const OctreeNode& node = tree.Nodes[n];
  const CsgExpression& expression = *tree.Expressions[n];
  const Box3 box = tree.Grid.CellBox(node.Level, node.Ijk);
  surface.Creases.clear();
  surface.SceneOfOneMesh = IsOneMesh(*tree.SceneExpression);
  if (const CsgLeaf* leaf = LoneMeshLeaf(expression))
  {
    surface.OneMesh = true;
    surface.Slack = RoundingSlack(*leaf, prims, box);
    surface.Solid = &prims.Meshes[leaf->Primitive];
    SurfaceInCell(*leaf, prims, box, surface.Mesh, &surface.MeshTriangles);
    return true;
  }
  surface.OneMesh = false;
  surface.Solid = nullptr;
  const bool boolean = IsCertifiableMeshBoolean(expression) &&
    MeshBooleanSurfaceInCell(expression, prims, box, BooleanPieceShare * tree.HausdorffTolerance,
      BooleanPieceBudget, surface.Boolean, creases ? &surface.Creases : nullptr);
  surface.Slack = surface.Boolean.Slack;
  return boolean;
}

HausdorffEstimate CertifiedCellError(const CellSurface& surface, const CellPatches& patches, const TriangleMesh& mesh,
  double enough, double giveUp, std::size_t budget)
{
  HausdorffEstimate e = CertifiedSurfacePatchError(surface.OnSurface(), surface.Covering(),
    PatchTriangles(patches, mesh), surface.Slack, enough, giveUp, budget, nullptr,
    surface.SceneOfOneMesh ? enough : 0.0);
  e.Lower = surface.OneMesh ? e.Lower : 0.0;
  return e;
}

double SlabCellError(const CellSurface& surface, const CellPatches& patches, const TriangleMesh& mesh,
  double chordReach, const OwnChords& own, double enough, double giveUp)
{
  return surface.OneMesh && surface.SceneOfOneMesh && surface.Solid && surface.Solid->EveryEdgeHasTwoTriangles()
    ? SlabPatchError(*surface.Solid, surface.MeshTriangles, surface.Mesh, PatchTriangles(patches, mesh), chordReach,
        surface.Slack, own, enough, giveUp)
    : HUGE_VAL;
}

} // namespace tpc
