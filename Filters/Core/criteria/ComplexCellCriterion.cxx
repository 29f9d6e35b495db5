#include "ComplexCellCriterion.h"

#include "CubeTopology.h"
#include "EdgeCrossings.h"
#include "SeparatingPlane.h"
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
  const Box3& box, int depth, int& budget);

/// ProveConstant of `pruned`, an expression already pruned to `box` with a
/// mixed sign there: by its pieces.
RegionSign ProvePiecesConstant(const CsgExpressionPtr& pruned, const PrimitiveSet& primitives,
  const Box3& box, int depth, int& budget)
{
  if (depth == 0 || --budget < 0)
  {
    return RegionSign::Mixed;
  }
  Box3 pieces[8];
  const int count = SplitBox(box, pieces);
  RegionSign common = RegionSign::Mixed;
  for (int piece = 0; piece < count; ++piece)
  {
    const RegionSign s = ProveConstant(pruned, primitives, pieces[piece], depth - 1, budget);
    if (s == RegionSign::Mixed || (piece > 0 && s != common))
    {
      return RegionSign::Mixed;
    }
    common = s;
  }
  return common;
}

RegionSign ProveConstant(const CsgExpressionPtr& expression, const PrimitiveSet& primitives,
  const Box3& box, int depth, int& budget)
{
  const auto pruned = CsgExpression::Prune(expression, box, primitives);
  return pruned.Sign != RegionSign::Mixed ? pruned.Sign
                                          : ProvePiecesConstant(pruned.Expression, primitives, box, depth, budget);
}
} // namespace

RegionSign ProveConstantSign(const CsgExpressionPtr& expression,
  const PrimitiveSet& primitives, const Box3& box, int depth, int budget)
{
  return ProveConstant(expression, primitives, box, depth, budget);
}

