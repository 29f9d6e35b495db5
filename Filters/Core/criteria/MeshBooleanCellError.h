// Cells where meshes meet accepted larger than the tolerance (issue 17), as
// cells of one mesh are (MeshCellError.h).
//
// What is proven, and where. A cell where two or more meshes meet
// (IsMeshBoolean, MeshBooleanSurface.h) larger than the tolerance that
// passes the topology tests is accepted when the fan predicted here is
// within the tolerance; its bound is the certificate of its final patch:
// the extraction draws the fan around the apex kept here (one per loop,
// Several loops below) over the cell's final loop (after crack patching)
// and bounds its E(P') against S's two
// sides (MeshBooleanSurface.h) by the branch and bound. Where that is not
// within the tolerance, the cell is split by a repair round (CellRepair.h)
// and the guarantee is decided on the next run's final patches alone. So
// nothing here needs to be a bound: it decides which cells to try.
//
// The prediction. The cell's own loop L, drawn through the CSG crease tiles
// of its expression as the extraction draws them (CsgCreaseCrossing.h: the
// crease where the meshes meet runs through the loop's crease vertices),
// its points placed as the extraction places them, and an apex kept 1/32
// of the cell's width inside it (Creases, below). The fan P around it over
// L has E(P) bounded against S's two sides. The final loop L' adds points
// of S's trace on the cell's faces where finer neighbours sample them
// (crack patching); the fan over L' is within E(P) + delta where delta
// bounds how far the trace on each chord's tile strays from that chord
// (MeshCellError.h proves it for one mesh). Here delta is how far the trace
// on the cell's faces (the covering pieces clipped to each face, at their
// corners) strays from the loop as a whole - no bound (a trace point near
// another chord counts the smaller distance, and a covering piece's clipped
// corners need not be where its distance peaks), but what the final
// certificate then rarely refuses. The cell is accepted when E(P) + delta
// is within the tolerance.
//
// Creases. Where the meshes cross in the cell (their listed triangles'
// intersection segments, MeshBooleanSurfaceInCell), the fan must draw that
// crease as the CSG crease tiles draw it on the faces: its apex is a point
// of the crease - on each segment the point nearest the point S's planes
// give (MeshCellApex), nearest first, up to CreaseApexesTried of them - and
// every point of the crease must lie within BooleanCreaseReach of the
// fan's creases (CreasesFollowed, CreaseFollowing.h). A tenth of the
// tolerance rather than one mesh's whole tolerance: the output's crease
// then runs from crease vertex to apex to crease vertex, each on the exact
// crease, as the cells of the tolerance's size draw it (a box minus a
// 96-sided prism, two meshes: the rims' corners within 0.094 tolerances of
// an output crease at 1/64, against 0.5 with the planes' point for apex and
// no check). Where the meshes do not cross in the cell, the apex is the
// planes' point. The extraction checks the final fan again and, where the
// final loop's extra points bend it off the crease, tries the other crease
// points (SurfaceExtraction.cxx) - a quality criterion, as for one mesh, no
// part of the bound.
// Several loops. A cell whose tests pass with several loops (the two tubes
// of a torus beside another's wall) is fanned around an apex per loop, each
// in its loop's room (ApexRooms.h) - the point S's planes give there
// (LoopApex, MeshCellError.h) or, where the meshes cross in the room, the
// crease points nearest it - the k-th try taking each loop's k-th
// candidate; delta is the trace's distance to the nearest chord of any
// loop, E(P) that of all the fans together. The extraction fans each final
// loop around the apex nearest its room and certifies the whole patch.
// Measured (2026-12-06): the sixteen reference Booleans at 1/128 and 1/256
// 646 712 -> 591 568 triangles, every one still guaranteed with its
// topology; joint - knot1 12 908 at 1/128 (14 800 with one loop only).
//
// Measured on the sixteen reference Booleans of Data/CsgReference.csv at
// 1/128 and 1/256 (2026-12-06, one run each): 2.4 times fewer triangles in
// all (1 523 344 -> 646 712; couplingdown ∩ knot1 at 1/256 122 172 ->
// 35 470, its operands alone 20 056 and 8 848; the five whose meshes only
// come near each other unchanged), 0.89 times the time, every one still
// guaranteed with its topology; the tests' Booleans needed no repair round.
#pragma once

#include "BoundaryLoops.h"
#include "CsgExpression.h"
#include "MeshBooleanSurface.h"
#include "RootGrid.h"

#include <cstddef>
#include <vector>

namespace tpc
{

/// How finely S's pieces are decided in a cell where meshes meet
/// (MeshBooleanSurface.h), relative to the tolerance, and at most how many:
/// pieces left undecided count in the patch's distance from S but not in
/// S's from the patch, so where the patch's nearest point of S lies on one
/// the bound is loose by about their width.
constexpr double BooleanPieceShare = 1.0 / 32.0;
constexpr std::size_t BooleanPieceBudget = 4096;

/// How close to the patch's creases the crease where meshes meet must be,
/// in tolerances (header: Creases).
constexpr double BooleanCreaseReach = 0.1;

/// The crease points tried as apexes (header: Creases).
constexpr std::size_t CreaseApexesTried = 4;

/// The most listed triangles (all meshes together) of a cell certified
/// where meshes meet: deciding S's pieces compares each with the other
/// meshes' polygons in the cell, so a cell holding thousands of both costs
/// millions of comparisons - and one holding that many rarely has a fan
/// within the tolerance. Such cells keep the tolerance's size, bounded by
/// their diagonal, as before.
constexpr std::size_t BooleanFanTriangles = 4096;

/// Whether the patch of a cell of `expression` is certified where meshes
/// meet, and, larger than the tolerance, may be accepted on a predicted fan
/// (header): meshes meet there (IsMeshBoolean), listing at most
/// BooleanFanTriangles triangles. (Elsewhere the cell keeps the tolerance's
/// size and is bounded by its diagonal.)
bool IsCertifiableMeshBoolean(const CsgExpression& expression);

/// The apexes on `creases` a fan may take in `cell`: on each segment, the
/// point nearest `planesPoint` among those 1/32 of the cell's width inside
/// it (as MeshCellApex keeps its own: strictly inside), nearest first, each
/// once, at most CreaseApexesTried. (CreaseApexes, MeshCellError.h, clamps
/// the nearest point into that box instead, which may move it off the
/// crease: here that drew the box minus a prism's rims 0.94 on them at
/// 1/128 where the test asks 0.95. For one mesh, whose creases are
/// followed within the whole tolerance, clipping was measured worse:
/// couplingdown 11 792 -> 12 658 triangles at 1/128, fandisk 1 882 -> 1 952,
/// armadillo 18 360 -> 18 432.)
std::vector<Vec3> ApexesOnCreases(const Box3& cell, const std::vector<CreaseSegment>& creases, const Vec3& planesPoint);

/// The apexes of the fans a cell where meshes meet, larger than the
/// tolerance, is accepted with (header), one per loop of its tiles
/// `boundary` (as the topology tests left them); a bound of its E(P) + delta
/// within the tolerance in `predicted` (not the least the branch and bound
/// could prove: only its being within the tolerance is read). None where
/// the loops drawn so are not consistent, or E(P) + delta exceeds
/// `tolerance`.
std::vector<Vec3> PredictMeshBooleanFan(const CsgExpressionPtr& expression, const PrimitiveSet& primitives,
  const RootGrid& grid, const Box3& cell, const CellBoundary& boundary, double tolerance, double& predicted);

} // namespace tpc
