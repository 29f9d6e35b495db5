// A certified bound of a mesh cell's error E(P) without a branch and bound,
// where S_C and its fan both face one way (issue 17's "mesh inputs" bound,
// made two-sided; MeshCellError.h's setting and names).
//
// Setting. S_C is the part in the cell C of a closed oriented mesh - every edge
// between two triangles that walk it opposite ways, so that S is a 2-cycle (the
// callers ask MeshSolid::EveryEdgeHasTwoTriangles; the repair orients them,
// MeshRepair.h) - and its boundary is the trace T on C's faces: one arc A_c per
// chord c of the cell's loops (the tiles passed the face tests - the surface
// crosses each in one arc whose ends are its chord's, BoundaryLoops.h; a crease
// tile's two chords a -> x, x -> b each take their half of it,
// CreaseCrossing.h). The patch P spans those loops - a fan around an apex or
// from a loop point, any triangulated surface whose boundary they are; delta_c
// bounds the arc A_c's distance from its chord c (MeasureChords: every point of
// S on c's tile or half).
// Take a unit direction n, heights h(x) = x . n, the projection pi along n
// onto a plane across it, and t = the thickness of the slab of heights
// holding S_C and P (their corners: P's points are convex combinations of
// its corners, S_C's polygons are convex).
//
// Claim. If every triangle of the mesh with a part in C and every triangle
// of P face along n ((b - a) x (c - a) . n > 0), then
//   E(P) <= sqrt(t^2 + delta^2),  delta = max over chords of delta_c.
//
// Proof. Degree: for a compact oriented piecewise-linear surface F with
// boundary curve dF and a point x of the plane off pi(dF), the signed count of
// F's points over x is the winding number w(pi(dF), x); where every triangle of
// F faces along n each point over x counts +1, so F has a point over x exactly
// where w(pi(dF), x) >= 1 (where w != 0, F has one whatever its triangles'
// facing). Let L_T be the chord polygon of each loop traversed as T is (the
// loop itself, or it reversed - the same for every loop, since loops and fans
// alike take their orientation from the solid's inside (BoundaryLoops.h); the
// argument needs no more). As 1-cycles T - L_T = sum over chords of C_c, C_c =
// A_c followed by c backwards, so
//   w(T, x) - w(L_T, x) = sum_c w(C_c, x).                            (1)
// A point x with w(C_c, x) != 0 lies in the convex hull of pi(C_c); every
// point of A_c is within delta_c of c, so pi(C_c) lies in the delta_c-
// neighbourhood of the segment pi(c) (pi is 1-Lipschitz), which is convex:
// x is within delta_c of pi(c).                                        (2)
// Such an x is also within delta_c of pi(A_c): let q be the point of pi(c)
// nearest x. If x = q, x = pi(u) for a point u of c = [a, b], and the arc,
// connected from a to b, projects onto the line ab over all of [a, b]: a
// point w of A_c projects onto u, |w - u| = d(w, line) <= delta_c. Else the
// ray from x away from q gets farther from pi(c) at unit rate (q stays the
// nearest point of a convex set) and must meet pi(C_c), since x is wound
// around: not on pi(c), so at pi(w) for a point w of A_c, at most delta_c
// from pi(c), hence at most delta_c from x.                            (3)
// - S_C to P. Take y of S_C over x = pi(y), x generic (off the projections
//   of every edge and corner: such y are dense in S_C, since no triangle
//   faces across n, and d(., P) is continuous). S_C's triangles face along
//   n, so w(T, x) >= 1. If w(L_T, x) != 0, P has a point p over x, and
//   |y - p| = |h(y) - h(p)| <= t. Else by (1) some w(C_c, x) != 0, and by
//   (2) a point u of c (in P) has |pi(u) - x| <= delta_c: |y - u|^2 <=
//   delta_c^2 + t^2. (A point of S_C on C's faces - a triangle touching a
//   face - is a point of T, within delta_c of its chord.)
// - P to S_C. Take p of P over a generic x. P's triangles face along n, so
//   w(L_T, x) != 0. If w(T, x) != 0, S_C has a point y over x: |p - y| <= t.
//   Else by (1) some w(C_c, x) != 0, and by (3) a point w of A_c (in S_C's
//   closure) has |pi(w) - x| <= delta_c: |p - w|^2 <= delta_c^2 + t^2.
// Several loops change nothing above (T and L_T are sums over the loops). A
// closed piece of S inside C would count 0 over every point: it cannot face
// along n everywhere, so the facing test leaves none.
//
// Loops refining the cell's own (the extraction's final loops,
// FinalLoopRefines in MeshCellError.h). Where crack patching replaced each
// chord c = [a, b] by a polyline lambda_c from a to b through points of S on
// c's tile, every point of lambda_c is within delta_c of [a, b] too (its
// corners are, and that neighbourhood is convex). With C_c = A_c followed by
// lambda_c backwards, (1) and (2) hold as they are. Both lambda_c and A_c
// run from a to b, so each projects onto the line of pi(c) over all of
// pi(c) (where pi(a) = pi(b), pi(a) is a point of both): a point x within
// delta_c of pi(c), at q, has a point of each within delta_c of q, so within
// 2 delta_c of x. The two cases above go through with 2 delta_c for
// delta_c: E(P) <= sqrt(t^2 + 4 delta^2) - the caller passes 2 delta as the
// chords' reach. (Where the final loop is the own loop, delta.)
//
// Why it helps. Where S_C is nearly flat across a cell - most cells of a
// scan or a CAD part's faces at their largest size - t and delta are the
// error's own scale, and the bound settles what a branch and bound
// (PolygonHausdorff.h) would, at the cost of a pass over S_C's corners: on
// armadillo at 1/128 three quarters of the subdivision's passing
// predictions and of the extraction's loop-point fans (MeshCellError.h:
// Slab bound), 7 % of a run's time.
//
// Which n. Any direction the triangles face along proves a bound: two are
// tried, S_C's area-weighted mean normal and the normal of the plane
// fitted to S_C's corners (least squares: the thinnest slab's direction for
// a flat S_C, 6 % thinner on average where the first fails), and the
// smaller bound kept.
//
// Local heights. Where the slab is too thick - S_C curved across the cell -
// the same degree argument bounds each point by what lies over and beside
// it: LocalHeights.h, tried along the directions that face.
//
// Rounding. Facing is decided with a margin of 1e-9 |b - a| |c - a|, a million times
// the rounding of the computed triple product (about 16 units in the last
// place of |b - a| |c - a|; b - a is rounded relative to itself), so a sign
// read is the sign; a triangle within the margin of edge-on refuses the
// bound. The mesh's triangles are tested on their exact corners, P's on its
// computed ones (P is what is drawn). The heights are rounded within a few
// units in the last place of the coordinates, and S_C's clipped corners
// within a few hundred: the caller's slack (RoundingSlack, MeshCellError.h)
// is added, as to the branch and bound's E(P).
#pragma once

#include "ConvexPolygons.h"
#include "LocalHeights.h"
#include "MeshSolid.h"
#include "PolygonHausdorff.h"

#include <cmath>
#include <vector>

namespace tpc
{

/// E(P) <= sqrt(t^2 + r^2) + slack (header) for the patch `patch` against
/// S_C `surface` - clipped from `mesh`'s triangles `surfaceTriangles`, one
/// per polygon (SurfaceInCell's `triangles`) - with `chordReach` r the
/// largest delta_c of the patch's chords (twice that of the cell's own loop
/// where the patch's loops refine it: header); where that is above `enough`
/// and `chords` are given, the smaller of it and the local heights' bound
/// max(G, D_S, D_P) + slack (LocalHeights.h), which stops once found above
/// `giveUp`.
/// +inf where a triangle of either faces along neither direction tried (or
/// S_C is empty, or the lists disagree in size), and no bound is proven.
double SlabPatchError(const MeshSolid& mesh, const TriangleList& surfaceTriangles, const PolygonSet& surface,
  const std::vector<SourceTriangle>& patch, double chordReach, double slack, const OwnChords& chords = {},
  double enough = HUGE_VAL, double giveUp = HUGE_VAL);

} // namespace tpc
