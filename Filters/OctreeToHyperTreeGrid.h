// Adapter: the core's adaptive octree -> vtkHyperTreeGrid with cell data
// "Depth", "SplitReason", "SizeReason", "CellState", "FailedTest" and
// "CertifiedError", and field data
// "SplitReasonNames" and "CellStateNames" (the name of each value).
#ifndef OctreeToHyperTreeGrid_h
#define OctreeToHyperTreeGrid_h

#include "AdaptiveOctree.h"
#include "Parallel.h"

#include "vtkType.h"

#include <cstdint>
#include <utility>
#include <vector>

class vtkHyperTreeGrid;

namespace tpc
{
namespace vtkadapter
{

/// Fills `grid`. `nodeToCell[n]` receives the HTG cell (global node) index of
/// octree node n. Reports progress every 2^16 cells; returns false (with
/// `grid` incomplete) when it asks to abort.
bool ConvertOctree(const AdaptiveOctree& octree, vtkHyperTreeGrid* grid, std::vector<vtkIdType>& nodeToCell,
  const ProgressCallback& progress = nullptr);

/// Adds the cell array "CertifiedError": each error-bounded cell's certified
/// two-sided error (QuadricCellError.h, MeshCellError.h; +inf where its certificate failed),
/// NaN on every other cell.
void AddCertifiedErrors(vtkHyperTreeGrid* grid, const std::vector<vtkIdType>& nodeToCell,
  const std::vector<std::pair<std::uint32_t, double>>& cellErrors);

} // namespace vtkadapter
} // namespace tpc

#endif
