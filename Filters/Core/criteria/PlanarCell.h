// Error-driven acceptance of cells larger than the tolerance: cells where the
// exact surface is a plane section (issue 5; generalizes the paper's 5.3.4).
//
// The paper bounds the Hausdorff distance by the cell size: the surface and
// its patch both lie in the cell, so a surface cell no larger than epsilon
// keeps them within epsilon of each other. That makes every surface cell the
// finest size, and flat regions as dense as a uniform grid. The bound that
// matters is the distance between the surface in the cell and the patch
// extracted there, and it is zero when the surface in the cell is a plane:
//
// - If the expression pruned to the cell has only linear quadric leaves
//   (planes, faces of boxes: a min/max tree of half-spaces) and no two of the
//   planes meet inside the cell (each plane's other leaves have one sign on
//   its section of the cell - a thin plate's two faces), the surface there is
//   a disjoint union of whole convex polygons plane ∩ cell: on each polygon
//   every other leaf has one sign, so the combination is decided by that
//   plane's leaf on all of it or on none of it.
// - If it is a single mesh leaf whose triangle list (a superset of the
//   triangles meeting the cell) lies in one plane, the surface in the cell is
//   a subset of plane ∩ cell without boundary inside the open cell (the mesh
//   is closed), i.e. a union of components of the connected set
//   plane ∩ open cell: all of it (a cell with surface) or nothing.
//
// Such a cell is usually MC-compatible at a large size (a plane crosses each
// edge at most once and meets a face only where its corners change sign), and
// each loop's patch is the fan from the loop's centroid to points on one
// polygon's boundary: the loop's points
// are exact edge crossings (on the cell's edges, or on finer neighbours' edges
// lying in its faces, crack patching), all on the polygon's boundary, so the
// fan is the polygon itself up to rounding. The two-sided Hausdorff distance
// of such a cell is rounding-level whatever its size; the filter reports the
// finest lattice cell's diagonal for it. The topology tests are unchanged:
// such a cell still passes all of them before it is accepted.
#pragma once

#include "CsgExpression.h"

namespace tpc
{

/// True when the surface of the solid described by `expression` (pruned to
/// `cell`) is provably a disjoint union of plane sections of the cell: linear
/// quadric leaves whose planes do not meet in the cell (interval enclosures),
/// or one mesh leaf whose listed triangles are exactly coplanar (exact
/// predicates).
bool IsPlanarCell(const CsgExpression& expression, const PrimitiveSet& primitives, const Box3& cell);

} // namespace tpc
