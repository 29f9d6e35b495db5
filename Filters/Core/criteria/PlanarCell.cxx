#include "PlanarCell.h"

#include "ExactPredicates.h"

#include <algorithm>

namespace tpc
{
namespace
{
/// True when every vertex of every listed triangle lies exactly in the plane
/// of the first non-degenerate one.
bool TrianglesCoplanar(const MeshSolid& mesh, const TriangleList* listed)
{
  const std::size_t count = listed ? listed->size() : mesh.Triangles().size();
  auto triangle = [&](std::size_t i) { return listed ? (*listed)[i] : static_cast<std::uint32_t>(i); };
  if (count == 0)
  {
    return false;
  }
  // The reference plane: a triangle is non-degenerate iff some point is off
  // its plane; one of three points a unit step from a vertex is (a degenerate
  // triangle gives 0 for every point).
  const Vec3 &a = mesh.Vertex(triangle(0), 0), &b = mesh.Vertex(triangle(0), 1),
             &c = mesh.Vertex(triangle(0), 2);
  bool degenerate = true;
  for (int axis = 0; axis < 3 && degenerate; ++axis)
  {
    Vec3 q = a;
    q[axis] += 1.0;
    degenerate = Orient3D(a, b, c, q) == 0;
  }
  if (degenerate)
  {
    return false; // (repaired meshes have none; refine as usual)
  }
  const auto& faces = mesh.Triangles();
  const auto& reference = faces[triangle(0)];
  for (std::size_t i = 1; i < count; ++i)
  {
    const auto& f = faces[triangle(i)];
    for (int k = 0; k < 3; ++k)
    {
      const std::uint32_t v = f[k];
      if (v != reference[0] && v != reference[1] && v != reference[2] &&
        Orient3D(a, b, c, mesh.Points()[v]) != 0)
      {
        return false;
      }
    }
  }
  return true;
}

/// True when plane j's function has one sign on plane i's section of the
/// cell. There f_j = f_j - lambda f_i for any lambda; with lambda removing
/// f_j's gradient component along f_i's, the affine g = f_j - lambda f_i
/// varies only along plane i, and its enclosure over the cell (interval
/// coefficients, exact up to outward rounding for an affine function) bounds
/// f_j on the section. Parallel planes give a constant g.
bool OneSignOnSection(const Quadric& i, const Quadric& j, const Box3& cell)
{
  const auto& a = i.Coefficients();
  const auto& b = j.Coefficients();
  const double aa = a[6] * a[6] + a[7] * a[7] + a[8] * a[8];
  const double lambda = (a[6] * b[6] + a[7] * b[7] + a[8] * b[8]) / aa;
  Interval g = Interval(b[9]) - Interval(lambda) * Interval(a[9]);
  for (int k = 0; k < 3; ++k)
  {
    const Interval c = Interval(b[6 + k]) - Interval(lambda) * Interval(a[6 + k]);
    g = g + c * Interval(cell.lo[k], cell.hi[k]);
  }
  return !g.ContainsZero();
}
} // namespace

bool IsPlanarCell(const CsgExpression& expression, const PrimitiveSet& primitives, const Box3& cell)
{
  const std::vector<CsgLeaf> leaves = expression.Leaves();
  if (leaves.size() == 1 && leaves[0].Kind == PrimitiveKind::Mesh)
  {
    return TrianglesCoplanar(primitives.Meshes[leaves[0].Primitive], leaves[0].Triangles);
  }
  std::vector<const Quadric*> planes;
  for (const CsgLeaf& leaf : leaves)
  {
    if (leaf.Kind != PrimitiveKind::Quadric || !primitives.Quadrics[leaf.Primitive].IsLinear())
    {
      return false;
    }
    const Quadric* q = &primitives.Quadrics[leaf.Primitive];
    if (std::find(planes.begin(), planes.end(), q) == planes.end())
    {
      planes.push_back(q); // (both signs of one plane: one zero set)
    }
  }
  for (const Quadric* i : planes)
  {
    for (const Quadric* j : planes)
    {
      if (i != j && !OneSignOnSection(*i, *j, cell))
      {
        return false;
      }
    }
  }
  return !planes.empty();
}

} // namespace tpc
