#include "TopologyPreservingSubdivision.h"

#include "DistinctRecords.h"
#include "ExactCellCriterion.h"
#include "FaceDecisionCache.h"
#include "QuadricCellError.h"
#include "ScratchPool.h"
#include "SplitDecision.h"

#include <algorithm>
#include <cmath>
#include <functional>

namespace tpc
{
namespace
{
/// Long loops run in chunks reporting progress, so that an abort request
/// stops them within a chunk (Parallel.h). (256 cells: a cell's tests can
/// take milliseconds - 4096 kept an abort waiting half a minute on a scene of
/// two quadrics meeting at a grazing angle.)
constexpr std::size_t Chunk = 256;

/// The time a chunk of the cells' tests aims at (ForEachTimedChunk): its
/// barrier and its serial part are a small share of it, and an abort waits
/// for about that long (at most for 8 chunks of Chunk cells, where cells turn
/// costly at once).
constexpr double ChunkSeconds = 0.05;

CellState StateOf(RegionSign s)
{
  return s == RegionSign::Inside ? CellState::Inside : CellState::Outside;
}

/// The first level whose cells' diagonal is at most `size` (with a relative
/// slack of 1e-9: a diagonal an ulp above a tolerance it was sized to meets
/// it).
int FirstLevelWithin(const RootGrid& grid, double size)
{
  int level = 0;
  while (grid.CellDiagonal(level) > size * (1.0 + 1e-9))
  {
    ++level;
  }
  return level;
}

/// One run of the subdivision: the octree being built and the cells of the
/// current level that still meet the surface.
class LevelByLevel
{
public:
  LevelByLevel(const ImplicitScene& scene, const RootGrid& grid, const SubdivisionParameters& parameters,
    const ParallelFor& parallelFor, const ProgressCallback& progress)
    : Scene(scene)
    , Grid(grid)
    , Parameters(parameters)
    , For(parallelFor)
    , Progress(progress)
  {
    this->Result.Octree.Grid = grid;
    this->Result.Octree.HausdorffTolerance = parameters.HausdorffTolerance;
    this->Result.Octree.SceneExpression = scene.Expression;
    this->Result.Octree.Roles = parameters.TreeRoles;
    this->Limits.FinestWidth = std::ldexp(grid.RootSize, -std::min(parameters.MaximumDepth, grid.MaxDepth));
    this->Limits.ExactToleranceLevel = FirstLevelWithin(grid, parameters.HausdorffTolerance);
    this->Limits.ExactLevel = FirstLevelWithin(grid,
                                ExactCellReferenceSize(parameters.HausdorffTolerance, parameters.SurfaceDiagonal)) +
      ExactCellLevelsBelowTolerance;
    this->ExpectedLevels = std::max(1,
      static_cast<int>(std::ceil(std::log2(grid.RootSize * std::sqrt(3.0) / parameters.HausdorffTolerance))) + 3);
  }

  SubdivisionResult Run()
  {
    this->MakeRoots();
    for (int level = 0; !this->Active.empty(); ++level)
    {
      this->Limits.Level = level;
      this->Limits.ToleranceSize = this->Grid.CellDiagonal(level) <= this->Parameters.HausdorffTolerance;
      std::vector<CellTests> tests;
      std::vector<std::uint32_t> parents;
      if ((this->Progress && this->Progress(std::min(0.95, static_cast<double>(level) / this->ExpectedLevels))) ||
        !this->EvaluateUnseenCorners() || !this->TestCells(tests) || !this->DecideCells(tests, parents) ||
        !this->MakeChildren(parents))
      {
        this->Result.Aborted = true;
        return std::move(this->Result);
      }
    }
    this->Result.Octree.IndexRefinementPoints();
    if (this->Progress)
    {
      this->Progress(1.0);
    }
    return std::move(this->Result);
  }

private:
  /// Progress over [lo, hi] of the current level's share. Within a level:
  /// corner signs [0, 0.2], tests [0.2, 0.7], fates [0.7, 0.8], children
  /// [0.8, 1].
  ProgressCallback Within(double lo, double hi) const
  {
    if (!this->Progress)
    {
      return nullptr;
    }
    return [this, level = this->Limits.Level, lo, hi](double f) {
      return this->Progress(std::min(0.95, (level + lo + (hi - lo) * f) / this->ExpectedLevels));
    };
  }
  /// In sequential loops: asks every 2^16 items; true to stop.
  bool StopAt(double lo, std::size_t i) const
  {
    return (i & 0xFFFF) == 0xFFFF && this->Progress && this->Within(lo, lo)(0.0);
  }

