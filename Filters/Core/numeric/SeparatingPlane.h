// A plane strictly between two finite point sets, found among a few
// candidate directions.
//
// Where it is used: two loops of one cell that no axis-aligned plane
// separates (LoopsSeparated in ComplexCellCriterion.h, ApexRegion in
// LoopTriangulation.h). Near the edge of a thin wedge in a generic
// orientation the cell holds a piece of each of the wedge's two sheets:
// nearly parallel, parallel to no axis, so their loops' points are two thin,
// nearly parallel sets whose common best-fit plane's normal separates them
// while every axis sees them overlap - at every level, since the picture is
// the same at every scale. Candidates, in order: the normal of the best-fit
// plane of both sets together (smallest-variance direction), of each set
// alone, and the direction between their centroids. A candidate that does not
// separate is simply not chosen; callers prove what they need of the plane
// themselves.
#pragma once

#include "BestFitNormal.h"
#include "Vector3.h"

#include <vector>

namespace tpc
{

/// Normal . x < Offset - Gap / 2 on the first set, > Offset + Gap / 2 on the
/// second (unit Normal; Gap > 0, in floating point on the given points).
struct SeparatingPlane
{
  Vec3 Normal;
  double Offset = 0.0;
  double Gap = 0.0;
};

namespace detail
{
/// The smallest-variance direction of the points of `sets` (zero if fewer
/// than three).
inline Vec3 BestFitNormal(const std::vector<const std::vector<Vec3>*>& sets)
{
  return tpc::BestFitNormal([&](const auto& visit) {
    for (const auto* set : sets)
    {
      for (const Vec3& p : *set)
      {
        visit(p);
      }
    }
  });
}

inline Vec3 Centroid(const std::vector<Vec3>& points)
{
  return MeanOf(points.data(), points.size());
}
} // namespace detail

/// The candidate plane with the widest gap between `first` and `second`
/// (first on its negative side); false when no candidate separates them.
inline bool FindSeparatingPlane(const std::vector<Vec3>& first, const std::vector<Vec3>& second, SeparatingPlane& plane)
{
  if (first.empty() || second.empty())
  {
    return false;
  }
  const Vec3 candidates[4] = { detail::BestFitNormal({ &first, &second }), detail::BestFitNormal({ &first }),
    detail::BestFitNormal({ &second }), detail::Centroid(second) - detail::Centroid(first) };
  bool found = false;
  for (const Vec3& candidate : candidates)
  {
    if (!(Norm(candidate) > 0.0))
    {
      continue;
    }
    for (const double sign : { 1.0, -1.0 })
    {
      const Vec3 n = Normalized(candidate) * sign;
      double top = -HUGE_VAL, bottom = HUGE_VAL;
      for (const Vec3& p : first)
      {
        top = std::max(top, Dot(n, p));
      }
      for (const Vec3& p : second)
      {
        bottom = std::min(bottom, Dot(n, p));
      }
      if (bottom > top && bottom - top > plane.Gap)
      {
        plane.Normal = n;
        plane.Offset = 0.5 * (top + bottom);
        plane.Gap = bottom - top;
        found = true;
      }
    }
  }
  return found;
}

} // namespace tpc
