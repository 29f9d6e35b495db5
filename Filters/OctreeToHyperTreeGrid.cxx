#include "OctreeToHyperTreeGrid.h"

#include "vtkCellData.h"
#include "vtkDoubleArray.h"
#include "vtkFieldData.h"
#include "vtkHyperTree.h"
#include "vtkHyperTreeGrid.h"
#include "vtkHyperTreeGridNonOrientedCursor.h"
#include "vtkNew.h"
#include "vtkStringArray.h"
#include "vtkUnsignedCharArray.h"

#include <algorithm>
#include <cmath>
#include <deque>

namespace tpc
{
namespace vtkadapter
{
namespace
{
struct Arrays
{
  vtkUnsignedCharArray* Depth;
  vtkUnsignedCharArray* Reason;
  vtkUnsignedCharArray* SizeReason;
  vtkUnsignedCharArray* State;
  vtkUnsignedCharArray* Failed;
};

/// Counts visited cells, asks `Progress` every 2^16 of them.
struct VisitProgress
{
  const ProgressCallback& Progress;
  std::size_t Total;
  std::size_t Visited = 0;
  bool Aborted = false;

  bool Stop()
  {
    if (this->Progress && (++this->Visited & 0xFFFF) == 0)
    {
      this->Aborted = this->Aborted || this->Progress(static_cast<double>(this->Visited) / this->Total);
    }
    return this->Aborted;
  }
};

/// One tree's cells numbered breadth first, as vtkXMLHyperTreeGridReader
/// numbers them: written and read back, a cell keeps its index, so the
/// surface's GridCell names the same cell in the files as in memory (a
/// depth-first numbering did not survive the round trip).
void VisitBreadthFirst(const AdaptiveOctree& tree, std::size_t root, vtkHyperTree* vtkTree, vtkIdType start,
  const Arrays& arrays, std::vector<vtkIdType>& nodeToCell, VisitProgress& progress)
{
  struct Queued
  {
    std::size_t Node;
    vtkIdType Vertex;       ///< the vtkHyperTree's own index
    SplitReason SizeReason; ///< why the parent was split: why this cell is this small
  };
  std::deque<Queued> queue{ { root, 0, SplitReason::None } };
  while (!queue.empty() && !progress.Stop())
  {
    const Queued q = queue.front();
    queue.pop_front();
    const OctreeNode& n = tree.Nodes[q.Node];
    const vtkIdType id = start + q.Vertex;
    nodeToCell[q.Node] = id;
    arrays.Depth->InsertValue(id, n.Level);
    arrays.Reason->InsertValue(id, static_cast<unsigned char>(n.Reason));
    arrays.SizeReason->InsertValue(id, static_cast<unsigned char>(q.SizeReason));
    arrays.State->InsertValue(id, static_cast<unsigned char>(n.State));
    arrays.Failed->InsertValue(id, static_cast<unsigned char>(n.FailedTest));
    if (n.IsLeaf())
    {
      continue;
    }
    // Children are appended in the order leaves are subdivided: breadth first.
    vtkTree->SubdivideLeaf(q.Vertex, static_cast<unsigned int>(n.Level - tree.Nodes[root].Level));
    const vtkIdType elder = vtkTree->GetElderChildIndex(static_cast<unsigned int>(q.Vertex));
    for (int c = 0; c < 8; ++c)
    {
      // Our child c = x + 2y + 4z is also vtkHyperTree's child order.
      queue.push_back({ static_cast<std::size_t>(n.FirstChild + c), elder + c, n.Reason });
    }
  }
}
} // namespace

bool ConvertOctree(const AdaptiveOctree& tree, vtkHyperTreeGrid* grid, std::vector<vtkIdType>& nodeToCell,
  const ProgressCallback& progress)
{
  const RootGrid& g = tree.Grid;
  grid->Initialize();
  grid->SetDimensions(g.Dims[0] + 1, g.Dims[1] + 1, g.Dims[2] + 1);
  grid->SetBranchFactor(2);
  vtkNew<vtkDoubleArray> coords[3];
  for (int a = 0; a < 3; ++a)
  {
    coords[a]->SetNumberOfValues(g.Dims[a] + 1);
    for (int i = 0; i <= g.Dims[a]; ++i)
    {
      coords[a]->SetValue(i, g.Origin[a] + i * g.RootSize);
    }
  }
  grid->SetXCoordinates(coords[0]);
  grid->SetYCoordinates(coords[1]);
  grid->SetZCoordinates(coords[2]);

  vtkNew<vtkUnsignedCharArray> depth, reason, sizeReason, state, failed;
  depth->SetName("Depth");
  reason->SetName("SplitReason");
  sizeReason->SetName("SizeReason");
  state->SetName("CellState");
  failed->SetName("FailedTest");
  const Arrays arrays{ depth, reason, sizeReason, state, failed };
  nodeToCell.assign(tree.Nodes.size(), -1);

  // Trees in the grid's index order, as the writer writes them and the
  // reader numbers them.
  std::vector<std::pair<vtkIdType, int>> trees;
  for (int t = 0; t < g.TreeCount(); ++t)
  {
    const OctreeNode& root = tree.Nodes[static_cast<std::size_t>(t)];
    if (tree.RoleOf(root) == TreeRole::Own) // else another piece's tree: absent here (a distributed grid)
    {
      vtkIdType index = 0;
      grid->GetIndexFromLevelZeroCoordinates(index, root.Ijk[0], root.Ijk[1], root.Ijk[2]);
      trees.emplace_back(index, t);
    }
  }
  std::sort(trees.begin(), trees.end());
  vtkNew<vtkHyperTreeGridNonOrientedCursor> cursor;
  vtkIdType offset = 0;
  VisitProgress visits{ progress, tree.Nodes.size() };
  for (const auto& [index, t] : trees)
  {
    if (visits.Aborted)
    {
      break;
    }
    grid->InitializeNonOrientedCursor(cursor, index, true);
    cursor->SetGlobalIndexStart(offset);
    VisitBreadthFirst(tree, static_cast<std::size_t>(t), cursor->GetTree(), offset, arrays, nodeToCell, visits);
    offset += cursor->GetTree()->GetNumberOfVertices();
  }
  grid->GetCellData()->AddArray(depth);
  grid->GetCellData()->AddArray(reason);
  grid->GetCellData()->AddArray(sizeReason);
  grid->GetCellData()->AddArray(state);
  grid->GetCellData()->AddArray(failed);
  // ParaView draws leaves, whose own SplitReason is "none": what explains a
  // leaf's size is its parent's reason.
  grid->GetCellData()->SetActiveScalars("SizeReason");

  // What the values mean, for anyone reading the file or the spreadsheet
  // (and checked against the colour presets by the tests).
  vtkNew<vtkStringArray> reasonNames, stateNames;
  reasonNames->SetName("SplitReasonNames");
  for (int r = 0; r < SplitReasonCount; ++r)
  {
    reasonNames->InsertNextValue(SplitReasonName(static_cast<SplitReason>(r)));
  }
  stateNames->SetName("CellStateNames");
  for (int s = 0; s < CellStateCount; ++s)
  {
    stateNames->InsertNextValue(CellStateName(static_cast<CellState>(s)));
  }
  grid->GetFieldData()->AddArray(reasonNames);
  grid->GetFieldData()->AddArray(stateNames);
  return !visits.Aborted;
}

void AddCertifiedErrors(vtkHyperTreeGrid* grid, const std::vector<vtkIdType>& nodeToCell,
  const std::vector<std::pair<std::uint32_t, double>>& cellErrors)
{
  vtkNew<vtkDoubleArray> certified;
  certified->SetName("CertifiedError");
  certified->SetNumberOfValues(grid->GetNumberOfCells());
  certified->Fill(std::nan(""));
  for (const auto& [node, error] : cellErrors)
  {
    if (nodeToCell[node] >= 0)
    {
      certified->SetValue(nodeToCell[node], error);
    }
  }
  grid->GetCellData()->AddArray(certified);
}

} // namespace vtkadapter
} // namespace tpc
