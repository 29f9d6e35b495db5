#include "TriangleErrorBounds.h"

#include <algorithm>
#include <cmath>

namespace tpc
{

std::vector<double> TriangleErrorBounds(const AdaptiveOctree& tree, const ExtractionResult& extraction)
{
  std::vector<double> certified(tree.Nodes.size(), HUGE_VAL);
  for (const auto& [node, error] : extraction.CellErrors)
  {
    certified[node] = error;
  }
  const RootGrid& grid = tree.Grid;
  const std::vector<std::uint32_t>& cells = extraction.Mesh.TriangleCell;
  std::vector<double> bounds(cells.size());
  for (std::size_t t = 0; t < cells.size(); ++t)
  {
    const OctreeNode& node = tree.Nodes[cells[t]];
    const double diagonal = grid.CellDiagonal(node.Level);
    // (In the order DecideCell and GatherCertifiedBound count them.)
    // (Contour marks the leaves whose patch failed the check so; a cell a
    // repair round split first for it is no leaf, and one that became an
    // exact cell keeps it as its FailedTest, its patch the mesh.)
    if (node.Reason == SplitReason::PatchNotEmbedded)
    {
      bounds[t] = std::nan(""); // (header: not proven)
    }
    else if (node.State == CellState::Surface && node.ErrorBounded)
    {
      bounds[t] = std::min(certified[cells[t]], diagonal);
    }
    else if (node.State == CellState::Exact || (node.State == CellState::Surface && node.PlaneSection))
    {
      bounds[t] = grid.CellDiagonal(grid.MaxDepth);
    }
    else
    {
      bounds[t] = diagonal;
    }
  }
  return bounds;
}

} // namespace tpc
