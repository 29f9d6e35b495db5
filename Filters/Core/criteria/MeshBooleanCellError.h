// Cells where meshes meet accepted larger than the tolerance (issue 17), as
// cells of one mesh are (MeshCellError.h).
//
// What is proven, and where. A cell where two or more meshes meet
// (IsMeshBoolean, MeshBooleanSurface.h) larger than the tolerance that
// passes the topology tests is accepted when the fan predicted here is
// within the tolerance; its bound is the certificate of its final patch:
// the extraction draws the fan around the apex kept here over the cell's
// final loop (after crack patching) and bounds its E(P') against S's two
// sides (MeshBooleanSurface.h) by the branch and bound. Where that is not
// within the tolerance, the cell is split by a repair round (CellRepair.h)
// and the guarantee is decided on the next run's final patches alone. So
// nothing here needs to be a bound: it decides which cells to try.
//
// The prediction. The cell's own loop L, drawn through the CSG crease tiles
// of its expression as the extraction draws them (CsgCreaseCrossing.h: the
// crease where the meshes meet runs through the loop's crease vertices and
// the apex), its points placed as the extraction places them; the apex is
// the point nearest the planes of S's pieces on the surface (MeshCellApex:
// on the crease where both meshes' planes are among them), kept 1/32 of the
// cell's width inside it. The fan P around it over L has E(P) bounded
// against S's two sides. The final loop L' adds points of S's trace on the
// cell's faces where finer neighbours sample them (crack patching); the fan
// over L' is within E(P) + delta where delta bounds how far the trace on
// each chord's tile strays from that chord (MeshCellError.h proves it for
// one mesh). Here delta is how far the trace on the cell's faces (the
// covering pieces clipped to each face, at their corners) strays from the
// loop as a whole - no bound (a trace point near another chord counts the
// smaller distance, and a covering piece's clipped corners need not be
// where its distance peaks), but what the final certificate then rarely
// refuses. The cell is accepted when E(P) + delta is within the tolerance.
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
#include <optional>

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

/// The most listed triangles (all meshes together) of a cell whose fan is
/// predicted: deciding S's pieces compares each with the other meshes'
/// polygons in the cell, so a cell holding thousands of both costs millions
/// of comparisons - and one holding that many rarely has a fan within the
/// tolerance. Larger cells split for their size, as before.
constexpr std::size_t BooleanFanTriangles = 4096;

/// Whether a cell of `expression` larger than the tolerance may be accepted
/// on a predicted fan (header): meshes meet there (IsMeshBoolean), listing
/// at most BooleanFanTriangles triangles.
bool MayPredictMeshBooleanFan(const CsgExpression& expression);

/// S's two sides in `cell` for an expression of meshes meeting, decided as
/// finely as the tolerance `tolerance` asks (BooleanPieceShare); false
/// where the expression is no mesh Boolean.
bool MeshBooleanSurfaceForTolerance(
  const CsgExpression& expression, const PrimitiveSet& primitives, const Box3& cell, double tolerance,
  MeshBooleanSurface& surface);

/// The apex of the fan a cell where meshes meet, larger than the tolerance,
/// is accepted with (header), its tiles `boundary` (as the topology tests
/// left them); its E(P) + delta in `predicted`. Nothing where the cell has
/// no single loop drawn so, or E(P) + delta exceeds `tolerance`.
std::optional<Vec3> PredictMeshBooleanFan(const CsgExpressionPtr& expression, const PrimitiveSet& primitives,
  const RootGrid& grid, const Box3& cell, const CellBoundary& boundary, double tolerance, double& predicted);

} // namespace tpc
