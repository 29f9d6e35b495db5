#include "ExactCellCriterion.h"

#include <algorithm>

namespace tpc
{

const CsgLeaf* LoneMeshLeaf(const CsgExpression& expression)
{
  const CsgExpression::Node& root = expression.NodeAt(expression.Root());
  return root.NodeKind == CsgExpression::Node::Kind::Leaf && root.LeafData.Kind == PrimitiveKind::Mesh &&
      root.LeafData.Triangles
    ? &root.LeafData
    : nullptr;
}

bool KeepsTheMesh(const CsgExpression& expression, bool toleranceSize, bool hopeless)
{
  const CsgLeaf* leaf = LoneMeshLeaf(expression);
  return leaf && (hopeless || (toleranceSize && leaf->Triangles->size() <= ExactCellTriangles));
}

double ExactCellReferenceSize(double tolerance, double surfaceDiagonal)
{
  return surfaceDiagonal > 0.0 ? std::min(tolerance, surfaceDiagonal / 8.0) : tolerance;
}

bool IsOneMesh(const CsgExpression& expression)
{
  const CsgExpression::Node& root = expression.NodeAt(expression.Root());
  return root.NodeKind == CsgExpression::Node::Kind::Leaf && root.LeafData.Kind == PrimitiveKind::Mesh;
}

} // namespace tpc