  void MakeRoots();
  void PruneRoots(const int lo[3], const int hi[3], const CsgExpressionPtr& expression);
  CsgExpressionPtr NearExpressionOf(const CsgExpressionPtr& enclosing, int level, const LatticeIndex ijk[3]) const;
  bool EvaluateUnseenCorners();
  bool TestCells(std::vector<CellTests>& tests);
  bool DecideCells(std::vector<CellTests>& tests, std::vector<std::uint32_t>& parents);
  bool MakeChildren(const std::vector<std::uint32_t>& parents);

  const ImplicitScene& Scene;
  const RootGrid& Grid;
  const SubdivisionParameters& Parameters;
  const ParallelFor& For;
  const ProgressCallback& Progress;
  SubdivisionResult Result;
  LevelLimits Limits;
  int ExpectedLevels = 1;
  /// The cells of the current level that meet the surface, in node order.
  std::vector<std::uint32_t> Active;
  /// Where the tests build S_C, reused from cell to cell and level to level.
  ScratchPool<PolygonSet> SurfaceScratch;
  /// The crease tiles and face tilings decided by this level's cells
  /// (FaceDecisionCache.h), cleared after it.
  FaceDecisionCache FaceDecisions;
};

/// The roots: one per tree, each with the scene's expression pruned to it;
/// those that meet the surface start the first level.
void LevelByLevel::MakeRoots()
{
  AdaptiveOctree& tree = this->Result.Octree;
  const int treeCount = this->Grid.TreeCount();
  tree.Nodes.resize(static_cast<std::size_t>(treeCount));
  tree.Expressions.resize(static_cast<std::size_t>(treeCount));
  for (int t = 0; t < treeCount; ++t)
  {
    OctreeNode& n = tree.Nodes[static_cast<std::size_t>(t)];
    int ijk[3];
    this->Grid.TreeCoordinates(t, ijk);
    for (int a = 0; a < 3; ++a)
    {
      n.Ijk[a] = static_cast<LatticeIndex>(ijk[a]);
    }
    n.State = CellState::Outside;
  }
  if (!this->Scene.Expression)
  {
    return;
  }
  const int lo[3] = { 0, 0, 0 };
  this->PruneRoots(lo, this->Grid.Dims, this->Scene.Expression);
  for (int t = 0; t < treeCount; ++t)
  {
    if (tree.Nodes[static_cast<std::size_t>(t)].State == CellState::Surface)
    {
      this->Active.push_back(static_cast<std::uint32_t>(t));
    }
  }
  tree.NearExpressions.resize(static_cast<std::size_t>(treeCount));
  for (const std::uint32_t t : this->Active)
  {
    if (!tree.Expressions[t]->HasMeshLeaves())
    {
      tree.NearExpressions[t] = this->NearExpressionOf(this->Scene.Expression, 0, tree.Nodes[t].Ijk);
    }
  }
}

/// The scene's expression pruned to the cell (level, ijk) grown by the
/// tolerance, from `enclosing`, the scene's on a box holding that grown cell
/// (null where the scene has one sign on all of it).
CsgExpressionPtr LevelByLevel::NearExpressionOf(const CsgExpressionPtr& enclosing, int level,
  const LatticeIndex ijk[3]) const
{
  const Box3 grown = GrownByMargin(this->Grid.CellBox(level, ijk), this->Parameters.HausdorffTolerance);
  return CsgExpression::Prune(enclosing, grown, this->Scene.Primitives).Expression;
}

/// The expression pruned to each computed root of the block of trees
/// [lo, hi), by halving blocks: a split run has thousands of roots, and
/// pruning each from the whole scene would test every mesh triangle against
/// every root.
void LevelByLevel::PruneRoots(const int lo[3], const int hi[3], const CsgExpressionPtr& expression)
{
  AdaptiveOctree& tree = this->Result.Octree;
  std::vector<std::size_t> trees; // the block's trees this run computes
  for (int k = lo[2]; k < hi[2]; ++k)
  {
    for (int j = lo[1]; j < hi[1]; ++j)
    {
      for (int i = lo[0]; i < hi[0]; ++i)
      {
        const auto t = static_cast<std::size_t>(this->Grid.TreeIndex(i, j, k));
        if (tree.RoleOf(tree.Nodes[t]) != TreeRole::Skipped)
        {
          trees.push_back(t);
        }
      }
    }
  }
  if (trees.empty())
  {
    return;
  }
  Box3 box;
  for (int a = 0; a < 3; ++a)
  {
    box.lo[a] = this->Grid.Coordinate(a, static_cast<LatticeIndex>(lo[a]) << this->Grid.MaxDepth);
    box.hi[a] = this->Grid.Coordinate(a, static_cast<LatticeIndex>(hi[a]) << this->Grid.MaxDepth);
  }
  const auto pruned = CsgExpression::Prune(expression, box, this->Scene.Primitives);
  const bool single = hi[0] - lo[0] == 1 && hi[1] - lo[1] == 1 && hi[2] - lo[2] == 1;
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
    axis = hi[a] - lo[a] > hi[axis] - lo[axis] ? a : axis;
  }
  int middle[3] = { hi[0], hi[1], hi[2] };
  middle[axis] = (lo[axis] + hi[axis]) / 2;
  this->PruneRoots(lo, middle, pruned.Expression);
  middle[axis] = hi[axis];
  int upper[3] = { lo[0], lo[1], lo[2] };
  upper[axis] = (lo[axis] + hi[axis]) / 2;
  this->PruneRoots(upper, hi, pruned.Expression);
}

/// Pass 1: the exact sign at every corner of this level's cells not seen
/// before, evaluated once (by the smallest cell index among the cells
/// sharing it) and entered into the lattice's table.
bool LevelByLevel::EvaluateUnseenCorners()
{
  AdaptiveOctree& tree = this->Result.Octree;
  using Corner = std::pair<PointKey, std::uint32_t>; // (corner, a cell having it)
  constexpr std::size_t Blocks = 64, Buckets = 64;
  BucketedRecords<Corner> unseen;
  const bool gathered = GatherDistinct<Corner>(Blocks, Buckets,
    [&](std::size_t b, const auto& out) {
      const std::size_t n = this->Active.size();
      for (std::size_t i = n * b / Blocks; i < n * (b + 1) / Blocks; ++i)
      {
        for (int c = 0; c < 8; ++c)
        {
          LatticeIndex p[3];
          CornerLattice(this->Grid, tree.Nodes[this->Active[i]], c, p);
          const PointKey key = MakePointKey(p[0], p[1], p[2]);
          if (tree.Signs.Find(key) < 0)
          {
            out(Corner(key, this->Active[i]));
          }
        }
      }
    },
    [](const Corner& c) { return HashKey(c.first) >> 58; },
    std::less<>(), [](const Corner& x, const Corner& y) { return x.first == y.first; }, this->For,
    this->Within(0.0, 0.1), unseen);
  if (!gathered || this->StopAt(0.1, 0xFFFF))
  {
    return false;
  }
  const std::vector<Corner>& pending = unseen.Records;
  std::vector<std::uint8_t> inside(pending.size());
  if (!ChunkedFor(pending.size(), 8 * Chunk, this->For, [&](std::size_t begin, std::size_t end) {
        for (std::size_t i = begin; i < end; ++i)
        {
          inside[i] = tree.Expressions[pending[i].second]->IsInside(
            this->Grid.Point(pending[i].first), this->Scene.Primitives);
        }
      }, this->Within(0.1, 0.2)))
  {
    return false;
  }
  for (std::size_t i = 0; i < pending.size(); ++i)
  {
    tree.Signs.Insert(pending[i].first, inside[i] != 0);
    if (this->StopAt(0.2, i))
    {
      return false;
    }
  }
  return true;
}

/// Pass 2: the tests of every cell of this level, in parallel
/// (SplitDecision.h). After each chunk, the new signs and face tilings of
/// the cells that passed go into the tables (in cell order: the first tiling
/// of a face stays) and every verdict drops them, so a level's cells never
/// hold them all at once (face refinement may sample thousands of points per
/// cell; a chunk's cells hold at most what they computed in about
/// ChunkSeconds). The face decisions the level shares (FaceDecisionCache.h)
/// - a tiling and its corners' signs per face one cell has tiled and the
/// other not yet - are held until the level ends. The chunks are sized by
/// the clock (ForEachTimedChunk), which no verdict depends on: a cell's tests
/// read its level's tilings only through those decisions - what the cell
/// would compute, kept until the level ends - and of the sign table only
/// exact signs, which the cell computes alike where they are not in it yet.
bool LevelByLevel::TestCells(std::vector<CellTests>& tests)
{
  AdaptiveOctree& tree = this->Result.Octree;
  tests.resize(this->Active.size());
  const ProgressCallback progress = this->Within(0.2, 0.7);
  const bool done = ForEachTimedChunk(this->Active.size(), Chunk, ChunkSeconds, this->For,
    [&](std::size_t begin, std::size_t end) {
    ScratchPool<PolygonSet>::Lease surface(this->SurfaceScratch);
    for (std::size_t i = begin; i < end; ++i)
    {
      tests[i] = TestCell(
        tree, this->Active[i], this->Scene.Primitives, this->Parameters, this->Limits, &*surface, &this->FaceDecisions);
    }
  }, [&](std::size_t first, std::size_t last) {
    for (std::size_t i = first; i < last; ++i)
    {
      McCompatibility& v = tests[i].Verdict;
      if (v.Kind == McVerdict::Pass)
      {
        for (const auto& sign : v.NewSigns)
        {
          tree.Signs.Insert(sign.first, sign.second);
        }
        for (auto& r : v.Refinements)
        {
          // (The two cells sharing a face may have refined it differently:
          // the tiling kept refines both, FaceTile.h.)
          const auto [entry, added] = tree.FaceRefinements.emplace(r.first, r.second);
          if (!added)
          {
            MergeFaceTilings(entry->second, r.second);
          }
        }
        this->Result.RefinedFaces +=
          tree.RoleOf(tree.Nodes[this->Active[i]]) == TreeRole::Own ? v.Refinements.size() : 0;
      }
      std::vector<std::pair<PointKey, bool>>().swap(v.NewSigns);
      std::vector<std::pair<FaceKey, std::vector<FaceTile>>>().swap(v.Refinements);
    }
    return progress && progress(static_cast<double>(last) / static_cast<double>(this->Active.size()));
  });
  this->FaceDecisions.Clear(); // (what is left: faces one cell asked about and the other did not)
  return done;
}

/// Pass 3: each cell's fate, in cell order (SplitDecision.h); the limits
/// turn splits into unresolved leaves. The split cells are `parents`.
bool LevelByLevel::DecideCells(std::vector<CellTests>& tests, std::vector<std::uint32_t>& parents)
{
  AdaptiveOctree& tree = this->Result.Octree;
  const std::size_t splits = static_cast<std::size_t>(std::count_if(tests.begin(), tests.end(),
    [](const CellTests& t) { return t.Verdict.Kind == McVerdict::Split; }));
  this->Limits.AtDepthLimit = this->Limits.Level >= std::min(this->Parameters.MaximumDepth, this->Grid.MaxDepth);
  this->Limits.AtCellLimit =
    !this->Limits.AtDepthLimit && tree.Nodes.size() + 8 * splits > this->Parameters.MaximumNumberOfCells;
  for (std::size_t i = 0; i < this->Active.size(); ++i)
  {
    if (this->StopAt(0.7, i))
    {
      return false;
    }
    if (DecideCell(tree, this->Active[i], tests[i], this->Parameters, this->Limits, this->Result))
    {
      parents.push_back(this->Active[i]);
    }
  }
  return true;
}

/// Pass 4: the children of the split cells, each with the parent's
/// expression pruned to it; those that meet the surface are the next level.
bool LevelByLevel::MakeChildren(const std::vector<std::uint32_t>& parents)
{
  AdaptiveOctree& tree = this->Result.Octree;
  const int level = this->Limits.Level;
  const std::size_t first = tree.Nodes.size();
  tree.Nodes.resize(first + 8 * parents.size());
  tree.Expressions.resize(tree.Nodes.size());
  tree.NearExpressions.resize(tree.Nodes.size());
  for (std::size_t i = 0; i < parents.size(); ++i)
  {
    tree.Nodes[parents[i]].FirstChild = static_cast<std::int32_t>(first + 8 * i);
  }
  if (!ChunkedFor(parents.size(), Chunk / 8, this->For, [&](std::size_t begin, std::size_t end) {
        for (std::size_t i = begin; i < end; ++i)
        {
          const OctreeNode& parent = tree.Nodes[parents[i]];
          for (int c = 0; c < 8; ++c)
          {
            const std::size_t ci = first + 8 * i + static_cast<std::size_t>(c);
            OctreeNode& child = tree.Nodes[ci];
            child.Level = static_cast<std::uint8_t>(level + 1);
            for (int a = 0; a < 3; ++a)
            {
              child.Ijk[a] = 2 * parent.Ijk[a] + ((c >> a) & 1);
            }
            const auto pruned = CsgExpression::Prune(
              tree.Expressions[parents[i]], this->Grid.CellBox(level + 1, child.Ijk), this->Scene.Primitives);
            child.State = pruned.Sign == RegionSign::Mixed ? CellState::Surface : StateOf(pruned.Sign);
            if (pruned.Sign == RegionSign::Mixed)
            {
              tree.Expressions[ci] = pruned.Expression;
              // (From the parent's where it has one; else from the scene,
              // once per cell that first holds no mesh.)
              if (tree.NearExpressions[parents[i]] || !pruned.Expression->HasMeshLeaves())
              {
                tree.NearExpressions[ci] =
                  this->NearExpressionOf(tree.NearExpression(parents[i], this->Parameters.HausdorffTolerance),
                    level + 1, child.Ijk);
              }
            }
          }
        }
      }, this->Within(0.8, 1.0)))
  {
    return false;
  }
  this->Active.clear();
  for (std::size_t i = 0; i < parents.size(); ++i)
  {
    tree.Expressions[parents[i]].reset();
    tree.NearExpressions[parents[i]].reset();
    for (std::size_t ci = first + 8 * i; ci < first + 8 * i + 8; ++ci)
    {
      if (tree.Nodes[ci].State == CellState::Surface)
      {
        this->Active.push_back(static_cast<std::uint32_t>(ci));
      }
    }
  }
  return true;
}
} // namespace

SubdivisionResult RunTopologyPreservingSubdivision(const ImplicitScene& scene, const RootGrid& grid,
  const SubdivisionParameters& parameters, const ParallelFor& parallelFor, const ProgressCallback& progress)
{
  return LevelByLevel(scene, grid, parameters, parallelFor, progress).Run();
}

} // namespace tpc
