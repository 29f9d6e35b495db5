// How many times the surface crosses an axis-aligned edge (the complex-edge
// criterion, paper 5.3.1), proven with interval arithmetic.
//
// The paper uses directed distances for polyhedra. For our primitives each leaf
// restricted to the edge is a polynomial of degree <= 2; rather than solving it
// in floating point (which can miss a double root), the edge is bisected until
// on every piece each active leaf is sign-definite, strictly monotone
// (derivative enclosure excluding zero) or constant, and the leaves that change
// sign all change the same way. On such a piece the combined min/max field
// changes sign at most once, so the count is exact. Tangential contact never reaches that state: the bisection
// budget (depth, and a cap on the pieces examined) runs out and the edge is
// reported as not proven (hence complex).
#pragma once

#include "BoundaryLoops.h"
#include "CsgExpression.h"

namespace tpc
{

struct EdgeCrossingCount
{
  int Count = 0;       ///< number of crossings found (meaningful if Proven)
  bool Proven = false; ///< false: could not be decided within the budget
};

/// Counts crossings on the segment from `a` to `b` (which differ only along
/// `axis`); `insideA`/`insideB` are the exact signs at the endpoints. Stops
/// early once two crossings are found. `opposite` (if given) receives the
/// coordinate along `axis` of a bisection point whose sign differs from
/// `insideA`, when one was met: with equal end signs, a point between two
/// crossings - inside a gap or a wedge however thin, which samples at fixed
/// spacings miss (left unchanged otherwise; a lone mesh leaf never sets it).
/// `maxPieces` caps the pieces examined (a surface grazing the edge would
/// visit 2^depth of them).
EdgeCrossingCount CountEdgeCrossings(const CsgExpressionPtr& expression,
  const PrimitiveSet& primitives, const Vec3& a, const Vec3& b, int axis, bool insideA,
  bool insideB, int maxBisections = 24, double* opposite = nullptr, int maxPieces = 4096);

/// A point of the surface on a segment whose endpoint signs differ (root
/// finding on the exact field, paper 4.3), with `insideA` the sign at a.
Vec3 FindEdgeCrossing(const CsgExpression& expression, const PrimitiveSet& primitives,
  const Vec3& a, const Vec3& b, bool insideA);

/// The point of a sub-edge crossing (CrossingKind::SubEdge): found on the
/// exact field (FindEdgeCrossing; a lone mesh leaf crossed once gives the
/// point on the crossed triangle's plane), then put exactly on the sub-edge's
/// line and strictly inside it, so that crossings of different sub-edges never
/// coincide and a loop's chords meet only at their ends (LoopTriangulation.h).
Vec3 PlaceSubEdgeCrossing(const Crossing& c, const RootGrid& grid, const CsgExpression& expression,
  const PrimitiveSet& primitives);

} // namespace tpc
