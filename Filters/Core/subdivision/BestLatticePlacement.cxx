#include "BestLatticePlacement.h"

#include "ForestPartition.h"
#include "LatticePlacement.h"

#include <algorithm>
#include <cmath>

namespace tpc
{
namespace
{
/// `base` shifted by `shift`, on each axis only where the shifted roots
/// still cover the domain.
RootGrid Shifted(const RootGrid& base, const Vec3& shift, const Box3& domain)
{
  RootGrid grid = base;
  for (int a = 0; a < 3; ++a)
  {
    if (grid.Origin[a] - shift[a] <= domain.lo[a] &&
      grid.Origin[a] - shift[a] + grid.Dims[a] * grid.RootSize >= domain.hi[a])
    {
      grid.Origin[a] -= shift[a];
    }
  }
  return grid;
}

/// A piece of a split run: the root cells split so that the longest axis has
/// sixteen trees per piece, so that the ghost ring (a tree on either side of
/// a slab) costs a fraction of the piece's own work, while the trees stay at
/// least four times as wide as the tolerance's cells; the same finest cell
/// as one piece. Sets the piece's parameters (depth below the new roots,
/// its share of the cells, the roles of the trees).
RootGrid SplitForPiece(const RootGrid& grid, const Box3& domain, const SubdivisionParameters& parameters,
  const PieceOfRun& piece, SubdivisionParameters& pieceParameters)
{
  const int coarsest = std::max(1, ToleranceLevel(domain, parameters.HausdorffTolerance) - 2);
  const int longest = std::max({ grid.Dims[0], grid.Dims[1], grid.Dims[2] });
  int levels = 0;
  while (((longest << levels) < 2 * piece.Pieces || ((longest << levels) < 16 * piece.Pieces && levels < coarsest)) &&
    levels < grid.MaxDepth)
  {
    ++levels;
  }
  const RootGrid split = SplitRootCells(grid, levels, domain);
  pieceParameters.MaximumDepth = std::max(0, parameters.MaximumDepth - levels);
  pieceParameters.MaximumNumberOfCells = std::max<std::size_t>(8, parameters.MaximumNumberOfCells / piece.Pieces);
  pieceParameters.TreeRoles = TreeRoles(split, PartitionTrees(split, piece.Pieces), piece.Piece);
  return split;
}

/// Frees `expressions` in chunks, each followed by a progress report of
/// `at`; false when it asked to stop.
bool ReleaseInChunks(std::vector<CsgExpressionPtr>& expressions, const ProgressCallback& progress, double at)
{
  for (std::size_t first = 0; first < expressions.size(); first += 1 << 16)
  {
    const std::size_t last = std::min(expressions.size(), first + (1 << 16));
    std::for_each(expressions.begin() + static_cast<std::ptrdiff_t>(first),
      expressions.begin() + static_cast<std::ptrdiff_t>(last), [](CsgExpressionPtr& e) { e.reset(); });
    if (progress && progress(at))
    {
      return false;
    }
  }
  return true;
}
} // namespace

bool ReleaseExpressions(AdaptiveOctree& octree, const ProgressCallback& progress, double at)
{
  return ReleaseInChunks(octree.Expressions, progress, at) && ReleaseInChunks(octree.NearExpressions, progress, at);
}

PlacedSubdivision RunOnBestLatticePlacement(const ImplicitScene& scene, const Box3& domain,
  const SubdivisionParameters& parameters, int maximumPlacements, const ParallelFor& parallelFor,
  const ProgressCallback& reportAndAsk, const PieceOfRun& piece)
{
  // A piece of a split run reports progress but stops only where every
  // piece agrees (after a placement): the pieces' calls to Sum must match.
  const bool split = piece.Pieces > 1;
  bool abortAsked = false;
  ProgressCallback progress = reportAndAsk;
  if (split && reportAndAsk)
  {
    progress = [&reportAndAsk, &abortAsked](double f) {
      abortAsked = reportAndAsk(f) || abortAsked;
      return false;
    };
  }
  auto sum = [&piece, split](std::size_t x) { return split ? piece.SumOverPieces(x) : x; };
  PlacedSubdivision best;
  if (progress && progress(0.0))
  {
    best.Result.Aborted = true;
    return best;
  }
  const RootGrid base = MakeRootGrid(domain, parameters.HausdorffTolerance, parameters.MaximumDepth);
  const std::vector<Vec3> shifts = RankLatticeShifts(scene.Primitives, base, parameters.HausdorffTolerance,
    parameters.MaximumDepth, std::max(1, maximumPlacements), parallelFor,
    progress ? ProgressCallback([&progress](double) { return progress(0.0); }) : nullptr);
  if (shifts.empty())
  {
    best.Result.Aborted = true;
    return best;
  }
  // Progress stays monotonic: the first placement (usually the only one)
  // reports over most of [0, 1], each retry over a share of what is left.
  double start = 0.0;
  for (const Vec3& shift : shifts)
  {
    const bool last = best.PlacementsTried + 1 == static_cast<int>(shifts.size());
    const double span = last ? 1.0 - start : (1.0 - start) * (best.PlacementsTried == 0 ? 0.8 : 0.5);
    const ProgressCallback placementProgress = ProgressRange(progress, start, start + span);
    start += span;
    RootGrid grid = Shifted(base, shift, domain);
    SubdivisionParameters params = parameters;
    if (split)
    {
      grid = SplitForPiece(grid, domain, parameters, piece, params);
    }
    SubdivisionResult run = RunTopologyPreservingSubdivision(scene, grid, params, parallelFor, placementProgress);
    ++best.PlacementsTried;
    // Decisions every piece takes alike.
    const std::size_t unresolved = sum(run.UnresolvedCells);
    const std::size_t touching = sum(run.TouchingSurfaceCells);
    const std::size_t facing = sum(run.FacingSurfaceCells);
    const bool cellLimit = sum(run.CellLimitReached ? 1 : 0) > 0;
    const bool aborted = sum(run.Aborted || abortAsked ? 1 : 0) > 0;
    run.Aborted = aborted;
    if (best.PlacementsTried == 1 || aborted || unresolved < best.UnresolvedCellsOfAllPieces)
    {
      best.Grid = grid;
      best.UnresolvedCellsOfAllPieces = unresolved;
      best.FinestCell = std::ldexp(grid.RootSize, -std::min(params.MaximumDepth, grid.MaxDepth));
      best.Parameters = params;
      std::swap(best.Result, run);
    }
    if (!ReleaseExpressions(run.Octree, progress, start) && !best.Result.Aborted)
    {
      best.Result.Aborted = true;
      return best;
    }
    // Surfaces lying in one plane do not move apart on another lattice, nor
    // do surfaces closer than the finest cell when that cell is at most two
    // lattice spacings wide (the default MaximumDepth: ~1e-12 of the domain,
    // they touch). With MaximumDepth lowered, surfaces merely close - beside
    // a thin wedge's edge, where a few cells may stay unresolved at one
    // placement - often resolve on another.
    const bool atLatticeEnd = params.MaximumDepth + 1 >= grid.MaxDepth;
    const bool inContact = unresolved == touching || (atLatticeEnd && unresolved == facing);
    if (aborted || best.UnresolvedCellsOfAllPieces == 0 ||
      (best.UnresolvedCellsOfAllPieces == unresolved && inContact) || cellLimit)
    {
      break;
    }
  }
  return best;
}

} // namespace tpc
