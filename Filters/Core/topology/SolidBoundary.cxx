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
  ++this->Count;
}

int EnclosedVolume::Sign() const
{
  // Why the bound holds. Every rounding, underflow included, gives
  // fl(x op y) = (x op y)(1 + d) + e with |d| <= u (the unit roundoff,
  // DBL_EPSILON / 2) and |e| <= DBL_TRUE_MIN / 2. With d = x - o rounded,
  // det(d_a, d_b, d_c) = d_a . (d_b x d_c) takes six products of three
  // coordinates, a subtraction in each cross component, two additions in the
  // dot: each term carries a relative error below 9u (three differences, two
  // products, a subtraction, two additions, one more product), so the
  // determinant's is below 9u times the sum M_t of its terms' absolute
  // values, plus at most 11 absolute errors e. Summing n determinants adds
  // at most (n - 1) u times the sum of their absolute values (at most M_t
  // each, to first order) and n - 1 errors e. So |computed - exact| <=
  // (n + 9) u sum M_t + 12 n DBL_TRUE_MIN / 2, taken here as (n + 16)
  // DBL_EPSILON sum M_t + 16 (n + 1) DBL_TRUE_MIN: room for the second-order
  // terms and the rounding of sum M_t itself. (Without the absolute term the
  // bound would fail where the products underflow - differences of about
  // 1e-106 - and call a sign it cannot know.)
  const double n = static_cast<double>(this->Count);
  const double bound =
    (n + 16.0) * DBL_EPSILON * this->Magnitudes + 16.0 * (n + 1.0) * std::numeric_limits<double>::denorm_min();
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
