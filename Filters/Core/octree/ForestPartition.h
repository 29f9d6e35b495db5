// Splitting the work by trees of the root grid (issue 7: MPI ranks).
//
// A piece subdivides its own trees and a ring of ghost trees around them (the
// trees sharing a face, an edge or a corner with one of its own) and
// extracts the surface of its own trees only. The pieces fit without any
// exchange because everything a cell of an own tree depends on is computed
// identically in every piece that computes it:
// - a cell's verdict depends on the cell alone (exact signs at lattice
//   points, the scene pruned to the cell), so a tree is subdivided the same
//   way in every piece that computes it;
// - the extraction of a cell reads only cells that touch it (finer
//   neighbours' crossings on its faces, face tilings, refinement points on
//   its edges), all in its own tree or the ghost ring;
// - where several cells could place a vertex or tile a face, the first one in
//   node order wins (a crease-fan cell before the others for a CSG crease
//   tile's vertex, CrossingVertices.h: a property each piece computes alike
//   from the cell), and node order is (level, tree, path in the tree) in any
//   subset of the trees kept in tree order, so every piece chooses the cell
//   the whole run chooses. The ghost ring's cells take part in those choices.
// The root grid must have enough trees to split: SplitRootCells divides each
// root cell into 2^levels per axis on the same finest lattice.
#pragma once

#include "RootGrid.h"
#include "Vector3.h"

#include <cstdint>
#include <vector>

namespace tpc
{

/// Role of a tree in a piece's run.
enum class TreeRole : std::uint8_t
{
  Skipped = 0, ///< not computed (left as an empty root)
  Ghost = 1,   ///< subdivided so that own trees' neighbours are known; no output
  Own = 2      ///< subdivided and extracted
};

/// The same finest lattice with root cells 2^levels times smaller per axis
/// (MaxDepth decreases by `levels`), keeping only trees that meet `domain`.
RootGrid SplitRootCells(const RootGrid& grid, int levels, const Box3& domain);

/// Piece of each tree: `pieces` slabs of consecutive tree indices along the
/// grid's longest axis, as even in tree count as the grid allows.
std::vector<int> PartitionTrees(const RootGrid& grid, int pieces);

/// Roles of the trees for piece `piece`: its own trees, the ring of trees
/// around them, the rest skipped.
std::vector<TreeRole> TreeRoles(const RootGrid& grid, const std::vector<int>& pieceOfTree, int piece);

/// Index of the tree containing a cell at `level` with integer coordinates `ijk`.
inline int TreeOf(const RootGrid& grid, int level, const LatticeIndex ijk[3])
{
  return grid.TreeIndex(
    static_cast<int>(ijk[0] >> level), static_cast<int>(ijk[1] >> level), static_cast<int>(ijk[2] >> level));
}

} // namespace tpc
