// The complex-cell test (paper 4.2 and 5.3.1).
//
// A cell is complex if the surface meets its voxel or a face whose corners show
// no sign change (complex voxel / face), crosses an edge more than once
// (complex edge), or its corner signs are ambiguous for Marching Cubes (face or
// voxel ambiguity). For polyhedra the paper answers "does the surface meet this
// voxel/face" with max-norm distances; for our implicit primitives the same
// question is answered conservatively by interval enclosures of the pruned CSG
// expression: a box is free of the surface only if the enclosure proves a
// single sign on it. Overestimation can only cause extra subdivision, never a
// missed intersection.
#pragma once

#include "CsgExpression.h"
#include "SplitReason.h"

namespace tpc
{

/// Sign of the field on a closed box, refining the box `depth` times (2^k
/// pieces per refinement along its k non-degenerate axes) before giving up.
RegionSign ProveConstantSign(const CsgExpressionPtr& expression,
  const std::vector<Quadric>& primitives, const Box3& box, int depth);

/// Box of face f of a cell box.
Box3 FaceBox(const Box3& cell, int face);

struct ComplexCellQuery
{
  const CsgExpressionPtr& Expression; ///< pruned to the cell
  const std::vector<Quadric>& Primitives;
  Box3 Cell;
  unsigned InsideMask = 0; ///< bit c: corner c inside
};

/// Ambiguous sign configurations: FaceAmbiguity, VoxelAmbiguity or None.
SplitReason SignAmbiguityTest(unsigned insideMask);

/// ComplexVoxel (no sign change at corners; the caller has already failed to
/// prove the cell free of the surface), ComplexFace, or None.
SplitReason ComplexVoxelOrFaceTest(const ComplexCellQuery& q);

/// ComplexEdge if some edge is crossed more than once (or cannot be proven
/// simple), else None.
SplitReason ComplexEdgeTest(const ComplexCellQuery& q);

} // namespace tpc
