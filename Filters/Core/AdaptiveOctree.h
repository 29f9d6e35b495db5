// The adaptive octree forest produced by the topology preserving subdivision
// (paper 5.3): nodes with their level, lattice position, split reason and
// state, the exact corner signs, and for each leaf meeting the surface the
// CSG expression pruned to it (what the extraction evaluates).
#pragma once

#include "CsgExpression.h"
#include "LatticeSignTable.h"
#include "RootGrid.h"
#include "SplitReason.h"

#include <cstdint>
#include <vector>

namespace tpc
{

struct OctreeNode
{
  std::uint32_t Ijk[3] = { 0, 0, 0 }; ///< integer position at this node's level
  std::uint8_t Level = 0;
  SplitReason Reason = SplitReason::None;
  CellState State = CellState::Outside;
  /// For Unresolved leaves: the criterion that still failed.
  SplitReason FailedTest = SplitReason::None;
  /// Children are FirstChild + c, c = x + 2y + 4z (VTK's HyperTree order); -1 for leaves.
  std::int32_t FirstChild = -1;

  bool IsLeaf() const { return FirstChild < 0; }
};

/// Corner c of a cell is at offset (c&1, (c>>1)&1, (c>>2)&1).
inline void CornerLattice(const RootGrid& grid, const OctreeNode& n, int c, std::uint32_t p[3])
{
  const int shift = grid.MaxDepth - n.Level;
  for (int a = 0; a < 3; ++a)
  {
    p[a] = (n.Ijk[a] + ((c >> a) & 1)) << shift;
  }
}

class AdaptiveOctree
{
public:
  RootGrid Grid;
  /// Roots first: node t is the root of tree t (t = i + Dims0 * (j + Dims1 * k)).
  std::vector<OctreeNode> Nodes;
  /// Pruned expression of each node that meets the surface (null elsewhere).
  std::vector<CsgExpressionPtr> Expressions;
  /// Exact inside/outside at lattice corners of cells that met the surface.
  LatticeSignTable Signs;

  /// Index of the node at (level, ijk) if it exists, otherwise of the deepest
  /// existing ancestor (a leaf containing that position), or -1 outside the grid.
  std::int64_t Find(int level, const std::int64_t ijk[3]) const;

  /// Inside/outside at a corner of node `n` (constant leaves know their sign
  /// without a table entry).
  bool CornerInside(std::size_t n, int corner) const;
  bool PointInside(std::size_t leafContainingPoint, PointKey key) const;

  std::size_t MemoryBytes() const;
};

} // namespace tpc
