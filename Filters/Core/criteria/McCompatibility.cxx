#include "McCompatibility.h"

#include "BoundaryLoops.h"
#include "ComplexCellCriterion.h"
#include "CreaseCrossing.h"
#include "CreaseFollowing.h"
#include "CsgCreaseCrossing.h"
#include "EdgeCrossings.h"
#include "ExactCellCriterion.h"
#include "FaceDecisionCache.h"
#include "FaceRefinement.h"
#include "MeshBooleanCellError.h"
#include "MeshCellError.h"
#include "PlanarCell.h"
#include "QuadricCellError.h"
#include "StarShapedCriterion.h"

#include <algorithm>
#include <cmath>
#include <optional>

namespace tpc
{

namespace
{
/// Refines each face of cell `n` until its tiles pass the face tests
/// (FaceRefinement.h) and gathers the tiles and their corner samples into
/// `boundary`; false, with the failing test in `v.Reason`, when a face
/// cannot be tiled within `levels`. With `faceDecisions`, a face of one
/// mesh that the cell beside it, of the same level, has tiled is not tiled
/// again (FaceDecisionCache.h).
bool TileFaces(const AdaptiveOctree& tree, std::uint32_t n, const PrimitiveSet& prims, int levels,
  CellSignCache& signs, FaceDecisionCache* faceDecisions, CellBoundary& boundary, McCompatibility& v)
{
  const RootGrid& grid = tree.Grid;
  const OctreeNode& node = tree.Nodes[n];
  const int shift = grid.MaxDepth - node.Level;
  const LatticeIndex size = LatticeIndex(1) << shift;
  boundary.Size = size;
  for (int a = 0; a < 3; ++a)
  {
    boundary.Base[a] = node.Ijk[a] << shift;
  }
  for (int f = 0; f < 6; ++f)
  {
    const int axis = f / 2, side = f % 2;
    const LatticeIndex plane = boundary.Base[axis] + (side ? size : 0);
    const LatticeIndex u0 = boundary.Base[(axis + 1) % 3], v0 = boundary.Base[(axis + 2) % 3];
    const FaceRefinementResult r = TileFace(faceDecisions, tree.Expressions[n], prims, grid, axis, plane,
      { u0, v0, u0 + size, v0 + size }, std::min(levels, shift), signs);
    if (r.Tiles.empty())
    {
      v.Reason = r.Failure;
      return false;
    }
    for (const FaceTile& t : r.Tiles)
    {
      for (int c = 0; c < 4; ++c)
      {
        const PointKey key = TileCorner(axis, plane, t, c);
        boundary.Points.emplace_back(key, signs.Inside(key));
      }
    }
    if (r.Tiles.size() > 1)
    {
      v.Refinements.emplace_back(FaceOf(grid, node, f), r.Tiles);
    }
    boundary.Tiles[f] = r.Tiles;
  }
  return true;
}

/// The prediction of mesh cell `n` made again where it failed, over its loop
/// with the tiles of its wide chords split (RefineChordTiles); where it then
/// passes, the cell keeps that tiling (`boundary`, and the faces it records)
/// and that prediction (in `v`). Else `boundary` and `v` stay. Where
/// `creaseTiles`, `boundary`'s crease tiles are marked. `surface`: S_C, its
/// polygons clipped from `surfaceTriangles`.
bool PredictOverFinerChords(const AdaptiveOctree& tree, std::uint32_t n, const PrimitiveSet& prims, double tolerance,
  int faceRefinementLevels, bool creaseTiles, bool probesFirst, const PolygonSet& surface,
  const TriangleList& surfaceTriangles, CellSignCache& signs,
  CellBoundary& boundary, McCompatibility& v)
{
  const RootGrid& grid = tree.Grid;
  const OctreeNode& node = tree.Nodes[n];
  const CsgExpressionPtr& expression = tree.Expressions[n];
  CellBoundary finer = boundary;
  if (RefineChordTiles(expression, prims, grid, surface, creaseTiles, ChordRefinementShare * tolerance,
        std::min(faceRefinementLevels, grid.MaxDepth - node.Level), signs, finer) == 0)
  {
    return false;
  }
  AdaptiveOctree::MeshCellPrediction prediction;
  const double bound = PredictedMeshCellError(*expression, prims, grid, grid.CellBox(node.Level, node.Ijk), finer,
    TraceBoundaryLoops(finer), tolerance, prediction, &surface, &surfaceTriangles, probesFirst, nullptr, creaseTiles);
  if (!(bound <= tolerance))
  {
    return false;
  }
  boundary = std::move(finer);
  v.MeshPrediction = std::move(prediction);
  v.PredictedError = bound;
  v.Refinements.clear();
  for (int f = 0; f < 6; ++f)
  {
    if (boundary.Tiles[f].size() > 1)
    {
      v.Refinements.emplace_back(FaceOf(grid, node, f), boundary.Tiles[f]);
    }
  }
  return true;
}

/// Whether a crease cell's patch will be made of sectors, each on one leaf
/// (QuadricCellError.h: In a crease cell), as the prediction assumes: its
/// loop, drawn as the extraction draws it (CSG crease tiles through the
/// crease, CsgCreaseCrossing.h), is one loop whose fan around CreaseApex is
/// certified within the tolerance. (The extraction draws the same fan over
/// the final loop, which adds points on the same traces where its tiles nest
/// in the cell's own, and certifies that again.) `ownLoop`: the bound for
/// any patch failed, so the fan's error over every loop refining this one
/// must be predicted within it too (QuadricCellError.h: Predicted on the
/// cell's own loop, with the crease's crossings among the loop's points);
/// that prediction is then set in `predicted`.
bool CreaseFanWithinTolerance(const QuadricCellError& bound, const Vec3& apex, const CellBoundary& boundary,
  const CsgExpressionPtr& expression, const PrimitiveSet& prims, const RootGrid& grid, double tolerance, bool ownLoop,
  double& predicted)
{
  CellBoundary bent = boundary;
  MarkCsgCreaseTiles(bent, prims, grid, [&](int, std::size_t) { return &expression; });
  const BoundaryLoopSet loops = TraceBoundaryLoops(bent);
  if (loops.LoopSizes.size() != 1 || !loops.Consistent)
  {
    return false;
  }
  std::vector<Vec3> loop;
  if (!PlaceCsgLoopPoints(loops.Crossings, expression, prims, grid, loop))
  {
    return false;
  }
  if (ownLoop)
  {
    predicted = PredictedFanError(bound, loop, apex);
  }
  return FanError(bound, loop, apex) <= tolerance && (!ownLoop || predicted <= tolerance);
}

/// How far beyond the tolerance the bound for any patch of a quadric cell may
/// be for the fan over its own loop to be tried (after the topology tests,
/// which cost more than a split). Measured (with local rises) on spheres of
/// radius 3 to 40 tolerances and the benchmark's sphere, demo CSG and plate
/// at 1/64 to 1/256, trying up to 16 times: of the 3 583 cells whose fan was
/// within the tolerance, 43 had the bound for any patch beyond 4 times it;
/// of the 5 397 whose fan was not, 1 815.
constexpr double FanPredictionReach = 4.0;

/// The fan a quadric cell larger than the tolerance may be accepted with
/// (QuadricCellError.h: Predicted on the cell's own loop): over its one
/// loop, its points placed by PlaceSubEdgeCrossing as the extraction places
/// them (up to rounding where a neighbour placed a shared one first), around
/// the point of S along n from the loop's centroid (or the cell's centre),
/// 1/32 of the cell's width inside it. The apex where PredictedFanError, set
/// in `error`, is within the tolerance (the bound's margin); nothing
/// otherwise.
std::optional<Vec3> PredictQuadricFan(const QuadricCellError& bound, const BoundaryLoopSet& loops,
  const CsgExpression& expression, const PrimitiveSet& prims, const RootGrid& grid, double& error)
{
  if (loops.LoopSizes.size() != 1 || !loops.Consistent)
  {
    return std::nullopt;
  }
  std::vector<Vec3> loop;
  Vec3 centroid;
  for (const Crossing& c : loops.Crossings)
  {
    if (c.Kind != CrossingKind::SubEdge)
    {
      return std::nullopt;
    }
    loop.push_back(PlaceSubEdgeCrossing(c, grid, expression, prims));
    centroid += loop.back();
  }
  centroid = centroid * (1.0 / static_cast<double>(loop.size()));
  const Box3 inner = bound.Cell.Shrunk(1.0 / 32.0);
  std::optional<Vec3> apex = SurfacePointAlongDirection(bound, centroid, inner);
  if (!apex)
  {
    apex = SurfacePointAlongDirection(bound, bound.Cell.Center(), inner);
  }
  error = apex ? PredictedFanError(bound, loop, *apex) : HUGE_VAL;
  return error <= bound.Margin ? apex : std::nullopt;
}
} // namespace

McCompatibility TestMcCompatibility(const AdaptiveOctree& tree, std::uint32_t n, const PrimitiveSet& prims,
  double tolerance, int faceRefinementLevels, bool provenFailuresFirst, PolygonSet* surfaceScratch,
  bool refineChords, FaceDecisionCache* faceDecisions)
{
  McCompatibility v;
  v.Kind = McVerdict::Split;
  const RootGrid& grid = tree.Grid;
  const OctreeNode& node = tree.Nodes[n];
  const CsgExpressionPtr& expression = tree.Expressions[n];
  const Box3 box = grid.CellBox(node.Level, node.Ijk);
  unsigned mask = 0;
  for (int c = 0; c < 8; ++c)
  {
    mask |= tree.CornerInside(n, c) ? (1u << c) : 0u;
  }
  // Corners of one sign: free of the surface if an enclosure proves it,
  // else (in a cell no larger than the tolerance) a complex voxel unless the
  // faces' loops show surface.
  const bool uniform = mask == 0 || mask == 0xFF;
  if (uniform)
  {
    const RegionSign s =
      ProveConstantSign(expression, prims, box, ConstantProofDepth, ConstantProofBudget);
    if (s != RegionSign::Mixed)
    {
      v.Kind = McVerdict::Constant;
      v.Sign = s;
      return v;
    }
  }
  // Cells that must shrink anyway skip the costlier tests; a plane section
  // (PlanarCell.h) or a cell whose certified error is within the tolerance
  // (QuadricCellError.h; MeshCellError.h, decided on the cell's loop once the
  // tests passed) may stay larger.
  v.Oversized = grid.CellDiagonal(node.Level) > tolerance * (1.0 + 1e-9);
  const bool planar = v.Oversized && !uniform && IsPlanarCell(*expression, prims, box);
  std::optional<QuadricCellError> quadric;
  std::optional<Vec3> creaseApex;
  if (!uniform && !planar)
  {
    // (A crease cell only when larger than the tolerance: it needs its own
    // patch checked, below, where a smaller cell is bounded by its size.)
    quadric = BoundQuadricCell(expression, tree.NearExpression(n, tolerance), prims, box, tolerance, v.Oversized);
    v.PredictedError = quadric ? PredictedCellError(*quadric) : HUGE_VAL;
    // (A crease cell without a crease point well inside has no fan to
    // check: it splits before the costlier tests.)
    creaseApex = quadric && quadric->Crease && v.PredictedError <= FanPredictionReach * tolerance
      ? CreaseApex(*quadric, prims)
      : std::nullopt;
    v.ErrorBounded = v.PredictedError <= tolerance && (!quadric->Crease || creaseApex);
  }
  // (A crease cell whose bound for any patch fails: perhaps its fan over its
  // own loop, as for one quadric below.)
  const bool creaseFanOwnLoop = !v.ErrorBounded && creaseApex.has_value();
  const bool meshBounded = v.Oversized && !uniform && !planar && !v.ErrorBounded && LoneMeshLeaf(*expression);
  // (Bounded, but not for any patch: perhaps for the fan over its own loop,
  // once the tests traced it.)
  const bool quadricFan = v.Oversized && !uniform && !planar && !v.ErrorBounded && quadric && !quadric->Crease &&
    v.PredictedError <= FanPredictionReach * tolerance;
  // (Meshes meeting: perhaps the fan over its own loop too,
  // MeshBooleanCellError.h.)
  const bool booleanFan =
    v.Oversized && !uniform && !planar && !v.ErrorBounded && !meshBounded && IsCertifiableMeshBoolean(*expression);
  if (v.Oversized && !planar && !v.ErrorBounded && !meshBounded && !quadricFan && !creaseFanOwnLoop && !booleanFan)
  {
    v.Reason = uniform ? SplitReason::ComplexVoxel : SplitReason::HausdorffSize;
    return v;
  }
  // S_C, for the prediction; a spoke of every fan it could be made with that
  // strays beyond the tolerance fails it before the costlier tests
  // (MeshCellError.h: Spokes) - where it may pass with several loops, a
  // spoke to its sheet's apex. In a scene of one mesh, its creases in the
  // cell (CreaseFollowing.h), found when first asked.
  PolygonSet ownSurface;
  PolygonSet& meshSurface = surfaceScratch ? *surfaceScratch : ownSurface;
  meshSurface.clear();
  const bool oneMesh = meshBounded && IsOneMesh(*tree.SceneExpression);
  std::optional<std::vector<CreaseSegment>> creasesFound;
  const auto meshCreases = [&]() -> const std::vector<CreaseSegment>& {
    if (!creasesFound)
    {
      creasesFound = oneMesh ? CreasesInCell(*LoneMeshLeaf(*expression), prims, box) : std::vector<CreaseSegment>();
    }
    return *creasesFound;
  };
  TriangleList surfaceTriangles; // (each polygon's triangle: SheetSpokesStray, SlabPatchError)
  if (meshBounded)
  {
    SurfaceInCell(*LoneMeshLeaf(*expression), prims, box, meshSurface, &surfaceTriangles);
  }
  if (meshBounded && provenFailuresFirst &&
    SpokeStrays(*LoneMeshLeaf(*expression), prims, box, mask, meshSurface, tolerance) &&
    SheetSpokesStray(*LoneMeshLeaf(*expression), prims, box, mask, meshSurface, surfaceTriangles, tolerance))
  {
    v.Reason = SplitReason::HausdorffSize;
    v.SplitBySpoke = true;
    return v;
  }
  CellSignCache signs(tree.Signs, grid, *expression, prims);
  CellBoundary boundary;
  if (!TileFaces(tree, n, prims, faceRefinementLevels, signs, faceDecisions, boundary, v))
  {
    return v;
  }
  std::vector<Box3> loopRegions;
  const BoundaryLoopSet loops = TraceBoundaryLoops(boundary);
  v.Reason = VoxelCompatibilityTest(loops, expression, prims, grid, box, &loopRegions);
  if (v.Reason != SplitReason::None)
  {
    return v;
  }
  // Several loops: each is tested in its own region, bounded by the cell and
  // by planes the surface misses (LoopsSeparated). There the surface's only
  // boundary is that loop, so a verified witness (StarShapedCriterion.h)
  // makes it one disc - while two sheets facing each other across a near
  // contact have no common witness in the whole cell.
  const auto starShaped = [&]() {
    for (const Box3& region : loopRegions)
    {
      // (Pruned to the region: the other loops' leaves are absent from it.)
      const auto pruned = loopRegions.size() > 1 ? CsgExpression::Prune(expression, region, prims)
                                                 : CsgExpression::Pruned{ RegionSign::Mixed, expression };
      if (pruned.Sign == RegionSign::Mixed && !IsStarShapedWithRespectToVoxel(pruned.Expression, prims, region))
      {
        v.Reason = SplitReason::NotStarShapedVoxel;
        return false;
      }
    }
    return true;
  };
  // (Where proven failures come first, the error tests below run before it:
  // a large cell that splits mostly fails them - on the turbine at 1/64, 62
  // of the 72 cells of levels 3-5 that reached the star-shaped test and
  // split passed it and failed their error bound or their creases, and it
  // was a fifth of their tests' time. Either way a cell passes only if both
  // pass: the same cells split, but one failing both records its error's
  // reason (SplitReason, FailedTest), not NotStarShapedVoxel - except at a
  // depth or cell limit, where every test runs in the paper's order and the
  // topological failure is the one reported.)
  if (!provenFailuresFirst && !starShaped())
  {
    return v;
  }
  if (meshBounded)
  {
    // In a scene of one mesh every cell draws crease tiles through their
    // crease (CreaseCrossing.h: every non-exact neighbour is a cell of the
    // same mesh, and the decision is the same for a tile and its sub-tiles),
    // so the loops the prediction starts from may too: the final loops follow
    // the same halves of the trace there.
    // (Without a crease tile the loops are those traced above.)
    const bool creases = oneMesh &&
      MarkCreaseTiles(
        boundary, *LoneMeshLeaf(*expression), prims, grid, [](int, std::size_t) { return true; }, faceDecisions);
    v.PredictedError = PredictedMeshCellError(*expression, prims, grid, box, boundary,
      creases ? TraceBoundaryLoops(boundary) : loops, tolerance, v.MeshPrediction, &meshSurface, &surfaceTriangles,
      provenFailuresFirst, oneMesh ? &meshCreases() : nullptr, oneMesh);
    v.ErrorBounded = v.MeshSurface = v.PredictedError <= tolerance;
    // Failed with chords far from the trace: again over a loop whose wide
    // chords' tiles are split (MeshCellError.h: Chords refined) - not in a
    // cell that must draw creases.
    if (!v.ErrorBounded && refineChords && !(v.MeshPrediction.Delta <= ChordRefinementShare * tolerance) &&
      meshCreases().empty() &&
      PredictOverFinerChords(tree, n, prims, tolerance, faceRefinementLevels, oneMesh, provenFailuresFirst,
        meshSurface, surfaceTriangles, signs, boundary, v))
    {
      v.ErrorBounded = v.MeshSurface = v.ChordsRefined = true;
    }
    if (!v.ErrorBounded)
    {
      v.SplitByCreases = v.MeshPrediction.Creases == AdaptiveOctree::MeshCellPrediction::CreaseFans::NoneFollows;
      v.Reason = v.SplitByCreases ? SplitReason::CreaseNotFollowed : SplitReason::HausdorffSize;
      v.SplitByProbe = v.MeshPrediction.ProbeStrayed;
      return v;
    }
    // Its fan must draw the mesh's creases too (CreaseFollowing.h), where
    // crease tiles put them in the loops: in a scene of one mesh. Where the
    // fan around the apex S_C's planes give misses one, a fan around a point
    // of a crease may follow them all (MeshCellError.h: Crease apexes).
    if (oneMesh)
    {
      const CsgLeaf& leaf = *LoneMeshLeaf(*expression);
      const double reach = CreaseReach * tolerance;
      // (Known where the prediction looked at the creases first.)
      using CreaseFans = AdaptiveOctree::MeshCellPrediction::CreaseFans;
      const CreaseFans found = v.MeshPrediction.Creases;
      if (found == CreaseFans::OtherFanFollows ||
        (found == CreaseFans::NotAsked &&
          !CreasesFollowed(meshCreases(), ApexFans(v.MeshPrediction.Loops, v.MeshPrediction.Apexes), reach)))
      {
        if (!PredictCreaseApex(meshSurface, box, meshCreases(), reach, RoundingSlack(leaf, prims, box), tolerance,
              v.MeshPrediction))
        {
          v.ErrorBounded = v.MeshSurface = false;
          v.Reason = SplitReason::CreaseNotFollowed;
          return v;
        }
        v.PredictedError = v.MeshPrediction.Bound;
      }
    }
  }
  else if ((v.ErrorBounded && quadric->Crease) || creaseFanOwnLoop)
  {
    if (!CreaseFanWithinTolerance(*quadric, *creaseApex, boundary, expression, prims, grid, tolerance,
          creaseFanOwnLoop, v.PredictedError))
    {
      v.ErrorBounded = false;
      v.Reason = SplitReason::HausdorffSize;
      return v;
    }
    v.ErrorBounded = v.CreaseFan = true;
  }
  else if (quadricFan)
  {
    v.QuadricFanApex = PredictQuadricFan(*quadric, loops, *expression, prims, grid, v.PredictedError);
    if (!v.QuadricFanApex)
    {
      v.Reason = SplitReason::HausdorffSize;
      return v;
    }
    v.ErrorBounded = true;
  }
  else if (booleanFan)
  {
    v.BooleanFanApexes = PredictMeshBooleanFan(expression, prims, grid, box, boundary, tolerance, v.PredictedError);
    if (v.BooleanFanApexes.empty())
    {
      v.Reason = SplitReason::HausdorffSize;
      return v;
    }
    // (Its faces' CSG crease tiles decided with its own expression, as the
    // prediction drew them: CsgCreaseCrossing.h.)
    v.ErrorBounded = v.CreaseFan = true;
  }
  else if (!v.Oversized && !v.ErrorBounded && (LoneMeshLeaf(*expression) || IsCertifiableMeshBoolean(*expression)))
  {
    // Within the tolerance by its size, whatever its patch; the extraction
    // certifies the patch's distance to the mesh too (MeshCellError.h), or
    // to the meshes where they meet (MeshBooleanSurface.h), so that the
    // reported bound is what the cells' patches need.
    v.ErrorBounded = true;
    v.PredictedError = grid.CellDiagonal(node.Level);
  }
  if (provenFailuresFirst && !starShaped())
  {
    return v;
  }
  v.Kind = McVerdict::Pass;
  v.Reason = SplitReason::None;
  v.Planar = planar;
  v.NewSigns = signs.NewSigns();
  return v;
}

} // namespace tpc
