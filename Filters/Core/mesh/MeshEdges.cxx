#include "MeshEdges.h"

namespace tpc
{

bool BuildEdgeTable(const Triangle* triangles, std::size_t count, std::vector<EdgeUse>& uses,
  const ParallelFor& parallelFor, const ProgressCallback& progress)
{
  uses.resize(3 * count);
  parallelFor(count, [&](std::size_t begin, std::size_t end) {
    for (std::size_t t = begin; t < end; ++t)
    {
      for (int k = 0; k < 3; ++k)
      {
        const std::uint32_t from = triangles[t][k], to = triangles[t][(k + 1) % 3];
        uses[3 * t + k] = { EdgeKey(from, to), static_cast<std::uint32_t>(t), static_cast<std::uint8_t>(k), from < to };
      }
    }
  });
  return ParallelSort(uses, std::less<>(), parallelFor, progress);
}

} // namespace tpc
