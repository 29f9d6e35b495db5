// Adapter: the core's adaptive octree -> vtkHyperTreeGrid with cell data
// "Depth", "SplitReason", "SizeReason", "CellState" and "FailedTest", and field data
// "SplitReasonNames" and "CellStateNames" (the name of each value).
#ifndef OctreeToHyperTreeGrid_h
#define OctreeToHyperTreeGrid_h

#include "AdaptiveOctree.h"
#include "Parallel.h"

#include "vtkType.h"

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

} // namespace vtkadapter
} // namespace tpc

#endif
