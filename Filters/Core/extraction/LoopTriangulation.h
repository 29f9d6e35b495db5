// The patch of one boundary loop (paper 4.3): the triangles that span a loop
// the surface draws on a cell's boundary, placed so that the extracted
// surface is embedded - no two triangles meet except in a shared edge or
// vertex - by construction.
//
// Why the patches are embedded. Let C be a (closed, convex) cell and L one of
// its loops: a closed polygon whose vertices lie on the boundary of C and
// whose every edge is a chord of one face tile, so lies in one face of C. L is
// simple when its edges meet only at the ends they share: every crossing lies
// strictly inside its own lattice sub-edge (CrossingVertices.h places them so,
// exactly on the sub-edge's line), a tile of a cell that passed the tests
// holds one chord (MC-compatible tiles; BoundaryLoops.h), and a chord touches
// its tile's boundary only at its ends. (A crease tile, CreaseCrossing.h,
// holds its chord bent at its sharpest edge's crossing x: segments
// a -> x -> b with a and b on the tile's boundary and x strictly inside the
// tile, so they meet only at x and touch the boundary at a and b only.) Three
// triangulations of a simple L are embedded discs that meet the boundary of
// C in L only:
//
// 1. ApexFan: the triangles (p_k, p_k+1, c) around an apex c strictly inside
//    C. A point x != c of triangle (a, b, c) is c + t (p - c) with p on the
//    chord ab and 0 < t <= 1. The ray from c through x leaves the convex cell
//    once, at p, so x determines p; two triangles share x only if their chords
//    share p, i.e. only along the edge (c, p) from a common end p. A triangle
//    meets the boundary only in its chord (t = 1) and is not degenerate (c is
//    not in the plane of the face holding ab).
// 2. LoopFan: Marching Cubes' k - 2 triangles (s, p_i, p_i+1) from a loop
//    point s, allowed when no loop point but s and its two neighbours lies
//    on a face of C that holds s. The same argument with s for c: a point p of
//    a chord not incident to s lies on a face with s only if both ends of the
//    chord do (p inside the chord) or p is such an end, so the open segment
//    (s, p) is interior and p is the only other point of the boundary on the
//    ray from s through p. The diagonals (s, p_i) cross the interior. (This
//    reads the faces a point lies on from its Faces. A mesh edge's point - a
//    crease's x, or a point of an exact neighbour's trace - lies on its
//    lattice plane exactly, and on that face alone where its computed
//    position is strictly inside the face; where it is not - an exact
//    neighbour's trace point is placed without that check, and may round
//    onto a side - FacesAsPlaced gives it all six faces, so it is neither a
//    fan point nor the far end of a diagonal.)
// 3. Triangle: three loop points not on one face of C. They are not collinear
//    (three collinear points of a convex cell's boundary lie on one face).
//    (A point read as lying on every face - FacesAsPlaced - only sends such
//    a loop to the apex fan.)
//
// Several loops in one cell: each loop's apex lies in its own room
// (ApexRooms.h), so the patches of different loops, each in the convex hull
// of its loop and apex, lie strictly on opposite sides of a plane.
//
// Patches of different cells are in different cells, which meet on their
// boundaries only; there each patch is its chords, and both cells sharing a
// tile draw the same chords between the same crossing vertices
// (BoundaryLoops.h), so patches of different cells meet in shared edges and
// vertices only. Every comparison above is exact on the computed
// coordinates; the result is checked exactly anyway (SurfaceEmbedding.h),
// which also covers cells stopped by a limit, where a tile may hold several
// chords and loops need not be separated.
#pragma once

#include "CsgExpression.h"
#include "QuadricCellError.h"
#include "ApexRooms.h"
#include "Vector3.h"

#include <vector>

