#include "SplitDecision.h"

#include "ExactCellCriterion.h"
#include "FacingSurfaces.h"

#include <algorithm>

namespace tpc
{
namespace
{
CellState StateOf(RegionSign s)
{
  return s == RegionSign::Inside ? CellState::Inside : CellState::Outside;
}
} // namespace

CellTests TestCell(const AdaptiveOctree& tree, std::uint32_t n, const PrimitiveSet& primitives,
  const SubdivisionParameters& parameters, const LevelLimits& limits, PolygonSet* surfaceScratch,
  FaceDecisionCache* faceDecisions)
{
  CellTests tests;
  const OctreeNode& node = tree.Nodes[n];
  if (const CellToSplit* repair = parameters.SplitFirst.Find(node.Level, node.Ijk))
  {
    // (An earlier run's final surface found it wanting: CellRepair.h.)
    tests.Verdict.Kind = McVerdict::Split;
    tests.Verdict.Reason = repair->Reason;
    return tests;
  }
  const CsgExpression& expression = *tree.Expressions[n];
  // A cell that keeps its mesh if it fails need not refine its faces far to
  // find out (ExactCellCriterion.h).
  const bool keepsOnFailure = parameters.ExactCells && limits.ToleranceSize && KeepsTheMesh(expression, true, false);
  // Faces are sampled no deeper than SampleDepth (RootGrid.h).
  const int levels =
    std::max(0, std::min(FaceRefinementLevels, SampleDepth(tree.Grid, parameters.MaximumDepth) - limits.Level));
  tests.Verdict = TestMcCompatibility(tree, n, primitives, parameters.HausdorffTolerance,
    keepsOnFailure ? std::min(levels, ExactCellFaceRefinementLevels) : levels,
    // (A cell stopped by a limit reports the test it fails: all of them run.)
    parameters.ProvenFailuresFirst && !limits.AtDepthLimit && !limits.AtCellLimit, surfaceScratch,
    parameters.RefineChords, faceDecisions);
  if (limits.ToleranceSize && tests.Verdict.Kind == McVerdict::Split)
  {
    tests.Facing = HasFacingSurfaces(expression, primitives, tree.Grid.CellBox(limits.Level, tree.Nodes[n].Ijk),
      limits.FinestWidth, &tests.Touching);
  }
  return tests;
}

bool DecideCell(AdaptiveOctree& tree, std::uint32_t n, const CellTests& tests, const SubdivisionParameters& parameters,
  const LevelLimits& limits, SubdivisionResult& result)
{
  OctreeNode& node = tree.Nodes[n];
  const McCompatibility& v = tests.Verdict;
  const RootGrid& grid = tree.Grid;
  // (A piece of a split run counts its own trees' cells only.)
  const std::size_t mine = tree.RoleOf(node) == TreeRole::Own ? 1 : 0;
  const int level = limits.Level;
  if (v.Kind == McVerdict::Pass)
  {
    node.State = CellState::Surface;
    node.PlaneSection = v.Planar;
    node.ErrorBounded = v.ErrorBounded;
    node.CreaseFan = v.CreaseFan;
    if (v.MeshSurface)
    {
      tree.MeshCellPredictions[n] = v.MeshPrediction;
    }
    if (v.QuadricFanApex)
    {
      tree.QuadricFanApexes[n] = *v.QuadricFanApex;
    }
    if (!v.BooleanFanApexes.empty())
    {
      tree.BooleanFanApexes[n] = v.BooleanFanApexes;
    }
    result.SurfaceCells += mine;
    result.ChordRefinedCells += v.ChordsRefined ? mine : 0;
    result.PlanarSurfaceCells += v.Planar ? mine : 0;
    result.ErrorBoundedCells += v.ErrorBounded ? mine : 0;
    result.OversizedErrorBoundedCells += v.ErrorBounded && v.Oversized ? mine : 0;
    if (!v.ErrorBounded) // (certified on its patch: ExtractionResult::CertifiedBound)
    {
      result.HausdorffBound =
        std::max(result.HausdorffBound, mine * grid.CellDiagonal(v.Planar ? grid.MaxDepth : level));
    }
    return false;
  }
  if (v.Kind == McVerdict::Constant)
  {
    node.State = StateOf(v.Sign);
    tree.Expressions[n].reset();
    if (n < tree.NearExpressions.size())
    {
      tree.NearExpressions[n].reset();
    }
    return false;
  }
  const bool stopped = limits.AtDepthLimit || limits.AtCellLimit || tests.Facing;
  if (parameters.ExactCells &&
    KeepsTheMesh(*tree.Expressions[n], level >= limits.ExactToleranceLevel, level >= limits.ExactLevel || stopped))
  {
    // One mesh's surface that the tests cannot resolve: its patch is the mesh
    // itself (ExactCell.h).
    node.State = CellState::Exact;
    node.FailedTest = v.Reason;
    result.ExactCells += mine;
    result.HausdorffBound = std::max(result.HausdorffBound, mine * grid.CellDiagonal(grid.MaxDepth));
    return false;
  }
  if (stopped)
  {
    node.State = CellState::Unresolved;
    node.Reason = tests.Facing ? SplitReason::SurfacesTooClose : SplitReason::LimitReached;
    node.FailedTest = v.Reason;
    result.FacingSurfaceCells += mine * tests.Facing;
    result.TouchingSurfaceCells += mine * (tests.Facing && tests.Touching);
    result.DepthLimitReached |= mine && limits.AtDepthLimit && !tests.Facing;
    result.CellLimitReached |= mine && limits.AtCellLimit && !tests.Facing;
    result.UnresolvedCells += mine;
    result.HausdorffBound = std::max(result.HausdorffBound, mine * grid.CellDiagonal(level));
    result.UnresolvedByReason[static_cast<int>(v.Reason)] += mine;
    return false;
  }
  node.State = CellState::Refined;
  node.Reason = v.Reason;
  result.SplitsByReason[static_cast<int>(v.Reason)] += mine;
  result.SpokeSplitCells += v.SplitBySpoke ? mine : 0;
  result.ProbeSplitCells += v.SplitByProbe ? mine : 0;
  result.CreaseSplitCells += v.SplitByCreases ? mine : 0;
  return true;
}

} // namespace tpc
