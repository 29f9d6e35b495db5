#include "OctreeToHyperTreeGrid.h"

#include "vtkCellData.h"
#include "vtkDoubleArray.h"
#include "vtkHyperTree.h"
#include "vtkHyperTreeGrid.h"
#include "vtkHyperTreeGridNonOrientedCursor.h"
#include "vtkNew.h"
#include "vtkUnsignedCharArray.h"

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
  vtkUnsignedCharArray* State;
  vtkUnsignedCharArray* Failed;
};

void Visit(const AdaptiveOctree& tree, std::size_t node, vtkHyperTreeGridNonOrientedCursor* cursor,
  const Arrays& arrays, std::vector<vtkIdType>& nodeToCell)
{
  const OctreeNode& n = tree.Nodes[node];
  const vtkIdType id = cursor->GetGlobalNodeIndex();
  nodeToCell[node] = id;
  arrays.Depth->InsertValue(id, n.Level);
  arrays.Reason->InsertValue(id, static_cast<unsigned char>(n.Reason));
  arrays.State->InsertValue(id, static_cast<unsigned char>(n.State));
  arrays.Failed->InsertValue(id, static_cast<unsigned char>(n.FailedTest));
  if (n.IsLeaf())
  {
    return;
  }
  cursor->SubdivideLeaf();
  for (int c = 0; c < 8; ++c)
  {
    // Our child c = x + 2y + 4z is also vtkHyperTree's child order.
    cursor->ToChild(static_cast<unsigned char>(c));
    Visit(tree, static_cast<std::size_t>(n.FirstChild + c), cursor, arrays, nodeToCell);
    cursor->ToParent();
  }
}
} // namespace

void ConvertOctree(
  const AdaptiveOctree& tree, vtkHyperTreeGrid* grid, std::vector<vtkIdType>& nodeToCell)
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

  vtkNew<vtkUnsignedCharArray> depth, reason, state, failed;
  depth->SetName("Depth");
  reason->SetName("SplitReason");
  state->SetName("CellState");
  failed->SetName("FailedTest");
  const Arrays arrays{ depth, reason, state, failed };
  nodeToCell.assign(tree.Nodes.size(), -1);

  vtkNew<vtkHyperTreeGridNonOrientedCursor> cursor;
  vtkIdType offset = 0;
  for (int t = 0; t < g.TreeCount(); ++t)
  {
    const OctreeNode& root = tree.Nodes[static_cast<std::size_t>(t)];
    vtkIdType index = 0;
    grid->GetIndexFromLevelZeroCoordinates(index, root.Ijk[0], root.Ijk[1], root.Ijk[2]);
    grid->InitializeNonOrientedCursor(cursor, index, true);
    cursor->SetGlobalIndexStart(offset);
    Visit(tree, static_cast<std::size_t>(t), cursor, arrays, nodeToCell);
    offset += cursor->GetTree()->GetNumberOfVertices();
  }
  grid->GetCellData()->AddArray(depth);
  grid->GetCellData()->AddArray(reason);
  grid->GetCellData()->AddArray(state);
  grid->GetCellData()->AddArray(failed);
  grid->GetCellData()->SetActiveScalars("SplitReason");
}

} // namespace vtkadapter
} // namespace tpc
