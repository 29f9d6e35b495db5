// A brute-force lower estimate of the one-sided Hausdorff distance between
// two triangle sets, for the certified bounds' tests (PolygonHausdorff.h,
// SlabBound.h): dense samples of the sources, each measured to the nearest
// target by MeshSolid's own closest-point routine (independent of the
// polygons' distance the bounds use).
#pragma once

#include "MeshSolid.h"
#include "PolygonHausdorff.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <vector>

namespace tpctest
{
/// The triangles as one MeshSolid (a soup: for its closest-point routine).
inline tpc::MeshSolid AsMeshSolid(const std::vector<tpc::SourceTriangle>& triangles)
{
  std::vector<tpc::Vec3> points;
  std::vector<std::array<std::uint32_t, 3>> faces;
  for (const tpc::SourceTriangle& t : triangles)
  {
    const std::uint32_t base = static_cast<std::uint32_t>(points.size());
    points.insert(points.end(), t.begin(), t.end());
    faces.push_back({ base, base + 1, base + 2 });
  }
  return tpc::MeshSolid(points, faces);
}

/// max over samples of `sources` - each on a grid of `steps` intervals
/// along two edges - of the distance to the nearest of `targets`.
inline double SampledHausdorff(
  const std::vector<tpc::SourceTriangle>& sources, const std::vector<tpc::SourceTriangle>& targets, int steps = 40)
{
  const tpc::MeshSolid target = AsMeshSolid(targets);
  tpc::TriangleList all(targets.size());
  for (std::uint32_t k = 0; k < all.size(); ++k)
  {
    all[k] = k;
  }
  double worst = 0.0;
  for (const tpc::SourceTriangle& s : sources)
  {
    for (int i = 0; i <= steps; ++i)
    {
      for (int j = 0; i + j <= steps; ++j)
      {
        const double a = double(i) / steps, b = double(j) / steps;
        const tpc::Vec3 x = s[0] * (1 - a - b) + s[1] * a + s[2] * b;
        worst = std::max(worst, std::fabs(target.ApproximateSignedDistance(x, all)));
      }
    }
  }
  return worst;
}
} // namespace tpctest
