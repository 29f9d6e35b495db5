// Certified decimation: fewer triangles, and everything the extraction proved
// still true of the surface the user receives.
//
// The cells bound the output's error cell by cell, and a cell's patch has a
// vertex wherever the surface crosses one of its faces: along a flat face of
// a CAD part, or a straight crease, the patches of many cells draw what a few
// triangles would. This pass removes vertices by half-edge collapses (v moves
// onto a neighbour u; v's triangles that hold u vanish, the others take u for
// v), each one kept only when it is certified, so that the guarantee covers
// the decimated surface.
//
// Error. Each triangle t carries a bound e_t with (TriangleErrorBounds.h)
//   (a) every point of t is within e_t of the exact surface S, and
//   (b) every point of S is within e_t of some triangle t.
// A collapse replaces the star O of v (its triangles, with bounds e_o) by the
// new triangles N, which span the same boundary (the link of v). Let
//   h1 = max over o in O, y in o of  e_o + d(y, N)
//   h2 = max over x in N of  min over o in O of  d(x, o) + e_o
// (PolygonHausdorff.h bounds both from above, with offsets), and give every
// triangle of N the bound e_N = max(h1, h2) + rounding slack. Then (a) holds
// for N: a point x of N is within d(x, o) of a point of o, which is within
// e_o of S. And (b) still holds: a point s of S whose witness t was in O is
// within e_o of a point y of o, and y is within h1 - e_o of N. Triangles
// outside O keep their bounds and their witnesses. So by induction, after
// any number of collapses, the two-sided Hausdorff distance between S and
// the surface is at most the largest e_t; a collapse is kept only when
// e_N <= the tolerance. (Bounds grow as collapses compound - each e_N is at
// least the e_o it replaces - and the tolerance caps them.)
//
// Against the mesh. Bounds carried through collapses only grow, and the
// cells' bounds start near the tolerance (a cell is accepted as large as its
// certified error allows), so few collapses fit. Where S is one input mesh,
// each collapse is instead certified against S itself, with the invariant
// (a) every point of every triangle within B of S, (b) every point of S
// within B of the surface, B = the largest bound so far (the cells', then
// each kept collapse's). A collapse keeps (a) when
//   hA = max over x in N of d(x, S)   (targets: S's triangles near N)
// is at most the tolerance. For (b), only points s of S whose nearest point
// on the surface was in O can lose it; they lie within B <= tolerance of O,
// so in O's box grown by the tolerance, R. A collapse keeps (b) when
//   hB = max over s in S clipped to R of d(s, surface after)
// is at most the tolerance, with targets N and every other live triangle
// that meets R grown by the tolerance (a point within the tolerance of s
// lies there). B becomes max(B, hA, hB) + rounding slack. No bound
// accumulates: each collapse is measured against S.
//
// Witnesses. Most of S near a star is nearest to triangles outside it, and
// measuring it again at every collapse nearby was most of (b)'s work. When
// (b) settles a whole triangle s of S by one triangle w after the collapse
// (the single-target bound of PolygonHausdorff.h: every point of s within
// b_s <= the tolerance of w; b_s goes into B), w becomes s's witness. As long
// as w is alive and outside the star being collapsed, w is unchanged (only
// the star's triangles change), so s keeps b_s and (b) skips it. Every s
// whose witness is in the star lies in R (within the tolerance of w, inside
// the star's box), so (b) measures it again and gives it a new witness or
// none; a triangle of S without one (measured in pieces, or clipped to R) is
// measured by every collapse whose R it meets, as before. Only S's
// triangles whose coverage may change are measured. A skipped s would settle
// within the tolerance anyway, so the decisions are those of measuring all
// of S in R but for the branch and bound's budget and early stop, which see
// fewer sources (a collapse may now pass that ran out of pieces before, or
// get another bound - sound either way); on the meshes measured, the same
// surfaces byte for byte (armadillo at 1/128 decimated in 3.9 s instead of
// 5.7).
//
// Embedding. The surface before is embedded (the exact check of
// SurfaceEmbedding.h; the pass does not run otherwise). A collapse is kept
// only when no triangle of N meets another one of N, or any other live
// triangle, other than in the vertices and edge they share (exact predicates,
// SelfIntersection.h; degenerate triangles refused): the candidates are all
// triangles whose boxes overlap, from a grid that never misses one
// (TriangleGrid.h). Vertices are never created or moved, so no two coincide.
// Embedded before and no new improper pair: embedded after. That is not yet
// the same solid's boundary. Let Z be O followed by N reversed, a closed
// surface: for a point off the surfaces, the winding number about the
// surface after is the one before minus w_Z, and w_Z is nonzero only in the
// pocket, which lies in the union of the tetrahedra (v, u, a, b) over the
// far edges ab of N's triangles (the chains of their boundaries sum to O
// minus N, so a point of nonzero w_Z lies in one of nonzero volume) and
// whose boundary lies in O and N. A component C of the surface other than
// the star's shares no vertex with O or N; it meets O nowhere (embedded
// before) and N only improperly (refused above), so w_Z is constant on it:
// it lies wholly in the pocket or wholly out. Out, w_Z = 0 on it and near
// it, so whatever lay inside it still does and it lies inside what it did -
// nothing changed for it. In (a small void just below the surface), it
// would end on the other side: a void outside the solid, inside out. Then
// its vertices lie in the closed tetrahedra, and a collapse is refused when
// a vertex of another live triangle lies in one (exact Orient3D; a link
// vertex is tested against the tetrahedra it is not a corner of).
// `Core.CertifiedDecimation.ASmallVoidBelowTheSurfaceStaysInside` fails
// without this test (the void ends outside the solid, the report guaranteed).
// The star's own component A: after the collapse it is a closed, connected,
// embedded surface, consistently oriented (the collapse keeps the
// orientation of every triangle it keeps), so it bounds one region
// (Jordan-Brouwer) and its normals point out of that region everywhere or
// nowhere (the set where they do is open and closed in a connected surface).
// If A has a vertex x outside the star's box, the triangles around x are
// not made by the collapse, and near x - outside the box, so outside the
// closed tetrahedra - w_Z = 0: on both sides of them the winding is as
// before, and so is the way their normals point, hence everywhere. Then a
// part of A folded into the pocket - even a triangle whose vertices are all
// corners of the tetrahedra, which the vertex test cannot see - does no
// harm. If A has none, all the rest of A may lie in the pocket and the
// collapse may turn A inside out (a bipyramid of five vertices, reflex
// along an edge, an equator vertex moved onto one apex: the tetrahedron left
// lies beyond the faces it keeps;
// `Core.CertifiedDecimation.ASmallComponentIsNotTurnedInsideOut` fails
// without this). Such an A is found by a walk over its vertices inside the
// box (a walk that meets a vertex outside stops there, most among the link's
// neighbours), and the collapse is kept only when the volume A encloses
// keeps its sign, each decided beyond its rounding bound (SolidBoundary.h,
// EnclosedVolume): A bounds its region the same way round. And the nesting
// stays: A keeps its triangles outside the star (there are always some),
// which O and N meet only in shared edges and vertices, so A lies inside
// another component exactly when it did; and another component, with
// w_Z = 0 on it, lies inside A exactly when it did.
// (`Core.CertifiedDecimation.SmallComponentsDecimateAndStayOutward`: a
// tetrahedron, and a tetrahedral void in a box, down to four triangles
// each, every component still outward.) (The vertex test also refuses a collapse where a vertex of
// A lies in the pocket: more than needed, never less.) The report checks
// the whole surface once more, every component against its nesting
// (SolidBoundary.h).
//
// Topology. A collapse of the edge uv in a closed 2-manifold preserves its
// topological type when the link condition holds: Lk(u) and Lk(v) share
// exactly Lk(uv), the two vertices opposite the edge (Dey, Edelsbrunner,
// Guha, Nekhayev, "Topology preserving edge contraction", 1999); checked on
// vertices (their common neighbours are exactly those two) and on the one
// edge they could share (both triangles u w1 w2 and v w1 w2 exist: a
// tetrahedron). Components and genus are those of the extracted surface,
// which the cells proved equal to the exact surface's.
//
// Features. Where S is one input mesh, its sharp creases (SharpCreases.h:
// input edges of 40 degrees or more) are what must stay visible: the
// extraction draws each within the tolerance of output edges bent by
// FeatureAngle or more, and a collapse is kept only when every point of a
// sharp crease within the tolerance of a feature edge the collapse removes
// (gone, or no longer bent) is within the tolerance of a feature edge after
// it (StaysFollowed, a branch and bound along the crease): a point followed
// before stays followed. Otherwise
// (CSG, several meshes) S's creases are not at hand, and the surface's own
// are kept: an edge bent by more than FeatureAngle, or between triangles on
// different solids' surfaces (labels), is a feature; a vertex on none may
// move to any neighbour, one on exactly two only along them (the crease's
// polyline loses a vertex and stays a chain), corners and ends never; every
// feature edge of the star stays one (as its image), and no collapse makes a
// new one.
//
// Order: cheapest first, the cost of moving v onto u being how far u lies
// from the planes of v's triangles (zero on a flat face and along a straight
// crease between flat faces), then the shorter edge. A vertex whose star
// changed is queued again; a refused candidate is tried again only then.
//
// Parallel. Candidates are examined in batches of up to 16, taken in the
// heap's order; one joins only if what its examination reads is untouched by
// what the batch's earlier members write, else it goes back to the heap. The
// members are examined at once (every check above reads only), then the
// certified ones applied in the batch's order. Apply(j) writes the triangles
// of its star (corners, bounds, alive), the lists of triangles around the
// star's vertices, the grid (boxes inside the star's box) and witnesses.
// Examine(i) reads the live triangles whose boxes overlap X_i, the star's box
// grown by twice the tolerance (every box its checks query lies in X_i: (b)'s
// targets, the crease check's, the embedding's), the lists around their
// vertices and the triangles across their edges (link condition, dihedral
// angles; the walk over a small component's vertices, all inside the star's
// box, and their triangles), and the witnesses of S's triangles in (b)'s
// region. Whatever of
// that j changes involves a triangle overlapping X_i (before j, or made by j)
// with a vertex in j's star - itself, the list around that vertex, or the
// triangle across one of its edges - so a triangle around a vertex of j's
// star overlaps X_i; such triangles lie in W_j, the box of all triangles
// around the star's vertices, and a candidate joins only if its X is
// disjoint from every earlier member's W. A witness i relies on lies within
// the tolerance of a triangle of S meeting (b)'s region, so it overlaps X_i
// too. And the witness entries j rewrites: X_i misses j's star, so the
// regions R_i and R_j are disjoint, and a triangle s of S meeting both is
// clipped in both, so measured by both and left without a witness by both;
// a live witness of s in j's star would lie within 2 tolerances of i's star,
// inside X_i, which the rule refuses. (Boxes are grown in the same steps as
// Examine grows them, so the rule holds to the last rounding.) So each
// member's checks see what they would after the earlier members were
// applied, and the batch's decisions, bounds and witnesses are those of
// examining and applying its members one after another: the surface does
// not depend on the number of threads. Armadillo at 1/128: 5.2 s on one
// thread, 3.0 s on two.
#pragma once

