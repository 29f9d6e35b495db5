// Certified per-cell error where one quadric is the surface (issue 17;
// replaces the paper's 5.3.4 size criterion there).
//
// The paper bounds the two-sided Hausdorff distance by the cell's size: the
// surface S and the patch P both lie in the cell C. What matters is their
// distance, and where the solid in C is one quadric leaf it can be bounded
// from the quadric's shape and the patch's geometry, so a surface cell may
// stay larger than the tolerance wherever that bound is below it.
//
// Setting. f(x) = x'Ax + b'x + c (sign sigma applied, the solid is f < 0), A
// the half Hessian. C+ is C grown by the margin m (the tolerance) on every
// side; the expression pruned to C+ is the single leaf, so S ∩ C+ is the zero
// set of f there. Chosen: a unit direction n (the gradient at C's centre) and,
// for each face phi of C that may meet S, a unit direction m_phi in phi's
// plane (the gradient there with its normal part removed).
//   g      = min over C+ of grad f . n      (> 0 required)
//   g_phi  = min over phi of grad f . m_phi (> 0 required where phi meets S)
//   ||A||  <= min(max absolute row sum, Frobenius norm) of A
// grad f is affine, so grad f . n is affine and its minimum over a box (a
// rectangle) is at a corner; written G . x + h, each coordinate once, its
// interval extension over the box (Quadric::EncloseDirectionalDerivative)
// encloses that range, so these are proven lower bounds. (1) f increases at
// rate >= g along n throughout C+, and along m_phi within phi.
//
// The quadratic's interpolation error. For a triangle or segment with
// vertices v_i and a point x = sum l_i v_i (l_i >= 0, sum 1), expanding f at x
// gives exactly sum l_i f(v_i) - f(x) = sum l_i (v_i - x)'A(v_i - x), so
//   |f(x)| <= max |f(v_i)| + ||A|| sum l_i |v_i - x|^2 <= max |f(v_i)| + ||A|| R^2,
// R the radius of the smallest ball around the vertices (sum l_i |v_i - o|^2
// is smallest at o = x, and <= R^2 at that ball's centre); R = L/2 for a
// segment of length L. (2)
//
// The bound. Let F_T be (2) for a patch triangle T and F_ab for a chord ab of
// the patch's loop on face phi, and
//   E_C = max( max_T F_T / g,  max_ab F_ab (1/g + 1/g_phi) ),
// required <= m. Then every point of P_C is within E_C of S, and every point
// of S ∩ C within E_C of the output:
// - Patch to surface. x in P_C has |f(x)| <= F_T; by (1) f vanishes on the
//   segment from x along -sign(f(x)) n of length |f(x)|/g <= m, inside C+.
// - Surface to patch. Let y in S ∩ C and l the line through y along n; it
//   leaves C at e- below and e+ above, where f(e-) <= 0 <= f(e+) by (1). Call
//   a point of the boundary of C discretely inside when it is on the inside
//   side of the patch's loop L there. (a) If e- is discretely inside and e+
//   discretely outside, l crosses the patch (a union of discs spanning the
//   loops, which separates C into the loops' sides) at some x in C, and by (1)
//   |x - y| <= |f(x)|/g <= F_T/g. (b) Otherwise one end, say e+, has the wrong
//   side: it lies on a face tile whose chord ab (the tiles passed the face
//   tests: one chord per tile, and the surface crosses the tile in one arc
//   whose ends are the chord's, up to the crossings' rounding, which |f(a)|
//   covers) separates it from the arc, i.e. between the arc and the chord. On
//   the line through e+ along m_phi, f is monotone within the tile (1): it
//   meets the arc once and the chord once, at z_c, and the disagreement of the
//   two sides along it is the stretch between them, so |f(e+)| <= |f(z_c)| <=
//   F_ab and |e+ - z_c| <= F_ab/g_phi. Then |y - e+| <= f(e+)/g by (1), and
//   d(y, P) <= F_ab/g + F_ab/g_phi.
// The certified value is computed on the final patch (CellPatches.h), after
// crack patching, and the subdivision's prediction bounds it for any patch
// whose vertices lie on S in C, whatever the final loop: R <= D/2 (every
// triangle in C lies in C's circumscribed ball, D the diagonal), L <= the
// face's diagonal.
//
// Local rises. g and g_phi are minima over all of C+ and of the whole face;
// each term needs the rise only where its segments run. A triangle's: the
// segments along n of length <= |F|/g from its points (patch to surface;
// surface to patch, (a)), which lie in its box grown by F_T/g - inside C+
// when F_T/g <= m, else the term fails anyway. A chord's: the stretch
// between it and its arc along m_phi, within its box grown by F_ab/g_phi in
// the face (each arc point is within that of the chord, below), and the
// segments along n from there into C, of length <= F_ab/g. grad F . d is
// affine, so its range over each such box is that of its corners, as for g,
// and written G . x + h its interval extension gives it up to rounding in
// one evaluation (Quadric::EncloseDirectionalDerivative, for g and g_phi
// too): a triangle's term is F_T/g_T and a chord's F_ab (1/g_ab + 1/g_phi,ab)
// with those minima, each at least the global one (TriangleError,
// ChordError). On a sphere of radius 40 tolerances this took the output
// from 2 562 to 2 280 triangles, the rotated ellipsoid of
// Core.QuadricCellError's tests from 3 176 to 2 740.
//
// Predicted on the cell's own loop. The bound for any patch takes R = D/2
// and chords as long as a face's diagonal, where a cell's own fan has far
// smaller triangles: a sphere of radius 18 tolerances came out as 1 894
// triangles on it alone, 906 with what follows. A cell larger than the
// tolerance whose bound for any patch fails (by at most FanPredictionReach
// times, McCompatibility.cxx) goes through the topology tests, and passes
// if the fan around a fixed
// apex c over its own loop L - one chord ab per face tile, its points on S -
// is bounded within the tolerance for every loop refining L
// (PredictFanTerms): a loop L' that replaces each chord ab of a tile t by
// points a = q_0, .., q_r = b of S's arc in t, as crack patching's final
// loop does where its tiles nest in t (t, which passed the face tests, holds
// one arc of S from a to b; where they do not, below). Then:
// - The arc is within delta_ab = F_ab / g_phi of [a, b]: F rises at rate
//   >= g_phi along m_phi on the face (g_phi > 0), so each line along m_phi
//   meets S at most once in t, and the arc, connected from a to b, is a
//   graph over the axis u across m_phi spanning a's u to b's - as does the
//   chord. An arc point y and the chord point z at its u lie on one line
//   along m_phi, inside t (convex), F(y) = 0 and |F(z)| <= F_ab (the
//   chord's enclosure, (2)): |y - z| <= F_ab / g_phi.
// - A triangle (c, q_i, q_i+1) lies within delta_ab of (c, a, b) - its
//   vertices do - so in that triangle's smallest ball grown by delta_ab: its
//   R is at most R_abc + delta_ab. A sub-chord (q_i, q_i+1) is at most
//   |ab| + 2 delta_ab long (each end is a point of [a, b] moved by at most
//   delta_ab).
// So the certificate's terms (the formulas above, on L') are at most those
// of (c, a, b) and ab with these lengths, plus the vertices' |F|, with the
// local rises over the boxes of (c, a, b) and ab grown by delta_ab (which
// hold the refining pieces' boxes; delta_ab itself from the local g_phi,
// the stretch from an arc point to the chord lying in the chord's), where the
// own loop's largest |F| stands for the final points' (placed alike, by root
// finding on sub-edges, to the last bits: the prediction only decides; the
// guarantee rests on the certificate of the final patch). The apex c is the
// point of S along n from L's centroid (or C's centre), 1/32 of C's width
// inside it: strictly inside, so the fan over any simple loop is embedded
// (LoopTriangulation.h, case 1). The extraction draws its usual patch and
// certifies it; where that is not within the tolerance it draws the fan
// around c (AdaptiveOctree::QuadricFanApexes) over the final loop and
// certifies that. Tested: Core.QuadricCellError.FanPredictionBoundsTheFan
// OverLoopsRefiningItsOwn, chord by chord on a sphere, a saddle and a
// hyperboloid (the conic arcs there stay within the triangles' own balls:
// the delta allowance is for the argument, not attained).
// Where the final loop does not refine L. Crack patching keeps a face's
// tiling only where the cell across it is no finer: a finer neighbour's
// tiles replace it, and they nest in the cell's own only where those were
// split at midpoints - face refinement may split a tile at a lattice point
// of the other sign or a sample inside it (FaceRefinement.cxx) - and two
// same-size neighbours' tilings that do not nest keep the first
// (MergeFaceTilings). There the final loop may skip points of L, and its
// fan's certificate may exceed the prediction (a reviewer, over 281 000 own-
// fan cells of random CSG scenes: 233 such loops, at most 24 % over the
// prediction, none beyond the tolerance). The prediction then only decides
// the cell's size; the certificate of the patch drawn is what the report
// rests on, and a cell whose patch it fails is reported, not hidden
// (ExtractionResult::UncertifiedCells) - and split when the subdivision
// runs again (CellRepair.h). A reviewer's 3 800 random CSG runs had one: a
// crease cell whose final half chord's term, 1.57 tolerances, exceeded the
// margin. The same holds for the bound for
// any patch's statement above that crack patching only refines: it does
// not need it (R and chords are bounded by the cell whatever the loop).
//
// A plane (A = 0) gives zero: the patch is then the plane section
// (PlanarCell.h says the same for several planes and flat meshes).
//
// Beside a crease (several quadrics within the margin). Where the cell's own
// expression is one quadric leaf but another primitive lies within the
// margin - the band of cells along every crease of a CSG scene, which the
// proof above would make as small as the tolerance - or is several quadric
// leaves of which no two vanish at a common point of C (NoCommonZero:
// enclosures on sub-boxes; then S ∩ C splits into pieces on one leaf each,
// since pieces on two leaves meet only where both vanish, and each loop's
// disc lies on one leaf), the same proof holds
// word for word for F, the value of the expression pruned to C+, when that
// is one intersection (max) or one union (min) of quadric leaves
// sigma_i f_i (a difference is an intersection with a complement: a box's
// face and a sphere, a plate and a cylinder hole, two cylinders), provided
// every leaf rises along n:
//   g = min over leaves i and over C+ of grad(sigma_i f_i) . n > 0,
// n the cell's own leaf's normal at C's centre, or the sum of all the
// leaves' unit normals there (the crease's bisector), whichever gives the
// larger g (two faces of a thin plate, normals opposite, have none). Then
// F(x + t n) - F(x) >= g t for t > 0 (a max or min of functions that each
// rise at rate g rises at rate g), which is all (1) is used for, and S ∩ C+
// is the zero set of F (F < 0 below, > 0 above every zero along n). On a
// face, likewise along m_phi (the bisector of the projected normals) with
// F_phi, the expression pruned to the face: its sign is F's there, and
// |F| <= |F_phi| (pruning a max drops leaves negative on the face, a min
// leaves positive there), so the chord argument's bounds on F_phi hold.
// The interpolation error (2) becomes: each leaf's value over a triangle or
// chord lies in [min_i sigma f(v_i) - ||A|| R^2, max_i sigma f(v_i) + ||A|| R^2]
// (||A|| the largest of the leaves'), and the max (min) of these intervals
// encloses F there; its magnitude is F_T (F_ab) - for one leaf, at most
// max |f(v_i)| + ||A|| R^2 as above. A patch's vertices lie on S in C, on
// its loop's leaf, where every other leaf is on the side where
// it does not decide F (<= 0 in a max, >= 0 in a min, since F = 0), and so
// are their interpolations: F of the interpolated values is 0, so the
// prediction below (||A|| R^2 / g) bounds every patch on S in C here too.
//
// In a crease cell (its own expression two quadric leaves whose zero sets
// may meet in it: `creases`, cells larger than the tolerance only). The
// same holds for a patch made of sectors: the fan around a point c of the
// crease (CreaseApex: f1 = f2 = 0, so F(c) = 0) over a loop drawn through
// the crease's crossings x of the face tiles it crosses (CSG crease tiles,
// CsgCreaseCrossing.h). Then every triangle (p, q, c) has p and q on one
// leaf's zero set - x is on both - and so has c: its vertices lie on S and
// on one leaf, which is what the prediction needs. On a crease tile the
// trace is two arcs, a to x on one leaf and x to b on the other, each with
// its chord: the argument of (b) holds for each half (F is monotone along
// m_phi, the bisector, on the whole tile). Whether the patch will be that
// is decided before the cell is accepted: the subdivision draws the cell's
// own loop as the extraction draws it and requires the fan around CreaseApex
// over it to be certified within the tolerance (McCompatibility.h); the
// extraction then draws that fan over the final loop (crack patching adds
// points on the same arcs where its tiles nest in the cell's own - see
// "Where the final loop does not refine L" - and the tiles a finer
// neighbour cut are decided with the crease cell's expression,
// CrackPatching.h) and certifies it again. Where the bound for any patch fails (by at most
// FanPredictionReach times), the crease fan is predicted over its own loop
// as for one quadric (Predicted on the cell's own loop): the crease's
// crossings x are points of that loop, each half chord a -> x, x -> b lies
// on the tile's face with the trace's half from a to x - the trace is one
// graph over u, F rising along m_phi on the whole tile - so the half is
// within F_ax / g_phi of its chord, and the argument holds half by half.
// Where a final tile loses its crossing after all (the crease
// within a millionth of a sub-tile's side), the chord cuts the corner and the
// certificate - computed with the formulas above, which hold for any patch -
// says so: the cell's bound exceeds the tolerance and the guarantee is not
// claimed.
#pragma once

