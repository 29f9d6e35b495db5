// An indexed triangle mesh: the extracted surface A. Points, normals and
// triangles live in releasable arrays, so that the output's data arrays can
// take them without a copy (ReleasableArray.h).
#pragma once

#include "ReleasableArray.h"
#include "Vector3.h"

#include <algorithm>
#include <array>
#include <cstdint>
#include <vector>

namespace tpc
{

/// Three vertex ids, counter-clockwise seen from outside.
using Triangle = std::array<std::uint32_t, 3>;

/// The bounding box of triangle `t` of the points `points`.
inline Box3 TriangleBox(const Vec3* points, const Triangle& t)
{
  Box3 b{ points[t[0]], points[t[0]] };
  for (int k = 1; k < 3; ++k)
  {
    for (int a = 0; a < 3; ++a)
    {
      b.lo[a] = std::min(b.lo[a], points[t[k]][a]);
      b.hi[a] = std::max(b.hi[a], points[t[k]][a]);
    }
  }
  return b;
}

struct TriangleMesh
{
  ReleasableArray<Vec3> Points;
  ReleasableArray<Vec3> Normals; ///< unit outward normal per point
  ReleasableArray<Triangle> Triangles;
  std::vector<std::uint32_t> TriangleCell; ///< octree node each triangle came from
};

} // namespace tpc
