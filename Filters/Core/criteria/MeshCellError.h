// Certified per-cell error where one mesh is the surface (issue 17; replaces
// the paper's 5.3.4 size criterion there, as QuadricCellError.h does for one
// quadric).
//
// Setting. The scene's expression pruned to the cell C is a single mesh leaf,
// so the exact surface in C is S_C = the union of the convex polygons tau ∩ C
// over the leaf's listed triangles tau (a superset of those meeting C). The
// patch predicted is a fan around an apex c that depends on S_C and C only
// (MeshCellApex below; the extraction may draw a fan from a loop point
// instead, certified on its own - by the slab bound from the prediction's
// chords or a branch and bound - SurfaceExtraction.cxx): the triangles
// (p_k, p_k+1, c) over the cell's loop p_0 .. p_m-1, whose points are surface
// crossings on lattice sub-edges in C's faces, each on the crossed
// triangle's plane, i.e. on S up to rounding.
//
// The error. Both the patch P and S_C are unions of convex planar polygons, so
// their two-sided Hausdorff distance
//   E(P) = max( h(P, S_C), h(S_C, P) )
// is bounded by branch and bound (PolygonHausdorff.h). It is the cell's
// error: every point of the output in C (P) is within h(P, S_C) of S, and
// every point of S in C within h(S_C, P) of the output; every point of S lies
// in a cell, every point of the output in a patch.
//
// The subdivision's prediction, before crack patching. The cell's own loop L
// has one chord ab per face tile it crosses. Crack patching (BoundaryLoops.h)
// samples C's faces as their finer neighbours do; their tiles subdivide C's,
// so in the final loop L' each chord ab of a tile t becomes a polyline
// a = q_0, .., q_r = b of crossings on sub-edges inside t, all on S ∩ t. Let
//   delta = max over chords ab of max over S ∩ t of d(., [a, b]),
// computed exactly on S's polygons clipped to t (d(., [a, b]) is convex, so
// its maximum over a polygon is at a vertex). The final patch P' is the fan
// around the same c (the extraction takes the prediction's, and keeps the
// prediction's bound only where it drew the fan around it unchanged,
// FinalLoopsRefine in SurfaceExtraction.cxx). Then
//   E(P') <= E(P) + delta:
// - P' to S. x in P' is c + s (w - c), 0 <= s <= 1, w on a sub-chord
//   [q_i, q_i+1]; both ends are within delta of [a, b], hence so is w
//   (convexity): |w - u| <= delta for some u in [a, b]. x' = c + s (u - c) is
//   in P's triangle (a, b, c) and |x - x'| = s |w - u| <= delta, so
//   d(x, S) <= d(x', S) + delta <= h(P, S_C) + delta.
// - S to P'. For y in S_C take x' = c + s (u - c) in P with |y - x'| <=
//   h(S_C, P), u in a chord [a, b]. The polyline from a to b is connected and
//   its projection on the line ab runs from a to b, so some w on it projects
//   onto u; then |w - u| is w's distance to the line, which is its distance
//   to the segment (the projection u lies in it), <= delta. x = c + s (w - c)
//   is in P' and |x - x'| <= delta.
// Per chord. Both steps move a point by at most the delta of one chord, the
// one whose fan triangle T_ab = (a, b, c) it was taken in: with delta_ab the
// deviation of chord ab alone,
//   h(P', S_C) <= max over ab of ( h(T_ab, S_C) + delta_ab ),
//   h(S_C, P') <= max over y in S_C of min over ab of ( d(y, T_ab) + delta_ab )
// (for y, x' is taken in the T_ab attaining the minimum). Both are offset
// distances that OneSidedHausdorff bounds (PolygonHausdorff.h: Offsets), and
// each is at most E(P) + delta. It is tried where E(P) + delta fails and the
// chords' deltas differ: a chord that strays far from a trace the fan's other
// triangles meet closely (a fillet cut by one chord, a crease tile's half)
// no longer adds its delta to the whole fan's error. Its bound is also a
// bound of E(P) (the offsets are >= 0).
// Crease tiles (CreaseCrossing.h). In a scene of one mesh the subdivision's
// loop draws a crease tile t as the extraction will, a -> x -> b through the
// crossing x of its sharpest edge, and delta is taken for each half: the trace
// S ∩ t is one arc from a through x to b, the polyline through the mesh edges'
// crossings, so its largest distance from [a, x] over the half from a to x is
// at those crossings (CreaseChordDeviation). Every sub-tile of t holding x is
// a crease tile through x (the same edges, fewer of them - x is still the
// sharpest - and x was placed as decided, so inside every tile the exact tests
// put it in, MeshArrangement.h), and every other sub-tile holds pieces of one
// half (where one holds another sharp edge of that half, as a narrow chamfer's
// second edge or a fillet's step, it may be drawn through that edge's
// crossing: a point of the half too); so the final loop replaces a -> x and
// x -> b by points of the half each spans, and the argument above holds half
// by half. Where the extraction draws t straight after all (a neighbour holding
// another leaf, or a coarser face tiling from crack patching), the final loop
// lacks x or another point of the cell's loop: FinalLoopRefines refuses the
// prediction and the final patch is certified on its own.
//
// So a cell is accepted when E(P) + delta or the per-chord bound is within
// the tolerance, and the final patch is certified again on its own (usually
// tighter: its loop follows S closer); the filter reports the smaller of the
// two. Where the final loop
// is the cell's own loop, point for point (SameLoop), P' is P, triangle for
// triangle, and the bound of E(P) the prediction proved is P's certificate
// (kept as it is where it is within what the first certificates aim at).
//
// Crease apexes. In a scene of one mesh the accepted fan must also draw the
// cell's creases (CreaseFollowing.h). The apex S_C's planes give lands on a
// crease or corner where one is alone in the cell; beside a second crease (a
// chamfer, a groove, a fillet's step) it lands between them and its fan cuts
// across one. Where the fan around it is within the tolerance but misses a
// crease, the fans over the same loop around other apexes are tried, each a
// point of a crease - each crease segment's point nearest that apex, kept
// 1/32 of the cell's width inside it as MeshCellApex keeps its own, nearest
// first - and the first that follows every crease with E(P) + delta within
// the tolerance replaces the apex (PredictCreaseApex); the cell splits
// (CreaseNotFollowed) only when none does. Nothing above depends on which
// apex: E(P') <= E(P) + delta holds for the fan around any fixed c over a
// final loop refining the cell's own, the extraction draws the fan around
// the prediction's apex, and a c strictly inside the cell keeps the fan
// embedded (LoopTriangulation.h, case 1). Spokes and probes below still
// split only cells the prediction would split: a crease apex is tried only
// after the fan around S_C's apex passed. (Measured at 1/128: a crease
// apex's fan passes in 46-89 % of the cells whose first fan missed a crease
// - couplingdown 119 of 163, armadillo 76 of 166, the turbine 65 of 91,
// fandisk 8 of 9; couplingdown 13 974 -> 12 190 triangles, fandisk 2 208 -> 2 110,
// armadillo - a scan, whose sharp edges are followed too - 21 736 ->
// 20 124.)
//
// Creases first. The fans a cell of a scene of one mesh may pass with are
// the fan over its loops around S_C's apexes and those around the sets of
// crease points CreaseApexSets gives for the same loops and apexes; each
// must follow every crease of the cell within the reach (CreasesFollowed,
// asked of the first after its branch and bound, of the others before
// theirs: PredictCreaseApex). None of this depends on the branch and bound,
// and chords are never refined in a cell that must draw creases (Chords
// refined): where none of these fans follows the creases, the cell splits
// whatever E(P) + delta is - for its size where the bound fails,
// CreaseNotFollowed where it passes. So the prediction asks it first, after
// the probes (Probes), and fails without a branch and bound, the cell
// reported CreaseNotFollowed: the same cells split, the same surface (the
// grid's reasons - SplitReason, its children's SizeReason, an exact cell's
// FailedTest - may read CreaseNotFollowed where they read HausdorffSize). Measured (2026-12-06, tpc_benchmark on one
// thread under callgrind, the same surfaces): at 1/64 and 1/128 the turbine
// splits 25 and 47 cells so, 1.8 % and 2.4 % fewer instructions; armadillo
// 44 and 67 cells, 1.2 % and 1.0 %; couplingdown 1 and 70 cells, 0.2 % and
// 0.6 %.
//
// Chords refined. Face refinement tiles a face as the topology tests need
// (FaceRefinement.h), not for the error: a chord across a tile whose trace
// bends - over a fillet, a hole's rim, a scan's curve - strays from it by
// delta, and the fan has only tol - delta left (at 1/128 delta was above half
// the tolerance in 394 of couplingdown's cells that split for their size,
// 546 of armadillo's). Where the prediction fails with a chord straying more
// than ChordRefinementShare of the tolerance, the tiles of such chords are
// split, each into its four quadrants at its midpoint, each quadrant refined
// by face refinement as any face (RefineFace: its tiles pass the same face
// tests), and the prediction is made again over the finer loop; the cell
// keeps the finer tiling only if it then passes (RefineChordTiles,
// McCompatibility.cxx). Why the rest stands:
// - The tests. A tiling whose tiles all pass the face tests is one the tests
//   could have made: the loops traced on it are the cell's loops with more
//   points on the same traces (each tile corner keeps its exact sign), so
//   the complex-cell and star-shaped conclusions, drawn from the signs and
//   the surface, are unchanged.
// - The neighbour. The cell records its tiling (FaceRefinements); the cell
//   across a face of the same size records its own. Both refine the face
//   refinement of the same square by splits of single tiles, each split made
//   one way (the midpoint, then RefineFace with the same levels), so their
//   tiles nest or lie apart, and the tiling kept is the finest of both
//   (MergeFaceTilings, FaceTile.h): each cell's final loop holds its own
//   loop's points, and E(P') <= E(P) + delta holds for both, as with any
//   finer neighbour. Where they would not nest the first stays, and the
//   other's final loop fails FinalLoopRefines: its patch is certified on
//   its own, as always. So is a cell's patch where finer cells across a
//   face draw it with their own tilings, which may lack its points (and a
//   cell whose certificate then fails is split when the subdivision runs
//   again: CellRepair.h).
// - Only where the prediction failed, so cells that pass keep the loop they
//   have (every chord beyond a quarter of the tolerance split, in every
//   cell: the turbine 10 960 -> 15 742 triangles at 1/128).
// - Not in a cell that must draw creases (a scene of one mesh, a crease in
//   the cell: CreaseFollowing.h). A large cell accepted over finer chords
//   meets finer neighbours, and its final loop, with their points, may
//   change the bends at its fan's spokes: on armadillo at 1/64 a depth-4
//   cell left a sharp edge 1.4 tolerances from any output crease, which no
//   fan around another crease point fixed. Nor are crease tiles split
//   (their chords run through the crease, a -> x -> b): with both, far
//   fewer triangles on CAD parts (couplingdown 12 190 -> 7 884 at 1/128)
//   but the creases drawn off the input's (at 1/64 the output creases on
//   input creases fell from 0.47 to 0.15 of them, their length rose from
//   1.55 to 1.72 times the input's) and that sharp edge - left for the team
//   to weigh against a crease test of the final patch.
// Measured at 1/128 (shares of a quarter, 0.2, 0.3, 0.45 of the tolerance
// tried; 0.45 kept): triangles couplingdown 12 190 -> 11 792, armadillo
// 20 124 -> 18 360, the turbine 10 960 -> 9 702, fandisk 2 110 -> 1 882.
//
// Spokes: a necessary condition, checked before the topology tests (whose
// face refinement is most of the time spent on large cells that then fail
// the prediction: on armadillo at 1/64, the cells of levels 1-3 took 40 % of
// the tests). Let e be an edge of C whose corners have different signs and
// that S crosses exactly once, at x_e. Every tiling of C's faces cuts e into
// sub-edges of which exactly one has ends of different signs - the one
// holding x_e - so every loop the tests can trace holds its crossing, which
// PlaceSubEdgeCrossing puts at x_e: on the same triangle's plane and the same
// line, from another end of the segment (or by bisection on exact signs,
// to 2^-60 of the sub-edge), then clamped an ulp into the sub-edge. The two
// placements differ by about an ulp of the coordinates divided by |n[axis]|
// (n the triangle's unit normal): edges crossed with |n[axis]| < 1e-3 are
// not used, so that the rounding slack covers the difference. The fan P
// over that loop has the spoke [c, x_e] as an edge of two of its triangles,
// with c = MeshCellApex(S_C, C), which depends on C and S_C only. So
//   E(P) >= h(P, S_C) >= max over z in [c, x_e] of d(z, S_C),
// and the per-chord bound too (it is at least h(T_ab, S_C) for the T_ab
// holding the spoke, its offsets being >= 0); so does the apex c alone, a
// vertex of every fan triangle. Where a point of a spoke (c itself, and
// three points between c and each x_e) is farther than the tolerance plus
// the rounding slack from S_C, no loop the tests could trace gives a fan
// within the tolerance: the cell splits for its size at once (SpokeStrays).
// This only moves the decision earlier: a cell it splits would have failed
// its prediction (or an earlier test) after the tests; its grid reason is
// then HausdorffSize, whatever test would have failed first. (Not at the
// depth or cell limit, where the failed test is reported: SplitDecision.)
// That holds where the cell can only pass with one loop, whose apex is
// MeshCellApex(S_C, C): where S_C is one sheet (its polygons joined across
// mesh edges that meet the closed cell: a cell of several loops bounds
// several discs, which no edge of S in the cell joins). Where S_C is
// several sheets, each loop is fanned around its own apex (Several loops):
// the spokes then go from each
// crossing to the apex of its triangle's sheet (SheetSpokesStray) - the
// least squares point of that sheet's polygons, LoopApexMargin inside the
// cell - which is the prediction's apex up to the room's choice of polygons
// and its cut and clamp, not exactly it: there the spokes only guess, and a
// cell they split may have passed (splitting is always allowed, so no bound
// rests on it; MeshCellError.ProvenFailuresSplitOnlyCellsThePrediction
// WouldSplit finds no such cell on a slab whose cells hold both its faces,
// nor on the other scenes). The sheets are asked only where the spokes to
// S_C's apex stray, and for up to 8 of them (MostSheetsAsked: a cell of
// more splits on the one apex's spokes, as before).
//
// Several loops. A cell whose tests pass with several loops - two sheets of
// a thin part, a tube's two walls - bounds as many discs of S_C, apart
// across planes the surface misses (LoopsSeparated, ComplexCellCriterion.h).
// Each loop l is fanned around its own apex c_l in its room (ApexRooms.h:
// the cell cut between the loops, so that the fans lie strictly on opposite
// sides of a plane): the least squares point (as MeshCellApex) of the
// polygons of S_C whose corners' mean lies in the room, LoopApexMargin of
// the region inside it, moved into the room as the extraction moves its
// apexes (KeptInRoom). P is the union of the fans; E(P), delta (each chord
// against its own tile's trace), the probes and the per-chord bound are
// taken over all of P's triangles and all of S_C, exactly as for one loop.
// E(P') <= E(P) + delta holds fan by fan: each final loop refines one own
// loop and is fanned around that loop's apex (both steps of the argument
// above move a point within one fan triangle's chord). The extraction fans
// each final loop around the apex nearest its room (CellPatches.h) and
// keeps the prediction's Bound only where every final loop was fanned
// around an own loop's apex, unchanged, and refines that own loop
// (FinalLoopsRefine, SurfaceExtraction.cxx); elsewhere its patch is bounded
// by its own certificate, and split by a repair round where that is not
// within the tolerance. In a scene of one mesh the fans must follow the
// cell's creases too: where they miss one, each loop may take a point of a
// crease in its room instead (CreaseApexSets: the k-th try takes each loop's
// k-th, up to 4), and the extraction looks again at the final fans the same
// way (CellFromOtherApexes, SurfaceExtraction.cxx) - as for one loop (Crease
// apexes). Measured (2026-12-06; triangles at 1/64, 1/128, 1/256): the
// turbine 8 456 -> 6 146, 9 702 -> 8 104, 15 198 -> 13 748; couplingdown
// 5 978 -> 5 410, 11 792 -> 11 252, 20 056 -> 19 452; fandisk 1 430 ->
// 1 370, 1 882 -> 1 724, 2 892 -> 2 704; armadillo 9 948 -> 9 378, 18 360 ->
// 17 408, 34 048 -> 33 280. (Before a crease apex per loop, such cells split:
// couplingdown 5 840 at 1/64, armadillo 18 092 at 1/128; accepted without
// it - the union of the fans asked to follow the creases, no second look -
// a sharp edge of armadillo lay beyond the tolerance of every output crease.)
//
// Probes: once the fan P and the chords' deltas are known, a few points of
// P are measured before either bound's branch and bound. Let y be a point of
// the fan triangle T_k over chord k, whose delta with the slack is d_k
// (<= delta), and x its computed position (a centroid or an edge midpoint,
// within a few ulps of y). If the distance from x to S_C, as computed,
// exceeds tol - d_k + 2 slack, then d(y, S_C) > tol - d_k + slack (the
// slack is far above both roundings), so both bounds fail whatever their
// branch and bound would find: E(P) >= h(P, S_C) >= d(y, S_C) > tol - delta
// + slack, so E(P) + delta > tol; and the per-chord bound is at least
// d_k + g(y) (T_k's source offset; g has no target offsets in this
// direction) >= d_k + d(y, S_C) > tol. The cell then splits for its size
// as it would have after both (the per-chord bound is only tried after
// E(P) + delta failed, and fails too): the same cells, patches and reasons,
// one branch and bound fewer (two where the per-chord bound was tried). The
// points: each triangle's centroid and edge midpoints (the chord's midpoint
// among them, where a chord cutting across S strays most). On armadillo at
// 1/64 this and the crease tiles' kept halves take the prediction from 1.41
// to 0.99 G instructions of the filter's 5.92 G.
//
// Prediction precision. The prediction's branch and bounds (E(P), the
// per-chord bound, the crease apexes' fans) must prove a bound within the
// tolerance, and whether they do does not depend on how tight the bounds of
// the pieces they settle are (PolygonHausdorff.h: Settled pieces). Beyond
// that, in a scene of one mesh their values are read only against a quarter
// of the tolerance or more: OwnFanError against the first certificates' aim
// (a quarter at least, FirstCertificateAim in SurfaceExtraction.cxx) and
// through the loop-point fans' MeshEdgeFanKeptWithin (a quarter), Attained
// times 1.1 against that quarter in the aim, Bound only as a proven bound.
// (And Lower before the per-chord bound, `Lower + least delta < tolerance`:
// a lower Lower may only try it where it was not, in vain - the per-chord
// bound is at least E(P) plus the least delta.) So there their pieces settle
// with the first bound found within PredictionPrecision (a fifth) of the
// tolerance: max(a fifth, value) is what it would be without it, so every
// comparison above (1.1 times a fifth is below a quarter: a static_assert in
// SurfaceExtraction.cxx) and the cells accepted, their patches and their
// fans' apexes are the same; a bound below a fifth of the tolerance may read
// higher, proven all the same. In other scenes the decimation reads the
// cells' errors, which may be these, as their triangles' spent room
// (CertifiedError.h): the bounds are as tight as found. (With the
// extraction's certificates settling within their aim likewise, armadillo at
// 1/64 and 1/128 took 3.7 % and 4.4 % fewer instructions, the turbine 2.4 %
// and 3.7 %: the benchmark page, "settled pieces".)
//
// Slab bound. In a scene of one closed mesh (every edge between two triangles:
// S is a 2-cycle, the bound's premise; in other scenes the decimation reads the
// cells' errors as their triangles' spent room, so they stay as tight as found,
// below), before its branch and bound the prediction tries SlabPatchError
// (SlabBound.h): where every triangle of S_C and of the fan faces one way n,
// E(P) <= sqrt(t^2 + delta^2) + slack, t the thickness along n of the slab
// holding both. Where that and delta are within the tolerance the cell passes
// on it: OwnFanError and Bound are read from it, and Attained is the apexes'
// distance to S_C (the branch and bound's Lower is at least that: an apex is a
// piece's corner). The extraction tries it too on the final patch - the loop-
// point fan, or the apex fans over loops refining the cell's own - before the
// branch and bound of its first certificate (SurfaceExtraction.cxx: its chords'
// reach is Delta over the cell's own loop, twice that over a loop refining it).
// The bound is looser than the branch and bound's, but its cells are the flat
// ones, far within the tolerance: on armadillo at 1/128, 2 187 of the 2 954
// predictions that pass (and on fandisk one the branch and bound's budget
// fails), about 1 350 of the 1 900 loop-point fans; the same cells accepted but
// a few whose loop-point fan keeps its place (MeshEdgeFanKeptWithin and the
// first certificates' aim read OwnFanError, Attained): over CGAL's 91 closed
// demo meshes at 1/64, 16 surfaces changed, by 68 of 385 768 triangles in all,
// with the same topology, guarantees and no larger bound.
// Where the slab is too thick, its local heights are tried (LocalHeights.h;
// the prediction's own chords and their deltas, each chord's face read from
// the cell; the extraction's over the prediction's own loops and Delta).
// They bound more tightly than the branch and bound stopped at its first
// proof, so OwnFanError reads lower there and MeshEdgeFanKeptWithin
// keeps fewer loop-point fans: over CGAL's closed demo meshes at 1/64, 36 of 84
// surfaces changed, 682 triangles more of 197 536, 43 bounds lower, none
// higher, the same topology and guarantees.
// Several sheets. Where S_C is several sheets (SheetsInCell: its polygons
// joined across mesh edges that meet the closed cell) - a thin part's two
// faces, facing opposite ways, so that no direction passes the facing test -
// each sheet is bounded with its own loops' fans on its own
// (SheetwiseSlabError), and E(P) is at most the largest: P and S_C are the
// unions, and each point of a sheet (of a fan) is within that sheet's bound
// of its loops' fans (of its sheet). The slab bound's premise for a sheet S'
// and its loops' chords: S' is a chain whose boundary is the trace of those
// loops alone. Its boundary lies on C's faces (an edge of S' inside C is a
// mesh edge meeting the cell, whose two triangles are joined in one sheet);
// each arc of the trace lies in one sheet (it crosses mesh edges, which join,
// or vertices: where two sheets share a vertex in the closed cell - a pinched
// vertex - the bound is not tried, SheetsApartInCell). Each loop is given the
// sheet within the rounding slack of all its points (they lie on S; none
// where another sheet is as near, or a loop's points disagree), so each
// chord's arc - from its loop point, in that sheet - is on its loop's sheet;
// every sheet must have a loop (a sheet's boundary is its arcs, none of
// another sheet's loops). Measured on the turbine at 1/64: 97 of 129 cells of
// several loops settle so, halving the prediction's branch and bound time.
//
// Cells no larger than the tolerance keep their usual patch
// (LoopTriangulation.h), bounded by their diagonal; E of that patch is
// computed too, and the smaller of the two reported, so that HausdorffBound
// says what the patches need rather than what the cells' size allows.
//
// Rounding. The polygons, the crossings and the distances are computed in
// floating point from the mesh's coordinates (clipped points interpolate
// vertices that may lie far outside the cell): each is within a few hundred
// units in the last place of the mesh's largest coordinate M - a distance
// measured by a polygon's plane within 4096 of them, the polygon measured
// by its edges where that is not proven (ConvexPolygons.cxx,
// MeasuredByItsPlane); RoundingSlack (16384 ulps of M, plus 1e-12 of the
// cell's diagonal; 4096 ulps until the plane's share was proven) is added
// to E(P), to delta and to the final certificate.
#pragma once

