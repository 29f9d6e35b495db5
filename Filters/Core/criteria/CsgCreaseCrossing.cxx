#include "CsgCreaseCrossing.h"

#include "EdgeCrossings.h"
#include "MeshSolid.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <vector>

namespace tpc
{
namespace
{
/// The two leaves of `expression` pruned to the tile - quadrics, or meshes
/// with the triangles that may meet it - if that is what it has, with the
/// pruned expression that owns the meshes' triangle lists.
struct TwoLeaves
{
  CsgExpressionPtr Owner; ///< keeps the mesh leaves' triangle lists alive
  std::pair<CsgLeaf, CsgLeaf> Leaves;
};

std::optional<TwoLeaves> TwoLeavesOnTile(
  const CsgExpressionPtr& expression, const PrimitiveSet& primitives, const Box3& tileBox)
{
  const CsgExpression::Pruned pruned = CsgExpression::Prune(expression, tileBox, primitives);
  if (pruned.Sign != RegionSign::Mixed)
  {
    return std::nullopt;
  }
  const std::vector<CsgLeaf> leaves = pruned.Expression->Leaves();
  if (leaves.size() != 2 || (leaves[0].Kind == leaves[1].Kind && leaves[0].Primitive == leaves[1].Primitive))
  {
    return std::nullopt;
  }
  for (const CsgLeaf& leaf : leaves)
  {
    if (leaf.Kind == PrimitiveKind::Mesh && !leaf.Triangles)
    {
      return std::nullopt;
    }
  }
  return TwoLeaves{ pruned.Expression, { leaves[0], leaves[1] } };
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

/// Whether the point's (U, V) coordinates lie inside `tileBox` by at least
/// `margin` of its width along each (a negative margin: within the box
/// grown by that much).
bool InsideTile(const Vec3& x, int U, int V, const Box3& tileBox, double margin)
{
  const double width = tileBox.Width(U), height = tileBox.Width(V);
  return x[U] > tileBox.lo[U] + margin * width && x[U] < tileBox.hi[U] - margin * width &&
    x[V] > tileBox.lo[V] + margin * height && x[V] < tileBox.hi[V] - margin * height;
}

/// The sine of the angle between the two leaves' zero curves on the plane
/// at x: of their gradients projected on it (NaN where one vanishes).
double CrossingSine(const Vec3& df, const Vec3& dg, int U, int V)
{
  return std::fabs(df[U] * dg[V] - df[V] * dg[U]) / (std::hypot(df[U], df[V]) * std::hypot(dg[U], dg[V]));
}

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
      return CrossingSine(df, dg, U, V) >= Transversal && InsideTile(x, U, V, tileBox, SideMargin)
        ? std::optional<Vec3>(x)
        : std::nullopt;
    }
  }
  return std::nullopt;
}

/// A piece of a mesh's trace on a plane: its ends' (U, V) coordinates.
struct TraceSegment
{
  double A[2], B[2];
};

/// A mesh leaf's trace on the plane x_axis = c near a tile: the segments its
/// listed triangles cut from the plane, each edge's crossing interpolated
/// from its lower-numbered vertex, so that the two triangles sharing the edge
/// put it at the same point (the trace is a chain; a crossing of another
/// trace at one of its vertices is then seen in both segments or in
/// neither, never in one of them by rounding). False where a listed
/// triangle touches the plane at a vertex or lies in it (the crossing of the
/// traces would not be one point of two segments: the tile is drawn
/// straight).
bool MeshTrace(const CsgLeaf& leaf, const PrimitiveSet& primitives, int axis, double c, std::vector<TraceSegment>& out)
{
  const int U = (axis + 1) % 3, V = (axis + 2) % 3;
  const MeshSolid& mesh = primitives.Meshes[leaf.Primitive];
  for (const std::uint32_t t : *leaf.Triangles)
  {
    const auto& corners = mesh.Triangles()[t];
    const Vec3* p[3] = { &mesh.Points()[corners[0]], &mesh.Points()[corners[1]], &mesh.Points()[corners[2]] };
    int above = 0, below = 0;
    for (const Vec3* q : p)
    {
      above += (*q)[axis] > c ? 1 : 0;
      below += (*q)[axis] < c ? 1 : 0;
    }
    if (above == 3 || below == 3)
    {
      continue;
    }
    if (above + below != 3)
    {
      return false;
    }
    TraceSegment segment;
    int found = 0;
    for (int k = 0; k < 3; ++k)
    {
      const bool lowerFirst = corners[k] < corners[(k + 1) % 3];
      const Vec3 &a = lowerFirst ? *p[k] : *p[(k + 1) % 3], &b = lowerFirst ? *p[(k + 1) % 3] : *p[k];
      if ((a[axis] > c) != (b[axis] > c))
      {
        const double s = (c - a[axis]) / (b[axis] - a[axis]);
        double* end = found++ == 0 ? segment.A : segment.B;
        end[0] = a[U] + s * (b[U] - a[U]);
        end[1] = a[V] + s * (b[V] - a[V]);
      }
    }
    out.push_back(segment);
  }
  return true;
}

