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

/// The triangles of `patches` (positions `triangles`) as `groups` fans, in
/// their order: each triangle in the fan groupOf(i, its apex's local id)
/// names; false where a triangle has no apex (a local vertex) or groupOf
/// refuses it (returns `groups` or more).
template <typename GroupOf>
bool FansAroundApexes(const CellPatches& patches, const std::vector<SourceTriangle>& triangles, std::size_t groups,
  const GroupOf& groupOf, std::vector<std::vector<SourceTriangle>>& fans)
{
  fans.assign(groups, {});
  for (std::size_t i = 0; i < triangles.size(); ++i)
  {
    const Triangle& t = patches.Triangles[i];
    const auto local = std::find_if(t.begin(), t.end(), [](std::uint32_t v) { return v & CellPatches::LocalFlag; });
    if (local == t.end())
    {
      return false;
    }
    const std::size_t group = groupOf(i, *local);
    if (group >= groups)
    {
      return false;
    }
    fans[group].push_back(triangles[i]);
  }
  return true;
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
  // (Each triangle with the own loop whose apex - the prediction's - it is
  // drawn around.)
  const std::size_t loops = prediction.Loops.size();
  std::vector<std::vector<SourceTriangle>> fans;
  if (!FansAroundApexes(patches, PatchTriangles(patches, mesh), loops,
        [&](std::size_t, std::uint32_t local) {
          const Vec3& apex = patches.Apexes[local & ~CellPatches::LocalFlag];
          const auto own = std::find_if(prediction.Apexes.begin(), prediction.Apexes.end(),
            [&](const Vec3& a) { return a[0] == apex[0] && a[1] == apex[1] && a[2] == apex[2]; });
          return own == prediction.Apexes.end() || prediction.Apexes.size() != loops
            ? loops
            : static_cast<std::size_t>(own - prediction.Apexes.begin());
        },
        fans))
  {
    return HUGE_VAL;
  }
  const OwnChords chords{ nullptr, nullptr, prediction.Delta, !same, cell };
  return SheetwiseSlabError(*surface.Solid, surface.MeshTriangles, surface.Mesh, cell, prediction.Loops, chords,
    fans, (same ? 1.0 : 2.0) * prediction.Delta, surface.Slack, enough, giveUp);
}

namespace
{
/// The triangles of `patches` grouped by loop: those around apex l are loop
/// l's fan when their other corners are points of `finals[l]` (TriangulateCell
/// fans the loops in order, an apex each); false where a triangle has no
/// apex, or not its loop's points, or the apexes are not one per loop.
bool FansByLoop(const CellPatches& patches, const std::vector<SourceTriangle>& triangles,
  const std::vector<std::vector<Vec3>>& finals, std::vector<std::vector<SourceTriangle>>& fans)
{
  if (patches.Apexes.size() != finals.size())
  {
    return false;
  }
  const auto onLoop = [](const std::vector<Vec3>& loop, const Vec3& p) {
    return std::any_of(loop.begin(), loop.end(),
      [&](const Vec3& q) { return q[0] == p[0] && q[1] == p[1] && q[2] == p[2]; });
  };
  return FansAroundApexes(patches, triangles, finals.size(),
    [&](std::size_t i, std::uint32_t local) {
      const std::size_t l = local & ~CellPatches::LocalFlag;
      for (int k = 0; k < 3; ++k)
      {
        if (patches.Triangles[i][k] != local && !onLoop(finals[l], triangles[i][k]))
        {
          return finals.size();
        }
      }
      return l;
    },
    fans);
}
} // namespace

double FinalChordsCellError(const CellSurface& surface, const CellPatches& patches, const TriangleMesh& mesh,
  const RootGrid& grid, const CellBoundary& boundary, const BoundaryLoopSet& loops,
  const std::vector<std::vector<Vec3>>& finals, const Box3& cell, double enough, double giveUp)
{
  if (!SlabApplies(surface))
  {
    return HUGE_VAL;
  }
  const std::vector<std::vector<Crossing>> each = EachLoop(loops); // (FinalLoopPoints' order)
  std::vector<double> deltas; // (the own chords' order: loop by loop, chord k from point k)
  double delta = 0.0;
  for (std::size_t l = 0; l < each.size(); ++l)
  {
    std::vector<ChordTile> chords;
    if (!MeasureChords(surface.Mesh, grid, boundary, each[l], finals[l], giveUp, chords) ||
      chords.size() != each[l].size())
    {
      return HUGE_VAL;
    }
    for (const ChordTile& c : chords)
    {
      deltas.push_back(c.Deviation + surface.Slack);
      delta = std::max(delta, deltas.back());
    }
  }
  if (!(delta < giveUp))
  {
    return HUGE_VAL;
  }
  const OwnChords own{ &finals, &deltas, HUGE_VAL, false, cell };
  const std::vector<SourceTriangle> triangles = PatchTriangles(patches, mesh);
  double bound = SlabPatchError(
    *surface.Solid, surface.MeshTriangles, surface.Mesh, triangles, delta, surface.Slack, own, enough, giveUp);
  std::vector<std::vector<SourceTriangle>> fans;
  if (!(bound <= enough) && finals.size() > 1 && FansByLoop(patches, triangles, finals, fans))
  {
    bound = std::min(bound, SheetwiseSlabError(*surface.Solid, surface.MeshTriangles, surface.Mesh, cell, finals,
                              own, fans, delta, surface.Slack, enough, giveUp));
  }
  return bound;
}

} // namespace tpc
