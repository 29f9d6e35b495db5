#include "EdgeCrossings.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <optional>
#include <vector>

namespace tpc
{
namespace
{
/// What one count gathers besides the count: the pieces examined, and the
/// first bisection point whose sign differs from the sign at the edge's
/// lower end (a point inside a gap or wedge between two crossings).
struct CountState
{
  int Pieces = 0;
  int MaximumPieces = 0;
  bool LowerInside = false;
  double* Opposite = nullptr;
};

EdgeCrossingCount Count(const CsgExpressionPtr& expression, const PrimitiveSet& prims,
  const Vec3& a, const Vec3& b, int axis, bool inA, bool inB, int budget, CountState& state)
{
  int& pieces = state.Pieces;
  if (++pieces > state.MaximumPieces)
  {
    return { 0, false };
  }
  Box3 seg{ a, b };
  const auto pruned = CsgExpression::Prune(expression, seg, prims);
  if (pruned.Sign != RegionSign::Mixed)
  {
    return { 0, true };
  }
  // The combined status is a monotone Boolean function (union and
  // intersection; complements are in the leaves' sigma) of the leaves'
  // statuses. If each leaf changes status at most once on the piece and all
  // that change do so the same way (all enter, or all leave), the combined
  // status changes at most once. (Coincident surfaces - a Bounds plane on a
  // box face - change together: still decided.)
  bool decided = true;
  std::vector<CsgLeaf> changing; // leaves whose status differs at a and b
  for (const CsgLeaf& leaf : pruned.Expression->Leaves())
  {
    if (leaf.Kind == PrimitiveKind::Quadric)
    {
      // A quadric strictly monotone along the piece, or constant on it.
      const Interval slope = prims.Quadrics[leaf.Primitive].EncloseDerivative(seg, axis);
      if (slope.ContainsZero() && !(slope.lo == 0.0 && slope.hi == 0.0))
      {
        decided = false;
        break;
      }
      if (LeafIsInside(leaf, prims, a) != LeafIsInside(leaf, prims, b))
      {
        changing.push_back(leaf);
      }
      continue;
    }
    // A mesh leaf changes status iff it is crossed once (exact parity).
    const int crossings = prims.Meshes[leaf.Primitive].CountCrossings(a, b, axis, *leaf.Triangles);
    if (crossings > 1)
    {
      decided = false;
      break;
    }
    if (crossings == 1)
    {
      changing.push_back(leaf);
    }
  }
  // Which way each changes matters only when several do; then the mesh
  // leaves' statuses are asked (rays to infinity, the costly part).
  int enters = 0, exits = 0;
  for (std::size_t i = 0; decided && changing.size() > 1 && i < changing.size(); ++i)
  {
    (LeafIsInside(changing[i], prims, a) ? exits : enters) += 1;
  }
  if (decided && (enters == 0 || exits == 0))
  {
    return { inA != inB ? 1 : 0, true };
  }
  if (budget == 0)
  {
    return { 0, false };
  }
  Vec3 m = a;
  m[axis] = 0.5 * (a[axis] + b[axis]);
  if (m[axis] <= a[axis] || m[axis] >= b[axis])
  {
    return { 0, false }; // no representable midpoint left
  }
  const bool inM = pruned.Expression->IsInside(m, prims);
  if (state.Opposite && inM != state.LowerInside)
  {
    *state.Opposite = m[axis];
    state.Opposite = nullptr;
  }
  const EdgeCrossingCount left = Count(pruned.Expression, prims, a, m, axis, inA, inM, budget - 1, state);
  if (!left.Proven || left.Count >= 2)
  {
    return left;
  }
  const EdgeCrossingCount right = Count(pruned.Expression, prims, m, b, axis, inM, inB, budget - 1, state);
  return { left.Count + right.Count, right.Proven };
}
/// Illinois (modified regula falsi) on the floating-point field between `a`
/// (value fa) and `b` (value fb), whose signs differ.
Vec3 IllinoisRoot(const CsgExpression& expression, const PrimitiveSet& primitives, const Vec3& a, const Vec3& b,
  double fa, double fb)
{
  double ta = 0.0, tb = 1.0;
  const Vec3 d = b - a;
  auto at = [&](double t) { return a + d * t; };
  int side = 0;
  for (int it = 0; it < 100 && tb - ta > 1e-15; ++it)
  {
    double t = (ta * fb - tb * fa) / (fb - fa);
    if (!(t > ta && t < tb))
    {
      t = 0.5 * (ta + tb);
    }
    const double ft = expression.Value(at(t), primitives);
    if (ft == 0.0)
    {
      return at(t);
    }
    if ((ft < 0.0) == (fa < 0.0))
    {
      ta = t;
      fa = ft;
      if (side == -1)
      {
        fb *= 0.5;
      }
      side = -1;
    }
    else
    {
      tb = t;
      fb = ft;
      if (side == 1)
      {
        fa *= 0.5;
      }
      side = 1;
    }
    if (std::fabs(ft) < 1e-300)
    {
      break;
    }
  }
  return at(0.5 * (ta + tb));
}

/// Where the expression's exact sign along an axis-aligned edge first
/// differs from `insideA`, from its leaves' own crossings: when every leaf
/// is a mesh with the cell's triangles, each leaf's sign changes exactly at
/// its crossings (those CountCrossings counts), so the expression, evaluated
/// with each leaf's sign at `a` flipped by its crossings so far, changes at
/// one of them - found in one pass over the leaves' triangles instead of one
/// per bisection step. The crossings' coordinates are rounded, and two
/// leaves' crossings closer than that may be taken in the wrong order: the
/// coordinate found is kept only where the exact signs (`insideAt`) two
/// units in the last place either side of it are `insideA` and not, which
/// brackets an exact change as the bisection's last interval does (units of
/// the larger end's coordinate, the scale both are rounded on). Nothing
/// otherwise (another kind of leaf, a crossing without a point, a check
/// that fails): the bisection decides. `meshInsideAtA(i)`: leaf node i's
/// exact sign at `a`.
template <typename InsideAt, typename MeshInsideAtA>
std::optional<double> FirstChangeAmongLeafCrossings(const CsgExpression& expression, const PrimitiveSet& primitives,
  const Vec3& a, const Vec3& b, int axis, bool insideA, const InsideAt& insideAt, const MeshInsideAtA& meshInsideAtA)
{
  struct LeafCrossing
  {
    double Coordinate;
    std::uint32_t Node;
  };
  thread_local std::vector<LeafCrossing> crossings;
  thread_local std::vector<double> coordinates;
  const auto isLeaf = [&](std::uint32_t i) {
    return expression.NodeAt(i).NodeKind == CsgExpression::Node::Kind::Leaf;
  };
  for (std::uint32_t i = 0; i < expression.NodeCount(); ++i)
  {
    const CsgExpression::Node& n = expression.NodeAt(i);
    if (isLeaf(i) && (n.LeafData.Kind != PrimitiveKind::Mesh || !n.Triangles))
    {
      return std::nullopt;
    }
  }
  crossings.clear();
  for (std::uint32_t i = 0; i < expression.NodeCount(); ++i)
  {
    if (!isLeaf(i))
    {
      continue;
    }
    const CsgExpression::Node& n = expression.NodeAt(i);
    coordinates.clear();
    if (!primitives.Meshes[n.LeafData.Primitive].CrossingCoordinates(a, b, axis, *n.Triangles, coordinates))
    {
      return std::nullopt;
    }
    for (const double x : coordinates)
    {
      crossings.push_back({ x, i });
    }
  }
  std::sort(crossings.begin(), crossings.end(),
    [](const LeafCrossing& p, const LeafCrossing& q) { return p.Coordinate < q.Coordinate; });
  thread_local std::vector<std::int8_t> flipped; // (per leaf node: crossed an odd number of times so far)
  flipped.assign(expression.NodeCount(), 0);
  std::optional<double> found;
  for (std::size_t k = 0; k < crossings.size() && !found;)
  {
    const double x = crossings[k].Coordinate;
    for (; k < crossings.size() && crossings[k].Coordinate == x; ++k)
    {
      flipped[crossings[k].Node] ^= 1;
    }
    const bool inside = expression.Evaluate([&](std::uint32_t i, const CsgExpression::Node& n) {
      return (meshInsideAtA(i) != (flipped[i] != 0)) == (n.LeafData.Sigma > 0);
    });
    if (inside != insideA)
    {
      found = x;
    }
  }
  if (!found)
  {
    return std::nullopt;
  }
  // (Units of the larger end's coordinate: the crossing's own coordinate,
  // a + s (b - a), is rounded on that scale, as the bisection's points are.)
  const double scale = std::max(std::fabs(a[axis]), std::fabs(b[axis]));
  const double step = 2.0 * (std::nextafter(scale, HUGE_VAL) - scale);
  Vec3 before = a, after = a;
  before[axis] = std::max(*found - step, a[axis]);
  after[axis] = std::min(*found + step, b[axis]);
  if (insideAt(before) != insideA || insideAt(after) == insideA)
  {
    return std::nullopt;
  }
  return found;
}

/// Bisection on exact signs. A mesh leaf's sign along an axis-aligned edge
/// is its sign at `a` (one ray to infinity) flipped by each crossing of the
/// cell's own triangles between a and the point: the same perturbed solid
/// as IsInside, so the same answers, without a ray per step. Where every
/// leaf is a mesh, its crossings are found first
/// (FirstChangeAmongLeafCrossings).
Vec3 BisectOnExactSigns(
  const CsgExpression& expression, const PrimitiveSet& primitives, const Vec3& a, const Vec3& b, bool insideA)
{
  double ta = 0.0, tb = 1.0;
  const Vec3 d = b - a;
  auto at = [&](double t) { return a + d * t; };
  int axis = -1, differing = 0;
  for (int k = 0; k < 3; ++k)
  {
    if (a[k] != b[k])
    {
      axis = k;
      ++differing;
    }
  }
  const bool alongAxis = differing == 1 && a[axis] < b[axis];
  // A lone mesh leaf crossed once: the crossing is on that triangle's plane.
  const CsgExpression::Node& root = expression.NodeAt(expression.Root());
  if (alongAxis && root.NodeKind == CsgExpression::Node::Kind::Leaf &&
    root.LeafData.Kind == PrimitiveKind::Mesh && root.Triangles)
  {
    Vec3 p;
    if (primitives.Meshes[root.LeafData.Primitive].CrossingPoint(a, b, axis, *root.Triangles, p))
    {
      return p;
    }
  }
  std::vector<std::int8_t> meshInsideAtA(expression.NodeCount(), -1);
  const auto meshInsideAt = [&](std::uint32_t i) {
    std::int8_t& atA = meshInsideAtA[i];
    if (atA < 0)
    {
      atA = primitives.Meshes[expression.NodeAt(i).LeafData.Primitive].IsInside(a) ? 1 : 0;
    }
    return atA != 0;
  };
  auto insideAt = [&](const Vec3& p) {
    if (!alongAxis)
    {
      return expression.IsInside(p, primitives);
    }
    return expression.Evaluate([&](std::uint32_t i, const CsgExpression::Node& n) {
      const CsgLeaf& leaf = n.LeafData;
      if (leaf.Kind != PrimitiveKind::Mesh || !n.Triangles)
      {
        return LeafIsInside(leaf, primitives, p);
      }
      const MeshSolid& mesh = primitives.Meshes[leaf.Primitive];
      const bool inside = meshInsideAt(i) != ((mesh.CountCrossings(a, p, axis, *n.Triangles) & 1) != 0);
      return inside == (leaf.Sigma > 0);
    });
  };
  if (alongAxis)
  {
    if (const std::optional<double> x =
          FirstChangeAmongLeafCrossings(expression, primitives, a, b, axis, insideA, insideAt, meshInsideAt))
    {
      Vec3 p = a;
      p[axis] = *x;
      return p;
    }
  }
  for (int it = 0; it < 60; ++it)
  {
    const double t = 0.5 * (ta + tb);
    if (insideAt(at(t)) == insideA)
    {
      ta = t;
    }
    else
    {
      tb = t;
    }
  }
  return at(0.5 * (ta + tb));
}
} // namespace

EdgeCrossingCount CountEdgeCrossings(const CsgExpressionPtr& expression,
  const PrimitiveSet& primitives, const Vec3& a, const Vec3& b, int axis, bool insideA,
  bool insideB, int maxBisections, double* opposite, int maxPieces)
{
  // A lone mesh leaf (remeshing): its crossings with the cell's triangles are
  // counted exactly, with the perturbation that decides the signs. The
  // bisection would find the same number, or give up on two crossings closer
  // than its depth: a complex edge either way.
  const CsgExpression::Node& root = expression->NodeAt(expression->Root());
  if (root.NodeKind == CsgExpression::Node::Kind::Leaf && root.LeafData.Kind == PrimitiveKind::Mesh &&
    root.Triangles)
  {
    return { primitives.Meshes[root.LeafData.Primitive].CountCrossings(a, b, axis, *root.Triangles), true };
  }
  CountState state;
  state.LowerInside = insideA;
  state.Opposite = opposite;
  // Depth alone does not bound the work: a leaf that is undecided on every
  // piece yet proven on the finest ones (a surface grazing the edge) would
  // visit 2^depth pieces.
  state.MaximumPieces = maxPieces;
  return Count(expression, primitives, a, b, axis, insideA, insideB, maxBisections, state);
}

Vec3 FindEdgeCrossing(const CsgExpression& expression, const PrimitiveSet& primitives,
  const Vec3& a, const Vec3& b, bool insideA)
{
  // The floating-point field is used where its signs agree with the exact
  // ones at the ends; mesh leaves only have an approximate value, and
  // rounding may contradict the exact signs: then exact bisection. (Their
  // value is not even computed: it costs a pass over the leaf's triangles.)
  if (expression.HasMeshLeaves())
  {
    return BisectOnExactSigns(expression, primitives, a, b, insideA);
  }
  const double fa = expression.Value(a, primitives);
  const double fb = expression.Value(b, primitives);
  const bool usable = insideA ? (fa < 0.0 && fb >= 0.0) : (fa >= 0.0 && fb < 0.0);
  return usable ? IllinoisRoot(expression, primitives, a, b, fa, fb)
                : BisectOnExactSigns(expression, primitives, a, b, insideA);
}

Vec3 PlaceSubEdgeCrossing(const Crossing& c, const RootGrid& grid, const CsgExpression& expression,
  const PrimitiveSet& primitives)
{
  const int axis = AxisOf(c.Key);
  LatticeIndex lo[3], hi[3];
  SplitPointKey(PointOf(c.Key), lo);
  std::copy(lo, lo + 3, hi);
  hi[axis] = c.Upper;
  const Vec3 a = grid.Point(lo), b = grid.Point(hi);
  const Vec3 found = FindEdgeCrossing(expression, primitives, a, b, c.LowerInside);
  Vec3 p = a;
  p[axis] = std::clamp(found[axis], std::nextafter(a[axis], b[axis]), std::nextafter(b[axis], a[axis]));
  return p;
}

} // namespace tpc