/// Where segment `m` crosses the quadric leaf's zero curve on the plane
/// x_axis = c: the quadric along the segment is a quadratic in its
/// parameter, given by its values at the ends and the middle; its roots
/// strictly inside the segment, appended to `points` (U, V).
void CrossingsWithQuadric(const TraceSegment& m, const CsgLeaf& leaf, const PrimitiveSet& primitives, int axis,
  double c, std::vector<std::array<double, 2>>& points)
{
  const int U = (axis + 1) % 3, V = (axis + 2) % 3;
  const auto at = [&](double s) {
    Vec3 x;
    x[axis] = c;
    x[U] = m.A[0] + s * (m.B[0] - m.A[0]);
    x[V] = m.A[1] + s * (m.B[1] - m.A[1]);
    return x;
  };
  const double f0 = LeafValue(leaf, primitives, at(0.0)), fh = LeafValue(leaf, primitives, at(0.5)),
               f1 = LeafValue(leaf, primitives, at(1.0));
  // f(s) = f0 + b s + a s^2 through the three values.
  const double a = 2.0 * (f1 - 2.0 * fh + f0), b = f1 - f0 - a;
  std::vector<double> roots;
  if (std::fabs(a) <= 1e-12 * (std::fabs(b) + std::fabs(f0)))
  {
    if (b != 0.0)
    {
      roots.push_back(-f0 / b);
    }
  }
  else
  {
    const double disc = b * b - 4.0 * a * f0;
    if (disc >= 0.0)
    {
      const double q = -0.5 * (b + std::copysign(std::sqrt(disc), b));
      roots.push_back(q / a);
      if (q != 0.0)
      {
        roots.push_back(f0 / q);
      }
    }
  }
  Vec3 direction; // (of the segment, along which the roots are polished)
  direction[U] = m.B[0] - m.A[0];
  direction[V] = m.B[1] - m.A[1];
  for (double s : roots)
  {
    // (Two Newton steps on the quadric itself: the three samples span the
    // whole segment, which may be far longer than the tile, and the fit's
    // coefficients lose digits to cancellation there.)
    for (int step = 0; step < 2 && s > 0.0 && s < 1.0; ++step)
    {
      const double slope = Dot(LeafGradient(leaf, primitives, at(s)), direction);
      s = slope != 0.0 ? s - LeafValue(leaf, primitives, at(s)) / slope : s;
    }
    if (s > 0.0 && s < 1.0)
    {
      const Vec3 x = at(s);
      points.push_back({ x[U], x[V] });
    }
  }
}

/// Where two mesh traces' segments cross (strictly inside both), appended
/// to `points`.
void CrossingsOfSegments(const TraceSegment& p, const TraceSegment& q, std::vector<std::array<double, 2>>& points)
{
  const double d1[2] = { p.B[0] - p.A[0], p.B[1] - p.A[1] }, d2[2] = { q.B[0] - q.A[0], q.B[1] - q.A[1] };
  const double det = d1[0] * d2[1] - d1[1] * d2[0];
  if (!(std::fabs(det) > 0.0))
  {
    return;
  }
  const double w[2] = { q.A[0] - p.A[0], q.A[1] - p.A[1] };
  const double s = (w[0] * d2[1] - w[1] * d2[0]) / det, t = (w[0] * d1[1] - w[1] * d1[0]) / det;
  if (s > 0.0 && s < 1.0 && t > 0.0 && t < 1.0)
  {
    points.push_back({ p.A[0] + s * d1[0], p.A[1] + s * d1[1] });
  }
}

