// The faces of a polygon mesh (OFF, OBJ, PLY: nearly planar, possibly
// non-convex polygons) as triangles, without losing one: every polygon of n
// corners becomes n - 2 triangles that use exactly its edges and diagonals,
// so a closed polygon mesh stays closed. (VTK's vtkPolygon::Triangulate
// decides with tolerances and drops triangles of nearly planar non-convex
// faces: CGAL's closed mpi.off and double-torus-example.off were refused as
// open.)
//
// Ear clipping in a projection decided by exact orientation tests. The
// polygon is projected onto the coordinate plane most nearly parallel to it
// (the largest component of its Newell normal), by dropping one coordinate:
// the projected points are the input's own doubles, so every orientation
// test on them is exact (Orient2D). An ear is a corner c, between p and n,
// that turns strictly left (Orient2D(p, c, n) > 0) and whose closed
// triangle p, c, n holds no other corner of the remaining polygon (corners
// at the position of p, c or n excepted). Clipping such an ear keeps the
// remaining polygon simple and of positive area, and every simple polygon
// of positive area with four or more corners has one - also with collinear
// corners, since it has a triangulation by diagonals without degenerate
// triangles, whose dual tree has a leaf, and a leaf triangle is such an ear.
// So when the projection is simple the triangles are never degenerate in it,
// their projections tile the projected polygon without overlap, and
// triangles whose projections do not overlap cannot intersect in space
// except along the edges and corners they share.
//
// Cost: each ear test scans the remaining ring, so a convex or typical face
// of n corners takes O(n^2) orientation tests (n^3 at worst); mesh faces have
// tens of corners.
//
// When no ear is found (the projection is not simple: a polygon folded over
// itself, or of zero area) the polygon is fanned from its first corner:
// still n - 2 triangles on its edges, so the mesh stays closed; the exact
// self-intersection test then reports any overlap.
#pragma once

#include "TriangleMesh.h"
#include "Vector3.h"

#include <cstddef>
#include <cstdint>
#include <vector>

namespace tpc
{

enum class PolygonTriangulation
{
  Ears, ///< exact ear clipping: the triangles tile the polygon's projection
  Fan   ///< no ear in the projection: fanned from the first corner
};

/// Appends to `triangles` the n - 2 triangles of the polygon whose corners
/// are points[corners[0]], ..., points[corners[n - 1]] (n >= 3), each
/// oriented as the polygon. Triangles (n = 3) are appended as they are.
PolygonTriangulation TriangulatePolygon(
  const std::vector<Vec3>& points, const std::uint32_t* corners, std::size_t n, std::vector<Triangle>& triangles);

} // namespace tpc
