#include "ComplexCellTest.h"

#include "CubeTopology.h"
#include "EdgeCrossings.h"
#include "StarShapedTest.h"

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

namespace
{
RegionSign ProveConstant(const CsgExpressionPtr& expression, const PrimitiveSet& primitives,
  const Box3& box, int depth, int& budget)
{
  const auto pruned = CsgExpression::Prune(expression, box, primitives);
  if (pruned.Sign != RegionSign::Mixed || depth == 0 || --budget < 0)
  {
    return pruned.Sign;
  }
  Box3 pieces[8];
  const int count = SplitBox(box, pieces);
  RegionSign common = RegionSign::Mixed;
  for (int piece = 0; piece < count; ++piece)
  {
    const RegionSign s = ProveConstant(pruned.Expression, primitives, pieces[piece], depth - 1, budget);
    if (s == RegionSign::Mixed || (piece > 0 && s != common))
    {
      return RegionSign::Mixed;
    }
    common = s;
  }
  return common;
}
} // namespace

RegionSign ProveConstantSign(const CsgExpressionPtr& expression,
  const PrimitiveSet& primitives, const Box3& box, int depth, int budget)
{
  return ProveConstant(expression, primitives, box, depth, budget);
}

SplitReason FaceCompatibilityTest(const CsgExpressionPtr& expression,
  const PrimitiveSet& primitives, const Box3& face, int axis, const bool inside[4],
  int* failingEdge)
{
  const bool change = inside[0] != inside[1] || inside[1] != inside[2] || inside[2] != inside[3];
  if (!change)
  {
    return ProveConstantSign(expression, primitives, face, ConstantProofDepth, ConstantProofBudget) ==
        RegionSign::Mixed
      ? SplitReason::ComplexFace
      : SplitReason::None;
  }
  if (inside[0] == inside[2] && inside[1] == inside[3])
  {
    return SplitReason::FaceAmbiguity;
  }
  const int U = (axis + 1) % 3, V = (axis + 2) % 3;
  const double u[4] = { face.lo[U], face.hi[U], face.hi[U], face.lo[U] };
  const double v[4] = { face.lo[V], face.lo[V], face.hi[V], face.hi[V] };
  for (int k = 0; k < 4; ++k)
  {
    const int l = (k + 1) % 4;
    Vec3 a = face.lo, b = face.lo;
    a[U] = u[k];
    a[V] = v[k];
    b[U] = u[l];
    b[V] = v[l];
    const int along = u[k] != u[l] ? U : V;
    const bool lowerIsA = a[along] < b[along];
    const EdgeCrossingCount n = CountEdgeCrossings(expression, primitives, lowerIsA ? a : b,
      lowerIsA ? b : a, along, lowerIsA ? inside[k] : inside[l], lowerIsA ? inside[l] : inside[k]);
    if (!n.Proven || n.Count >= 2)
    {
      if (failingEdge)
      {
        *failingEdge = k;
      }
      return SplitReason::ComplexEdge;
    }
  }
  if (!IsStarShapedWithRespectToFace(expression, primitives, face, axis))
  {
    return SplitReason::NotStarShapedFace;
  }
  return SplitReason::None;
}

} // namespace tpc
