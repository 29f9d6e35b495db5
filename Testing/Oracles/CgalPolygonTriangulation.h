// An oracle for sampling polygon meshes: CGAL's triangulation of each face in
// its own plane, independent of the product's PolygonTriangulation.h (and of
// VTK's, which puts triangles of nearly planar non-convex faces outside
// them). CGAL is GPL: linked into test programs only, never into the product.
#pragma once

#include <array>
#include <cstdint>
#include <vector>

namespace tpcoracle
{

/// The triangles of CGAL::Polygon_mesh_processing::triangulate_faces (each
/// face triangulated in its best-fitting plane) of the closed polygon mesh
/// (points, polygons), by the same vertex ids.
std::vector<std::array<std::uint32_t, 3>> TriangulateFacesWithCgal(
  const std::vector<std::array<double, 3>>& points, const std::vector<std::vector<std::uint32_t>>& polygons);

} // namespace tpcoracle
