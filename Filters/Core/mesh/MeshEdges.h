// The edge table of an indexed triangle mesh: every use of an edge by a
// triangle, sorted so that the uses of one edge are consecutive, and what
// the edge counts give - the Euler characteristic's genus. Mesh repair, the
// topology report, the pieces' report and the lattice placement all read a
// mesh's edges here.
#pragma once

#include "Parallel.h"
#include "TriangleMesh.h"

#include <cstddef>
#include <cstdint>
#include <vector>

namespace tpc
{

/// An undirected edge {a, b} as a key: the smaller vertex id in the high half.
inline std::uint64_t EdgeKey(std::uint32_t a, std::uint32_t b)
{
  return a < b ? (static_cast<std::uint64_t>(a) << 32) | b : (static_cast<std::uint64_t>(b) << 32) | a;
}
inline std::uint32_t EdgeLow(std::uint64_t key)
{
  return static_cast<std::uint32_t>(key >> 32);
}
inline std::uint32_t EdgeHigh(std::uint64_t key)
{
  return static_cast<std::uint32_t>(key & 0xFFFFFFFFu);
}

/// Triangle `Triangle` walks edge `Key` from its corner `Corner` to the next
/// corner; `Ascending`: from the edge's smaller vertex id to its larger.
struct EdgeUse
{
  std::uint64_t Key = 0;
  std::uint32_t Triangle = 0;
  std::uint8_t Corner = 0;
  bool Ascending = false;

  bool operator<(const EdgeUse& o) const
  {
    return Key != o.Key ? Key < o.Key : Triangle != o.Triangle ? Triangle < o.Triangle : Corner < o.Corner;
  }
};

/// Every edge use of the `count` triangles at `triangles`, sorted by edge,
/// then triangle and corner (a total order: the same table for any number of
/// threads): counted by smaller vertex, each vertex's uses sorted in
/// parallel; `progress` is asked once at the end, false when it asked to stop.
bool BuildEdgeTable(const Triangle* triangles, std::size_t count, std::vector<EdgeUse>& uses,
  const ParallelFor& parallelFor = SequentialFor, const ProgressCallback& progress = nullptr);

/// Calls visit(first, count) for each edge of a table: uses[first] to
/// uses[first + count - 1] are its uses (two for an edge of a closed
/// manifold, one on a boundary, more where the mesh is not manifold).
template <typename Visit>
void ForEachEdge(const std::vector<EdgeUse>& uses, Visit&& visit)
{
  for (std::size_t i = 0; i < uses.size();)
  {
    std::size_t j = i + 1;
    while (j < uses.size() && uses[j].Key == uses[i].Key)
    {
      ++j;
    }
    visit(i, j - i);
    i = j;
  }
}

/// The genus of a closed orientable surface from its components c and Euler
/// characteristic chi: each component has chi_i = 2 - 2 g_i, so the genera
/// sum to (2c - chi) / 2. -1 when that is not a whole number >= 0 (then the
/// counts are not those of a closed orientable surface).
inline std::int64_t GenusFromEuler(std::int64_t components, std::int64_t euler)
{
  const std::int64_t twice = 2 * components - euler;
  return twice >= 0 && twice % 2 == 0 ? twice / 2 : -1;
}

} // namespace tpc
