#include "ComplexCellCriterion.h"

#include "CubeTopology.h"
#include "EdgeCrossings.h"
#include "StarShapedCriterion.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
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
  int* failingEdge, double* opposite)
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
  for (int k = 0; k < 4; ++k)
  {
    if (!EdgeCrossedOnce(expression, primitives, face, axis, inside, k, opposite))
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

bool EdgeCrossedOnce(const CsgExpressionPtr& expression, const PrimitiveSet& primitives, const Box3& face,
  int axis, const bool inside[4], int k, double* opposite)
{
  const int U = (axis + 1) % 3, V = (axis + 2) % 3;
  const double u[4] = { face.lo[U], face.hi[U], face.hi[U], face.lo[U] };
  const double v[4] = { face.lo[V], face.lo[V], face.hi[V], face.hi[V] };
  const int l = (k + 1) % 4;
  Vec3 a = face.lo, b = face.lo;
  a[U] = u[k];
  a[V] = v[k];
  b[U] = u[l];
  b[V] = v[l];
  const int along = u[k] != u[l] ? U : V;
  const bool lowerIsA = a[along] < b[along];
  double between = std::numeric_limits<double>::quiet_NaN();
  const bool ask = opposite && inside[k] == inside[l];
  const EdgeCrossingCount n = CountEdgeCrossings(expression, primitives, lowerIsA ? a : b, lowerIsA ? b : a,
    along, lowerIsA ? inside[k] : inside[l], lowerIsA ? inside[l] : inside[k], 24, ask ? &between : nullptr);
  if (ask && (between - face.lo[along]) * (face.hi[along] - between) > 0.0) // (false for NaN)
  {
    *opposite = between;
  }
  return n.Proven && n.Count <= 1;
}

namespace
{
/// Lattice extent of each loop. A crossing is only known to lie on its
/// sub-edge; bisection on exact signs narrows it to `target` lattice units.
std::vector<std::array<LatticeIndex, 6>> LoopExtents(const BoundaryLoopSet& loops,
  const CsgExpression& expression, const PrimitiveSet& prims, const RootGrid& grid,
  LatticeIndex target)
{
  std::vector<std::array<LatticeIndex, 6>> extents;
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

namespace
{
bool SeparatedWithin(const BoundaryLoopSet& loops, const CsgExpressionPtr& expression,
  const PrimitiveSet& primitives, const RootGrid& grid, const Box3& cell, LatticeIndex target,
  std::vector<Box3>& regions)
{
  const auto extents = LoopExtents(loops, *expression, primitives, grid, target);
  regions.assign(extents.size(), cell);
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
          if (separated)
          {
            const double at = section.lo[a];
            Box3& below = regions[order == 0 ? i : j];
            Box3& above = regions[order == 0 ? j : i];
            below.hi[a] = std::min(below.hi[a], at);
            above.lo[a] = std::max(above.lo[a], at);
          }
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
} // namespace

bool LoopsSeparated(const BoundaryLoopSet& loops, const CsgExpressionPtr& expression,
  const PrimitiveSet& primitives, const RootGrid& grid, const Box3& cell, std::vector<Box3>* regions)
{
  LatticeIndex size = 1;
  for (int a = 0; a < 3; ++a)
  {
    // Lattice size of the cell from its world size (exact enough for a bound).
    size = std::max(size, static_cast<LatticeIndex>(std::llround(cell.Width(a) / std::ldexp(grid.RootSize, -grid.MaxDepth))));
  }
  // A sixteenth of the cell separates loops of surfaces that are apart by
  // more than that (most cells, cheaply); surfaces passing closer - a near
  // contact - are located down to the lattice, so that a gap of a few
  // lattice spacings is found without refining the cell down to the gap.
  std::vector<Box3> found;
  const bool separated =
    SeparatedWithin(loops, expression, primitives, grid, cell, std::max<LatticeIndex>(1, size / 16), found) ||
    (size > 16 && SeparatedWithin(loops, expression, primitives, grid, cell, 1, found));
  if (separated && regions)
  {
    *regions = std::move(found);
  }
  return separated;
}

SplitReason VoxelCompatibilityTest(const BoundaryLoopSet& loops, const CsgExpressionPtr& expression,
  const PrimitiveSet& primitives, const RootGrid& grid, const Box3& cell, std::vector<Box3>* loopRegions)
{
  if (loopRegions)
  {
    loopRegions->assign(1, cell);
  }
  if (loops.LoopSizes.empty() || !loops.Consistent)
  {
    return SplitReason::ComplexVoxel;
  }
  if (loops.LoopSizes.size() > 1 && !LoopsSeparated(loops, expression, primitives, grid, cell, loopRegions))
  {
    return SplitReason::VoxelAmbiguity;
  }
  return SplitReason::None;
}

} // namespace tpc
