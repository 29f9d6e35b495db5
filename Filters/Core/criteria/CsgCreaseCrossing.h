// Creases of a CSG solid as polylines of the output (issue 17).
//
// Where two primitives of a CSG scene meet (a box's edge, a drilled hole's
// rim, a sphere clipping a cube) the surface has a crease, and a loop's chord
// across a face tile the crease crosses cuts its corner: the output's crease
// is a saw-tooth of chamfers, as a mesh's was before CreaseCrossing.h. A CSG
// crease tile is drawn through the crease's crossing of the tile instead
// (a -> x -> b), so the fans on both sides of the face have x as a vertex,
// and with their apexes at the tangent planes' point (Extended Marching
// Cubes, LoopTriangulation.h), on the crease, the crease runs through the
// output's edges.
//
// A tile is a CSG crease tile when the cell's expression pruned to the tile
// has exactly two leaves, both quadrics (planes, spheres, cylinders, a box's
// faces; a mesh among them: Meshes, below), whose zero curves on the tile's
// plane cross transversally at a point x that Newton's method (from the tile's centre, else its corners and
// sides' middles, on the two leaves' values) finds strictly inside the
// tile, at least a millionth of its width from every side. x is on the surface (both leaves vanish there, and only they
// are left), so the trace of the surface on the tile - one arc from a to b
// where the tile holds one chord - runs through it.
//
// Meshes (a Boolean of meshes, or of a mesh and a quadric: where the two
// solids' surfaces meet). A mesh leaf's trace on the tile's plane is the
// set of segments its listed triangles (those that may meet the tile) cut
// from the plane; x is where the two traces cross - a segment of one mesh's
// against a segment of the other's, or a mesh's segment against the
// quadric's zero curve, along which the quadric is a quadratic in the
// segment's parameter (its values at the ends and the middle give it) - when
// exactly one such crossing lies in the tile grown by the millionth, that
// one lies the millionth inside it, and the two surfaces cross there at a
// sine of at least Transversal (their normals projected on the plane). x is
// then on both leaves, so on the surface, as above. A listed triangle that
// touches the plane at a vertex or lies in it, or a second crossing, and the
// tile is drawn straight, as before. A surface cell whose expression holds a
// mesh and a quadric is never accepted larger than the tolerance (a cell
// stopped by a limit may be, but is not guaranteed), nor one where meshes
// meet unless its fan was predicted (MeshBooleanCellError.h): a crease cell
// of the tolerance's size is bounded by its size, and its apex goes to the
// middle of the loop's two crease vertices (LoopTriangulation.cxx,
// ApexOnCrease), so the output's crease runs from crease vertex to apex to
// crease vertex along the chord of the exact crease through the cell; a
// larger one where meshes meet draws its fan around the point of the crease
// it was accepted with, its patch certified (the fan over its own loop
// following the crease within a tenth of the tolerance, the final fan
// checked again: MeshBooleanCellError.h, Creases). A tilted box minus a 96-sided prism, as
// two meshes (`Filter.Creases.MeshBooleanCreasesAreFollowedByOutputEdges`):
// the output's 30-degree edges on the rims 0.24 -> 1.01 of their length at
// 1/64, and beside them (a saw-tooth) 2.86 -> 0.22; with larger cells where
// the meshes meet, 1.02 and 0.23.
// A cell of one mesh alone does not mark CSG crease tiles (its tiles are
// decided as one mesh's, CreaseCrossing.h), while its neighbour across a
// face, holding the mesh and another leaf, does: they still agree, since
// the other leaf keeps one sign over the lone cell's closed box - so on the
// tile it has no listed triangles (a mesh: no trace, no crossing), or it is
// a quadric that at most touches zero there, whose gradient along the plane
// then vanishes (the sine is 0 or NaN): the tile is drawn straight on both
// sides.
//
// Why the output stays what the guarantee says. Embedded: a and b lie on the
// tile's boundary and x strictly inside it, so the segments a -> x -> b lie
// in the convex tile and meet its boundary at a and b only - the argument of
// LoopTriangulation.h for crease tiles; the loop stays simple and the fans
// embedded. Closed: both cells sharing the tile decide alike - they decide
// with the same expression, that of a crease-fan cell if one of them is one
// (OctreeNode::CreaseFan), else of the one first in node order (each cell's
// own is pruned to its own box, and an enclosure that decides a leaf over one
// cell's box need not decide it over the tile, so the two could keep
// different leaves), which is also the cell that places x (CrossingVertices.h);
// x is named by its tile and placed by recomputing it, so both loops hold one
// vertex (a mesh leaf's trace is recomputed from the same listed triangles,
// those of the same pruned expression). Hausdorff: a crease cell no larger
// than the tolerance is bounded by its size; a larger one is a crease fan,
// certified (two quadrics: QuadricCellError.h; meshes meeting:
// MeshBooleanCellError.h, MeshBooleanSurface.h). The result is checked
// exactly anyway (SurfaceEmbedding.h).
#pragma once

