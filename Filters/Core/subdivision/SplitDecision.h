// Where a cell is split, and why (paper 5.3).
//
// Each cell of a level that meets the surface runs the paper's tests
// (McCompatibility.h: complex cell 5.3.1, star-shaped 5.3.2, Hausdorff size
// 5.3.4 - or a certified error, with the mesh's creases followed,
// CreaseFollowing.h -, with faces refined where a face test fails); a cell that fails at
// the tolerance's size also checks for two surfaces facing each other closer
// than the finest cell (FacingSurfaces.h). Then, in cell order, its fate:
//
//   passed                      a Surface leaf (a plane section may stay
//                               larger than the tolerance: PlanarCell.h);
//   proven free of the surface  an Inside or Outside leaf;
//   failed, one mesh's surface  an Exact leaf that keeps the mesh as its
//   that refining cannot help   patch (ExactCellCriterion.h);
//   failed at a limit, or with  an Unresolved leaf marked LimitReached or
//   facing surfaces             SurfacesTooClose, with the test that failed
//                               (the guarantee is withdrawn: 5.3.3, the
//                               tangential contacts that never pass);
//   failed otherwise            split, its SplitReason the test that failed.
#pragma once

#include "AdaptiveOctree.h"
#include "McCompatibility.h"
#include "TopologyPreservingSubdivision.h"

#include <cstdint>

namespace tpc
{

class FaceDecisionCache; // (FaceDecisionCache.h)

/// What a level knows before deciding its cells.
struct LevelLimits
{
  int Level = 0;
  /// The tolerance's cells are this level's or larger.
  bool ToleranceSize = false;
  bool AtDepthLimit = false;
  /// Splitting every failing cell would exceed MaximumNumberOfCells.
  bool AtCellLimit = false;
  /// The level from which a failing cell of one mesh keeps the mesh
  /// whatever it lists (ExactCellLevelsBelowTolerance below cells of
  /// ExactCellReferenceSize), and the first whose cells are at most the
  /// tolerance across, with a relative slack of 1e-9 (from which it keeps a
  /// mesh listing at most ExactCellTriangles).
  int ExactLevel = 0;
  int ExactToleranceLevel = 0;
  /// The width of the finest cell MaximumDepth allows.
  double FinestWidth = 0.0;
};

/// The outcome of one cell's tests.
struct CellTests
{
  McCompatibility Verdict;
  /// Failed at the tolerance's size with two surfaces facing each other
  /// closer than the finest cell.
  bool Facing = false;
  /// Of those, two surfaces lying in one plane (FacingSurfaces.h).
  bool Touching = false;
};

/// Runs the tests of cell `n` (thread-safe: reads the tree only);
/// `surfaceScratch` and `faceDecisions` as TestMcCompatibility's.
CellTests TestCell(const AdaptiveOctree& tree, std::uint32_t n, const PrimitiveSet& primitives,
  const SubdivisionParameters& parameters, const LevelLimits& limits, PolygonSet* surfaceScratch = nullptr,
  FaceDecisionCache* faceDecisions = nullptr);

/// Sets the state of cell `n` from its tests and counts it in `result` (its
/// own trees' cells only, in a piece of a split run); true when the cell is
/// split.
bool DecideCell(AdaptiveOctree& tree, std::uint32_t n, const CellTests& tests, const SubdivisionParameters& parameters,
  const LevelLimits& limits, SubdivisionResult& result);

} // namespace tpc