/// The one point where the traces of two leaves, at least one a mesh,
/// cross inside the tile, at least SideMargin of its width from its sides,
/// the traces crossing there at an angle whose sine is at least
/// Transversal; nothing where they cross there more than once or not at
/// all (the tile is then drawn straight).
std::optional<Vec3> CrossingOfTraces(const std::pair<CsgLeaf, CsgLeaf>& leaves, const PrimitiveSet& primitives,
  int axis, const Box3& tileBox)
{
  const int U = (axis + 1) % 3, V = (axis + 2) % 3;
  const double c = tileBox.lo[axis];
  const CsgLeaf& mesh = leaves.first.Kind == PrimitiveKind::Mesh ? leaves.first : leaves.second;
  const CsgLeaf& other = leaves.first.Kind == PrimitiveKind::Mesh ? leaves.second : leaves.first;
  std::vector<TraceSegment> first, second;
  if (!MeshTrace(mesh, primitives, axis, c, first) ||
    (other.Kind == PrimitiveKind::Mesh && !MeshTrace(other, primitives, axis, c, second)))
  {
    return std::nullopt;
  }
  std::vector<std::array<double, 2>> points;
  for (const TraceSegment& m : first)
  {
    if (other.Kind == PrimitiveKind::Mesh)
    {
      for (const TraceSegment& n : second)
      {
        CrossingsOfSegments(m, n, points);
      }
    }
    else
    {
      CrossingsWithQuadric(m, other, primitives, axis, c, points);
    }
  }
  std::optional<Vec3> found;
  int near = 0;
  for (const auto& q : points)
  {
    Vec3 x;
    x[axis] = c;
    x[U] = q[0];
    x[V] = q[1];
    if (InsideTile(x, U, V, tileBox, -SideMargin))
    {
      ++near; // (near or in the tile: one more crossing the trace may bend at)
      found = x;
    }
  }
  if (near != 1 || !InsideTile(*found, U, V, tileBox, SideMargin))
  {
    return std::nullopt;
  }
  // Transversal: the two surfaces' normals projected on the plane.
  return CrossingSine(LeafGradient(leaves.first, primitives, *found), LeafGradient(leaves.second, primitives, *found),
           U, V) >= Transversal
    ? found
    : std::nullopt;
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
  if (leaves.first.Kind == PrimitiveKind::Mesh || leaves.second.Kind == PrimitiveKind::Mesh)
  {
    return CrossingOfTraces(leaves, primitives, axis, tileBox);
  }
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
  const auto two = TwoLeavesOnTile(expression, primitives, box);
  return two ? CrossingOfZeroCurves(two->Leaves, primitives, axis, box) : std::nullopt;
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
  const auto two = TwoLeavesOnTile(expression, primitives, box);
  const auto position = two ? CrossingOfZeroCurves(two->Leaves, primitives, axis, box) : std::nullopt;
  if (!position)
  {
    return std::nullopt; // (the tile was decided otherwise: see the caller)
  }
  const Vec3 normal = Normalized(Normalized(LeafGradient(two->Leaves.first, primitives, *position)) +
    Normalized(LeafGradient(two->Leaves.second, primitives, *position)));
  return std::make_pair(*position, normal);
}

bool PlaceCsgLoopPoints(const std::vector<Crossing>& loop, const CsgExpressionPtr& expression,
  const PrimitiveSet& primitives, const RootGrid& grid, std::vector<Vec3>& points)
{
  points.clear();
  for (const Crossing& c : loop)
  {
    if (c.Kind == CrossingKind::SubEdge)
    {
      points.push_back(PlaceSubEdgeCrossing(c, grid, *expression, primitives));
    }
    else if (c.Kind == CrossingKind::CsgCrease)
    {
      const auto x = CsgCreaseVertex(c, expression, primitives, grid);
      if (!x)
      {
        return false;
      }
      points.push_back(x->first);
    }
    else
    {
      return false;
    }
  }
  return true;
}

} // namespace tpc
