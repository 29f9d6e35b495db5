#include "ForestPartition.h"

#include <algorithm>
#include <cmath>

namespace tpc
{

RootGrid SplitRootCells(const RootGrid& grid, int levels, const Box3& domain)
{
  RootGrid split = grid;
  levels = std::clamp(levels, 0, grid.MaxDepth);
  split.RootSize = std::ldexp(grid.RootSize, -levels); // exact: the lattice spacing is unchanged
  split.MaxDepth = grid.MaxDepth - levels;
  for (int a = 0; a < 3; ++a)
  {
    // The same origin (the same lattice); only the trees that reach the domain.
    const int needed = static_cast<int>(std::ceil((domain.hi[a] - grid.Origin[a]) / split.RootSize - 1e-12));
    split.Dims[a] = std::clamp(needed, 1, grid.Dims[a] << levels);
  }
  return split;
}

std::vector<int> PartitionTrees(const RootGrid& grid, int pieces)
{
  int axis = 0;
  for (int a = 1; a < 3; ++a)
  {
    axis = grid.Dims[a] > grid.Dims[axis] ? a : axis;
  }
  pieces = std::max(1, pieces);
  std::vector<int> piece(static_cast<std::size_t>(grid.TreeCount()));
  for (int t = 0; t < grid.TreeCount(); ++t)
  {
    int ijk[3];
    grid.TreeCoordinates(t, ijk);
    // Slab s holds coordinates [s n / p, (s + 1) n / p).
    piece[static_cast<std::size_t>(t)] =
      std::min(pieces - 1, static_cast<int>((static_cast<long long>(ijk[axis]) * pieces) / grid.Dims[axis]));
  }
  return piece;
}

std::vector<TreeRole> TreeRoles(const RootGrid& grid, const std::vector<int>& pieceOfTree, int piece)
{
  std::vector<TreeRole> roles(pieceOfTree.size(), TreeRole::Skipped);
  for (int t = 0; t < grid.TreeCount(); ++t)
  {
    if (pieceOfTree[static_cast<std::size_t>(t)] != piece)
    {
      continue;
    }
    int ijk[3];
    grid.TreeCoordinates(t, ijk);
    for (int dz = -1; dz <= 1; ++dz)
    {
      for (int dy = -1; dy <= 1; ++dy)
      {
        for (int dx = -1; dx <= 1; ++dx)
        {
          const int n[3] = { ijk[0] + dx, ijk[1] + dy, ijk[2] + dz };
          if (n[0] < 0 || n[1] < 0 || n[2] < 0 || n[0] >= grid.Dims[0] || n[1] >= grid.Dims[1] ||
            n[2] >= grid.Dims[2])
          {
            continue;
          }
          TreeRole& r = roles[static_cast<std::size_t>(grid.TreeIndex(n[0], n[1], n[2]))];
          r = std::max(r, TreeRole::Ghost);
        }
      }
    }
    roles[static_cast<std::size_t>(t)] = TreeRole::Own;
  }
  return roles;
}

} // namespace tpc
