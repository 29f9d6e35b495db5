// Reference topology for the mesh CSG tests, computed independently of our
// method: CGAL's corefinement Booleans (Polygon Mesh Processing) on an exact
// kernel, then components and Euler characteristic of the result.
//
//   CsgReference <meshA.off> <B> <union|intersection|difference> [tx ty tz]
//
// B is a mesh file (translated by t, as the test translates it) or
// "spheres:cx cy cz r;cx cy cz r;..." - a union of spheres, approximated
// here by icospheres fine enough (5 subdivisions, relative error < 2e-4)
// that the configurations used, which are far from tangency, keep the exact
// spheres' topology. Prints "components genus euler angle gap": angle is the
// smallest angle between crossing triangles of the two operands (degrees, -1
// where they do not cross); gap, where they do not meet, is the distance
// between them relative to the diagonal of their common bounding box (the
// filter's domain), else -1. Not built by default
// (configure with -DTPC_BUILD_CSG_REFERENCE=ON); its results are recorded in
// Data/CsgReference.csv.
#include <CGAL/Exact_predicates_exact_constructions_kernel.h>
#include <CGAL/Cartesian_converter.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Polygon_mesh_processing/connected_components.h>
#include <CGAL/Polygon_mesh_processing/corefinement.h>
#include <CGAL/Polygon_mesh_processing/IO/polygon_mesh_io.h>
#include <CGAL/Polygon_mesh_processing/orientation.h>
#include <CGAL/Polygon_mesh_processing/polygon_soup_to_polygon_mesh.h>
#include <CGAL/Polygon_mesh_processing/self_intersections.h>
#include <CGAL/Surface_mesh.h>

#include <array>
#include <cmath>
#include <cstdlib>
#include <iostream>
#include <limits>
#include <map>
#include <sstream>
#include <string>
#include <vector>

using Kernel = CGAL::Exact_predicates_exact_constructions_kernel;
using Inexact = CGAL::Exact_predicates_inexact_constructions_kernel;
using Mesh = CGAL::Surface_mesh<Kernel::Point_3>;
namespace PMP = CGAL::Polygon_mesh_processing;

