// The star-shaped test (paper 4.2, 5.2, 5.4) for CSG of curved primitives.
//
// Why a witness proves what the paper's lemmas need
// -------------------------------------------------
// Let the pruned expression over the cell have leaves g_i = sigma_i f_i (a
// difference contributes sigma = -1: the solid's complement of the subtracted
// primitive, whose constraint is "inverted" as the paper says). Suppose a
// point p satisfies, for every leaf i and every x in the cell with g_i(x) = 0,
//     grad g_i(x) . (x - p) > 0.                                   (*)
// Along any ray from p, each g_i can then cross zero only upwards (from inside
// to outside) inside the cell, so each leaf solid restricted to the ray within
// the cell is a prefix of it. Min (union) and max (intersection) of prefixes
// are prefixes, so the combined solid P restricted to every ray is a prefix:
// the ray crosses the exact surface E at most once in the cell. That is the
// property Lemmas 1-3 use: a closed component of E in the cell would be
// crossed twice by some ray, and E in the cell projects injectively on the
// sphere of directions around p (so it has no handle). This holds wherever p
// is, so p need not lie in the cell; and a point at infinity (parallel rays,
// condition grad g_i(x) . u > 0 for a direction u) is just as good - that is
// the witness that passes most cells near smooth surfaces and sharp CSG edges.
// The paper's kernel condition is the special case p in Kernel(P ∩ V).
//
// The condition must hold on the surface in the cell; we check it on the
// whole cell (conservative, paper 5.4), refining the cell into sub-boxes and
// skipping sub-boxes whose enclosure shows g_i has no zero there. Each check is
// an interval enclosure of the quadric (*) (Quadric::EncloseStarCondition), so
// an accepted witness is proven. For a face, p is restricted to the face's
// plane (a point at infinity to directions in the plane): then (x - p) lies in
// the plane and (*) is the 2-D condition on the curve E ∩ F.
//
// Witness candidates, cheapest first: the mean normal direction, the maximin
// direction of sampled surface normals, centres of ellipsoid leaves, points
// behind the surface along that direction, and last the paper's kernel LP
// (SmallDimensionLp.h) over the facets' planes (meshes, exact) and tangent
// planes at surface samples (quadrics, a linearization), for a point and for
// a direction. A wrong candidate is simply rejected by the verification.
#pragma once

#include "CsgExpression.h"

namespace tpc
{

/// True if a witness was found and verified for the solid restricted to the
/// voxel `cell` (expression pruned to the cell).
bool IsStarShapedWithRespectToVoxel(
  const CsgExpressionPtr& expression, const PrimitiveSet& primitives, const Box3& cell);

/// Same for a face (a box degenerate along `axis`); `prunedToFace`: the
/// expression is already pruned to the face (CsgExpression::Prune with it,
/// to a mixed sign), which is then not done again.
bool IsStarShapedWithRespectToFace(const CsgExpressionPtr& expression,
  const PrimitiveSet& primitives, const Box3& face, int axis, bool prunedToFace = false);

/// Verifies (*) for one witness; exposed for tests.
bool VerifyStarWitness(const CsgExpression& expression, const PrimitiveSet& primitives,
  const Box3& box, const StarWitness& witness, int refinementDepth);

} // namespace tpc
