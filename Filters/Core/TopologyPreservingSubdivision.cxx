#include "TopologyPreservingSubdivision.h"

#include "ExactCell.h"
#include "FacingSurfaces.h"
#include "ForestPartition.h"
#include "LatticePlacement.h"
#include "McCompatibilityTest.h"

#include <algorithm>
#include <cmath>
#include <functional>

namespace tpc
{

int MaximumSupportedDepth(const int dims[3])
{
  const int n = std::max({ dims[0], dims[1], dims[2], 1 });
  int depth = 0;
  while ((static_cast<std::uint64_t>(n) << (depth + 1)) < LatticeLimit)
  {
    ++depth;
  }
  return depth;
}

namespace
{
double LargestWidth(const Box3& domain, double tolerance)
{
  double extent = 0.0;
  for (int a = 0; a < 3; ++a)
  {
    extent = std::max(extent, domain.Width(a));
  }
  return extent > 0.0 ? extent : std::max(tolerance, 1e-12);
}
} // namespace

int ToleranceLevel(const Box3& domain, double tolerance)
{
  if (!(tolerance > 0.0))
  {
    return 0;
  }
  const double extent = LargestWidth(domain, tolerance);
  return std::max(0, static_cast<int>(std::ceil(std::log2(extent * std::sqrt(3.0) / tolerance))));
}

RootGrid MakeRootGrid(const Box3& domain, double tolerance, int maximumDepth, int placement)
{
  RootGrid grid;
  const double extent = LargestWidth(domain, tolerance);
  const double sqrt3 = std::sqrt(3.0);
  const int levels = ToleranceLevel(domain, tolerance);
  double size = extent;
  if (tolerance > 0.0 && levels <= maximumDepth)
  {
    // Level `levels` then has a diagonal of exactly the tolerance.
    size = std::max(extent, std::ldexp(tolerance / sqrt3, levels));
  }
  // A lattice aligned with the input's own numbers (a sphere of radius 0.5 at
  // (0.1, 0.2, 0.3) has many rational points) puts lattice corners at almost
  // exactly the surface; each such near-hit is a genuinely complex cell that
  // only refinement to the scale of the near-miss resolves. A lattice with a
  // generic spacing and a generic offset makes such coincidences as rare as
  // chance makes them. Deterministic: the same input gives the same grid.
  const double generic = 0.9876543210987654;
  // Further placements step the offset by golden-ratio fractions of the cell
  // at the tolerance's level: deep lattice planes then move by generic
  // fractions of their spacing.
  Vec3 shift(0.0731059, 0.0418603, 0.0586947);
  const Vec3 step(0.6180339887, 0.3819660113, 0.2360679775);
  for (int a = 0; a < 3; ++a)
  {
    shift[a] = std::fmod(shift[a] + placement * step[a], 1.0);
  }
  const double finest = std::ldexp(size, -levels);
  if (size * generic >= extent + 2.0 * finest)
  {
    size *= generic;
  }
  grid.RootSize = size;
  const Vec3 center = domain.Center();
  for (int a = 0; a < 3; ++a)
  {
    grid.Dims[a] = std::max(1, static_cast<int>(std::ceil(domain.Width(a) / size - 1e-12)));
    grid.Origin[a] = center[a] - 0.5 * grid.Dims[a] * size;
    const double offset = shift[a] * std::ldexp(size, -levels);
    if (grid.Origin[a] - offset <= domain.lo[a] &&
      grid.Origin[a] - offset + grid.Dims[a] * size >= domain.hi[a])
    {
      grid.Origin[a] -= offset;
    }
  }
  // The lattice is always as fine as supported: face refinement samples
  // below the deepest cells.
  grid.MaxDepth = MaximumSupportedDepth(grid.Dims);
  return grid;
}

namespace
{
CellState StateOf(RegionSign s)
{
  return s == RegionSign::Inside ? CellState::Inside : CellState::Outside;
}
} // namespace

SubdivisionResult RunTopologyPreservingSubdivision(const ImplicitScene& scene,
  const RootGrid& grid, const SubdivisionParameters& params, const ParallelFor& parallelFor,
  const ProgressCallback& progress)
{
  SubdivisionResult result;
  AdaptiveOctree& tree = result.Octree;
  tree.Grid = grid;
  tree.Roles = params.TreeRoles;
  const auto& prims = scene.Primitives;

  // Roots.
  const int treeCount = grid.TreeCount();
  tree.Nodes.resize(static_cast<std::size_t>(treeCount));
  tree.Expressions.resize(static_cast<std::size_t>(treeCount));
  std::vector<std::uint32_t> active;
  for (int t = 0; t < treeCount; ++t)
  {
    OctreeNode& n = tree.Nodes[static_cast<std::size_t>(t)];
    int ijk[3];
    grid.TreeCoordinates(t, ijk);
    for (int a = 0; a < 3; ++a)
    {
      n.Ijk[a] = static_cast<std::uint32_t>(ijk[a]);
    }
    n.Level = 0;
    n.State = CellState::Outside;
  }
  if (scene.Expression)
  {
    // The expression pruned to each computed root, by halving blocks of
    // trees: a split run has thousands of roots, and pruning each from the
    // whole scene would test every mesh triangle against every root.
    struct Block
    {
      int Lo[3], Hi[3]; // tree index ranges [Lo, Hi)
    };
    // The trees of a block that this run computes.
    auto computedTrees = [&](const Block& b) {
      std::vector<std::size_t> trees;
      for (int k = b.Lo[2]; k < b.Hi[2]; ++k)
      {
        for (int j = b.Lo[1]; j < b.Hi[1]; ++j)
        {
          for (int i = b.Lo[0]; i < b.Hi[0]; ++i)
          {
            const auto t = static_cast<std::size_t>(grid.TreeIndex(i, j, k));
            if (tree.RoleOf(tree.Nodes[t]) != TreeRole::Skipped)
            {
              trees.push_back(t);
            }
          }
        }
      }
      return trees;
    };
    std::function<void(const Block&, const CsgExpressionPtr&)> prune = [&](const Block& b,
                                                                          const CsgExpressionPtr& e) {
      const std::vector<std::size_t> trees = computedTrees(b);
      if (trees.empty())
      {
        return;
      }
      Box3 box;
      for (int a = 0; a < 3; ++a)
      {
        box.lo[a] = grid.Coordinate(a, static_cast<std::uint32_t>(b.Lo[a]) << grid.MaxDepth);
        box.hi[a] = grid.Coordinate(a, static_cast<std::uint32_t>(b.Hi[a]) << grid.MaxDepth);
      }
      const auto pruned = CsgExpression::Prune(e, box, prims);
      const bool single = b.Hi[0] - b.Lo[0] == 1 && b.Hi[1] - b.Lo[1] == 1 && b.Hi[2] - b.Lo[2] == 1;
      if (pruned.Sign != RegionSign::Mixed || single)
      {
        for (const std::size_t t : trees)
        {
          tree.Nodes[t].State = pruned.Sign == RegionSign::Mixed ? CellState::Surface : StateOf(pruned.Sign);
          tree.Expressions[t] = pruned.Expression;
        }
        return;
      }
      int axis = 0; // halve the longest side
      for (int a = 1; a < 3; ++a)
      {
        axis = b.Hi[a] - b.Lo[a] > b.Hi[axis] - b.Lo[axis] ? a : axis;
      }
      Block low = b, high = b;
      low.Hi[axis] = high.Lo[axis] = (b.Lo[axis] + b.Hi[axis]) / 2;
      prune(low, pruned.Expression);
      prune(high, pruned.Expression);
    };
    prune({ { 0, 0, 0 }, { grid.Dims[0], grid.Dims[1], grid.Dims[2] } }, scene.Expression);
    for (int t = 0; t < treeCount; ++t)
    {
      if (tree.Nodes[static_cast<std::size_t>(t)].State == CellState::Surface)
      {
        active.push_back(static_cast<std::uint32_t>(t));
      }
    }
  }

  const double finestWidth = std::ldexp(grid.RootSize, -std::min(params.MaximumDepth, grid.MaxDepth));
  int exactLevel = ExactCellLevelsBelowTolerance;
  while (grid.CellDiagonal(exactLevel - ExactCellLevelsBelowTolerance) > params.HausdorffTolerance * (1.0 + 1e-9))
  {
    ++exactLevel;
  }
  const int expectedLevels = std::max(1,
    static_cast<int>(std::ceil(std::log2(grid.RootSize * std::sqrt(3.0) / params.HausdorffTolerance))) + 3);

  // Long loops run in chunks reporting progress, so that an abort request
  // stops them within a chunk (Parallel.h).
  constexpr std::size_t Chunk = 4096;
  for (int level = 0; !active.empty(); ++level)
  {
    // Within a level: corner signs [0, 0.2] (gather, sort, evaluate), tests [0.2, 0.7], verdicts
    // [0.7, 0.8], children [0.8, 1]; the sequential loops ask every 2^16 cells.
    auto within = [&](double lo, double hi) -> ProgressCallback {
      if (!progress)
      {
        return nullptr;
      }
      return [&progress, level, lo, hi, expectedLevels](double f) {
        return progress(std::min(0.95, (level + lo + (hi - lo) * f) / expectedLevels));
      };
    };
    if (progress && progress(std::min(0.95, static_cast<double>(level) / expectedLevels)))
    {
      result.Aborted = true;
      return result;
    }

    // 1. Exact signs at corners not seen before, each evaluated once (with
    // the smallest cell index among the cells sharing it). Blocks of cells
    // gather their unseen corners in parallel (table lookups only) into
    // buckets by key; each bucket is sorted and deduplicated on its own.
    constexpr std::size_t Blocks = 64, Buckets = 64;
    std::vector<std::vector<std::pair<PointKey, std::uint32_t>>> parts(Blocks * Buckets);
    const bool gathered = ChunkedFor(Blocks, 8, parallelFor, [&](std::size_t begin, std::size_t end) {
      for (std::size_t b = begin; b < end; ++b)
      {
        for (std::size_t i = active.size() * b / Blocks; i < active.size() * (b + 1) / Blocks; ++i)
        {
          const std::uint32_t n = active[i];
          for (int c = 0; c < 8; ++c)
          {
            std::uint32_t p[3];
            CornerLattice(grid, tree.Nodes[n], c, p);
            const PointKey key = MakePointKey(p[0], p[1], p[2]);
            if (tree.Signs.Find(key) < 0)
            {
              parts[b * Buckets + ((key * 0x9E3779B97F4A7C15ULL) >> 58)].emplace_back(key, n);
            }
          }
        }
      }
    }, within(0.0, 0.05));
    std::vector<std::vector<std::pair<PointKey, std::uint32_t>>> buckets(Buckets);
    if (!gathered || !ChunkedFor(Buckets, 8, parallelFor, [&](std::size_t begin, std::size_t end) {
      for (std::size_t k = begin; k < end; ++k)
      {
        auto& bucket = buckets[k];
        for (std::size_t b = 0; b < Blocks; ++b)
        {
          bucket.insert(bucket.end(), parts[b * Buckets + k].begin(), parts[b * Buckets + k].end());
        }
        std::sort(bucket.begin(), bucket.end());
        bucket.erase(std::unique(bucket.begin(), bucket.end(),
                       [](const auto& x, const auto& y) { return x.first == y.first; }),
          bucket.end());
      }
    }, within(0.05, 0.1)))
    {
      result.Aborted = true;
      return result;
    }
    std::vector<std::pair<PointKey, std::uint32_t>> pending;
    for (const auto& bucket : buckets)
    {
      pending.insert(pending.end(), bucket.begin(), bucket.end());
    }
    auto stopAt = [&](double lo, std::size_t i) {
      if ((i & 0xFFFF) != 0xFFFF || !progress || !within(lo, lo)(0.0))
      {
        return false;
      }
      result.Aborted = true;
      return true;
    };
    if (stopAt(0.1, 0xFFFF))
    {
      return result;
    }
    std::vector<std::uint8_t> inside(pending.size());
    if (!ChunkedFor(pending.size(), 8 * Chunk, parallelFor, [&](std::size_t begin, std::size_t end) {
      for (std::size_t i = begin; i < end; ++i)
      {
        inside[i] = tree.Expressions[pending[i].second]->IsInside(grid.Point(pending[i].first), prims);
      }
    }, within(0.1, 0.2)))
    {
      result.Aborted = true;
      return result;
    }
    for (std::size_t i = 0; i < pending.size(); ++i)
    {
      tree.Signs.Insert(pending[i].first, inside[i] != 0);
      if (stopAt(0.2, i))
      {
        return result;
      }
    }

    // 2. The paper's tests on every cell of this level. A failing cell as
    // small as the tolerance asks, where two surfaces face each other closer
    // than the finest cell allowed, is stopped (FacingSurfaces.h).
    const bool toleranceSize = grid.CellDiagonal(level) <= params.HausdorffTolerance;
    std::vector<McCompatibility> verdicts(active.size());
    std::vector<std::uint8_t> facing(active.size(), 0);
    // After each chunk, the new signs and face tilings of the cells that
    // passed go into the tables (in cell order, as the first tiling of a face
    // stays) and every verdict drops them: a level's cells never hold them
    // all at once (face refinement may sample thousands of points per cell).
    const ProgressCallback testsProgress = within(0.2, 0.7);
    const bool tested = ForEachChunk(active.size(), Chunk, parallelFor, [&](std::size_t begin, std::size_t end) {
      for (std::size_t i = begin; i < end; ++i)
      {
        // A cell that keeps its mesh if it fails need not refine its faces
        // far to find out (ExactCell.h).
        const bool keepsOnFailure = params.ExactCells && toleranceSize &&
          KeepsTheMesh(*tree.Expressions[active[i]], true, false);
        verdicts[i] = TestMcCompatibility(tree, active[i], prims, params.HausdorffTolerance,
          keepsOnFailure ? ExactCellFaceRefinementLevels : FaceRefinementLevels);
        if (toleranceSize && verdicts[i].Kind == McVerdict::Split)
        {
          facing[i] = HasFacingSurfaces(*tree.Expressions[active[i]], prims,
            grid.CellBox(level, tree.Nodes[active[i]].Ijk), finestWidth);
        }
      }
    }, [&](std::size_t first, std::size_t last) {
      for (std::size_t i = first; i < last; ++i)
      {
        McCompatibility& v = verdicts[i];
        if (v.Kind == McVerdict::Pass)
        {
          for (const auto& sign : v.NewSigns)
          {
            tree.Signs.Insert(sign.first, sign.second);
          }
          for (auto& r : v.Refinements)
          {
            tree.FaceRefinements.emplace(r.first, std::move(r.second)); // the first one stays
          }
          result.RefinedFaces += tree.RoleOf(tree.Nodes[active[i]]) == TreeRole::Own ? v.Refinements.size() : 0;
        }
        std::vector<std::pair<PointKey, bool>>().swap(v.NewSigns);
        std::vector<std::pair<FaceKey, std::vector<FaceTile>>>().swap(v.Refinements);
      }
      return testsProgress && testsProgress(static_cast<double>(last) / static_cast<double>(active.size()));
    });
    if (!tested)
    {
      result.Aborted = true;
      return result;
    }

    // 3. Apply verdicts; limits turn splits into unresolved leaves.
    std::size_t splits = 0;
    for (const McCompatibility& v : verdicts)
    {
      splits += v.Kind == McVerdict::Split ? 1 : 0;
    }
    const bool atDepthLimit = level >= std::min(params.MaximumDepth, grid.MaxDepth);
    const bool atCellLimit =
      !atDepthLimit && tree.Nodes.size() + 8 * splits > params.MaximumNumberOfCells;

    std::vector<std::uint32_t> parents;
    for (std::size_t i = 0; i < active.size(); ++i)
    {
      if (stopAt(0.7, i))
      {
        return result;
      }
      const std::uint32_t n = active[i];
      OctreeNode& node = tree.Nodes[n];
      const McCompatibility& v = verdicts[i];
      // (A piece of a split run counts its own trees' cells only.)
      const std::size_t mine = tree.RoleOf(node) == TreeRole::Own ? 1 : 0;
      if (v.Kind == McVerdict::Pass)
      {
        node.State = CellState::Surface;
        node.PlaneSection = v.Planar;
        result.SurfaceCells += mine;
        result.PlanarSurfaceCells += v.Planar ? mine : 0;
        result.HausdorffBound = std::max(result.HausdorffBound,
          mine * grid.CellDiagonal(v.Planar ? grid.MaxDepth : level));
      }
      else if (v.Kind == McVerdict::Constant)
      {
        node.State = StateOf(v.Sign);
        tree.Expressions[n].reset();
      }
      else if (params.ExactCells && KeepsTheMesh(*tree.Expressions[n], level >= exactLevel - ExactCellLevelsBelowTolerance,
                                      level >= exactLevel || facing[i] || atDepthLimit || atCellLimit))
      {
        // One mesh's surface that the tests cannot resolve: its patch is the
        // mesh itself (ExactCell.h).
        node.State = CellState::Exact;
        node.FailedTest = v.Reason;
        result.ExactCells += mine;
        result.HausdorffBound = std::max(result.HausdorffBound, mine * grid.CellDiagonal(grid.MaxDepth));
      }
      else if (atDepthLimit || atCellLimit || facing[i])
      {
        node.State = CellState::Unresolved;
        node.Reason = facing[i] ? SplitReason::SurfacesTooClose : SplitReason::LimitReached;
        result.FacingSurfaceCells += mine * facing[i];
        result.DepthLimitReached |= mine && atDepthLimit && !facing[i];
        result.CellLimitReached |= mine && atCellLimit && !facing[i];
        node.FailedTest = v.Reason;
        result.UnresolvedCells += mine;
        result.HausdorffBound = std::max(result.HausdorffBound, mine * grid.CellDiagonal(level));
        result.UnresolvedByReason[static_cast<int>(v.Reason)] += mine;
      }
      else
      {
        node.State = CellState::Refined;
        node.Reason = v.Reason;
        result.SplitsByReason[static_cast<int>(v.Reason)] += mine;
        parents.push_back(n);
      }
    }

    // 4. Children of split cells, each with the parent's expression pruned to it.
    const std::size_t first = tree.Nodes.size();
    tree.Nodes.resize(first + 8 * parents.size());
    tree.Expressions.resize(tree.Nodes.size());
    for (std::size_t i = 0; i < parents.size(); ++i)
    {
      tree.Nodes[parents[i]].FirstChild = static_cast<std::int32_t>(first + 8 * i);
    }
    const bool childrenDone = ChunkedFor(parents.size(), Chunk / 8, parallelFor, [&](std::size_t begin, std::size_t end) {
      for (std::size_t i = begin; i < end; ++i)
      {
        const OctreeNode& parent = tree.Nodes[parents[i]];
        const CsgExpressionPtr& parentExpression = tree.Expressions[parents[i]];
        for (int c = 0; c < 8; ++c)
        {
          const std::size_t ci = first + 8 * i + static_cast<std::size_t>(c);
          OctreeNode& child = tree.Nodes[ci];
          child.Level = static_cast<std::uint8_t>(level + 1);
          for (int a = 0; a < 3; ++a)
          {
            child.Ijk[a] = 2 * parent.Ijk[a] + ((c >> a) & 1);
          }
          const auto pruned =
            CsgExpression::Prune(parentExpression, grid.CellBox(level + 1, child.Ijk), prims);
          if (pruned.Sign == RegionSign::Mixed)
          {
            child.State = CellState::Surface;
            tree.Expressions[ci] = pruned.Expression;
          }
          else
          {
            child.State = StateOf(pruned.Sign);
          }
        }
      }
    }, within(0.8, 1.0));
    if (!childrenDone)
    {
      result.Aborted = true;
      return result;
    }
    active.clear();
    for (std::size_t i = 0; i < parents.size(); ++i)
    {
      tree.Expressions[parents[i]].reset();
      for (int c = 0; c < 8; ++c)
      {
        const std::size_t ci = first + 8 * i + static_cast<std::size_t>(c);
        if (tree.Nodes[ci].State == CellState::Surface)
        {
          active.push_back(static_cast<std::uint32_t>(ci));
        }
      }
    }
  }
  tree.IndexRefinementPoints();
  if (progress)
  {
    progress(1.0);
  }
  return result;
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
    ProgressCallback placementProgress = nullptr;
    if (progress)
    {
      placementProgress = [&progress, start, span](double f) { return progress(start + span * f); };
    }
    start += span;
    RootGrid grid = base;
    for (int a = 0; a < 3; ++a)
    {
      // Only where the shifted roots still cover the domain.
      if (grid.Origin[a] - shift[a] <= domain.lo[a] &&
        grid.Origin[a] - shift[a] + grid.Dims[a] * grid.RootSize >= domain.hi[a])
      {
        grid.Origin[a] -= shift[a];
      }
    }
    SubdivisionParameters params = parameters;
    if (split)
    {
      // Sixteen trees per piece along the longest axis, so that the ghost
      // ring (a tree on either side of a slab) costs a fraction of the
      // piece's own work, while the trees stay at least four times as wide
      // as the tolerance's cells; the same finest cell as one piece.
      const int coarsest = std::max(1, ToleranceLevel(domain, parameters.HausdorffTolerance) - 2);
      int levels = 0;
      while ((std::max({ grid.Dims[0], grid.Dims[1], grid.Dims[2] }) << levels) < 2 * piece.Pieces ||
        ((std::max({ grid.Dims[0], grid.Dims[1], grid.Dims[2] }) << levels) < 16 * piece.Pieces &&
          levels < coarsest))
      {
        if (levels >= grid.MaxDepth)
        {
          break;
        }
        ++levels;
      }
      grid = SplitRootCells(grid, levels, domain);
      params.MaximumDepth = std::max(0, parameters.MaximumDepth - levels);
      params.MaximumNumberOfCells = std::max<std::size_t>(8, parameters.MaximumNumberOfCells / piece.Pieces);
      params.TreeRoles = TreeRoles(grid, PartitionTrees(grid, piece.Pieces), piece.Piece);
    }
    SubdivisionResult run =
      RunTopologyPreservingSubdivision(scene, grid, params, parallelFor, placementProgress);
    ++best.PlacementsTried;
    // Decisions every piece takes alike.
    const std::size_t unresolved = sum(run.UnresolvedCells);
    const std::size_t facing = sum(run.FacingSurfaceCells);
    const bool cellLimit = sum(run.CellLimitReached ? 1 : 0) > 0;
    const bool aborted = sum(run.Aborted || abortAsked ? 1 : 0) > 0;
    run.Aborted = aborted;
    if (best.PlacementsTried == 1 || aborted || unresolved < best.UnresolvedCellsOfAllPieces)
    {
      best.Grid = grid;
      best.UnresolvedCellsOfAllPieces = unresolved;
      best.FinestCell = std::ldexp(grid.RootSize, -std::min(params.MaximumDepth, grid.MaxDepth));
      std::swap(best.Result, run);
    }
    // The run left over holds millions of expressions: freeing them takes
    // about a second, so in chunks, each followed by an abort check.
    auto& expressions = run.Octree.Expressions;
    for (std::size_t first = 0; first < expressions.size(); first += 1 << 16)
    {
      const std::size_t last = std::min(expressions.size(), first + (1 << 16));
      std::for_each(expressions.begin() + static_cast<std::ptrdiff_t>(first),
        expressions.begin() + static_cast<std::ptrdiff_t>(last), [](CsgExpressionPtr& e) { e.reset(); });
      if (progress && progress(start) && !best.Result.Aborted)
      {
        best.Result.Aborted = true;
        return best;
      }
    }
    // (Facing surfaces do not move away on another lattice.)
    if (aborted || best.UnresolvedCellsOfAllPieces == 0 ||
      (best.UnresolvedCellsOfAllPieces == unresolved && unresolved == facing) || cellLimit)
    {
      break;
    }
  }
  return best;
}

} // namespace tpc
