// The surface in a cell where two or more meshes meet, bounded from both
// sides by convex polygons (issue 17: the certified error of such cells'
// patches; MeshCellError.h where one mesh is the surface).
//
// Setting. The scene's expression pruned to the cell C has mesh leaves
// only, of two or more meshes X_1 .. X_k (each leaf a mesh solid or its
// complement), combined by unions and intersections: F = Phi(X_1, .., X_k).
// The exact surface S is F's boundary. In C it is made of pieces of the
// meshes' surfaces, but not of all of them: in A ∪ B, A's surface inside B
// is not S. Cutting each mesh's triangles by the others' solids exactly
// would build their arrangement; two sets of convex polygons suffice:
//   OnSurface ⊆ S     and     Covering ⊇ S ∩ C,
// for they bound both directions of the Hausdorff distance of a patch P in
// C (MeshCellError.h, The error):
//   h(P, S)     <= h(P, OnSurface)   (no point of a subset is nearer), and
//   h(S ∩ C, P) <= h(Covering, P)    (a largest distance over a superset
//                                     is no smaller),
// so E(P) <= max of the two, each bounded by PolygonHausdorff.h's branch
// and bound (CertifiedSurfacePatchError, MeshCellError.h). For one mesh both
// sets are S_C.
//
// Deciding a piece. Let Q be a convex piece of mesh i's surface in C (one
// of its listed triangles clipped to C, or a part of one), farther than a
// margin from the surface of every other mesh in C (the polygons of their
// listed triangles clipped to C, which hold every point of their surfaces
// in C). Each other X_j then has one sign over all of Q: Q is convex, so
// connected, and lies in C, where X_j's sign changes only across X_j's
// surface. So near a point x of Q every other solid is constant (x is off
// their surfaces, which are closed sets) and F is Phi of those constants
// and of X_i alone: X_i, its complement, everything or nothing. x is on S
// exactly when Phi changes with X_i's value (then S is X_i's surface near
// x); when it does not, x is inside or outside F with a neighbourhood. So
// Q lies on S or off it as a whole, decided by evaluating Phi twice, with
// X_i in and out and the others' exact signs (MeshSolid::IsInside) at one
// point of Q. A piece not proven apart from exactly one polygon R of
// another mesh is cut along R's plane, pushed aside by twice the margin
// both ways: the parts beyond are then apart from R along its normal (R
// lies in its plane up to rounding) and are decided as above, while the
// strip between, four margins thick across R's plane, is decided only
// where it is apart from every other mesh after all and is never cut
// again. A piece near several polygons is cut in two at the middle of its
// box's longest side, down to a given width. The parts of a cut cover the
// piece (up to the rounding of the cut points). Pieces still undecided go
// into Covering only: they hold the curve where the meshes meet, and
// leaving them out of OnSurface costs the bound at most their width (a
// strip's, across the curve, is four margins over the sine of the angle
// between the meshes) where a point of P is nearest to S on them.
//
// Apart by a margin. Two convex polygons are disjoint when their
// projections on some axis do not overlap (separating axes: for convex
// polytopes their normals and the cross products of their edges suffice;
// coplanar ones - meshes with coincident faces, warned about and left
// unresolved elsewhere - need axes in their plane and are never found apart
// here, which only leaves them undecided). A gap g between the projections
// on an axis a puts every pair of their points at least g / |a| apart.
//
// Rounding. The computed polygons - clipped corners interpolate the mesh's
// vertices, and each cut interpolates again - lie within the rounding
// slack s (RoundingSlack, MeshCellError.h: a few hundred units in the last
// place of the largest coordinate M per clipping, against 16 384; a piece
// is cut at most 48 times, each cut a few ulps) of the exact pieces they
// stand for, and the projections are computed within a few ulps of M |a|.
// The margin is 4 s: computed pieces more than 4 s apart stand for exact
// ones more than 2 s apart. The point whose signs are read is Q's centroid
// clamped into C, c: within s of the exact piece Q*, and more than 3 s from
// the other meshes' surfaces in C, so the segment from c to Q* (in C,
// convex, at most s long) meets none of them, and c has Q*'s signs - which
// the exact test reads, c being off every surface. The slack is added to
// the bounds as for one mesh (MeshCellError.h: Rounding).
#pragma once

#include "ConvexPolygons.h"
#include "CreaseFollowing.h"
#include "CsgExpression.h"

#include <cstddef>
#include <vector>

namespace tpc
{

/// S in a cell where meshes meet, from both sides (header).
struct MeshBooleanSurface
{
  PolygonSet OnSurface; ///< pieces proven on S
  PolygonSet Covering;  ///< every piece not proven off S: every point of S in the cell lies in one
  double Slack = 0.0;   ///< the rounding slack of the meshes in the cell (header: Rounding)
  std::size_t Undecided = 0; ///< pieces left undecided at the width asked for (in Covering only)
};

/// Whether `expression` has mesh leaves only, each with its triangle list,
/// of two or more meshes (each mesh in one leaf): a cell where meshes meet.
bool IsMeshBoolean(const CsgExpression& expression);
/// Its distinct leaves where it holds, else none.
std::vector<CsgLeaf> MeshBooleanLeaves(const CsgExpression& expression);

/// S's two sides (header) in `cell`, for an expression IsMeshBoolean holds
/// for, pruned to `cell`; pieces near another mesh's surface cut down to
/// `width` (their box's longest side) or until `pieceBudget` pieces have
/// been decided. False, `surface` empty, when the expression is no mesh
/// Boolean. (Its sets are cleared first; their memory is reused.) With
/// `creases`, the segments where two meshes' listed triangles cross in the
/// cell at FollowedCreaseDegrees or more between their planes: the creases
/// of S there where two meshes meet (where three or more do, a crossing of
/// two may lie inside a third solid, off S, and is followed all the same),
/// up to rounding - what the patch must follow, a quality criterion, no
/// part of a bound.
bool MeshBooleanSurfaceInCell(const CsgExpression& expression, const PrimitiveSet& primitives, const Box3& cell,
  double width, std::size_t pieceBudget, MeshBooleanSurface& surface,
  std::vector<CreaseSegment>* creases = nullptr);

} // namespace tpc
