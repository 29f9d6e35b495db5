#include "McCompatibilityTest.h"

#include "BoundaryLoops.h"
#include "ComplexCellTest.h"
#include "FaceRefinement.h"
#include "StarShapedTest.h"

#include <algorithm>

namespace tpc
{

McCompatibility TestMcCompatibility(
  const AdaptiveOctree& tree, std::uint32_t n, const PrimitiveSet& prims, double tolerance)
{
  McCompatibility v;
  v.Kind = McVerdict::Split;
  const RootGrid& grid = tree.Grid;
  const OctreeNode& node = tree.Nodes[n];
  const CsgExpressionPtr& expression = tree.Expressions[n];
  const Box3 box = grid.CellBox(node.Level, node.Ijk);
  unsigned mask = 0;
  for (int c = 0; c < 8; ++c)
  {
    mask |= tree.CornerInside(n, c) ? (1u << c) : 0u;
  }
  const bool uniform = mask == 0 || mask == 0xFF;
  if (uniform)
  {
    const RegionSign s =
      ProveConstantSign(expression, prims, box, ConstantProofDepth, ConstantProofBudget);
    if (s != RegionSign::Mixed)
    {
      v.Kind = McVerdict::Constant;
      v.Sign = s;
      return v;
    }
  }
  if (grid.CellDiagonal(node.Level) > tolerance * (1.0 + 1e-9))
  {
    // Cells that must shrink anyway skip the costlier tests.
    v.Reason = uniform ? SplitReason::ComplexVoxel : SplitReason::HausdorffSize;
    return v;
  }

  CellSignCache signs(tree.Signs, grid, *expression, prims);
  const int shift = grid.MaxDepth - node.Level;
  const std::uint32_t size = 1u << shift;
  CellBoundary boundary;
  boundary.Size = size;
  for (int a = 0; a < 3; ++a)
  {
    boundary.Base[a] = node.Ijk[a] << shift;
  }
  for (int f = 0; f < 6; ++f)
  {
    const int axis = f / 2, side = f % 2;
    const std::uint32_t plane = boundary.Base[axis] + (side ? size : 0);
    const std::uint32_t u0 = boundary.Base[(axis + 1) % 3], v0 = boundary.Base[(axis + 2) % 3];
    const FaceRefinementResult r = RefineFace(expression, prims, grid, axis, plane,
      { u0, v0, u0 + size, v0 + size }, std::min(FaceRefinementLevels, shift), signs);
    if (r.Tiles.empty())
    {
      v.Reason = r.Failure;
      return v;
    }
    for (const FaceTile& t : r.Tiles)
    {
      for (int c = 0; c < 4; ++c)
      {
        const PointKey key = TileCorner(axis, plane, t, c);
        boundary.Points.emplace_back(key, signs.Inside(key));
      }
    }
    if (r.Tiles.size() > 1)
    {
      v.Refinements.emplace_back(FaceOf(grid, node, f), r.Tiles);
    }
    boundary.Tiles[f] = r.Tiles;
  }
  const BoundaryLoopSet loops = TraceBoundaryLoops(boundary);
  if (loops.LoopSizes.size() != 1 || !loops.Consistent)
  {
    v.Reason = loops.LoopSizes.empty() ? SplitReason::ComplexVoxel : SplitReason::VoxelAmbiguity;
    return v;
  }
  if (!IsStarShapedWithRespectToVoxel(expression, prims, box))
  {
    v.Reason = SplitReason::NotStarShapedVoxel;
    return v;
  }
  v.Kind = McVerdict::Pass;
  v.Reason = SplitReason::None;
  v.NewSigns = signs.NewSigns();
  return v;
}

} // namespace tpc
