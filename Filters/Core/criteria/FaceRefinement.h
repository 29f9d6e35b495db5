// Face refinement: sampling a cell face finely enough that every tile is
// MC-compatible, without refining the volume.
//
// Why: along a sharp CSG crease (two primitives meeting at an angle) a fixed
// fraction of the cells the crease crosses are complex at every scale - a
// wedge tip slips between the corners - and each refinement puts the crease in
// two or three children, so refining volumes never ends. But the crease only
// pierces a face at isolated points, and refining a face is a 2-D problem
// local to those points, which ends after a few levels. The paper's own
// crack patching (4.3) already lets a cell use finer samples on a face; face
// refinement makes those samples where the cell's own tests need them.
//
// A refined face is a tree of rectangular tiles, each split in four at a
// lattice point; each tile passes the face tests of ComplexCellCriterion.h on its
// own corners. Adding sample points on a passing
// tile's edges (T-junctions from finer neighbours) keeps it passing: each edge
// is crossed at most once, so a new point only says on which side of it the
// crossing lies.
#pragma once

#include "BoundaryLoops.h"
#include "CsgExpression.h"
#include "CellSignCache.h"
#include "SplitReason.h"

#include <cstdint>
#include <vector>

namespace tpc
{

struct FaceRefinementResult
{
  SplitReason Failure = SplitReason::None; ///< the test still failing when refinement gave up
  std::vector<FaceTile> Tiles;             ///< passing tiles covering the face
};

/// Refines the face `face` of a cell, lying in the plane `axis` = `plane`,
/// into at most `maxLevels` levels of tiles.
FaceRefinementResult RefineFace(const CsgExpressionPtr& expression,
  const PrimitiveSet& primitives, const RootGrid& grid, int axis, LatticeIndex plane,
  const FaceTile& face, int maxLevels, CellSignCache& signs);

} // namespace tpc