namespace
{
Mesh Icosphere(double cx, double cy, double cz, double r, int levels)
{
  const double t = (1.0 + std::sqrt(5.0)) / 2.0;
  std::vector<std::array<double, 3>> p = { { -1, t, 0 }, { 1, t, 0 }, { -1, -t, 0 }, { 1, -t, 0 },
    { 0, -1, t }, { 0, 1, t }, { 0, -1, -t }, { 0, 1, -t }, { t, 0, -1 }, { t, 0, 1 }, { -t, 0, -1 },
    { -t, 0, 1 } };
  std::vector<std::vector<std::size_t>> f = { { 0, 11, 5 }, { 0, 5, 1 }, { 0, 1, 7 }, { 0, 7, 10 },
    { 0, 10, 11 }, { 1, 5, 9 }, { 5, 11, 4 }, { 11, 10, 2 }, { 10, 7, 6 }, { 7, 1, 8 }, { 3, 9, 4 },
    { 3, 4, 2 }, { 3, 2, 6 }, { 3, 6, 8 }, { 3, 8, 9 }, { 4, 9, 5 }, { 2, 4, 11 }, { 6, 2, 10 },
    { 8, 6, 7 }, { 9, 8, 1 } };
  for (int l = 0; l < levels; ++l)
  {
    std::map<std::pair<std::size_t, std::size_t>, std::size_t> mid;
    auto midpoint = [&](std::size_t a, std::size_t b) {
      const auto key = std::minmax(a, b);
      auto it = mid.find(key);
      if (it != mid.end())
      {
        return it->second;
      }
      p.push_back({ (p[a][0] + p[b][0]) / 2, (p[a][1] + p[b][1]) / 2, (p[a][2] + p[b][2]) / 2 });
      return mid[key] = p.size() - 1;
    };
    std::vector<std::vector<std::size_t>> g;
    for (const auto& tri : f)
    {
      const std::size_t a = midpoint(tri[0], tri[1]), b = midpoint(tri[1], tri[2]), c = midpoint(tri[2], tri[0]);
      g.push_back({ tri[0], a, c });
      g.push_back({ tri[1], b, a });
      g.push_back({ tri[2], c, b });
      g.push_back({ a, b, c });
    }
    f.swap(g);
  }
  std::vector<Kernel::Point_3> points;
  for (const auto& q : p)
  {
    const double n = std::sqrt(q[0] * q[0] + q[1] * q[1] + q[2] * q[2]);
    points.emplace_back(cx + r * q[0] / n, cy + r * q[1] / n, cz + r * q[2] / n);
  }
  Mesh m;
  PMP::polygon_soup_to_polygon_mesh(points, f, m);
  PMP::orient_to_bound_a_volume(m);
  return m;
}

bool ReadMesh(const std::string& file, double tx, double ty, double tz, Mesh& m)
{
  if (!PMP::IO::read_polygon_mesh(file, m) || !CGAL::is_closed(m))
  {
    std::cerr << "cannot read a closed mesh from " << file << "\n";
    return false;
  }
  for (auto v : m.vertices())
  {
    // Translate in double, as VTK does, then make it exact.
    const auto& q = m.point(v);
    m.point(v) = Kernel::Point_3(CGAL::to_double(q.x()) + tx, CGAL::to_double(q.y()) + ty,
      CGAL::to_double(q.z()) + tz);
  }
  PMP::orient_to_bound_a_volume(m);
  return true;
}

bool Boolean(Mesh& a, Mesh& b, const std::string& op, Mesh& out)
{
  if (PMP::does_self_intersect(a) || PMP::does_self_intersect(b))
  {
    std::cerr << "an operand self-intersects\n";
    return false;
  }
  if (op == "union")
  {
    return PMP::corefine_and_compute_union(a, b, out);
  }
  if (op == "intersection")
  {
    return PMP::corefine_and_compute_intersection(a, b, out);
  }
  return PMP::corefine_and_compute_difference(a, b, out);
}
/// The triangle of a face of a (triangle) mesh.
Kernel::Triangle_3 FaceTriangle(const Mesh& m, Mesh::Face_index f)
{
  const auto h = m.halfedge(f);
  return { m.point(m.source(h)), m.point(m.target(h)), m.point(m.target(m.next(h))) };
}

/// The smallest angle (degrees, 0 to 90) between the planes of two crossing
/// triangles, one of each mesh: how shallow the intersection is, which is
/// what makes a Boolean hard for the filter (thin wedges along the curve).
/// Brute force over bounding-box-overlapping pairs (the test meshes are
/// small); -1 when the meshes do not meet.
double MinimumCrossingAngle(const Mesh& a, const Mesh& b)
{
  std::vector<std::pair<Kernel::Triangle_3, CGAL::Bbox_3>> fb;
  for (auto f : b.faces())
  {
    const Kernel::Triangle_3 t = FaceTriangle(b, f);
    fb.emplace_back(t, t.bbox());
  }
  double smallest = -1.0;
  for (auto f : a.faces())
  {
    const Kernel::Triangle_3 ta = FaceTriangle(a, f);
    const CGAL::Bbox_3 box = ta.bbox();
    const auto na = ta.supporting_plane().orthogonal_vector();
    const double ax = CGAL::to_double(na.x()), ay = CGAL::to_double(na.y()), az = CGAL::to_double(na.z());
    for (const auto& [tb, boxB] : fb)
    {
      if (!CGAL::do_overlap(box, boxB) || !CGAL::do_intersect(ta, tb))
      {
        continue;
      }
      const auto nb = tb.supporting_plane().orthogonal_vector();
      const double bx = CGAL::to_double(nb.x()), by = CGAL::to_double(nb.y()), bz = CGAL::to_double(nb.z());
      const double c = std::fabs(ax * bx + ay * by + az * bz) /
        (std::sqrt(ax * ax + ay * ay + az * az) * std::sqrt(bx * bx + by * by + bz * bz));
      const double angle = std::acos(std::min(1.0, c)) * 180.0 / M_PI;
      smallest = smallest < 0.0 ? angle : std::min(smallest, angle);
    }
  }
  return smallest;
}

/// A mesh's triangles in doubles with their boxes (distances need no exact
/// constructions: the gap is reported, not decided on).
std::vector<std::pair<Inexact::Triangle_3, CGAL::Bbox_3>> InexactTriangles(const Mesh& m)
{
  const CGAL::Cartesian_converter<Kernel, Inexact> toDoubles;
  std::vector<std::pair<Inexact::Triangle_3, CGAL::Bbox_3>> triangles;
  for (auto f : m.faces())
  {
    const Inexact::Triangle_3 t = toDoubles(FaceTriangle(m, f));
    triangles.emplace_back(t, t.bbox());
  }
  return triangles;
}

/// Distance between two disjoint triangles: attained at a vertex of one and
/// the other triangle, or between two edges.
double TriangleDistance(const Inexact::Triangle_3& s, const Inexact::Triangle_3& t)
{
  double d2 = std::numeric_limits<double>::infinity();
  for (int i = 0; i < 3; ++i)
  {
    d2 = std::min({ d2, CGAL::to_double(CGAL::squared_distance(s.vertex(i), t)),
      CGAL::to_double(CGAL::squared_distance(t.vertex(i), s)) });
    for (int j = 0; j < 3; ++j)
    {
      const Inexact::Segment_3 a(s.vertex(i), s.vertex((i + 1) % 3)), b(t.vertex(j), t.vertex((j + 1) % 3));
      d2 = std::min(d2, CGAL::to_double(CGAL::squared_distance(a, b)));
    }
  }
  return std::sqrt(d2);
}

/// Squared distance between two boxes (0 where they overlap).
double BoxDistance2(const CGAL::Bbox_3& a, const CGAL::Bbox_3& b)
{
  double d2 = 0.0;
  for (int k = 0; k < 3; ++k)
  {
    const double g = std::max({ 0.0, a.min(k) - b.max(k), b.min(k) - a.max(k) });
    d2 += g * g;
  }
  return d2;
}

/// The distance between two meshes that do not meet: brute force over the
/// triangle pairs whose boxes are closer than the best so far, seeded by the
/// closest pair of vertices (the test meshes are small).
double MinimumDistance(const Mesh& a, const Mesh& b)
{
  const auto ta = InexactTriangles(a), tb = InexactTriangles(b);
  double best = std::numeric_limits<double>::infinity();
  for (const auto& [s, boxS] : ta)
  {
    for (const auto& [t, boxT] : tb)
    {
      best = std::min(best, std::sqrt(CGAL::to_double(CGAL::squared_distance(s.vertex(0), t.vertex(0)))));
    }
  }
  for (const auto& [s, boxS] : ta)
  {
    for (const auto& [t, boxT] : tb)
    {
      if (BoxDistance2(boxS, boxT) < best * best)
      {
        best = std::min(best, TriangleDistance(s, t));
      }
    }
  }
  return best;
}

/// The distance from a point to a surface (its InexactTriangles).
double DistanceToSurface(const std::vector<std::pair<Inexact::Triangle_3, CGAL::Bbox_3>>& surface,
  const Inexact::Point_3& p)
{
  double d2 = std::numeric_limits<double>::infinity();
  for (const auto& [t, box] : surface)
  {
    d2 = std::min(d2, CGAL::to_double(CGAL::squared_distance(p, t)));
  }
  return std::sqrt(d2);
}

/// The diagonal of the box holding both meshes (the filter's domain).
double CommonDiagonal(const Mesh& a, const Mesh& b)
{
  CGAL::Bbox_3 box;
  for (const Mesh* m : { &a, &b })
  {
    for (auto v : m->vertices())
    {
      box += m->point(v).bbox();
    }
  }
  double d2 = 0.0;
  for (int k = 0; k < 3; ++k)
  {
    d2 += (box.max(k) - box.min(k)) * (box.max(k) - box.min(k));
  }
  return std::sqrt(d2);
}
} // namespace

