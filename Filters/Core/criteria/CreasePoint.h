// Points where two or three quadric leaves vanish together: the crease of
// two primitives of a CSG solid, or the corner of three (issue 17). Their
// patches' apexes go there, so that the output's crease runs along edges
// (LoopTriangulation.h) and, in a cell a crease crosses, the fan around it is
// made of sectors, each on one leaf (QuadricCellError.h).
#pragma once

#include "CsgExpression.h"

#include <optional>

namespace tpc
{

/// `start` moved onto the crease of two quadric leaves by Gauss-Newton steps
/// (the least change of position that zeroes both); nothing when they do
/// not settle within `scale` of it.
std::optional<Vec3> OntoCrease(
  const CsgLeaf& p, const CsgLeaf& q, const PrimitiveSet& primitives, const Vec3& start, double scale);

/// `start` moved to the corner where three quadric leaves vanish by Newton's
/// method; nothing when their normals are nearly coplanar there or the
/// steps do not settle within `scale` of it.
std::optional<Vec3> OntoCorner(const CsgLeaf leaves[3], const PrimitiveSet& primitives, const Vec3& start, double scale);

} // namespace tpc
