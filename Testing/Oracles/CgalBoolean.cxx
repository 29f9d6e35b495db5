#include "CgalBoolean.h"

#include <CGAL/Exact_predicates_exact_constructions_kernel.h>
#include <CGAL/Polygon_mesh_processing/connected_components.h>
#include <CGAL/Polygon_mesh_processing/corefinement.h>
#include <CGAL/Polygon_mesh_processing/intersection.h>
#include <CGAL/Polygon_mesh_processing/orientation.h>
#include <CGAL/Polygon_mesh_processing/polygon_soup_to_polygon_mesh.h>
#include <CGAL/Polygon_mesh_processing/repair.h>
#include <CGAL/Polygon_mesh_processing/self_intersections.h>
#include <CGAL/Surface_mesh.h>

#include <cstdlib>
#include <iterator>

namespace tpcoracle
{
namespace
{
using Kernel = CGAL::Exact_predicates_exact_constructions_kernel;
using Mesh = CGAL::Surface_mesh<Kernel::Point_3>;
namespace PMP = CGAL::Polygon_mesh_processing;

/// The solid bounded by the triangles, as a closed mesh oriented to bound
/// its volume; false where the triangles are not a closed manifold mesh
/// free of self-intersections.
bool SolidMesh(const TriangleSoup& soup, Mesh& mesh)
{
  std::vector<Kernel::Point_3> exact;
  for (const auto& p : soup.Points)
  {
    exact.emplace_back(p[0], p[1], p[2]);
  }
  std::vector<std::vector<std::size_t>> faces;
  for (const auto& t : soup.Triangles)
  {
    faces.push_back({ t[0], t[1], t[2] });
  }
  if (faces.empty() || !PMP::is_polygon_soup_a_polygon_mesh(faces))
  {
    return false;
  }
  PMP::polygon_soup_to_polygon_mesh(exact, faces, mesh);
  if (!CGAL::is_closed(mesh) || PMP::does_self_intersect(mesh))
  {
    return false;
  }
  PMP::orient_to_bound_a_volume(mesh);
  return true;
}
} // namespace

BooleanTopology ExactBooleanTopology(const TriangleSoup& soupA, const TriangleSoup& soupB, BooleanOperation operation)
{
  BooleanTopology result;
  if (std::getenv("TPC_SKIP_CGAL_ORACLE"))
  {
    result.Checked = false;
    return result;
  }
  Mesh a, b, out;
  if (!SolidMesh(soupA, a) || !SolidMesh(soupB, b))
  {
    return result;
  }
  result.SurfacesMeet = PMP::do_intersect(a, b); // (the surfaces only: bounded sides not tested)
  // (Each returns false when the result is not a 2-manifold.)
  const bool manifold = operation == BooleanOperation::Union ? PMP::corefine_and_compute_union(a, b, out)
    : operation == BooleanOperation::Intersection          ? PMP::corefine_and_compute_intersection(a, b, out)
                                                            : PMP::corefine_and_compute_difference(a, b, out);
  // (Surfaces touching at a point - a vertex on a face, two edges crossing
  // - make no intersection line: corefinement copies both sides with
  // coincident but separate vertices, a closed manifold mesh that touches
  // itself. Its self-intersection says so.)
  std::vector<Mesh::Halfedge_index> pinched; // (a halfedge per umbrella of each pinched vertex)
  PMP::non_manifold_vertices(out, std::back_inserter(pinched));
  if (!manifold || !pinched.empty() || !CGAL::is_closed(out) || PMP::does_self_intersect(out))
  {
    return result;
  }
  auto component = out.add_property_map<Mesh::Face_index, std::size_t>("f:component", 0).first;
  result.Components = static_cast<long long>(PMP::connected_components(out, component));
  const long long euler = static_cast<long long>(out.number_of_vertices()) -
    static_cast<long long>(out.number_of_edges()) + static_cast<long long>(out.number_of_faces());
  if ((2 * result.Components - euler) % 2 != 0)
  {
    return BooleanTopology{}; // (not a closed orientable surface after all)
  }
  result.Genus = (2 * result.Components - euler) / 2;
  // (Indexed by vertex: the mesh may have holes in its numbering.)
  std::vector<std::uint32_t> index(out.num_vertices(), 0);
  for (const Mesh::Vertex_index v : out.vertices())
  {
    index[v] = static_cast<std::uint32_t>(result.Surface.Points.size());
    const Kernel::Point_3& p = out.point(v);
    result.Surface.Points.push_back({ CGAL::to_double(p.x()), CGAL::to_double(p.y()), CGAL::to_double(p.z()) });
  }
  for (const Mesh::Face_index f : out.faces())
  {
    std::vector<std::uint32_t> corners;
    for (const Mesh::Vertex_index v : CGAL::vertices_around_face(out.halfedge(f), out))
    {
      corners.push_back(index[v]);
    }
    if (corners.size() != 3)
    {
      return BooleanTopology{}; // (corefinement keeps triangle meshes triangulated)
    }
    result.Surface.Triangles.push_back({ corners[0], corners[1], corners[2] });
  }
  result.Valid = true;
  return result;
}

} // namespace tpcoracle