int main(int argc, char** argv)
{
  if (argc != 4 && argc != 7)
  {
    std::cerr << "usage: CsgReference meshA.off <meshB.off | 'spheres:cx cy cz r;...'> "
                 "<union|intersection|difference> [tx ty tz]\n";
    return 2;
  }
  const std::string op = argv[3];
  const double tx = argc == 7 ? std::atof(argv[4]) : 0.0, ty = argc == 7 ? std::atof(argv[5]) : 0.0,
               tz = argc == 7 ? std::atof(argv[6]) : 0.0;
  Mesh a;
  if (!ReadMesh(argv[1], 0, 0, 0, a))
  {
    return 1;
  }
  Mesh b;
  const std::string second = argv[2];
  std::vector<std::array<double, 4>> spheres;
  if (second.rfind("spheres:", 0) == 0)
  {
    std::stringstream list(second.substr(8));
    std::string item;
    bool first = true;
    while (std::getline(list, item, ';'))
    {
      double c[4] = { 0, 0, 0, 0 };
      std::stringstream fields(item);
      for (double& x : c)
      {
        fields >> x;
      }
      spheres.push_back({ c[0], c[1], c[2], c[3] });
      Mesh s = Icosphere(c[0], c[1], c[2], c[3], 5);
      if (first)
      {
        b = s;
        first = false;
      }
      else
      {
        Mesh u;
        if (!Boolean(b, s, "union", u))
        {
          return 1;
        }
        b = u;
      }
    }
  }
  else if (!ReadMesh(second, tx, ty, tz, b))
  {
    return 1;
  }
  const double angle = MinimumCrossingAngle(a, b); // (before corefinement changes the meshes)
  // The gap between surfaces that do not cross: for spheres, the exact
  // spheres' (distance from the centre to A's surface, minus the radius).
  double gap = angle < 0.0 ? MinimumDistance(a, b) : -1.0;
  if (!spheres.empty())
  {
    gap = std::numeric_limits<double>::infinity();
    const auto surfaceA = InexactTriangles(a);
    for (const auto& c : spheres)
    {
      gap = std::min(gap, DistanceToSurface(surfaceA, Inexact::Point_3(c[0], c[1], c[2])) - c[3]);
    }
    gap = gap > 0.0 ? gap : -1.0;
  }
  const double relativeGap = gap > 0.0 ? gap / CommonDiagonal(a, b) : -1.0;
  Mesh out;
  if (!Boolean(a, b, op, out))
  {
    std::cerr << "corefinement failed\n";
    return 1;
  }
  const long long v = static_cast<long long>(out.number_of_vertices());
  const long long e = static_cast<long long>(out.number_of_edges());
  const long long f = static_cast<long long>(out.number_of_faces());
  auto fcc = out.add_property_map<Mesh::Face_index, std::size_t>("f:cc").first;
  const long long components = static_cast<long long>(PMP::connected_components(out, fcc));
  const long long euler = v - e + f;
  std::cout << components << " " << (2 * components - euler) / 2 << " " << euler << " " << angle << " " << relativeGap << "\n";
  return 0;
}
