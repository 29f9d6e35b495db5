// An indexed triangle mesh: the extracted surface A.
#pragma once

#include "Vector3.h"

#include <array>
#include <cstdint>
#include <vector>

namespace tpc
{

struct TriangleMesh
{
  std::vector<Vec3> Points;
  std::vector<Vec3> Normals; ///< unit outward normal per point
  std::vector<std::array<std::uint32_t, 3>> Triangles;
  std::vector<std::uint32_t> TriangleCell; ///< octree node each triangle came from
};

} // namespace tpc
