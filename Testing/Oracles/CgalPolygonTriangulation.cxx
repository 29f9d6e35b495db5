#include "CgalPolygonTriangulation.h"

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Polygon_mesh_processing/polygon_soup_to_polygon_mesh.h>
#include <CGAL/Polygon_mesh_processing/triangulate_faces.h>
#include <CGAL/Surface_mesh.h>

namespace tpcoracle
{

std::vector<std::array<std::uint32_t, 3>> TriangulateFacesWithCgal(
  const std::vector<std::array<double, 3>>& points, const std::vector<std::vector<std::uint32_t>>& polygons)
{
  using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;
  using Mesh = CGAL::Surface_mesh<Kernel::Point_3>;
  std::vector<Kernel::Point_3> soupPoints;
  for (const auto& p : points)
  {
    soupPoints.emplace_back(p[0], p[1], p[2]);
  }
  std::vector<std::vector<std::size_t>> soupPolygons;
  for (const auto& polygon : polygons)
  {
    soupPolygons.emplace_back(polygon.begin(), polygon.end());
  }
  Mesh mesh;
  // (The soup's points become the mesh's vertices in order: ids are kept.)
  CGAL::Polygon_mesh_processing::polygon_soup_to_polygon_mesh(soupPoints, soupPolygons, mesh);
  CGAL::Polygon_mesh_processing::triangulate_faces(mesh);
  std::vector<std::array<std::uint32_t, 3>> triangles;
  for (const Mesh::Face_index f : mesh.faces())
  {
    std::array<std::uint32_t, 3> t{};
    int k = 0;
    for (const Mesh::Vertex_index v : CGAL::vertices_around_face(mesh.halfedge(f), mesh))
    {
      t[static_cast<std::size_t>(k++)] = static_cast<std::uint32_t>(v.idx());
    }
    triangles.push_back(t);
  }
  return triangles;
}

} // namespace tpcoracle