#include "BoundaryLoops.h"
#include "CsgExpression.h"

#include <optional>

namespace tpc
{

/// The vertex a CSG crease tile's chord is bent through, named by its tile:
/// Tile its low corner and plane axis (as a bend's), Key and Partner its far
/// corner's coordinates along the plane's two axes.
Crossing CsgCreaseCrossing(int axis, LatticeIndex plane, const FaceTile& tile);

/// Where the crease of `expression` crosses tile `tile` of the lattice plane
/// x_axis = `plane`, when it is a CSG crease tile (header); nothing otherwise.
std::optional<Vec3> CsgCreaseOnTile(const CsgExpressionPtr& expression, const PrimitiveSet& primitives,
  const RootGrid& grid, int axis, LatticeIndex plane, const FaceTile& tile);

/// The position of a CsgCrease crossing `x` (its tile decoded) and the
/// bisector of the two leaves' outward normals there; nothing when its tile
/// is not a crease tile of `expression`.
std::optional<std::pair<Vec3, Vec3>> CsgCreaseVertex(
  const Crossing& x, const CsgExpressionPtr& expression, const PrimitiveSet& primitives, const RootGrid& grid);

/// The points of the loop `loop` (sub-edge crossings and CSG crease
/// crossings of `expression`'s crease tiles) as the extraction places them,
/// in `points`; false when a crossing is of another kind or its tile is no
/// crease tile.
bool PlaceCsgLoopPoints(const std::vector<Crossing>& loop, const CsgExpressionPtr& expression,
  const PrimitiveSet& primitives, const RootGrid& grid, std::vector<Vec3>& points);

/// The centre of a CsgCrease crossing's tile.
Vec3 CsgCreaseTileCentre(const Crossing& x, const RootGrid& grid);

/// Marks in boundary.Creases the CSG crease tiles of every face where no
/// mesh crease is marked, each decided with the expression
/// `expressionOf(f, k)` returns (none: the tile is drawn straight).
template <typename ExpressionOf>
void MarkCsgCreaseTiles(
  CellBoundary& boundary, const PrimitiveSet& primitives, const RootGrid& grid, const ExpressionOf& expressionOf)
{
  for (int f = 0; f < 6; ++f)
  {
    const int axis = f / 2;
    const LatticeIndex plane = boundary.Base[axis] + (f % 2 ? boundary.Size : 0);
    boundary.Creases[f].resize(boundary.Tiles[f].size());
    for (std::size_t k = 0; k < boundary.Tiles[f].size(); ++k)
    {
      if (boundary.Creases[f][k])
      {
        continue;
      }
      const CsgExpressionPtr* expression = expressionOf(f, k);
      if (expression && *expression &&
        CsgCreaseOnTile(*expression, primitives, grid, axis, plane, boundary.Tiles[f][k]))
      {
        boundary.Creases[f][k] = CreaseTile{ CsgCreaseCrossing(axis, plane, boundary.Tiles[f][k]), Vec3(), {} };
      }
    }
  }
}

} // namespace tpc
