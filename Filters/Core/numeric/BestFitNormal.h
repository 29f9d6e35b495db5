// The normal of the plane fitted to a point set in the least-squares sense:
// the eigenvector of the points' scatter about their mean with the least
// eigenvalue (the smallest-variance direction). Used where two loops are
// separated by an oblique plane (SeparatingPlane.h) and where a slab holding
// a mesh's piece is measured across it (SlabBound.cxx).
#pragma once

#include "SymmetricEigen.h"
#include "Vector3.h"

#include <cstddef>

namespace tpc
{

/// The smallest-variance direction of the points `forEachPoint` visits - it
/// calls its argument with each point, in the same order each time - or
/// zero where they are fewer than three. Not normalized (SymmetricEigen's
/// vectors are unit up to rounding); among equal least eigenvalues, the
/// first.
template <typename ForEachPoint>
Vec3 BestFitNormal(const ForEachPoint& forEachPoint)
{
  Vec3 mean;
  std::size_t n = 0;
  forEachPoint([&](const Vec3& p) {
    mean += p;
    ++n;
  });
  if (n < 3)
  {
    return {};
  }
  mean = mean * (1.0 / static_cast<double>(n));
  double c[3][3] = { { 0, 0, 0 }, { 0, 0, 0 }, { 0, 0, 0 } };
  forEachPoint([&](const Vec3& p) {
    const Vec3 d = p - mean;
    for (int i = 0; i < 3; ++i)
    {
      for (int j = 0; j < 3; ++j)
      {
        c[i][j] += d[i] * d[j];
      }
    }
  });
  double vectors[3][3], values[3];
  SymmetricEigen(c, vectors, values);
  int smallest = 0;
  for (int k = 1; k < 3; ++k)
  {
    smallest = values[k] < values[smallest] ? k : smallest;
  }
  return { vectors[0][smallest], vectors[1][smallest], vectors[2][smallest] };
}

} // namespace tpc
