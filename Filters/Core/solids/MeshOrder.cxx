#include "MeshOrder.h"

#include <algorithm>
#include <cassert>
#include <cmath>
#include <functional>
#include <utility>

namespace tpc
{
namespace
{
Vec3 Centroid(const std::vector<Vec3>& points, const std::array<std::uint32_t, 3>& t)
{
  return (points[t[0]] + points[t[1]] + points[t[2]]) * (1.0 / 3.0);
}

/// The median of `values` (reordered; 0 for none; a NaN counted as +inf,
/// which keeps the order a strict weak one).
double Median(std::vector<double>& values)
{
  if (values.empty())
  {
    return 0.0;
  }
  for (double& v : values)
  {
    v = std::isnan(v) ? HUGE_VAL : v;
  }
  const auto middle = values.begin() + static_cast<std::ptrdiff_t>(values.size() / 2);
  std::nth_element(values.begin(), middle, values.end());
  return *middle;
}

/// The bits of a 21-bit integer spread three apart (bit i to bit 3 i).
std::uint64_t Spread(std::uint64_t v)
{
  v &= 0x1FFFFF;
  v = (v | v << 32) & 0x1F00000000FFFFull;
  v = (v | v << 16) & 0x1F0000FF0000FFull;
  v = (v | v << 8) & 0x100F00F00F00F00Full;
  v = (v | v << 4) & 0x10C30C30C30C30C3ull;
  v = (v | v << 2) & 0x1249249249249249ull;
  return v;
}

/// The Morton code of `p` on a 2^21 grid over `box` (a coordinate outside
/// it, or not a number, clamped to its ends or taken as its lower end).
std::uint64_t MortonCode(const Vec3& p, const Box3& box)
{
  std::uint64_t code = 0;
  for (int a = 0; a < 3; ++a)
  {
    const double width = box.Width(a);
    const double t = width > 0.0 && std::isfinite(width) ? (p[a] - box.lo[a]) / width : 0.0;
    const double cell = std::clamp(std::isnan(t) ? 0.0 : t, 0.0, 1.0) * 2097151.0;
    code |= Spread(static_cast<std::uint64_t>(cell)) << a;
  }
  return code;
}
} // namespace

bool InLocalOrder(const std::vector<Vec3>& points, const std::vector<std::array<std::uint32_t, 3>>& triangles)
{
  if (triangles.size() < 2)
  {
    return true;
  }
  // (One buffer for the jumps, then the edges: fewer pages first touched.)
  std::vector<double> lengths;
  lengths.reserve(triangles.size());
  for (std::size_t k = 1; k < triangles.size(); ++k)
  {
    lengths.push_back(Norm(Centroid(points, triangles[k]) - Centroid(points, triangles[k - 1])));
  }
  const double jump = Median(lengths);
  lengths.clear();
  for (const std::array<std::uint32_t, 3>& t : triangles)
  {
    lengths.push_back(std::max(
      { Norm(points[t[1]] - points[t[0]]), Norm(points[t[2]] - points[t[1]]), Norm(points[t[0]] - points[t[2]]) }));
  }
  // (Where lengths are infinite and the comparison fails, the order stays.)
  return !(jump > LocalOrderJumps * Median(lengths));
}

void OrderAlongMortonCurve(std::vector<Vec3>& points, std::vector<std::array<std::uint32_t, 3>>& triangles,
  std::vector<std::array<std::uint32_t, 3>>& neighbours, std::uint32_t none, const ParallelFor& parallelFor)
{
  const std::size_t n = triangles.size();
  assert(n < none && (neighbours.empty() || neighbours.size() == n));
  // The curve over the box of the centroids' finite coordinates (a point no
  // triangle uses, or a non-finite one, would only squeeze it).
  // (Each centroid found twice rather than kept: an array of them was a
  // fifth of the reordering, in pages first touched.)
  Box3 box{ Vec3(HUGE_VAL, HUGE_VAL, HUGE_VAL), Vec3(-HUGE_VAL, -HUGE_VAL, -HUGE_VAL) };
  for (const std::array<std::uint32_t, 3>& t : triangles)
  {
    const Vec3 c = Centroid(points, t);
    for (int a = 0; a < 3; ++a)
    {
      if (std::isfinite(c[a]))
      {
        box.lo[a] = std::min(box.lo[a], c[a]);
        box.hi[a] = std::max(box.hi[a], c[a]);
      }
    }
  }
  // The triangles by (code, old index): the new order, deterministic.
  std::vector<std::pair<std::uint64_t, std::uint32_t>> keyed(n);
  parallelFor(n, [&](std::size_t begin, std::size_t end) {
    for (std::size_t t = begin; t < end; ++t)
    {
      keyed[t] = { MortonCode(Centroid(points, triangles[t]), box), static_cast<std::uint32_t>(t) };
    }
  });
  ParallelSort(keyed, std::less<>(), parallelFor, nullptr);
  std::vector<std::uint32_t> newTriangle(n);
  for (std::uint32_t k = 0; k < n; ++k)
  {
    newTriangle[keyed[k].second] = k;
  }
  // The points in the order the reordered triangles first use them.
  constexpr std::uint32_t unnamed = ~std::uint32_t{ 0 };
  std::vector<std::uint32_t> newPoint(points.size(), unnamed);
  std::vector<Vec3> reorderedPoints;
  reorderedPoints.reserve(points.size());
  std::vector<std::array<std::uint32_t, 3>> reordered(n);
  for (std::uint32_t k = 0; k < n; ++k)
  {
    for (int c = 0; c < 3; ++c)
    {
      const std::uint32_t v = triangles[keyed[k].second][c];
      if (newPoint[v] == unnamed)
      {
        newPoint[v] = static_cast<std::uint32_t>(reorderedPoints.size());
        reorderedPoints.push_back(points[v]);
      }
      reordered[k][c] = newPoint[v];
    }
  }
  for (std::size_t v = 0; v < points.size(); ++v)
  {
    if (newPoint[v] == unnamed)
    {
      reorderedPoints.push_back(points[v]);
    }
  }
  if (!neighbours.empty())
  {
    std::vector<std::array<std::uint32_t, 3>> renamed(n);
    parallelFor(n, [&](std::size_t begin, std::size_t end) {
      for (std::size_t k = begin; k < end; ++k)
      {
        for (int c = 0; c < 3; ++c)
        {
          const std::uint32_t across = neighbours[keyed[k].second][c];
          renamed[k][c] = across == none ? none : newTriangle[across];
        }
      }
    });
    neighbours = std::move(renamed);
  }
  points = std::move(reorderedPoints);
  triangles = std::move(reordered);
}

} // namespace tpc
