// The local heights' bound of a mesh cell's error E(P) (issue 17; SlabBound.h's
// setting, names and steps (1) - (3)): where S_C and its patch P face one way n
// but the slab holding them is thick - S_C curved across the cell, t its
// sagitta, several times E(P) - each point's distance is bounded by what lies
// over and beside it.
//
// Let every triangle of S_C and P face along n (SlabBound.h: Claim), and be
// steep enough along it (N . n >= |N| / 16, N a triangle's normal: heights
// over the plane change at most 16 times as fast as a point moves across
// it; Rounding).
// Chord regions. Where a face of C holds both ends of c, the arc A_c and a
// refining polyline lambda_c lie in that face (in C, in its plane), within
// delta_c of c. With unit vectors u along c, m across it in the face's
// plane and f the face's normal, each of their points is
// a + alpha u + beta m, -delta_c <= alpha <= |c| + delta_c, beta in
// [Low, High]: the range, with 0 (c itself), of beta over S_C's points on
// the face within delta_c (and the slack) of c's box - which hold A_c and
// lambda_c's corners (points of S on c's tile), hence lambda_c - clamped to
// [-delta_c, delta_c]. (a and b lie on the face up to rounding: they are
// put on its plane first, u along the line between them there, and a chord
// too short against that rounding is read as one no face holds.) So C_c
// lies in that region's part in C, and R_c, the rectangle of the plane
// aligned with pi(c) around its shadow, holds every x with w(C_c, x) != 0
// (SlabBound.h, (2)). (Where no face holds c, R_c holds every point within
// delta_c of pi(c).) Then
//   G   = max over a polygon Q of S_C and a triangle F of P, x in
//         pi(Q) and pi(F), of |h_Q(x) - h_F(x)| (heights of their planes
//         over x: both are graphs over their shadows);
//   D_S = max over c, y in S_C over R_c, of B(y);  D_P = likewise over P,
// B(x) a bound of x's distance to the other side in three parts, by where
// the point u of c's line nearest x lies: before a, |x - a|; past b,
// |x - b| (a and b are loop points: on S and corners of P); on c, the
// smaller of those and |x - w| for the other side's point w with w - u =
// beta m - A_c and lambda_c run from a to b, so each projects onto c's
// line over all of c, and lie in the face's plane - which is
//   sqrt((f . (x - a))^2 + max over beta in [Low, High] of (m . (x - a) - beta)^2)
// (x - u has no part along u); for S_C's points against the own loops'
// P, d(x, c) (c lies in P); with no face, d(x, c) + delta_c.
// Claim: E(P) <= max(G, D_S, D_P).
// Proof. In SlabBound.h's two cases where both have a point over x, y in Q
// and p in F with x in both shadows: |y - p| = |h_Q(x) - h_F(x)| <= G.
// Where the other side has none, x lies in some R_c, and B bounds the
// distance to a point of the other side's closure (A_c, lambda_c, c, a or
// b).
// Computing them: B is convex in each part (a norm of convex non-negative
// parts, or a distance to a point or segment), and a polygon of S_C or a
// triangle of P cut by R_c's prism and the planes across c at a and b is
// convex: B's largest over it is at the cut polygon's corners. h_Q - h_F is
// affine over the convex pi(Q) and pi(F): its largest is at the corners of
// pi(Q) cut to pi(F). Both are computed in the frame (e_1, e_2, n) -
// distances are the same in any orthonormal frame. Where both bounds hold
// (the same facing), the smaller is kept.
// Measured (armadillo at 1/128, one thread): of the 625 predictions whose
// slab was too thick, 406 settle on the local heights, at a sixth of a
// branch and bound's time each.
//
// Rounding. The local heights are computed in a rotated frame and at cut
// corners, each within a few units in the last place of the coordinates
// times the slopes (at most 16); a corner a cut misses by rounding lies
// within as much of a corner of the same polygon cut by a neighbour of the
// cutting triangle (P's fans are continuous across their inner edges) or by
// a rectangle R_c (across their chords; the slack widens R_c and [Low,
// High]), and the values change by at most the slopes times that. A chord's
// face is read where its ends lie within 64 units in the last place of a
// face of the cell (loop points are placed on it up to about one); put on
// its plane, they move by as much, by which the region is lengthened, and
// the bound's distances to the chord change by no more. All of it is far
// within the slack (RoundingSlack, MeshCellError.h), added by the caller.
#pragma once

#include "ConvexPolygons.h"
#include "MeshSolid.h"
#include "PolygonHausdorff.h"

#include <cmath>
#include <vector>

namespace tpc
{

/// The own chords a patch spans (header): the cell's own
/// loops' points, loop by loop; each chord's delta_c, in the same order
/// (chord k of a loop runs from its point k to the next; or Delta for
/// every chord where none are listed); whether the patch's loops refine
/// them (the extraction's final loops) rather than being them. No loops
/// given: the slab bound alone.
struct OwnChords
{
  const std::vector<std::vector<Vec3>>* Loops = nullptr;
  const std::vector<double>* Deltas = nullptr;
  double Delta = HUGE_VAL;
  bool Refined = false;
  /// The cell: each chord's face narrows R_c (header).
  Box3 Cell;
};

/// max(G, D_S, D_P) (header) over the own chords `chords` along the unit
/// direction `n`, every triangle of S_C `surface` (clipped from `mesh`'s
/// triangles `surfaceTriangles`) and of `patch` facing along it, without the
/// slack (the caller adds it) but with R_c and [Low, High] widened by it:
/// +inf where a triangle is not steep enough, no chord is given, a cut gives
/// up (capacity, NaN), or a term passes `giveUp`.
double LocalHeightsBound(const MeshSolid& mesh, const TriangleList& surfaceTriangles, const PolygonSet& surface,
  const std::vector<SourceTriangle>& patch, const OwnChords& chords, const Vec3& n, double slack, double giveUp);

} // namespace tpc
