#include "CgalEmbedding.h"

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Polygon_mesh_processing/orient_polygon_soup.h>
#include <CGAL/Polygon_mesh_processing/polygon_soup_to_polygon_mesh.h>
#include <CGAL/Polygon_mesh_processing/self_intersections.h>
#include <CGAL/Surface_mesh.h>

#include <algorithm>
#include <cstdlib>
#include <iterator>

namespace tpcoracle
{

EmbeddingVerdict CheckEmbeddingWithCgal(
  const std::vector<std::array<double, 3>>& points, const std::vector<std::array<std::uint32_t, 3>>& triangles)
{
  using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;
  using Mesh = CGAL::Surface_mesh<Kernel::Point_3>;
  namespace PMP = CGAL::Polygon_mesh_processing;

  EmbeddingVerdict v;
  if (std::getenv("TPC_SKIP_CGAL_ORACLE"))
  {
    v.Checked = false;
    return v;
  }
  std::vector<std::array<double, 3>> sorted = points;
  std::sort(sorted.begin(), sorted.end());
  for (std::size_t i = 1; i < sorted.size(); ++i)
  {
    v.CoincidentVertices += sorted[i] == sorted[i - 1] ? 1 : 0;
  }

  std::vector<Kernel::Point_3> cgalPoints;
  cgalPoints.reserve(points.size());
  for (const auto& p : points)
  {
    cgalPoints.emplace_back(p[0], p[1], p[2]);
  }
  std::vector<std::vector<std::size_t>> faces;
  faces.reserve(triangles.size());
  for (const auto& t : triangles)
  {
    faces.push_back({ t[0], t[1], t[2] });
  }
  // Vertex ids are kept when the triangles form an oriented manifold mesh;
  // otherwise CGAL reorients the soup first (splitting non-manifold vertices
  // into coincident copies, which then touch: the verdict stays "not embedded").
  v.PolygonMesh = PMP::is_polygon_soup_a_polygon_mesh(faces);
  if (!v.PolygonMesh)
  {
    PMP::orient_polygon_soup(cgalPoints, faces);
  }
  Mesh mesh;
  PMP::polygon_soup_to_polygon_mesh(cgalPoints, faces, mesh);
  std::vector<std::pair<Mesh::Face_index, Mesh::Face_index>> pairs;
  PMP::self_intersections(mesh, std::back_inserter(pairs));
  v.SelfIntersectingPairs = pairs.size();
  return v;
}

} // namespace tpcoracle