SplitReason FaceCompatibilityTest(const CsgExpressionPtr& expression,
  const PrimitiveSet& primitives, const Box3& face, int axis, const bool inside[4],
  int* failingEdge, double* opposite, bool prunedToFace)
{
  const bool change = inside[0] != inside[1] || inside[1] != inside[2] || inside[2] != inside[3];
  if (!change)
  {
    // (Pruned to the face already: proven by its pieces at once.)
    int budget = ConstantProofBudget;
    const RegionSign sign = prunedToFace
      ? ProvePiecesConstant(expression, primitives, face, ConstantProofDepth, budget)
      : ProveConstant(expression, primitives, face, ConstantProofDepth, budget);
    return sign == RegionSign::Mixed ? SplitReason::ComplexFace : SplitReason::None;
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
  if (!IsStarShapedWithRespectToFace(expression, primitives, face, axis, prunedToFace))
  {
    return SplitReason::NotStarShapedFace;
  }
  return SplitReason::None;
}

bool EdgeCrossedOnce(const CsgExpressionPtr& expression, const PrimitiveSet& primitives, const Box3& face,
  int axis, const bool inside[4], int k, double* opposite, int maxPieces)
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
    along, lowerIsA ? inside[k] : inside[l], lowerIsA ? inside[l] : inside[k], 24, ask ? &between : nullptr,
    maxPieces);
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
/// `ends` receives, per loop, the ends of its crossings' narrowed segments.
std::vector<std::array<LatticeIndex, 6>> LoopExtents(const BoundaryLoopSet& loops,
  const CsgExpression& expression, const PrimitiveSet& prims, const RootGrid& grid,
  LatticeIndex target, std::vector<std::vector<Vec3>>& ends)
{
  std::vector<std::array<LatticeIndex, 6>> extents;
  ends.assign(loops.LoopSizes.size(), {});
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
      LatticeIndex q[3] = { p[0], p[1], p[2] };
      q[along] = lo;
      ends[extents.size()].push_back(grid.Point(q));
      q[along] = hi;
      ends[extents.size()].push_back(grid.Point(q));
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
/// Rounding slack of n . x - c over `box` (generous: 64 ulps of its terms).
double Slack(const Box3& box, const SeparatingPlane& plane)
{
  double m = std::fabs(plane.Offset);
  for (int a = 0; a < 3; ++a)
  {
    m += std::fabs(plane.Normal[a]) * std::max(std::fabs(box.lo[a]), std::fabs(box.hi[a]));
  }
  return 64.0 * std::numeric_limits<double>::epsilon() * m;
}

/// The plane's crossings of the box's twelve edges: the section's vertices.
std::vector<Vec3> SectionVertices(const Box3& box, const SeparatingPlane& plane)
{
  std::vector<Vec3> vertices;
  for (int axis = 0; axis < 3; ++axis)
  {
    for (int corner = 0; corner < 4; ++corner)
    {
      Vec3 a = box.lo, b;
      a[(axis + 1) % 3] = (corner & 1) ? box.hi[(axis + 1) % 3] : box.lo[(axis + 1) % 3];
      a[(axis + 2) % 3] = (corner & 2) ? box.hi[(axis + 2) % 3] : box.lo[(axis + 2) % 3];
      b = a;
      b[axis] = box.hi[axis];
      const double sa = Dot(plane.Normal, a) - plane.Offset, sb = Dot(plane.Normal, b) - plane.Offset;
      if ((sa <= 0.0) != (sb <= 0.0))
      {
        vertices.push_back(a + (b - a) * (sa / (sa - sb)));
      }
    }
  }
  return vertices;
}

/// A mesh leaf's triangles miss the section: each lies on one side of the
/// plane, or meets it in a segment that misses the box (grown by the slack).
bool MeshMissesSection(const MeshSolid& mesh, const TriangleList* triangles, const Box3& box,
  const SeparatingPlane& plane, double slack)
{
  const Box3 grown{ box.lo - Vec3{ slack, slack, slack }, box.hi + Vec3{ slack, slack, slack } };
  const std::size_t count = triangles ? triangles->size() : mesh.Triangles().size();
  for (std::size_t i = 0; i < count; ++i)
  {
    const std::uint32_t t = triangles ? (*triangles)[i] : static_cast<std::uint32_t>(i);
    double side[3];
    for (int k = 0; k < 3; ++k)
    {
      side[k] = Dot(plane.Normal, mesh.Vertex(t, k)) - plane.Offset;
    }
    if ((side[0] > slack && side[1] > slack && side[2] > slack) ||
      (side[0] < -slack && side[1] < -slack && side[2] < -slack))
    {
      continue;
    }
    std::vector<Vec3> ends;
    for (int k = 0; k < 3; ++k)
    {
      const int l = (k + 1) % 3;
      if (std::fabs(side[k]) <= slack)
      {
        ends.push_back(mesh.Vertex(t, k));
      }
      else if ((side[k] < 0.0) != (side[l] < 0.0) && std::fabs(side[l]) > slack)
      {
        ends.push_back(mesh.Vertex(t, k) + (mesh.Vertex(t, l) - mesh.Vertex(t, k)) * (side[k] / (side[k] - side[l])));
      }
    }
    for (std::size_t a = 0; a < ends.size(); ++a)
    {
      for (std::size_t b = a; b < ends.size(); ++b)
      {
        if (grown.MeetsSegment(ends[a], ends[b]))
        {
          return false;
        }
      }
    }
  }
  return true;
}

/// The surface provably misses the plane's section of `box`: by pieces of
/// the box, each missing the plane or of one sign, down to `depth` levels.
bool SectionMissedByPieces(const CsgExpressionPtr& expression, const PrimitiveSet& primitives, const Box3& box,
  const SeparatingPlane& plane, int depth, int& budget)
{
  const double slack = Slack(box, plane);
  double low = HUGE_VAL, high = -HUGE_VAL;
  for (int c = 0; c < 8; ++c)
  {
    const double s = Dot(plane.Normal, box.Corner(c)) - plane.Offset;
    low = std::min(low, s);
    high = std::max(high, s);
  }
  if (low > slack || high < -slack)
  {
    return true;
  }
  const auto pruned = CsgExpression::Prune(expression, box, primitives);
  if (pruned.Sign != RegionSign::Mixed)
  {
    return true;
  }
  if (depth == 0 || --budget < 0)
  {
    return false;
  }
  Box3 pieces[8];
  const int count = SplitBox(box, pieces);
  for (int k = 0; k < count; ++k)
  {
    if (!SectionMissedByPieces(pruned.Expression, primitives, pieces[k], plane, depth - 1, budget))
    {
      return false;
    }
  }
  return true;
}

/// The surface provably misses the section of `cell` by `plane`. Planes and
/// meshes are decided leaf by leaf (no leaf's zero set meets the section:
/// then neither does the surface, which lies in their union) - exact up to
/// the slack, whatever the plane's distance to the sheets; curved quadrics
/// by pieces of the cell.
bool SectionMissed(const CsgExpressionPtr& expression, const PrimitiveSet& primitives, const Box3& cell,
  const SeparatingPlane& plane)
{
  const double slack = Slack(cell, plane);
  const std::vector<Vec3> section = SectionVertices(cell, plane);
  bool byLeaves = true;
  for (const CsgLeaf& leaf : expression->Leaves())
  {
    if (leaf.Kind == PrimitiveKind::Mesh)
    {
      byLeaves = MeshMissesSection(primitives.Meshes[leaf.Primitive], leaf.Triangles, cell, plane, slack);
    }
    else if (primitives.Quadrics[leaf.Primitive].IsLinear())
    {
      // A plane leaf: one sign at every vertex of the (convex) section, by
      // more than the rounding of the vertices and of the values.
      const auto& q = primitives.Quadrics[leaf.Primitive].Coefficients();
      const Vec3 gradient{ q[6], q[7], q[8] };
      const double margin = 1e-12 * (std::fabs(q[9]) + Norm(gradient) * (Norm(cell.lo) + Norm(cell.hi)));
      int above = 0, below = 0;
      for (const Vec3& v : section)
      {
        const double f = Dot(gradient, v) + q[9];
        above += f > margin;
        below += f < -margin;
      }
      byLeaves = above == static_cast<int>(section.size()) || below == static_cast<int>(section.size());
    }
    else
    {
      byLeaves = false;
    }
    if (!byLeaves)
    {
      break;
    }
  }
  if (byLeaves)
  {
    return true;
  }
  int budget = 4096;
  return SectionMissedByPieces(expression, primitives, cell, plane, 8, budget);
}

bool SeparatedWithin(const BoundaryLoopSet& loops, const CsgExpressionPtr& expression,
  const PrimitiveSet& primitives, const RootGrid& grid, const Box3& cell, LatticeIndex target,
  std::vector<Box3>& regions)
{
  std::vector<std::vector<Vec3>> ends;
  const auto extents = LoopExtents(loops, *expression, primitives, grid, target, ends);
  regions.assign(extents.size(), cell);
  bool oblique = false;
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
        // No axis: a plane parallel to neither, between the two loops' points.
        SeparatingPlane plane;
        separated = FindSeparatingPlane(ends[i], ends[j], plane) && SectionMissed(expression, primitives, cell, plane);
        oblique = oblique || separated;
      }
      if (!separated)
      {
        return false;
      }
    }
  }
  if (oblique)
  {
    // The loops' regions are no longer boxes: the star-shaped test is asked
    // of the whole cell (which implies it on either side of every plane).
    regions.assign(1, cell);
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
    size = std::max(size, static_cast<LatticeIndex>(std::llround(cell.Width(a) / grid.Spacing())));
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
