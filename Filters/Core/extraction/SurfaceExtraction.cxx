#include "SurfaceExtraction.h"

#include "CellPatches.h"
#include "CertifiedError.h"
#include "CrackPatching.h"
#include "CreaseFollowing.h"
#include "CrossingVertices.h"
#include "ExactCellCriterion.h"
#include "FaceDecisionCache.h"
#include "MeshBooleanCellError.h"
#include "ScratchPool.h"

#include <algorithm>
#include <cmath>
#include <optional>

namespace tpc
{
namespace
{
/// The per-cell loops run in chunks reporting progress, so that an abort
/// stops them within a chunk.
constexpr std::size_t Chunk = 8192;

/// Leaves that meet the surface (passed the tests, were stopped, or are
/// exact), in node order.
std::vector<std::uint32_t> SurfaceLeaves(const AdaptiveOctree& tree)
{
  std::vector<std::uint32_t> cells;
  for (std::size_t n = 0; n < tree.Nodes.size(); ++n)
  {
    const OctreeNode& node = tree.Nodes[n];
    if (node.IsLeaf() &&
      (node.State == CellState::Surface || node.State == CellState::Unresolved || node.State == CellState::Exact))
    {
      cells.push_back(static_cast<std::uint32_t>(n));
    }
  }
  return cells;
}

/// Cells whose patches the mesh holds (in a piece of a split run, ghost
/// cells take part in choosing each shared vertex's cell, as in the whole
/// run, but give no triangles).
std::vector<std::uint8_t> OwnCells(const AdaptiveOctree& tree, const std::vector<std::uint32_t>& cells)
{
  std::vector<std::uint8_t> own(cells.size());
  for (std::size_t i = 0; i < cells.size(); ++i)
  {
    own[i] = tree.RoleOf(tree.Nodes[cells[i]]) == TreeRole::Own;
  }
  return own;
}

/// In a piece of a split run: only the vertices of own cells' triangles.
void KeepUsedVertices(TriangleMesh& mesh)
{
  std::vector<std::uint32_t> index(mesh.Points.size(), UINT32_MAX);
  for (const auto& t : mesh.Triangles)
  {
    for (const auto v : t)
    {
      index[v] = 0;
    }
  }
  std::uint32_t kept = 0;
  for (std::size_t v = 0; v < index.size(); ++v)
  {
    if (index[v] == 0)
    {
      index[v] = kept;
      mesh.Points[kept] = mesh.Points[v];
      mesh.Normals[kept] = mesh.Normals[v];
      ++kept;
    }
  }
  mesh.Points.resize(kept);
  mesh.Normals.resize(kept);
  for (auto& t : mesh.Triangles)
  {
    for (auto& v : t)
    {
      v = index[v];
    }
  }
}
/// Own cells whose loops did not close, and own cells that may hold
/// surface but got no patch (ExtractionResult).
void CountDefects(const AdaptiveOctree& tree, const std::vector<std::uint32_t>& cells,
  const std::vector<std::uint8_t>& own, const std::vector<BoundaryLoopSet>& loops,
  const std::vector<CellPatches>& patches, ExtractionResult& result)
{
  for (std::size_t i = 0; i < cells.size(); ++i)
  {
    result.InconsistentCells += own[i] && !loops[i].Consistent ? 1 : 0;
    // (An exact cell without triangles holds none of the input: nothing is missing.)
    result.CellsWithoutPatch +=
      own[i] && patches[i].Triangles.empty() && tree.Nodes[cells[i]].State != CellState::Exact ? 1 : 0;
  }
}

/// What a surface leaf's patch is certified to (ExtractionResult): Error
/// (+inf where the certificate failed, 0 on cells that are not
/// error-bounded). Cells where one mesh is the surface also keep Bound, what
/// their error cannot exceed (the subdivision's prediction or their
/// diagonal), and Lower, a distance their patch attains (MeshCellError.h).
struct CellCertificate
{
  double Error = 0.0;
  double Bound = HUGE_VAL;
  double Lower = 0.0;
  bool Mesh = false;
  bool FinalChords = false; ///< settled by FinalChordsCellError
};

/// The error-bounded cells' bound: each one's certified error, or its
/// diagonal where that is smaller or the certificate failed (ExtractionResult).
void GatherCertifiedBound(const AdaptiveOctree& tree, const std::vector<std::uint32_t>& cells,
  const std::vector<CellCertificate>& certificates, ExtractionResult& result)
{
  for (std::size_t i = 0; i < cells.size(); ++i)
  {
    const OctreeNode& node = tree.Nodes[cells[i]];
    if (node.State == CellState::Surface && node.ErrorBounded && tree.RoleOf(node) == TreeRole::Own)
    {
      const double diagonal = tree.Grid.CellDiagonal(node.Level);
      const double error = certificates[i].Error;
      // (A cell no larger than the tolerance keeps its diagonal's bound.)
      result.UncertifiedCells += error == HUGE_VAL && diagonal > tree.HausdorffTolerance ? 1 : 0;
      result.CellErrors.emplace_back(cells[i], error);
      result.FinalChordCells += certificates[i].FinalChords ? 1 : 0;
      result.CertifiedBound = std::max(result.CertifiedBound, std::min(error, diagonal));
    }
  }
}

/// A fan from a mesh edge's point is kept within this fraction of the
/// tolerance even where the apex fan's own bound is smaller: along a straight
/// crease between planar sides, with the apex on the crease, both are exact
/// up to rounding, and the fan from x draws the crease as one edge with two
/// triangles fewer. A quarter: the least the first certificates aim at
/// (FirstCertificateAim), so this one is not pushed further than the others
/// (measured at acdff20: a tenth gave the same fandisk, tilted cube and
/// tilted bar of the tests, and couplingdown at 1/64 7 192 triangles where
/// a quarter gave 7 190).
constexpr double MeshEdgeFanKeptWithin = 0.25;
// (The predictions' values are tight only above PredictionPrecision of the
// tolerance, MeshCellError.h: read against this quarter and 1.1 times against
// it in FirstCertificateAim, they must be so above it.)
static_assert(1.1 * PredictionPrecision < MeshEdgeFanKeptWithin, "predictions read below their precision");

/// Pieces a cell's first certificate may examine (it needs a proof under the
/// tolerance, not a tight one: RefineMeshCertificates tightens those that
/// may set the reported bound).
constexpr std::size_t FirstCertificateBudget = 256;

/// What the mesh cells' first certificates aim at, once they have a proof
/// under the tolerance: 1.1 times the largest distance the subdivision's
/// predictions came upon, about what RefineMeshCertificates will ask for
/// (1.1 times the largest distance the final patches are seen to attain).
/// A certificate stopped at its first proof would be refined again from its
/// first pieces; going on here costs less (armadillo at 1/128: 9.17 G ->
/// 8.86 G instructions with a fixed 0.6 of the tolerance, which at 1/64 was
/// above what the refinement asked for). A quarter of the tolerance at least;
/// 0.6 of it without predictions. (A piece of a split run sees its own trees'
/// and its ghosts' predictions: its certificates may stop at another aim than
/// one run's would, each a proven bound all the same.)
double FirstCertificateAim(const AdaptiveOctree& tree)
{
  double attained = 0.0;
  for (const auto& entry : tree.MeshCellPredictions)
  {
    attained = std::max(attained, entry.second.Attained);
  }
  const double tolerance = tree.HausdorffTolerance;
  return tree.MeshCellPredictions.empty()
    ? 0.6 * tolerance
    : std::min(std::max(1.1 * attained, MeshEdgeFanKeptWithin * tolerance), tolerance);
}

/// The points of each of the final `loops`, in order.
std::vector<std::vector<Vec3>> FinalLoopPoints(
  const BoundaryLoopSet& loops, const CrossingVertices& vertices, const TriangleMesh& mesh)
{
  std::vector<std::vector<Vec3>> points(loops.LoopSizes.size());
  std::size_t k = 0;
  for (std::size_t l = 0; l < loops.LoopSizes.size(); ++l)
  {
    for (const std::size_t end = k + loops.LoopSizes[l]; k < end; ++k)
    {
      points[l].push_back(mesh.Points[vertices.IdOf(loops.Crossings[k])]);
    }
  }
  return points;
}

/// How a lone final loop stands to the cell's own (the slab bound's
/// premises, SlabBound.h): its chords' reach from the trace, from the
/// prediction's Delta (each own chord's deviation, at most) - Delta where
/// the final loop is the own loop (SameLoop), twice that where it refines
/// it (FinalLoopRefines: Loops refining the cell's own), +inf otherwise -
/// and whether it refines rather than is it.
struct LoneLoopReach
{
  double Reach = HUGE_VAL;
  bool Refines = false;
};

LoneLoopReach LoneLoopChordReach(
  const AdaptiveOctree::MeshCellPrediction& prediction, const std::vector<std::vector<Vec3>>& finals, const Box3& box)
{
  if (prediction.Loops.size() != 1 || finals.size() != 1)
  {
    return {};
  }
  return SameLoop(prediction.Loops[0], finals[0])  ? LoneLoopReach{ prediction.Delta, false }
    : FinalLoopRefines(prediction.Loops[0], finals[0], box) ? LoneLoopReach{ 2.0 * prediction.Delta, true }
                                                            : LoneLoopReach{};
}

/// A mesh cell larger than the tolerance (its prediction `prediction`)
/// spanned by Marching Cubes' fan from a loop point (TriangulateCellFromLoopPoint):
/// the apex fan's prediction says nothing of it, so it is kept on its own
/// certificate (the slab bound over the cell's own chords' reach, or a
/// branch and bound), set in `certificate`, the fan in `patches`. From a point
/// where the surface is smooth along the loop: kept within the tolerance.
/// From a mesh edge's point (a crease drawn along x -> x', MeshEdgeFanPoint):
/// kept only within the apex fan's own bound (the fan the cell was accepted
/// with, over its own loop; none where it was accepted on the per-chord
/// bound) or within MeshEdgeFanKeptWithin of the tolerance - a corner whose
/// third crease the diagonals would cut by more is kept sharp by the apex.
/// Either must follow the cell's `creases` (CreaseFollowing.h; none outside
/// scenes of one mesh). False when the loop allows no such fan or it is not
/// kept. `reach`: how far the final loop's chords may be from the trace for
/// the slab bound, and whether it refines the own (LoneLoopChordReach),
/// tried before the branch and bound where finite.
bool MeshCellFromLoopPoint(const AdaptiveOctree& tree, std::uint32_t n, const BoundaryLoopSet& loops,
  const CrossingVertices& vertices, const TriangleMesh& mesh, const CellSurface& surface,
  const std::vector<CreaseSegment>& creases, double aim, const AdaptiveOctree::MeshCellPrediction& prediction,
  const LoneLoopReach& reach, CellPatches& patches, CellCertificate& certificate)
{
  CellPatches fan;
  bool fromMeshEdge = false;
  if (!TriangulateCellFromLoopPoint(loops, tree.Nodes[n], tree.Grid, vertices, mesh, fan, fromMeshEdge))
  {
    return false;
  }
  // (The apex fan was accepted drawing the mesh's creases: this one must
  // too.)
  if (!CreasesFollowed(creases, PatchTriangles(fan, mesh), CreaseReach * tree.HausdorffTolerance))
  {
    return false;
  }
  const double tolerance = tree.HausdorffTolerance;
  const double ownFan = prediction.OwnFanError < HUGE_VAL ? prediction.OwnFanError : 0.0;
  const double keptWithin =
    fromMeshEdge ? std::min(std::max(MeshEdgeFanKeptWithin * tolerance, ownFan), tolerance) : tolerance;
  const Box3 box = tree.Grid.CellBox(tree.Nodes[n].Level, tree.Nodes[n].Ijk);
  const OwnChords own{ &prediction.Loops, nullptr, prediction.Delta, reach.Refines, box };
  const double slab = reach.Reach < HUGE_VAL
    ? SlabCellError(surface, fan, mesh, reach.Reach, own, std::min(aim, keptWithin), keptWithin)
    : HUGE_VAL;
  HausdorffEstimate e = slab <= std::min(aim, keptWithin)
    ? HausdorffEstimate{ slab, 0.0 }
    : CertifiedCellError(surface, fan, mesh, std::min(aim, keptWithin), keptWithin, FirstCertificateBudget);
  e.Upper = std::min(e.Upper, slab); // (both proven)
  if (!(e.Upper <= keptWithin))
  {
    return false;
  }
  patches = std::move(fan);
  certificate.Bound = certificate.Error = e.Upper;
  certificate.Lower = e.Lower;
  return true;
}

/// A cell larger than the tolerance whose fans around the apexes `apexes`
/// (one per loop) it was accepted with, drawn over the final loops in
/// `patches`, miss one of its `creases` by more than `reach` (the prediction
/// checked the fans over the cell's own loops; the final loops' points
/// between its own may change the bends at the spokes: CreaseFollowing.h):
/// the first fans around one of `otherApexSets()` (sets of points of the
/// creases, one per loop, asked for only then) that follow them all and are
/// certified within the tolerance on their own, in `patches`, their
/// certificate in `certificate`. False - `patches` unchanged - where the fans
/// follow them or none do. (One mesh: CreaseApexSets, within CreaseReach;
/// meshes meeting: ApexesOnCreases, one loop, within BooleanCreaseReach.)
template <typename OtherApexSets>
bool CellFromOtherApexes(const AdaptiveOctree& tree, std::uint32_t n, const BoundaryLoopSet& loops,
  const PrimitiveSet& prims, const CrossingVertices& vertices, const TriangleMesh& mesh, const CellSurface& surface,
  const std::vector<CreaseSegment>& creases, const OtherApexSets& otherApexSets, double reach, double aim,
  const std::vector<Vec3>& apexes, CellPatches& patches, CellCertificate& certificate)
{
  if (creases.empty() || loops.LoopSizes.size() != apexes.size() ||
    CreasesFollowed(creases, PatchTriangles(patches, mesh), reach))
  {
    return false;
  }
  const OctreeNode& node = tree.Nodes[n];
  const CsgExpression& expression = *tree.Expressions[n];
  const double tolerance = tree.HausdorffTolerance;
  for (const std::vector<Vec3>& others : otherApexSets())
  {
    if (others.size() != apexes.size() || std::equal(others.begin(), others.end(), apexes.begin(),
                                            [](const Vec3& a, const Vec3& b) { return Norm(a - b) == 0.0; }))
    {
      continue; // (the fans just drawn)
    }
    CellPatches fans;
    TriangulateCell(loops, node, expression, prims, tree.Grid, vertices, mesh, fans, nullptr, &others);
    if (!CreasesFollowed(creases, PatchTriangles(fans, mesh), reach))
    {
      continue;
    }
    const HausdorffEstimate e =
      CertifiedCellError(surface, fans, mesh, std::min(aim, tolerance), tolerance, FirstCertificateBudget);
    if (e.Upper <= tolerance)
    {
      patches = std::move(fans);
      certificate.Bound = certificate.Error = e.Upper;
      certificate.Lower = e.Lower;
      return true;
    }
  }
  return false;
}

/// Whether each final loop (`finals`, FinalLoopPoints) of a cell whose
/// prediction is `prediction` was fanned around one of its apexes,
/// unchanged, and refines the cell's own
/// loop of that apex (FinalLoopRefines): the prediction's Bound then holds
/// for the patch (MeshCellError.h; fan by fan where there are several
/// loops). `same`: each final loop is that own loop itself (SameLoop), so the
/// patch is the predicted fans.
bool FinalLoopsRefine(const AdaptiveOctree::MeshCellPrediction& prediction,
  const std::vector<std::vector<Vec3>>& finals, const CellPatches& patches, const Box3& box, bool& same)
{
  same = true;
  if (finals.size() != prediction.Loops.size() || patches.Apexes.size() != prediction.Loops.size())
  {
    return false;
  }
  std::vector<bool> used(prediction.Apexes.size(), false);
  for (std::size_t l = 0; l < finals.size(); ++l)
  {
    // (Each own loop once: two final loops around one apex would leave
    // another own loop's part of S_C unaccounted for.)
    const Vec3& drawn = patches.Apexes[l];
    const auto own = std::find_if(prediction.Apexes.begin(), prediction.Apexes.end(),
      [&](const Vec3& a) { return a[0] == drawn[0] && a[1] == drawn[1] && a[2] == drawn[2]; });
    if (own == prediction.Apexes.end() || used[static_cast<std::size_t>(own - prediction.Apexes.begin())])
    {
      return false;
    }
    used[static_cast<std::size_t>(own - prediction.Apexes.begin())] = true;
    const std::vector<Vec3>& ownLoop = prediction.Loops[static_cast<std::size_t>(own - prediction.Apexes.begin())];
    if (!FinalLoopRefines(ownLoop, finals[l], box))
    {
      return false;
    }
    same = same && SameLoop(ownLoop, finals[l]);
  }
  return true;
}

/// Surface leaf `n`'s patches (CellPatches.h) and what they are certified to.
/// A mesh cell's error is first bounded with a small budget of pieces
/// (FirstCertificateBudget); RefineMeshCertificates refines the ones that
/// matter. `surface`: where S in the cell is built (ScratchPool.h).
CellCertificate TriangulateSurfaceCell(const AdaptiveOctree& tree, std::uint32_t n, const BoundaryLoopSet& loops,
  const PrimitiveSet& prims, const CrossingVertices& vertices, const TriangleMesh& mesh, bool predictionsHold,
  double aim, CellPatches& patches, CellSurface& surface)
{
  const OctreeNode& node = tree.Nodes[n];
  const CsgExpression& expression = *tree.Expressions[n];
  const Box3 box = tree.Grid.CellBox(node.Level, node.Ijk);
  const bool bounded = node.State == CellState::Surface && node.ErrorBounded;
  CellCertificate certificate;
  const auto booleanFan = tree.BooleanFanApexes.find(n);
  if (bounded && SurfaceOfCell(tree, n, prims, booleanFan != tree.BooleanFanApexes.end(), surface))
  {
    // (MeshCellPredictions: where one mesh is the surface; BooleanFanApexes:
    // where meshes meet.)
    const auto prediction = tree.MeshCellPredictions.find(n);
    certificate.Mesh = true;
    if (prediction != tree.MeshCellPredictions.end())
    {
      // Larger than the tolerance: its patch must follow the mesh's creases
      // in a scene of one mesh (CreaseFollowing.h). First, two triangles
      // fewer.
      const std::vector<CreaseSegment> creases = IsOneMesh(*tree.SceneExpression)
        ? CreasesInCell(*LoneMeshLeaf(expression), prims, box)
        : std::vector<CreaseSegment>();
      const AdaptiveOctree::MeshCellPrediction& predicted = prediction->second;
      const std::vector<std::vector<Vec3>> finals = FinalLoopPoints(loops, vertices, mesh);
      const LoneLoopReach loneLoopReach =
        predictionsHold && loops.Consistent ? LoneLoopChordReach(predicted, finals, box) : LoneLoopReach{};
      if (MeshCellFromLoopPoint(tree, n, loops, vertices, mesh, surface, creases, aim, predicted, loneLoopReach,
            patches, certificate))
      {
        return certificate;
      }
      // Else the fans around the apexes the prediction was made with. The
      // prediction holds when each final loop refines the cell's own loop
      // whose apex it was fanned around, its points on the surface's trace
      // in the same tiles (no cell was stopped by a limit: its tiles may hold
      // bends or two chords); the patch is certified on its own anyway.
      TriangulateCell(loops, node, expression, prims, tree.Grid, vertices, mesh, patches, nullptr, &predicted.Apexes);
      if (CellFromOtherApexes(tree, n, loops, prims, vertices, mesh, surface, creases,
            [&] { return CreaseApexSets(box, creases, predicted.Loops, predicted.Apexes); },
            CreaseReach * tree.HausdorffTolerance, aim, predicted.Apexes, patches, certificate))
      {
        return certificate;
      }
      bool same = false;
      const bool refined = predictionsHold && loops.Consistent &&
        FinalLoopsRefine(predicted, finals, patches, box, same);
      certificate.Bound = refined ? predicted.Bound : HUGE_VAL;
      if (refined && predicted.OwnFanError <= aim && same)
      {
        // The fans the prediction bounded, unchanged (no finer neighbour
        // added a point to their loops): their bound is already as tight as
        // the first certificates aim at.
        certificate.Error = predicted.OwnFanError;
        certificate.Lower = predicted.Attained;
        return certificate;
      }
      // Else, over the cell's own loops or loops refining them, the slab
      // bound or its local heights where within the aim (SlabBound.h,
      // LocalHeights.h), sheet by sheet where S_C is several (MeshCellError.h:
      // Several sheets); a proven bound all the same where not. (Over the own
      // loops it repeats the prediction's where that settled the cell, which
      // missed the aim: a pass over S_C, where skipping it left the branch
      // and bound's attained distances to raise the reported bound -
      // knot1.off at 1/64: 0.0176 -> 0.0188.)
      const OwnChords own{ &predicted.Loops, nullptr, predicted.Delta, !same, box };
      double slab = refined
        ? SlabCellError(surface, patches, mesh, (same ? 1.0 : 2.0) * predicted.Delta, own, aim, tree.HausdorffTolerance)
        : HUGE_VAL;
      if (refined && !(slab <= aim) && predicted.Loops.size() > 1)
      {
        slab = std::min(
          slab, SheetwiseCellError(surface, patches, mesh, predicted, same, box, aim, tree.HausdorffTolerance));
      }
      // Else over the final loops as they are, each chord measured on its
      // final tile (FinalChordsCellError): where a finer neighbour retiled a
      // crease tile, so that they no longer refine the own, the one bound
      // short of the branch and bound, and where they do, tighter than twice
      // Delta (the turbine at 1/64: 51 of the 75 cells left here settle, 40
      // of them of two loops not refining their own; at about the branch and
      // bound's cost, and its HausdorffBound lower). (Not where a limit
      // stopped a cell: its tiles may hold two arcs.)
      if (!(slab <= aim) && predictionsHold && loops.Consistent)
      {
        const CellBoundary boundary = MarkedCellBoundary(tree, n, prims);
        const double measured = FinalChordsCellError(
          surface, patches, mesh, tree.Grid, boundary, loops, finals, box, aim, tree.HausdorffTolerance);
        certificate.FinalChords = measured <= aim;
        slab = std::min(slab, measured);
      }
      if (slab <= aim)
      {
        certificate.Error = std::min(certificate.Bound, slab);
        return certificate;
      }
      certificate.Bound = std::min(certificate.Bound, slab);
    }
    else if (booleanFan != tree.BooleanFanApexes.end())
    {
      // Meshes meeting in a cell larger than the tolerance: the fans around
      // the apexes it was accepted with (one per loop), over the final
      // loops, or - one loop - around another point of the crease where that
      // one misses it; bounded by its certificate alone
      // (MeshBooleanCellError.h).
      const std::vector<Vec3>& apexes = booleanFan->second;
      TriangulateCell(loops, node, expression, prims, tree.Grid, vertices, mesh, patches, nullptr, &apexes);
      const auto otherApexSets = [&] {
        std::vector<std::vector<Vec3>> sets;
        for (const Vec3& apex : ApexesOnCreases(box, surface.Creases, apexes[0]))
        {
          sets.push_back({ apex });
        }
        return sets;
      };
      if (apexes.size() == 1 &&
        CellFromOtherApexes(tree, n, loops, prims, vertices, mesh, surface, surface.Creases, otherApexSets,
          BooleanCreaseReach * tree.HausdorffTolerance, aim, apexes, patches, certificate))
      {
        return certificate;
      }
    }
    else
    {
      // Within the tolerance (one mesh, or meshes meeting): its own patch,
      // bounded by its diagonal.
      TriangulateCell(loops, node, expression, prims, tree.Grid, vertices, mesh, patches);
      certificate.Bound = tree.Grid.CellDiagonal(node.Level);
    }
    const HausdorffEstimate e = CertifiedCellError(
      surface, patches, mesh, aim, std::min(certificate.Bound, tree.HausdorffTolerance), FirstCertificateBudget);
    certificate.Error = std::min(certificate.Bound, e.Upper);
    certificate.Lower = e.Lower;
    return certificate;
  }
  // (A crease cell was accepted with the fan around its crease apex in mind,
  // QuadricCellError.h; that fan is drawn over the final loop.)
  const std::optional<QuadricCellError> quadric = bounded
    ? BoundQuadricCell(tree.Expressions[n], tree.NearExpression(n, tree.HausdorffTolerance), prims, box,
        tree.HausdorffTolerance, true)
    : std::nullopt;
  const std::optional<Vec3> creaseApex = quadric && quadric->Crease ? CreaseApex(*quadric, prims) : std::nullopt;
  const std::vector<Vec3> creaseApexes = creaseApex ? std::vector<Vec3>{ *creaseApex } : std::vector<Vec3>();
  TriangulateCell(loops, node, expression, prims, tree.Grid, vertices, mesh, patches, quadric ? &*quadric : nullptr,
    creaseApex ? &creaseApexes : nullptr);
  certificate.Error = !bounded ? 0.0 : quadric ? CertifiedPatchError(*quadric, patches, mesh) : HUGE_VAL;
  const auto fan = tree.QuadricFanApexes.find(n);
  if (quadric && certificate.Error == HUGE_VAL && fan != tree.QuadricFanApexes.end())
  {
    // The fan the cell was accepted with, over the final loop
    // (QuadricCellError.h: Predicted on the cell's own loop).
    CellPatches predicted;
    const std::vector<Vec3> apexes{ fan->second };
    TriangulateCell(loops, node, expression, prims, tree.Grid, vertices, mesh, predicted, nullptr, &apexes);
    const double error = CertifiedPatchError(*quadric, predicted, mesh);
    if (error < HUGE_VAL)
    {
      patches = std::move(predicted);
      certificate.Error = error;
    }
  }
  return certificate;
}

/// Refines the mesh cells' certificates that may set the reported bound:
/// those above 1.1 times the largest distance a patch was seen to attain
/// (the others cannot raise the bound past it), each until within that, or
/// within 10 % of its own attained distance (OneSidedHausdorff). Largest
/// first, in rounds of doubling size: refining the largest finds larger
/// attained distances, which the next round's threshold takes in, so fewer
/// cells need it - the bound reported is within 1.1 times an attained
/// distance all the same. Each round's cells are refined against one
/// threshold, so the result does not depend on the threads.
bool RefineMeshCertificates(const AdaptiveOctree& tree, const std::vector<std::uint32_t>& cells,
  const std::vector<std::uint8_t>& own, const std::vector<CellPatches>& patches, const TriangleMesh& mesh,
  const PrimitiveSet& prims, std::vector<CellCertificate>& certificates, ScratchPool<CellSurface>& surfaces,
  const ParallelFor& parallelFor, const ProgressCallback& progress)
{
  double attained = 0.0;
  std::vector<std::size_t> pending;
  for (std::size_t i = 0; i < cells.size(); ++i)
  {
    if (own[i] && certificates[i].Mesh)
    {
      attained = std::max(attained, certificates[i].Lower);
      pending.push_back(i);
    }
  }
  std::sort(pending.begin(), pending.end(), [&](std::size_t a, std::size_t b) {
    return certificates[a].Error != certificates[b].Error ? certificates[a].Error > certificates[b].Error : a < b;
  });
  std::size_t first = 0, round = 64;
  while (first < pending.size())
  {
    const double enough = 1.1 * attained;
    if (certificates[pending[first]].Error <= enough)
    {
      break; // (sorted: no later cell is above it)
    }
    const std::size_t last = std::min(pending.size(), first + round);
    // (Progress and abort within the round too: the last rounds hold half
    // the cells.)
    const ProgressCallback roundProgress = progress
      ? ProgressCallback([&, first, last](double f) {
          return progress((static_cast<double>(first) + f * static_cast<double>(last - first)) /
            static_cast<double>(pending.size()));
        })
      : ProgressCallback();
    if (!ChunkedFor(last - first, Chunk, parallelFor, [&](std::size_t begin, std::size_t end) {
          ScratchPool<CellSurface>::Lease surface(surfaces);
          for (std::size_t k = first + begin; k < first + end; ++k)
          {
            CellCertificate& c = certificates[pending[k]];
            if (c.Error > enough)
            {
              SurfaceOfCell(tree, cells[pending[k]], prims, false, *surface);
              const HausdorffEstimate e = CertifiedCellError(
                *surface, patches[pending[k]], mesh, enough, std::min(c.Bound, tree.HausdorffTolerance), 4096);
              c.Error = std::min(c.Error, e.Upper);
              c.Lower = std::max(c.Lower, e.Lower);
            }
          }
        }, roundProgress))
    {
      return false;
    }
    for (std::size_t k = first; k < last; ++k)
    {
      attained = std::max(attained, certificates[pending[k]].Lower);
    }
    first = last;
    round *= 2;
  }
  return true;
}
} // namespace

ExtractionResult ExtractSurface(const AdaptiveOctree& tree, const ImplicitScene& scene,
  const ParallelFor& parallelFor, const ProgressCallback& progress)
{
  // Progress: loops 40 %, vertex numbering 10 %, vertices 20 %, patches 20 %, certificates 5 %,
  // writing 5 %.
  ExtractionResult result;
  TriangleMesh& mesh = result.Mesh;
  const auto& prims = scene.Primitives;
  const std::vector<std::uint32_t> cells = SurfaceLeaves(tree);
  const std::vector<std::uint8_t> own = OwnCells(tree, cells);

  // Pass 1: each cell's loops, sampled as its neighbours sample (crack
  // patching); the crease tiles two cells share decided once.
  std::vector<BoundaryLoopSet> loops(cells.size());
  FaceDecisionCache faceDecisions;
  if (!ChunkedFor(cells.size(), Chunk, parallelFor, [&](std::size_t begin, std::size_t end) {
        for (std::size_t i = begin; i < end; ++i)
        {
          loops[i] = CellLoops(tree, cells[i], prims, &faceDecisions);
        }
      }, ProgressRange(progress, 0.0, 0.4)))
  {
    result.Aborted = true;
    return result;
  }

  // Pass 2: one vertex per distinct crossing, placed by its first cell. (At
  // most one apex per loop follows: reserved now, so the points are written
  // where they stay.)
  std::size_t loopCount = 0;
  for (const BoundaryLoopSet& l : loops)
  {
    loopCount += l.LoopSizes.size();
  }
  CrossingVertices vertices;
  std::vector<std::uint8_t> creaseFans(cells.size());
  for (std::size_t i = 0; i < cells.size(); ++i)
  {
    creaseFans[i] = tree.Nodes[cells[i]].CreaseFan ? 1 : 0;
  }
  if (!vertices.Build(loops, creaseFans, parallelFor, ProgressRange(progress, 0.4, 0.5)))
  {
    result.Aborted = true;
    return result;
  }
  mesh.Points.reserve(vertices.Records().size() + loopCount);
  mesh.Normals.reserve(vertices.Records().size() + loopCount);
  if (!PlaceCrossingVertices(vertices, tree, cells, prims, mesh, parallelFor, ProgressRange(progress, 0.5, 0.7)))
  {
    result.Aborted = true;
    return result;
  }

  // Pass 3: each own cell's patches, and the error-bounded cells' errors.
  std::vector<CellPatches> patches(cells.size());
  std::vector<CellCertificate> certificates(cells.size());
  const bool predictionsHold = std::none_of(cells.begin(), cells.end(),
    [&](std::uint32_t n) { return tree.Nodes[n].State == CellState::Unresolved; });
  const double aim = FirstCertificateAim(tree);
  ScratchPool<CellSurface> surfaces; // (S in the mesh cells, MeshCellError.h, MeshBooleanSurface.h)
  if (!ChunkedFor(cells.size(), Chunk, parallelFor, [&](std::size_t begin, std::size_t end) {
        ScratchPool<CellSurface>::Lease surface(surfaces);
        for (std::size_t i = begin; i < end; ++i)
        {
          if (own[i] && tree.Nodes[cells[i]].State == CellState::Exact)
          {
            TriangulateExactCell(loops[i], vertices, mesh, patches[i]);
          }
          else if (own[i])
          {
            certificates[i] =
              TriangulateSurfaceCell(tree, cells[i], loops[i], prims, vertices, mesh, predictionsHold, aim,
                patches[i], *surface);
          }
        }
      }, ProgressRange(progress, 0.7, 0.9)) ||
    !RefineMeshCertificates(tree, cells, own, patches, mesh, prims, certificates, surfaces, parallelFor,
      ProgressRange(progress, 0.9, 0.95)))
  {
    result.Aborted = true;
    return result;
  }
  CountDefects(tree, cells, own, loops, patches, result);
  GatherCertifiedBound(tree, cells, certificates, result);

  // Pass 4: the output, written once.
  if (!WritePatches(patches, cells, mesh, parallelFor, ProgressRange(progress, 0.95, 1.0)))
  {
    result.Aborted = true;
    return result;
  }
  if (!tree.Roles.empty())
  {
    KeepUsedVertices(mesh);
  }
  return result;
}

} // namespace tpc