namespace tpc
{

/// A vertex of a loop: a surface crossing on the cell boundary.
struct LoopPoint
{
  Vec3 Position;
  Vec3 Normal; ///< unit surface normal there (zero if unknown)
  /// Faces of the cell the point lies on: bit f (CubeTopology.h numbering;
  /// all six for a bend vertex, or a mesh edge's point placed off its face's
  /// interior, FacesAsPlaced: such a point never serves as a fan point).
  unsigned Faces = 0;
  /// Where a mesh's edge crosses a face of the cell: a crease tile's x
  /// (CreaseCrossing.h) or a point of an exact neighbour's trace (ExactCell.h).
  bool OnMeshEdge = false;
};

enum class LoopPatchKind
{
  Triangle, ///< the three loop points
  LoopFan,  ///< k - 2 triangles from loop point FanPoint
  ApexFan   ///< k triangles around Apex
};

struct LoopPatch
{
  LoopPatchKind Kind = LoopPatchKind::ApexFan;
  int FanPoint = -1;
  Vec3 Apex;
};

/// How to span `loop` (at least three points, in order) inside its cell, with
/// an apex (if any) in `room` (the whole cell for a lone loop, ApexRooms.h).
/// `planeSection`: the surface in the cell is a union of plane sections kept
/// larger than the tolerance (PlanarCell.h), so the patch must stay in the
/// loop's plane up to rounding: the apex is the loop's centroid. Otherwise the
/// apex recovers sharp features from the crossing normals (as Extended Marching
/// Cubes does) and keeps 1/32 of the region's width from its boundary.
/// `expression` (pruned to the cell) places apexes of caps over one face.
/// `surface`: the cell's error is certified (QuadricCellError.h); the apex is
/// then put on the surface where it can be, so that it adds no error.
/// `meshApex`: the cell's error is certified where meshes are the surface
/// (MeshCellError.h, MeshBooleanCellError.h): the patch is the fan around
/// that apex (moved into the room, KeptInRoom), whatever the loop, as the
/// certificate requires.
LoopPatch TriangulateLoop(const std::vector<LoopPoint>& loop, const ApexRoom& room, bool planeSection,
  const CsgExpression& expression, const PrimitiveSet& primitives, const QuadricCellError* surface = nullptr,
  const Vec3* meshApex = nullptr);

/// The faces of `cell` (bits, as LoopPoint::Faces) a loop point at
/// `position` lies on, `faces` being those its crossing names: a sub-edge's
/// crossing is placed strictly inside its sub-edge (CrossingVertices.h), so
/// `faces` it is; a mesh edge's point (`onMeshEdge`) lies on its face's
/// plane exactly, and where its position is not strictly inside the face
/// along the other two axes the faces it lies on are not known: all six.
unsigned FacesAsPlaced(unsigned faces, bool onMeshEdge, const Vec3& position, const Box3& cell);

/// Marching Cubes' fan: the loop point whose fan satisfies case 2 of the
/// header (no other point on a face with it but its neighbours) and faces
/// the way the normals do, with the shortest diagonals; -1 if none, or if
/// the surface is not smooth along the loop (every crossing normal within
/// 25 degrees of their mean: no crease or corner for an apex to keep sharp).
int LoopFanPoint(const std::vector<LoopPoint>& loop);

/// The point of the loop on a mesh edge (LoopPoint::OnMeshEdge) whose fan
/// satisfies case 2 of the header and faces the way the normals do, with the
/// shortest diagonals; -1 if none. The loop need not be smooth: an
/// apex fan draws a crease through a cell as two spokes x -> c -> x' and
/// tilts the faces beside it wherever c is off the crease, while from x the
/// diagonal x -> x' runs along a straight crease and each planar side is
/// drawn in its plane, by k - 2 triangles. The caller certifies its error
/// (MeshCellError.h) and keeps it only where that is small: a curved crease,
/// a corner or a point of a smooth trace make the diagonals cut across S.
int MeshEdgeFanPoint(const std::vector<LoopPoint>& loop);

} // namespace tpc
