#include "MeshEdges.h"

#include "BucketStarts.h"

#include <algorithm>
#include <numeric>

namespace tpc
{

bool BuildEdgeTable(const Triangle* triangles, std::size_t count, std::vector<EdgeUse>& uses,
  const ParallelFor& parallelFor, const ProgressCallback& progress)
{
  // A counting sort on each edge's smaller vertex (the key's high half), then
  // each vertex's few uses sorted by the whole order: the table a sort of all
  // uses by EdgeUse's order gives, in linear time (that sort was most of the
  // edge work of the input's checks).
  std::size_t vertices = 0;
  for (std::size_t t = 0; t < count; ++t)
  {
    for (const std::uint32_t v : triangles[t])
    {
      vertices = std::max<std::size_t>(vertices, std::size_t(v) + 1);
    }
  }
  std::vector<std::size_t> start(vertices + 1, 0);
  for (std::size_t t = 0; t < count; ++t)
  {
    for (int k = 0; k < 3; ++k)
    {
      ++start[std::size_t(std::min(triangles[t][k], triangles[t][(k + 1) % 3])) + 1];
    }
  }
  std::partial_sum(start.begin(), start.end(), start.begin());
  uses.resize(3 * count);
  for (std::size_t t = 0; t < count; ++t)
  {
    for (int k = 0; k < 3; ++k)
    {
      const std::uint32_t from = triangles[t][k], to = triangles[t][(k + 1) % 3];
      uses[start[std::min(from, to)]++] = { EdgeKey(from, to), static_cast<std::uint32_t>(t),
        static_cast<std::uint8_t>(k), from < to };
    }
  }
  RestoreBucketStarts(start);
  parallelFor(vertices, [&](std::size_t begin, std::size_t end) {
    for (std::size_t v = begin; v < end; ++v)
    {
      std::sort(uses.begin() + static_cast<std::ptrdiff_t>(start[v]),
        uses.begin() + static_cast<std::ptrdiff_t>(start[v + 1]));
    }
  });
  return !(progress && progress(1.0));
}

} // namespace tpc
