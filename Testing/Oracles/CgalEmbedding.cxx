#include "CgalEmbedding.h"

#include <CGAL/Exact_predicates_exact_constructions_kernel.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/intersections.h>
#include <CGAL/Polygon_mesh_processing/orient_polygon_soup.h>
#include <CGAL/Polygon_mesh_processing/orientation.h>
#include <CGAL/Polygon_mesh_processing/repair.h>
#include <CGAL/Polygon_mesh_processing/polygon_soup_to_polygon_mesh.h>
#include <CGAL/Polygon_mesh_processing/self_intersections.h>
#include <CGAL/Surface_mesh.h>

#include <algorithm>
#include <cstdlib>
#include <functional>
#include <iterator>

namespace tpcoracle
{

bool TrianglePairMeetsImproperly(const std::vector<std::array<double, 3>>& points,
  const std::array<std::uint32_t, 3>& t1, const std::array<std::uint32_t, 3>& t2)
{
  using Kernel = CGAL::Exact_predicates_exact_constructions_kernel;
  auto point = [&](std::uint32_t i) { return Kernel::Point_3(points[i][0], points[i][1], points[i][2]); };
  const Kernel::Triangle_3 a(point(t1[0]), point(t1[1]), point(t1[2])), b(point(t2[0]), point(t2[1]), point(t2[2]));
  std::vector<std::uint32_t> shared;
  for (const auto i : t1)
  {
    if (std::find(t2.begin(), t2.end(), i) != t2.end())
    {
      shared.push_back(i);
    }
  }
  const auto meet = CGAL::intersection(a, b);
  if (!meet)
  {
    return false;
  }
  if (shared.size() == 1)
  {
    const Kernel::Point_3* p = boost::get<Kernel::Point_3>(&*meet);
    return !p || *p != point(shared[0]);
  }
  if (shared.size() == 2)
  {
    const Kernel::Segment_3* s = boost::get<Kernel::Segment_3>(&*meet);
    const Kernel::Segment_3 edge(point(shared[0]), point(shared[1]));
    return !s || !(*s == edge || *s == edge.opposite());
  }
  return true; // no shared vertex (or the same triangle)
}

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
  if (v.PolygonMesh && pairs.empty() && !faces.empty() && CGAL::is_closed(mesh))
  {
    // (does_bound_a_volume also accepts an inward component at level 0, the
    // boundary of the unbounded volume outside it: the orientation of each
    // component is compared with its nesting level here instead.)
    PMP::remove_isolated_vertices(mesh); // (points no triangle uses: CGAL's volume test crashes on them)
    std::vector<std::size_t> levels;
    std::vector<bool> outward;
    auto volumeOf = mesh.add_property_map<Mesh::Face_index, std::size_t>("f:volume", 0).first;
    PMP::volume_connected_components(mesh, volumeOf,
      PMP::parameters::nesting_levels(std::ref(levels)).is_cc_outward_oriented(std::ref(outward)).do_orientation_tests(true));
    v.Outward = !levels.empty() && levels.size() == outward.size();
    for (std::size_t c = 0; c < levels.size() && v.Outward; ++c)
    {
      v.Outward = outward[c] == (levels[c] % 2 == 0);
    }
    v.VolumeChecked = true;
  }
  return v;
}

} // namespace tpcoracle