#include "MeshSolid.h"
#include "Parallel.h"
#include "ReleasableArray.h"
#include "TriangleMesh.h"

#include <cstddef>
#include <cstdint>
#include <vector>

namespace tpc
{

struct DecimationParameters
{
  /// The two-sided Hausdorff bound every collapse keeps (absolute).
  double Tolerance = 0.0;
  /// Degrees: an edge whose triangles' normals differ by more is a feature.
  double FeatureAngle = 30.0;
  /// Against the mesh, pieces the branch and bound may evaluate for each
  /// made triangle in (a), and for (b) (a collapse whose bound needs more is
  /// refused, and tried again when its star changes: a small budget refuses
  /// many that would pass, and their retries cost more than the pieces
  /// saved - measured at 1/128 with 1 024 and 512: fandisk 200 and 278
  /// triangles instead of 164, the turbine 662 and 1 038 instead of 632,
  /// couplingdown slower).
  std::size_t CertificateBudget = 4096;
  /// The same through the cells' bounds (CSG; header: Error). There most
  /// refused collapses spend the whole budget: a star whose bounds are near
  /// the tolerance leaves d(y, N) almost no room, and where N's nearest
  /// triangle changes the pieces must shrink to that room - measured on the
  /// demo CSG at 1/128 (one thread), 13 595 of 38 028 certificates ran out
  /// of 4 096 pieces, 95 % of the pieces evaluated, while 90 % of those
  /// that passed needed 512 or fewer. At 1/64, 1/128, 1/256: 4 450, 7 788,
  /// 9 224 triangles in 3.4, 7.4, 9.0 s (2 threads) with 4 096; 4 516,
  /// 7 950, 9 618 in 1.4, 2.7, 3.6 s with 1 024; 4 668 and
  /// 10 224 in 1.1, 2.7 s with 512 (at 1/64 and 1/256).
  std::size_t BoundsCertificateBudget = 1024;
  /// Told the share of candidates tried (not monotone: collapses queue new
  /// ones); true asks to stop. The surface is valid after every collapse, so
  /// stopping early leaves a surface for which everything above holds.
  ProgressCallback Progress;
  /// (For tests.) Examines each member of a batch again once the earlier
  /// ones are applied, counting those whose verdict, bound or witnesses
  /// differ (header: Parallel; there should be none).
  bool CheckBatches = false;
};

struct DecimationResult
{
  std::size_t TrianglesBefore = 0;
  std::size_t TrianglesAfter = 0;
  std::size_t Collapses = 0;
  /// Candidates refused, by the first condition that failed.
  std::size_t RefusedByFeature = 0;   ///< a sharp crease no longer followed; or a feature rule
  std::size_t RefusedByLink = 0;      ///< the link condition
  std::size_t RefusedByShape = 0;     ///< a triangle degenerate or turned over
  std::size_t RefusedByError = 0;     ///< e_N beyond the tolerance
  std::size_t RefusedByEmbedding = 0; ///< a new triangle meets another improperly
  bool Aborted = false; ///< Progress asked to stop (the surface is still valid)
  /// The surface given is not a closed, consistently oriented manifold (the
  /// link condition, the pocket test and every certificate above assume
  /// one): nothing was done.
  bool NotAClosedManifold = false;
  std::size_t BatchDisagreements = 0; ///< with CheckBatches
  /// B: the two-sided Hausdorff distance between S and the decimated surface
  /// is at most this (with the cells' bound before it: the larger of the two).
  double Bound = 0.0;
};

/// The exact surface S itself, where it is one closed input mesh (the
/// scene's expression is one mesh leaf, not capped by Bounds): collapses are
/// then certified against S directly (header: Against the mesh) instead of
/// through the bounds they inherit.
struct ExactMesh
{
  const MeshSolid* Mesh = nullptr;
};

/// Decimates `mesh` (closed, oriented, manifold, embedded) in place; not at
/// all when a triangle's bound already exceeds the tolerance, nor when the
/// mesh is not a closed, consistently oriented manifold (checked on the
/// mesh: NotAClosedManifold; whether it is embedded is the caller's exact
/// check, SurfaceEmbedding.h).
/// `bounds` holds e_t per triangle (header; TriangleErrorBounds.h), `labels`
/// the solid each triangle lies on (edges between labels are features); both
/// are compacted with the triangles, as is mesh.TriangleCell (each triangle
/// keeps the cell of the patch it descends from). Vertices no triangle uses
/// any more are dropped.
DecimationResult DecimateCertified(TriangleMesh& mesh, std::vector<double>& bounds,
  ReleasableArray<std::int32_t>& labels, const DecimationParameters& parameters, const ExactMesh& surface = {},
  const ParallelFor& parallelFor = SequentialFor);

} // namespace tpc
