#include "SolidBoundary.h"

#include "MeshSolid.h"
#include "UnionFind.h"

#include <cfloat>
#include <cmath>
#include <limits>
#include <vector>

namespace tpc
{
namespace
{
/// Each triangle's component, numbered from 0; their count.
std::int64_t LabelComponents(const TriangleMesh& mesh, std::vector<std::uint32_t>& component)
{
  UnionFind parts(mesh.Points.size());
  for (const Triangle& t : mesh.Triangles)
  {
    parts.Join(t[0], t[1]);
    parts.Join(t[1], t[2]);
  }
  const std::uint32_t none = ~std::uint32_t{ 0 };
  std::vector<std::uint32_t> number(mesh.Points.size(), none);
  std::uint32_t count = 0;
  component.resize(mesh.Triangles.size());
  for (std::size_t t = 0; t < mesh.Triangles.size(); ++t)
  {
    std::uint32_t& n = number[parts.Find(mesh.Triangles[t][0])];
    n = n == none ? count++ : n;
    component[t] = n;
  }
  return count;
}

} // namespace

void EnclosedVolume::Add(const Vec3* points, const Triangle& t)
{
  if (!this->Started)
  {
    this->Base = t[0];
    this->Started = true;
  }
  const Vec3& o = points[this->Base];
  const Vec3 a = points[t[0]] - o, b = points[t[1]] - o, c = points[t[2]] - o;
  this->Six += Dot(a, Cross(b, c));
  this->Magnitudes += std::fabs(a[0]) * (std::fabs(b[1] * c[2]) + std::fabs(b[2] * c[1])) +
    std::fabs(a[1]) * (std::fabs(b[2] * c[0]) + std::fabs(b[0] * c[2])) +
    std::fabs(a[2]) * (std::fabs(b[0] * c[1]) + std::fabs(b[1] * c[0]));
  this->Reach += std::fabs(a[0]) + std::fabs(a[1]) + std::fabs(a[2]);
  ++this->Count;
}

int EnclosedVolume::Sign() const
{
  // Why the bound holds. Every rounding, underflow included, gives
  // fl(x op y) = (x op y)(1 + d) + e with |d| <= u (the unit roundoff,
  // DBL_EPSILON / 2) and |e| <= m / 2, m the smallest subnormal
  // (denorm_min); a difference x - o that underflows is exact.
  // Relative errors: det(d_a, d_b, d_c) = d_a . (d_b x d_c) takes six
  // products of three coordinates, a subtraction in each cross component,
  // two additions in the dot: each term carries a relative error below 9u
  // (three differences, two products, a subtraction, two additions, one more
  // product), so the determinant's is below 9u times the sum M_t of its
  // terms' absolute values; summing n determinants adds at most (n - 1) u
  // times the sum of their absolute values (at most M_t each, to first
  // order). Absolute errors: a cross component carries at most 3m/2 (two
  // products, a subtraction), multiplied by d_a's coordinate; the dot adds
  // three products and two additions: at most m (3/2 |d_a|_1 + 5/2) per
  // determinant, and n/2 m for the sum. So
  //   |computed - exact| <= (n + 9) u sum M_t + m (3/2 sum |d_a|_1 + 3 n),
  // taken here as (n + 16) DBL_EPSILON sum M_t + 4 m (sum |d_a|_1 + 2 n + 1):
  // room for the second-order terms and the roundings of the sums
  // themselves. (With the relative term alone the bound fails where products
  // underflow - differences of about 1e-106 - and calls signs it cannot
  // know; SolidBoundary.TinyCoordinatesNeverGiveTheWrongSign, and a constant
  // absolute term fails UnderflowTimesALongEdgeNeverGivesTheWrongSign.)
  const double n = static_cast<double>(this->Count);
  const double bound = (n + 16.0) * DBL_EPSILON * this->Magnitudes +
    4.0 * std::numeric_limits<double>::denorm_min() * (this->Reach + 2.0 * n + 1.0);
  return std::fabs(this->Six) > bound ? (this->Six > 0.0 ? 1 : -1) : 0;
}

OutwardReport CheckOutward(const TriangleMesh& mesh, const ParallelFor& parallelFor)
{
  OutwardReport report;
  std::vector<std::uint32_t> component;
  report.Components = LabelComponents(mesh, component);
  std::vector<EnclosedVolume> volumes(static_cast<std::size_t>(report.Components));
  for (std::size_t t = 0; t < mesh.Triangles.size(); ++t)
  {
    volumes[component[t]].Add(mesh.Points.data(), mesh.Triangles[t]);
  }
  // Depths: one component lies inside no other; with more, a ray from each.
  std::vector<char> odd(volumes.size(), 0);
  if (volumes.size() > 1)
  {
    const MeshSolid solid(mesh.Points.ToVector(), mesh.Triangles.ToVector(), parallelFor);
    parallelFor(volumes.size(), [&](std::size_t begin, std::size_t end) {
      for (std::size_t k = begin; k < end; ++k)
      {
        const int crossings = solid.CrossingsAlongX(
          mesh.Points[volumes[k].Origin()], [&](std::uint32_t t) { return component[t] != k; });
        odd[k] = (crossings & 1) != 0;
      }
    });
  }
  for (std::size_t k = 0; k < volumes.size(); ++k)
  {
    const int sign = volumes[k].Sign();
    report.Undecided += sign == 0 ? 1 : 0;
    report.InsideOut += sign != 0 && (sign > 0) == (odd[k] != 0) ? 1 : 0;
  }
  return report;
}

} // namespace tpc
