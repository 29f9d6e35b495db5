#include "CsgCreaseCrossing.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace tpc
{
namespace
{
/// The two quadric leaves of `expression` pruned to the tile, if that is
/// what it has.
std::optional<std::pair<CsgLeaf, CsgLeaf>> TwoQuadricLeaves(
  const CsgExpressionPtr& expression, const PrimitiveSet& primitives, const Box3& tileBox)
{
  const CsgExpression::Pruned pruned = CsgExpression::Prune(expression, tileBox, primitives);
  if (pruned.Sign != RegionSign::Mixed)
  {
    return std::nullopt;
  }
  const std::vector<CsgLeaf> leaves = pruned.Expression->Leaves();
  if (leaves.size() != 2 || leaves[0].Kind != PrimitiveKind::Quadric || leaves[1].Kind != PrimitiveKind::Quadric ||
    leaves[0].Primitive == leaves[1].Primitive)
  {
    return std::nullopt;
  }
  return std::make_pair(leaves[0], leaves[1]);
}

/// Newton's iterations at most; the step it converges at, relative to the
/// tile's width - or to the coordinates' size, where a double's spacing
/// there is coarser (a small tile far from the origin: the last steps are
/// rounding noise, and would never reach 1e-13 of the tile).
constexpr int NewtonSteps = 40;
constexpr double Converged = 1e-13;
constexpr double Ulps = 8.0 * std::numeric_limits<double>::epsilon();
/// The fraction of the tile's width x keeps from its sides: far above a
/// double's rounding of x (so x is strictly inside wherever it is placed),
/// and small, so that a crease crossing a tile is missed only where it
/// passes within a millionth of a tile side (a crease cell larger than the
/// tolerance needs every crossing of its crease in its final loop, whose
/// tiles a finer neighbour may have cut anywhere, QuadricCellError.h).
constexpr double SideMargin = 1e-6;
/// The smallest sine of the angle between the two zero curves at x (below:
/// nearly tangent, x is ill-conditioned and the crease too shallow to miss).
constexpr double Transversal = 0.05;

/// x solving both leaves' equations on the plane x_axis = c, from `start`;
/// nothing when the iteration does not settle inside the tile with the
/// curves crossing transversally.
std::optional<Vec3> CrossingOfZeroCurvesFrom(const std::pair<CsgLeaf, CsgLeaf>& leaves,
  const PrimitiveSet& primitives, int axis, const Box3& tileBox, Vec3 x)
{
  const int U = (axis + 1) % 3, V = (axis + 2) % 3;
  const double width = tileBox.Width(U), height = tileBox.Width(V);
  x[axis] = tileBox.lo[axis];
  for (int step = 0; step < NewtonSteps; ++step)
  {
    const double f = LeafValue(leaves.first, primitives, x), g = LeafValue(leaves.second, primitives, x);
    const Vec3 df = LeafGradient(leaves.first, primitives, x), dg = LeafGradient(leaves.second, primitives, x);
    const double det = df[U] * dg[V] - df[V] * dg[U];
    if (!(std::fabs(det) > 0.0))
    {
      return std::nullopt;
    }
    const double du = (-f * dg[V] + df[V] * g) / det, dv = (-df[U] * g + dg[U] * f) / det;
    x[U] += du;
    x[V] += dv;
    if (!std::isfinite(x[U]) || !std::isfinite(x[V]) || std::fabs(x[U] - tileBox.Center()[U]) > 2.0 * width ||
      std::fabs(x[V] - tileBox.Center()[V]) > 2.0 * height)
    {
      return std::nullopt; // wandered off: no crossing near this tile
    }
    const double rounding = Ulps * std::max(std::fabs(x[U]), std::fabs(x[V]));
    if (std::fabs(du) <= std::max(Converged * width, rounding) &&
      std::fabs(dv) <= std::max(Converged * height, rounding))
    {
      const double sine = std::fabs(det) /
        (std::hypot(df[U], df[V]) * std::hypot(dg[U], dg[V]));
      const bool inside = x[U] > tileBox.lo[U] + SideMargin * width && x[U] < tileBox.hi[U] - SideMargin * width &&
        x[V] > tileBox.lo[V] + SideMargin * height && x[V] < tileBox.hi[V] - SideMargin * height;
      return sine >= Transversal && inside ? std::optional<Vec3>(x) : std::nullopt;
    }
  }
  return std::nullopt;
}

/// CrossingOfZeroCurvesFrom the tile's centre, else from its corners and
/// the middles of its sides, in that order: two conics on the tile's plane
/// may cross twice, and from the centre Newton's steps can settle on the
/// crossing outside the tile while the one inside is what the trace bends
/// at (a cell the crease crosses keeps its certificate only if its loop
/// holds it, QuadricCellError.h).
std::optional<Vec3> CrossingOfZeroCurves(const std::pair<CsgLeaf, CsgLeaf>& leaves, const PrimitiveSet& primitives,
  int axis, const Box3& tileBox)
{
  const int U = (axis + 1) % 3, V = (axis + 2) % 3;
  for (const double u : { 0.5, 0.0, 1.0 })
  {
    for (const double v : { 0.5, 0.0, 1.0 })
    {
      Vec3 start = tileBox.Center();
      start[U] = tileBox.lo[U] + u * tileBox.Width(U);
      start[V] = tileBox.lo[V] + v * tileBox.Width(V);
      if (const auto x = CrossingOfZeroCurvesFrom(leaves, primitives, axis, tileBox, start))
      {
        return x;
      }
    }
  }
  return std::nullopt;
}
} // namespace

Crossing CsgCreaseCrossing(int axis, LatticeIndex plane, const FaceTile& tile)
{
  Crossing x;
  x.Kind = CrossingKind::CsgCrease;
  x.Tile = TileKey(axis, plane, tile);
  x.Key = tile.U1;
  x.Partner = tile.V1;
  return x;
}

std::optional<Vec3> CsgCreaseOnTile(const CsgExpressionPtr& expression, const PrimitiveSet& primitives,
  const RootGrid& grid, int axis, LatticeIndex plane, const FaceTile& tile)
{
  const Box3 box = TileBox(grid, axis, plane, tile);
  const auto leaves = TwoQuadricLeaves(expression, primitives, box);
  return leaves ? CrossingOfZeroCurves(*leaves, primitives, axis, box) : std::nullopt;
}

namespace
{
/// The box of a CsgCrease crossing's tile, and the tile's plane axis.
Box3 CreaseTileBox(const Crossing& x, const RootGrid& grid, int& axis)
{
  axis = TileKeyAxis(x.Tile);
  LatticeIndex corner[3];
  TileKeyCorner(x.Tile, corner);
  FaceTile tile;
  tile.U0 = corner[(axis + 1) % 3];
  tile.V0 = corner[(axis + 2) % 3];
  tile.U1 = static_cast<LatticeIndex>(x.Key);
  tile.V1 = static_cast<LatticeIndex>(x.Partner);
  return TileBox(grid, axis, corner[axis], tile);
}
} // namespace

Vec3 CsgCreaseTileCentre(const Crossing& x, const RootGrid& grid)
{
  int axis = 0;
  return CreaseTileBox(x, grid, axis).Center();
}

std::optional<std::pair<Vec3, Vec3>> CsgCreaseVertex(
  const Crossing& x, const CsgExpressionPtr& expression, const PrimitiveSet& primitives, const RootGrid& grid)
{
  int axis = 0;
  const Box3 box = CreaseTileBox(x, grid, axis);
  const auto leaves = TwoQuadricLeaves(expression, primitives, box);
  const auto position = leaves ? CrossingOfZeroCurves(*leaves, primitives, axis, box) : std::nullopt;
  if (!position)
  {
    return std::nullopt; // (the tile was decided otherwise: see the caller)
  }
  const Vec3 normal = Normalized(Normalized(LeafGradient(leaves->first, primitives, *position)) +
    Normalized(LeafGradient(leaves->second, primitives, *position)));
  return std::make_pair(*position, normal);
}

} // namespace tpc
