#include "ComplexCellCriterion.h"

#include "CubeTopology.h"
#include "EdgeCrossings.h"
#include "StarShapedCriterion.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <vector>

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

namespace
{
/// Lattice extent of each loop. A crossing is only known to lie on its
/// sub-edge; bisection on exact signs narrows it to a sixteenth of the cell.
std::vector<std::array<LatticeIndex, 6>> LoopExtents(const BoundaryLoopSet& loops,
  const CsgExpression& expression, const PrimitiveSet& prims, const RootGrid& grid,
  LatticeIndex cellSize)
{
  std::vector<std::array<LatticeIndex, 6>> extents;
  const LatticeIndex target = std::max<LatticeIndex>(1, cellSize / 16);
  std::size_t offset = 0;
  for (const std::uint32_t size : loops.LoopSizes)
  {
    constexpr LatticeIndex none = ~LatticeIndex(0);
    std::array<LatticeIndex, 6> e = { none, none, none, 0, 0, 0 };
    for (std::uint32_t k = 0; k < size; ++k)
    {
      const Crossing& c = loops.Crossings[offset + k];
      LatticeIndex p[3];
      SplitPointKey(PointOf(c.Key), p);
      const int along = AxisOf(c.Key);
      const bool bend = c.Kind == CrossingKind::Bend;
      LatticeIndex lo = p[along], hi = bend ? p[along] : c.Upper;
      while (!bend && hi - lo > target)
      {
        LatticeIndex m[3] = { p[0], p[1], p[2] };
        m[along] = lo + (hi - lo) / 2;
        (expression.IsInside(grid.Point(m), prims) == c.LowerInside ? lo : hi) = m[along];
      }
      for (int a = 0; a < 3; ++a)
      {
        e[a] = std::min(e[a], a == along ? lo : p[a]);
        e[3 + a] = std::max(e[3 + a], a == along ? hi : p[a]);
      }
    }
    extents.push_back(e);
    offset += size;
  }
  return extents;
}
} // namespace

bool LoopsSeparated(const BoundaryLoopSet& loops, const CsgExpressionPtr& expression,
  const PrimitiveSet& primitives, const RootGrid& grid, const Box3& cell)
{
  LatticeIndex size = 1;
  for (int a = 0; a < 3; ++a)
  {
    // Lattice size of the cell from its world size (exact enough for a bound).
    size = std::max(size, static_cast<LatticeIndex>(std::llround(cell.Width(a) / std::ldexp(grid.RootSize, -grid.MaxDepth))));
  }
  const auto extents = LoopExtents(loops, *expression, primitives, grid, size);
  for (std::size_t i = 0; i < extents.size(); ++i)
  {
    for (std::size_t j = i + 1; j < extents.size(); ++j)
    {
      bool separated = false;
      for (int a = 0; a < 3 && !separated; ++a)
      {
        for (int order = 0; order < 2 && !separated; ++order)
        {
          const auto& low = order == 0 ? extents[i] : extents[j];
          const auto& high = order == 0 ? extents[j] : extents[i];
          if (low[3 + a] >= high[a])
          {
            continue;
          }
          // A section of the cell strictly between the two loops that the
          // surface provably misses.
          Box3 section = cell;
          section.lo[a] = section.hi[a] =
            0.5 * (grid.Coordinate(a, low[3 + a]) + grid.Coordinate(a, high[a]));
          separated = ProveConstantSign(expression, primitives, section, ConstantProofDepth,
                        ConstantProofBudget) != RegionSign::Mixed;
        }
      }
      if (!separated)
      {
        return false;
      }
    }
  }
  return true;
}

SplitReason VoxelCompatibilityTest(const BoundaryLoopSet& loops, const CsgExpressionPtr& expression,
  const PrimitiveSet& primitives, const RootGrid& grid, const Box3& cell)
{
  if (loops.LoopSizes.empty() || !loops.Consistent)
  {
    return SplitReason::ComplexVoxel;
  }
  if (loops.LoopSizes.size() > 1 && !LoopsSeparated(loops, expression, primitives, grid, cell))
  {
    return SplitReason::VoxelAmbiguity;
  }
  return SplitReason::None;
}

} // namespace tpc