#include "AdaptiveOctree.h"
#include "ApexRooms.h"
#include "BoundaryLoops.h"
#include "CellSignCache.h"
#include "CreaseFollowing.h"
#include "CsgExpression.h"
#include "PolygonHausdorff.h"
#include "SlabBound.h"

#include <cmath>
#include <cstddef>
#include <vector>

namespace tpc
{

/// S_C: each listed triangle of the lone mesh leaf (LoneMeshLeaf,
/// ExactCellCriterion.h) clipped to `cell` (the empty clips dropped).
PolygonSet SurfaceInCell(const CsgLeaf& leaf, const PrimitiveSet& primitives,
  const Box3& cell);
/// The same in `surface` (cleared first; its memory is reused: ScratchPool.h);
/// with `triangles`, the listed triangle each polygon is clipped from, in
/// the same order (cleared first).
void SurfaceInCell(const CsgLeaf& leaf, const PrimitiveSet& primitives, const Box3& cell, PolygonSet& surface,
  TriangleList* triangles = nullptr);

/// The fan's apex: the point nearest to S_C's planes (least squares, area
/// weighted, as Dual Contouring places vertices: on a crease or corner of S it
/// lands on it), flat directions left at S_C's area centroid; kept 1/32 of the
/// cell's width inside it, so strictly inside (the fan is then embedded,
/// LoopTriangulation.h).
Vec3 MeshCellApex(const PolygonSet& surface, const Box3& cell);

/// The apex of one of several loops (header: Several loops): the point
/// nearest to the planes of the polygons of S_C `surface` whose corners'
/// mean lies in `room`'s region (closed) and below its cuts, kept
/// LoopApexMargin (1/1024) of the region's width inside it, then moved into
/// the room as the extraction moves its apexes (KeptInRoom, `loop`'s
/// centroid as fallback).
Vec3 LoopApex(const PolygonSet& surface, const ApexRoom& room, const std::vector<Vec3>& loop);

/// max over S ∩ tile of the distance to the chord [a, b] (`tile` is a face
/// tile, degenerate along the face's axis).
double ChordDeviation(const PolygonSet& surface, const Box3& tile, const Vec3& a, const Vec3& b);

/// The points of the loop `loop` as the extraction places them (a crease
/// crossing on its mesh edge, a sub-edge crossing on its sub-edge), in
/// `points`; false when a crossing is of another kind.
bool PlaceLoopPoints(const CsgExpression& expression, const PrimitiveSet& primitives, const RootGrid& grid,
  const std::vector<Crossing>& loop, std::vector<Vec3>& points);

/// A chord of a loop: the tile it crosses (face, index in boundary.Tiles;
/// NoTile, and Deviation +inf, where none holds it) and how far the trace
/// on it strays from it (delta_k; on a crease tile, its half of the trace).
struct ChordTile
{
  static constexpr std::size_t NoTile = static_cast<std::size_t>(-1);
  int Face = -1;
  std::size_t Tile = NoTile;
  double Deviation = HUGE_VAL;
};

/// Each chord of `loop` (points `points`) on `boundary`, in order, until
/// one strays more than `stopAbove`; false where a chord has no tile or no
/// deviation (then the prediction fails).
bool MeasureChords(const PolygonSet& surface, const RootGrid& grid, const CellBoundary& boundary,
  const std::vector<Crossing>& loop, const std::vector<Vec3>& points, double stopAbove,
  std::vector<ChordTile>& chords);

/// The share of the tolerance beyond which a chord's tile is split (header:
/// Chords refined), and the rounds of splitting (a chord split twice is a
/// quarter of its tile).
constexpr double ChordRefinementShare = 0.45;
/// The share of the tolerance within which the prediction's branch and
/// bounds settle a piece with the first bound found (header: Prediction
/// precision).
constexpr double PredictionPrecision = 0.2;
constexpr int ChordRefinementRounds = 3;

/// Splits the tiles of `boundary` (a cell of the lone mesh leaf of
/// `expression`; where `creaseTiles`, its crease tiles marked on entry, and
/// marked again after each round that split tiles) whose chord strays more than `threshold` from the trace
/// on them, each into its quadrants refined by RefineFace (`levels`; a tile
/// whose quadrants do not all pass stays whole), for ChordRefinementRounds
/// rounds (header: Chords refined); the number of tiles split.
int RefineChordTiles(const CsgExpressionPtr& expression, const PrimitiveSet& primitives, const RootGrid& grid,
  const PolygonSet& surface, bool creaseTiles, double threshold, int levels, CellSignCache& signs,
  CellBoundary& boundary);

/// E(P) for the patch triangles `patch`: Upper (`slack` added) proven when <=
/// `giveUp` (+inf beyond it, or when there is nothing to compare), Lower
/// attained; pieces are refined until within `enough` or 10 % of Lower, at
/// most `budget` of them per direction (OneSidedHausdorff). With
/// `patchOffsets` (one per patch triangle: its chord's delta, >= 0), the
/// per-chord bound of E(P') instead (header); Lower is then a value the
/// offset distances attain, not a distance. `anyBoundWithin`: where the
/// caller needs no tighter bound (PolygonHausdorff.h: Settled pieces), so
/// that max(anyBoundWithin, Upper) and max(anyBoundWithin, Lower) are what
/// they would be without it.
HausdorffEstimate CertifiedMeshPatchError(const PolygonSet& surface,
  const std::vector<SourceTriangle>& patch, double slack, double enough, double giveUp,
  std::size_t budget = 4096, const std::vector<double>* patchOffsets = nullptr, double anyBoundWithin = 0.0);
/// The same where S is known from two sides, `onSurface` ⊆ S and `covering`
/// ⊇ S_C (MeshBooleanSurface.h): h(patch, onSurface) and h(covering,
/// patch) bounded (one mesh: both S_C). Lower is then what the branch and
/// bound came upon, a distance attained only where the two sets are S_C.
HausdorffEstimate CertifiedSurfacePatchError(const PolygonSet& onSurface, const PolygonSet& covering,
  const std::vector<SourceTriangle>& patch, double slack, double enough, double giveUp, std::size_t budget,
  const std::vector<double>* patchOffsets = nullptr, double anyBoundWithin = 0.0);

/// The slack for rounding in a cell of the mesh of `leaf` (header: Rounding),
/// and the largest coordinate M it is taken of.
double RoundingSlack(const CsgLeaf& leaf, const PrimitiveSet& primitives, const Box3& cell);
double SlackMagnitude(const CsgLeaf& leaf, const PrimitiveSet& primitives, const Box3& cell);
/// That slack for coordinates up to `magnitude` in a region `size` across:
/// 16384 ulps of the magnitude plus 1e-12 of the size (header: Rounding) -
/// the cells' and the certified decimation's (ErrorCertificates.h) alike.
double RoundingSlackFor(double magnitude, double size);

/// The fan around `apex` over `loop`: triangles (p_k, p_k+1, apex).
std::vector<SourceTriangle> ApexFan(const std::vector<Vec3>& loop, const Vec3& apex);
/// The fans around `apexes[l]` over `loops[l]`, loop after loop.
std::vector<SourceTriangle> ApexFans(const std::vector<std::vector<Vec3>>& loops, const std::vector<Vec3>& apexes);

/// The apexes a fan around a point of a crease may take in `cell` (header:
/// Crease apexes): the point of each segment of `creases` nearest `apex`,
/// kept 1/32 of the cell's width inside it as MeshCellApex keeps its own
/// (strictly inside), nearest `apex` first, each once.
std::vector<Vec3> CreaseApexes(const Box3& cell, const std::vector<CreaseSegment>& creases, const Vec3& apex);

/// The sets of apexes (one per loop of `loops`, around `apexes`) a cell's
/// fans may take where they miss a crease of `creases` (header: Crease
/// apexes, Several loops), tried in order: a lone loop's CreaseApexes; with
/// several loops, each loop's CreaseApexes in its room (those InRoom, or its
/// own apex where none is), the k-th set each loop's k-th or its last, up to
/// 4 sets.
std::vector<std::vector<Vec3>> CreaseApexSets(const Box3& cell, const std::vector<CreaseSegment>& creases,
  const std::vector<std::vector<Vec3>>& loops, const std::vector<Vec3>& apexes);

/// Where the apex fans of `prediction` (PredictedMeshCellError, within the
/// tolerance) miss a crease of `creases` (CreasesInCell, CreaseFollowing.h):
/// the fans over the same loops around points of creases instead
/// (CreaseApexSets) - the first whose fans follow every crease within
/// `reach` and have E(P) + delta within `tolerance` (header: Crease apexes;
/// `slack` the rounding slack). True when there is one: `prediction` then
/// holds it as its apexes, with its Bound, OwnFanError and Attained.
bool PredictCreaseApex(const PolygonSet& surface, const Box3& cell, const std::vector<CreaseSegment>& creases,
  double reach, double slack, double tolerance, AdaptiveOctree::MeshCellPrediction& prediction);

/// The subdivision's prediction, E(P) + delta or else the per-chord bound
/// (header), for a cell whose tests passed
/// with the loops `loops` (sub-edge crossings, and crease crossings in
/// a scene of one mesh; several: header, Several loops) on its `boundary` tiles
/// (`cell`: its box, as the extraction computes it, so that both find the
/// same apex);
/// +inf when it exceeds `tolerance` or the cell is not a lone mesh leaf
/// with consistent loops of three points or more.
/// `prediction` receives it as Bound, the loops' points as Loops (what the
/// final loops must hold in order for the prediction to apply,
/// FinalLoopRefines) and their apexes as Apexes, the largest distance
/// between the fans and the mesh the
/// bound came upon as Attained (a lower bound of E(P)) and the bound of E(P)
/// alone as OwnFanError (the final patch's error where the final loop is the
/// cell's own, SameLoop; +inf where the cell passed on the per-chord bound,
/// E(P) + delta having failed before E(P) was proven).
/// `surface`: S_C when the caller has it (SurfaceInCell with `cell`), else
/// null; `surfaceTriangles`: its polygons' triangles, where given (else the
/// slab bound is not tried: header, Slab bound). With `probesFirst`, the
/// fan's probes (header: Probes) may fail it before the branch and bound
/// (then prediction.ProbeStrayed is set), and,
/// given the cell's `creases` (CreasesInCell, in a scene of one mesh, where
/// its fan must follow them), so may fans that follow them around no apex
/// (header: Creases first; then prediction.Creases is NoneFollows, and it
/// says what was found where the prediction goes on): off only to check that
/// they change nothing. `sceneOfOneMesh`: the scene is one mesh, where its
/// branch and bounds settle within PredictionPrecision (header: Prediction
/// precision); elsewhere they are as tight as they find.
double PredictedMeshCellError(const CsgExpression& expression, const PrimitiveSet& primitives,
  const RootGrid& grid, const Box3& cell, const CellBoundary& boundary, const BoundaryLoopSet& loops,
  double tolerance, AdaptiveOctree::MeshCellPrediction& prediction,
  const PolygonSet* surface = nullptr, const TriangleList* surfaceTriangles = nullptr, bool probesFirst = true,
  const std::vector<CreaseSegment>* creases = nullptr, bool sceneOfOneMesh = false);

/// Whether a spoke of the fan over every loop the tests could trace in
/// `cell` strays farther than `tolerance` from S_C `surface` (header:
/// Spokes), so that the cell's prediction fails whatever they trace. Corner
/// c of the cell (bit a of c: the upper end along axis a) is inside the
/// solid when bit c of `insideCorners` is set (the exact signs).
/// (The apex is S_C's: proven only where the cell can pass with one loop
/// alone - SheetSpokesStray.)
bool SpokeStrays(const CsgLeaf& leaf, const PrimitiveSet& primitives, const Box3& cell, unsigned insideCorners,
  const PolygonSet& surface, double tolerance);

/// E(P) of a cell whose S_C `surface` (its polygons' triangles
/// `surfaceTriangles` of `mesh`, in order) is several sheets, by the slab bound
/// and its local heights (SlabBound.h, LocalHeights.h) sheet by sheet (header: Slab bound,
/// Several sheets): the cell's own loops `loops` - their chords' deltas
/// `chords` (its Loops unread) - and `fans[l]`, the patch's triangles over own
/// loop l (or over the final loop refining it), `chordReach` as for
/// SlabPatchError (the largest delta: each sheet's bound takes it), `enough`
/// and `giveUp` as for SlabPatchError, sheet by sheet. +inf where the sheets
/// and the loops do not match (each loop on one sheet, each sheet with a
/// loop, no two sharing a vertex in the cell) or a sheet's bound is above
/// `giveUp`.
double SheetwiseSlabError(const MeshSolid& mesh, const TriangleList& surfaceTriangles, const PolygonSet& surface,
  const Box3& cell, const std::vector<std::vector<Vec3>>& loops, const OwnChords& chords,
  const std::vector<std::vector<SourceTriangle>>& fans, double chordReach, double slack, double enough,
  double giveUp);

/// Where SpokeStrays is true: true where S_C is one sheet (then the cell can
/// only pass with one loop, and the spokes' proof stands), else - the cell
/// may pass with several loops (header: Several loops) - whether a spoke
/// from a crossing to the apex of its triangle's sheet strays: a guess
/// (header: Spokes). True too where S_C is more than 8 sheets.
/// `surfaceTriangles`: the triangle each polygon of `surface` is clipped
/// from (SurfaceInCell's `triangles`).
bool SheetSpokesStray(const CsgLeaf& leaf, const PrimitiveSet& primitives, const Box3& cell, unsigned insideCorners,
  const PolygonSet& surface, const TriangleList& surfaceTriangles, double tolerance);

/// Whether the final loop `final` holds every point of the cell's own loop
/// `own` in the same cyclic order (up to rounding): then each chord ab of
/// the cell's loop is kept or replaced by final points on its tile's trace,
/// which is what the prediction assumes. (Face tiles of two cells are
/// quadtree tilings of the same face, so they nest: a final tile coarser
/// than the cell's own tile t would drop a crossing of t's inner sides, or
/// draw the same chord ab.)
bool FinalLoopRefines(const std::vector<Vec3>& own, const std::vector<Vec3>& final, const Box3& cell);

/// Whether the final loop `final` is the cell's own loop `own`, the same
/// points exactly (from the same crossings, placed alike) in the same cyclic
/// order: then the final fan around the same apex is the fan the prediction
/// bounded, triangle for triangle, and E(P) is its error.
bool SameLoop(const std::vector<Vec3>& own, const std::vector<Vec3>& final);

} // namespace tpc