#include "CsgExpression.h"
#include "Quadric.h"

#include <optional>
#include <vector>

namespace tpc
{

struct QuadricCellError
{
  /// At most this many leaves (a corner of three faces, with a fourth
  /// primitive near it).
  static constexpr std::size_t MaximumFields = 4;
  Box3 Cell;
  double Margin = 0.0; ///< C+ is Cell grown by this on every side
  /// The leaves' quadrics with their signs, sigma_i f_i; the solid is where
  /// their max (intersection) or min (union) is negative.
  std::vector<Quadric> Fields;
  bool Union = false;
  Vec3 Direction;      ///< n
  double Rise = 0.0;   ///< g
  double Curvature = 0.0; ///< upper bound of ||A_i||_2 over the leaves
  /// Per face (CubeTopology.h numbering, 2 axis + side): m_phi and g_phi,
  /// g_phi = 0 where the face may meet S but F is not monotone along m_phi
  /// on it, +inf where the face provably misses S; the leaves of the
  /// expression pruned to the face (bit i: Fields[i]).
  Vec3 FaceDirection[6];
  double FaceRise[6] = { 0, 0, 0, 0, 0, 0 };
  unsigned FaceFields[6] = { 0, 0, 0, 0, 0, 0 };
  /// A crease of the cell's two leaves (CreaseLeaves) may cross the cell: its
  /// patch must be the fan around CreaseApex, over a loop through the
  /// crease's crossings (header: In a crease cell).
  bool Crease = false;
  CsgLeaf CreaseLeaves[2];
};

/// `cell` grown by `margin` on every side, rounded outward (C+ above: it holds
/// the exact grown cell).
Box3 GrownByMargin(const Box3& cell, double margin);

/// The setting above for `cell` when the scene's expression pruned to the
/// cell grown by `margin` is a single quadric leaf, or one intersection or
/// union of at most MaximumFields of them, and g > 0; nothing otherwise.
/// `cellExpression` is the scene's pruned to the cell (as the octree keeps
/// it): unless it is a single quadric leaf, or several with no crease in the
/// cell, nothing is looked at further.
/// (It cannot stand for the scene's: another primitive may lie outside the
/// cell but within the margin.) `nearExpression` is the scene's, or any
/// expression equal to it on the grown cell (GrownByMargin): the scene's
/// pruned to a box holding the grown cell (AdaptiveOctree::NearExpression),
/// which saves an enclosure per leaf of a scene of many primitives.
/// `creases`: a cell whose own expression is two quadric leaves whose crease
/// may cross it is bounded too (Crease set).
std::optional<QuadricCellError> BoundQuadricCell(const CsgExpressionPtr& cellExpression,
  const CsgExpressionPtr& nearExpression, const PrimitiveSet& primitives, const Box3& cell, double margin,
  bool creases = false);

/// The apex of a crease cell's fan: the point of the crease Gauss-Newton
/// steps reach from the cell's centre, if it lies 1/32 of the cell's width
/// inside it (it depends on the cell and its leaves only, so the subdivision
/// and the extraction find the same).
std::optional<Vec3> CreaseApex(const QuadricCellError& bound, const PrimitiveSet& primitives);

/// The chord term of the edge ab if it lies in a face of the cell (the larger
/// one for an edge on two faces), 0 otherwise - a spoke to an inner apex.
/// (So a loop's points must lie exactly on their faces' planes, as
/// PlaceSubEdgeCrossing and CsgCreaseVertex put them: a chord read as
/// inner would lose its term.)
double EdgeChordError(const QuadricCellError& bound, const Vec3& a, const Vec3& b);

/// E_C of the fan around `apex` over the closed polyline `loop` (points on
/// the cell's faces): its triangles' terms and its chords' on the faces they
/// lie in; +inf beyond the margin.
double FanError(const QuadricCellError& bound, const std::vector<Vec3>& loop, const Vec3& apex);

/// An upper bound of E_C of the fan around `apex` over any loop that refines
/// `loop`, the cell's own (one chord per face tile, its points on S): each
/// chord ab replaced by points of the arc of S in its tile from a to b, as
/// crack patching does where its tiles nest in the cell's (header: Predicted
/// on the cell's own loop); up to the rounding of the final points, for
/// which the own points' stand (so a decision, not a certificate). +inf
/// where a chord lies on no face or on one without a rise.
double PredictedFanError(const QuadricCellError& bound, const std::vector<Vec3>& loop, const Vec3& apex);

/// PredictedFanError's terms for the part of the fan over one chord of
/// `loop` (chord k from loop[k] to loop[k + 1]): at least TriangleError of
/// every triangle around `apex` over a refinement of the chord, and
/// EdgeChordError of every sub-chord of it.
struct PredictedChordTerms
{
  double Triangles = HUGE_VAL;
  double Chords = HUGE_VAL;
};
std::vector<PredictedChordTerms> PredictFanTerms(
  const QuadricCellError& bound, const std::vector<Vec3>& loop, const Vec3& apex);

/// An upper bound of E_C for any patch whose vertices lie on S in the cell
/// (the subdivision's acceptance test); +inf when a face that may meet S has
/// g_phi <= 0.
double PredictedCellError(const QuadricCellError& bound);

/// F_T / g for the patch triangle (a, b, c).
double TriangleError(const QuadricCellError& bound, const Vec3& a, const Vec3& b, const Vec3& c);

/// F_ab (1/g + 1/g_phi) for the chord ab lying in face `face`; +inf where
/// g_phi is not positive.
double ChordError(const QuadricCellError& bound, int face, const Vec3& a, const Vec3& b);

/// The exact sign of F at p (-1 inside the solid, 0 on S, 1 outside).
int ExactSign(const QuadricCellError& bound, const Vec3& p);

/// The point of S on the line through `p` along n inside `region` (part of
/// the cell), found by bisection on the exact sign; nothing when the line
/// does not cross S there.
std::optional<Vec3> SurfacePointAlongDirection(const QuadricCellError& bound, const Vec3& p, const Box3& region);

} // namespace tpc
