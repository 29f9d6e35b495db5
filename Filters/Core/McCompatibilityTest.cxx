#include "McCompatibilityTest.h"

#include "BoundaryLoops.h"
#include "ComplexCellTest.h"
#include "FaceRefinement.h"
#include "PlanarCell.h"
#include "StarShapedTest.h"

#include <algorithm>
#include <cmath>

namespace tpc
{

namespace
{
/// Lattice extent of each loop. A crossing is only known to lie on its
/// sub-edge; bisection on exact signs narrows it to a sixteenth of the cell.
std::vector<std::array<std::uint32_t, 6>> LoopExtents(const BoundaryLoopSet& loops,
  const CsgExpression& expression, const PrimitiveSet& prims, const RootGrid& grid,
  std::uint32_t cellSize)
{
  std::vector<std::array<std::uint32_t, 6>> extents;
  const std::uint32_t target = std::max<std::uint32_t>(1, cellSize / 16);
  std::size_t offset = 0;
  for (const std::uint32_t size : loops.LoopSizes)
  {
    std::array<std::uint32_t, 6> e = { UINT32_MAX, UINT32_MAX, UINT32_MAX, 0, 0, 0 };
    for (std::uint32_t k = 0; k < size; ++k)
    {
      const Crossing& c = loops.Crossings[offset + k];
      std::uint32_t p[3];
      SplitPointKey(c.Key >> 2, p);
      const int along = static_cast<int>(c.Key & 3);
      const bool bend = c.Kind == CrossingKind::Bend;
      std::uint32_t lo = p[along], hi = bend ? p[along] : c.Upper;
      while (!bend && hi - lo > target)
      {
        std::uint32_t m[3] = { p[0], p[1], p[2] };
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
  std::uint32_t size = 1;
  for (int a = 0; a < 3; ++a)
  {
    // Lattice size of the cell from its world size (exact enough for a bound).
    size = std::max(size, static_cast<std::uint32_t>(std::llround(cell.Width(a) / std::ldexp(grid.RootSize, -grid.MaxDepth))));
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

McCompatibility TestMcCompatibility(const AdaptiveOctree& tree, std::uint32_t n, const PrimitiveSet& prims,
  double tolerance, int faceRefinementLevels)
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
  // Cells that must shrink anyway skip the costlier tests; a plane section
  // may stay larger (error-driven acceptance, PlanarCell.h).
  const bool oversized = grid.CellDiagonal(node.Level) > tolerance * (1.0 + 1e-9);
  if (oversized && (uniform || !IsPlanarCell(*expression, prims, box)))
  {
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
      { u0, v0, u0 + size, v0 + size }, std::min(faceRefinementLevels, shift), signs);
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
  if (loops.LoopSizes.empty() || !loops.Consistent)
  {
    v.Reason = SplitReason::ComplexVoxel;
    return v;
  }
  if (loops.LoopSizes.size() > 1 && !LoopsSeparated(loops, expression, prims, grid, box))
  {
    v.Reason = SplitReason::VoxelAmbiguity;
    return v;
  }
  if (!IsStarShapedWithRespectToVoxel(expression, prims, box))
  {
    v.Reason = SplitReason::NotStarShapedVoxel;
    return v;
  }
  v.Kind = McVerdict::Pass;
  v.Reason = SplitReason::None;
  v.Planar = oversized; // (an oversized cell only gets this far as a plane section)
  v.NewSigns = signs.NewSigns();
  return v;
}

} // namespace tpc
