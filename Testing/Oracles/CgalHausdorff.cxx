#include "CgalHausdorff.h"

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Polygon_mesh_processing/distance.h>
#include <CGAL/Polygon_mesh_processing/orient_polygon_soup.h>
#include <CGAL/Polygon_mesh_processing/polygon_soup_to_polygon_mesh.h>
#include <CGAL/Surface_mesh.h>

#include <algorithm>

namespace tpcoracle
{
namespace
{
using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;
using Mesh = CGAL::Surface_mesh<Kernel::Point_3>;

Mesh AsCgalMesh(const TriangleSoup& soup)
{
  std::vector<Kernel::Point_3> points;
  for (const auto& p : soup.Points)
  {
    points.emplace_back(p[0], p[1], p[2]);
  }
  std::vector<std::vector<std::size_t>> polygons;
  for (const auto& t : soup.Triangles)
  {
    polygons.push_back({ t[0], t[1], t[2] });
  }
  if (!CGAL::Polygon_mesh_processing::is_polygon_soup_a_polygon_mesh(polygons))
  {
    CGAL::Polygon_mesh_processing::orient_polygon_soup(points, polygons);
  }
  Mesh mesh;
  CGAL::Polygon_mesh_processing::polygon_soup_to_polygon_mesh(points, polygons, mesh);
  return mesh;
}
} // namespace

HausdorffEstimate DirectedHausdorffWithCgal(const TriangleSoup& from, const TriangleSoup& to, double errorBound)
{
  const Mesh a = AsCgalMesh(from), b = AsCgalMesh(to);
  const double d =
    CGAL::Polygon_mesh_processing::bounded_error_Hausdorff_distance<CGAL::Sequential_tag>(a, b, errorBound);
  return { std::max(0.0, d - errorBound), d + errorBound };
}

} // namespace tpcoracle
