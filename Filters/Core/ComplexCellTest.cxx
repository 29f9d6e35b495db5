#include "ComplexCellTest.h"

#include "CubeTopology.h"
#include "EdgeCrossings.h"

namespace tpc
{

Box3 FaceBox(const Box3& cell, int face)
{
  Box3 b = cell;
  const int axis = cube::FaceAxis(face);
  if (cube::FaceSide(face) == 0)
  {
    b.hi[axis] = b.lo[axis];
  }
  else
  {
    b.lo[axis] = b.hi[axis];
  }
  return b;
}

RegionSign ProveConstantSign(const CsgExpressionPtr& expression,
  const std::vector<Quadric>& primitives, const Box3& box, int depth)
{
  const auto pruned = CsgExpression::Prune(expression, box, primitives);
  if (pruned.Sign != RegionSign::Mixed || depth == 0)
  {
    return pruned.Sign;
  }
  int axes[3], count = 0;
  for (int a = 0; a < 3; ++a)
  {
    if (box.hi[a] > box.lo[a])
    {
      axes[count++] = a;
    }
  }
  RegionSign common = RegionSign::Mixed;
  for (int piece = 0; piece < (1 << count); ++piece)
  {
    Box3 sub = box;
    for (int k = 0; k < count; ++k)
    {
      const int a = axes[k];
      const double mid = 0.5 * (box.lo[a] + box.hi[a]);
      if ((piece >> k) & 1)
      {
        sub.lo[a] = mid;
      }
      else
      {
        sub.hi[a] = mid;
      }
    }
    const RegionSign s = ProveConstantSign(pruned.Expression, primitives, sub, depth - 1);
    if (s == RegionSign::Mixed || (piece > 0 && s != common))
    {
      return RegionSign::Mixed;
    }
    common = s;
  }
  return common;
}

SplitReason SignAmbiguityTest(unsigned insideMask)
{
  if (cube::HasFaceAmbiguity(insideMask))
  {
    return SplitReason::FaceAmbiguity;
  }
  if (cube::HasVoxelAmbiguity(insideMask))
  {
    return SplitReason::VoxelAmbiguity;
  }
  return SplitReason::None;
}

SplitReason ComplexVoxelOrFaceTest(const ComplexCellQuery& q)
{
  if (q.InsideMask == 0 || q.InsideMask == 0xFF)
  {
    return SplitReason::ComplexVoxel;
  }
  for (int f = 0; f < 6; ++f)
  {
    if (!cube::FaceHasSignChange(q.InsideMask, f) &&
      ProveConstantSign(q.Expression, q.Primitives, FaceBox(q.Cell, f), 1) == RegionSign::Mixed)
    {
      return SplitReason::ComplexFace;
    }
  }
  return SplitReason::None;
}

SplitReason ComplexEdgeTest(const ComplexCellQuery& q)
{
  for (int e = 0; e < 12; ++e)
  {
    const int c0 = cube::EdgeCorner(e, 0), c1 = cube::EdgeCorner(e, 1);
    const EdgeCrossingCount n = CountEdgeCrossings(q.Expression, q.Primitives, q.Cell.Corner(c0),
      q.Cell.Corner(c1), cube::EdgeAxis(e), cube::Inside(q.InsideMask, c0),
      cube::Inside(q.InsideMask, c1));
    if (!n.Proven || n.Count >= 2)
    {
      return SplitReason::ComplexEdge;
    }
  }
  return SplitReason::None;
}

} // namespace tpc
