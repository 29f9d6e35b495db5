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

namespace
{
/// Whether the slab bound's premise holds for the cell's surface (SlabBound.h:
/// one closed mesh, in a scene of it alone).
bool SlabApplies(const CellSurface& surface)
{
  return surface.OneMesh && surface.SceneOfOneMesh && surface.Solid && surface.Solid->EveryEdgeHasTwoTriangles();
}
} // namespace

double SlabCellError(const CellSurface& surface, const CellPatches& patches, const TriangleMesh& mesh,
  double chordReach, const OwnChords& own, double enough, double giveUp)
{
  return SlabApplies(surface) ? SlabPatchError(*surface.Solid, surface.MeshTriangles, surface.Mesh,
                                  PatchTriangles(patches, mesh), chordReach, surface.Slack, own, enough, giveUp)
                              : HUGE_VAL;
}

double SheetwiseCellError(const CellSurface& surface, const CellPatches& patches, const TriangleMesh& mesh,
  const AdaptiveOctree::MeshCellPrediction& prediction, bool same, const Box3& cell, double enough, double giveUp)
{
  if (!SlabApplies(surface))
  {
    return HUGE_VAL;
  }
  std::vector<std::vector<SourceTriangle>> fans(prediction.Loops.size());
  const std::vector<SourceTriangle> triangles = PatchTriangles(patches, mesh);
  for (std::size_t i = 0; i < triangles.size(); ++i)
  {
    const Triangle& t = patches.Triangles[i];
    const auto local = std::find_if(t.begin(), t.end(), [](std::uint32_t v) { return v & CellPatches::LocalFlag; });
    if (local == t.end())
    {
      return HUGE_VAL;
    }
    const Vec3& apex = patches.Apexes[*local & ~CellPatches::LocalFlag];
    const auto own = std::find_if(prediction.Apexes.begin(), prediction.Apexes.end(),
      [&](const Vec3& a) { return a[0] == apex[0] && a[1] == apex[1] && a[2] == apex[2]; });
    if (own == prediction.Apexes.end() || prediction.Apexes.size() != fans.size())
    {
      return HUGE_VAL;
    }
    fans[static_cast<std::size_t>(own - prediction.Apexes.begin())].push_back(triangles[i]);
  }
  const OwnChords chords{ nullptr, nullptr, prediction.Delta, !same, cell };
  return SheetwiseSlabError(*surface.Solid, surface.MeshTriangles, surface.Mesh, cell, prediction.Loops, chords,
    fans, (same ? 1.0 : 2.0) * prediction.Delta, surface.Slack, enough, giveUp);
}

} // namespace tpc
