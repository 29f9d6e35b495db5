// Input surfaces facing each other closer than the finest cell (issue 6).
//
// Where two solids touch along a face (two boxes sharing one, a mesh resting
// on a box) or a slab or gap thinner than the finest cell separates two
// surfaces, the paper's tests fail at every depth down to that gap: an edge
// across the contact crosses the surface twice or touches it, a face over it
// shows no sign change. Refinement then grows like an area - four times the
// cells per level - for hours before MaximumDepth or MaximumNumberOfCells
// stops it, and the cells still fail. The subdivision stops such a cell as
// soon as it is as small as the tolerance asks, marks it (SplitReason
// SurfacesTooClose) and withdraws the guarantee there, as any limit does; the
// run costs what the contact's boundary costs, not its area.
//
// Detection is local and needs no exactness: stopping a cell only withdraws
// the guarantee (never a silently wrong answer), so a floating-point affine
// model of each locally planar leaf is enough.
// - A quadric leaf: its first-order Taylor expansion at the cell's centre
//   divided by the gradient's length there (a signed distance for a plane);
//   the model's error over the cell is the quadratic term, at most
//   ||H||_F r^2 / (2 |grad f(c)|) for the constant Hessian H and the cell's
//   half-diagonal r.
// - A mesh leaf: when its listed triangles lie on at most two planes (within
//   the gap, over the cell), each plane; a thin part of one mesh has two.
// Two models l1, l2 (unit outward normals) face each other closer than g
// throughout the cell when their normals are opposite and
// |l1 + l2| + e1 + e2 <= g at every corner: l1 + l2 is affine, so that holds
// on the whole cell, and wherever either surface meets the cell the other
// lies within g of it.
#pragma once

#include "CsgExpression.h"

namespace tpc
{

/// True when two leaves of `expression` (pruned to `cell`), or two planes of
/// one mesh leaf, are locally planar surfaces facing each other closer than
/// `gap` throughout the cell. `touching` (if given) is set when such a pair
/// lies in one plane, up to rounding (solids touching along a face: no
/// lattice placement separates them), and cleared otherwise.
bool HasFacingSurfaces(const CsgExpression& expression, const PrimitiveSet& primitives, const Box3& cell,
  double gap, bool* touching = nullptr);

} // namespace tpc
