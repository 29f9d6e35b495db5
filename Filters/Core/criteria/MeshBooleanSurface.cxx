#include "MeshBooleanSurface.h"

#include "MeshCellError.h"

#include <algorithm>
#include <cmath>
#include <optional>
#include <vector>

namespace tpc
{
namespace
{
/// The most cuts a piece takes (header: Rounding).
constexpr int MostCuts = 48;

/// A piece of a mesh's surface in the cell still to be decided: its
/// corners, its mesh (an index in the expression's leaves) and the cuts
/// that made it.
struct Piece
{
  ClippedCorners Corners;
  std::size_t Leaf = 0;
  int Cuts = 0;
  bool Strip = false; ///< the strip along another mesh's plane: not cut again (header: Deciding a piece)
};

PointSpan SpanOf(const ClippedCorners& corners)
{
  return { corners.data(), corners.size() };
}

/// Whether Phi changes with mesh `mesh`'s sign at `point`, every other
/// leaf's exact sign read there (header: Deciding a piece).
bool OnSurfaceAt(const CsgExpression& expression, const PrimitiveSet& primitives, std::uint32_t mesh,
  const Vec3& point, std::vector<signed char>& inside)
{
  inside.assign(expression.NodeCount(), -1); // (each other leaf read once)
  const auto evaluate = [&](bool meshInside) {
    return expression.Evaluate([&](std::uint32_t i, const CsgExpression::Node& n) {
      const CsgLeaf& leaf = n.LeafData;
      if (leaf.Primitive == mesh)
      {
        return meshInside == (leaf.Sigma > 0);
      }
      if (inside[i] < 0)
      {
        inside[i] = LeafIsInside(leaf, primitives, point) ? 1 : 0;
      }
      return inside[i] == 1;
    });
  };
  return evaluate(true) != evaluate(false);
}

/// How many polygons of the other meshes' surfaces in the cell
/// (`meshSurfaces`, one set per leaf) piece `corners` of leaf `leaf` is not
/// proven more than `margin` from, counted up to 2; the first in `nearest`
/// (mesh, polygon).
int NearPolygons(const PointSpan& corners, std::size_t leaf, const std::vector<PolygonSet>& meshSurfaces,
  double margin, std::pair<std::size_t, std::size_t>& nearest)
{
  Box3 reach = BoundsOf(corners.begin(), corners.size());
  for (int a = 0; a < 3; ++a)
  {
    reach.lo[a] -= margin;
    reach.hi[a] += margin;
  }
  int near = 0;
  std::optional<PolygonOnItsNormal> piece; // (once a polygon is in reach)
  for (std::size_t j = 0; j < meshSurfaces.size() && near < 2; ++j)
  {
    const PolygonSet& other = meshSurfaces[j];
    for (std::size_t r = 0; j != leaf && r < other.size() && near < 2; ++r)
    {
      if (!other.Bounds(r).Overlaps(reach))
      {
        continue;
      }
      if (!piece)
      {
        piece = OnItsNormal(corners);
      }
      if (!PolygonsApartBesideTheirBoxes(*piece, other[r], margin))
      {
        nearest = near == 0 ? std::make_pair(j, r) : nearest;
        ++near;
      }
    }
  }
  return near;
}

/// The part of polygon `points` where Dot(normal, x) - offset is >= 0
/// (`above`) or <= 0, in `out` (Sutherland-Hodgman).
void ClipToPlane(const ClippedCorners& points, ClippedCorners& out, const Vec3& normal, double offset, bool above)
{
  out.clear();
  const std::size_t m = points.size();
  const auto side = [&](const Vec3& p) { return (Dot(normal, p) - offset) * (above ? 1.0 : -1.0); };
  for (std::size_t i = 0; i < m; ++i)
  {
    const Vec3& a = points[i];
    const Vec3& b = points[(i + 1) % m];
    const double sa = side(a), sb = side(b);
    if (sa >= 0.0)
    {
      out.push_back(a);
    }
    if ((sa >= 0.0) != (sb >= 0.0) && m > 1)
    {
      out.push_back(a + (b - a) * (sa / (sa - sb)));
    }
  }
}

/// The segments where two meshes' polygons in the cell cross at
/// FollowedCreaseDegrees or more between their planes (header of
/// MeshBooleanSurfaceInCell), appended to `creases`.
void CrossingCreases(const std::vector<PolygonSet>& meshSurfaces, std::vector<CreaseSegment>& creases)
{
  const double parallel = std::cos(FollowedCreaseDegrees * M_PI / 180.0);
  for (std::size_t i = 0; i < meshSurfaces.size(); ++i)
  {
    for (std::size_t j = i + 1; j < meshSurfaces.size(); ++j)
    {
      for (const ConvexPolygon& p : meshSurfaces[i])
      {
        for (std::size_t k = 0; k < meshSurfaces[j].size() && p.TwiceArea > 0.0; ++k)
        {
          if (!meshSurfaces[j].Bounds(k).Overlaps(p.Bounds))
          {
            continue;
          }
          const ConvexPolygon q = meshSurfaces[j][k];
          Vec3 a, b;
          if (q.TwiceArea > 0.0 && std::fabs(Dot(p.Normal, q.Normal)) <= parallel &&
            SectionByPlane(q.Points, p.Normal, Dot(p.Normal, p.Points[0]), a, b) && ClipSegmentToPolygon(p, a, b))
          {
            creases.push_back({ a, b });
          }
        }
      }
    }
  }
}
} // namespace

std::vector<CsgLeaf> MeshBooleanLeaves(const CsgExpression& expression)
{
  // (A quadric leaf first, without building the list: most cells of a CSG
  // scene stop here.)
  for (std::size_t i = 0; i < expression.NodeCount(); ++i)
  {
    const CsgExpression::Node& n = expression.NodeAt(i);
    if (n.NodeKind == CsgExpression::Node::Kind::Leaf &&
      (n.LeafData.Kind != PrimitiveKind::Mesh || !n.LeafData.Triangles))
    {
      return {};
    }
  }
  std::vector<CsgLeaf> leaves = expression.Leaves();
  if (leaves.size() < 2)
  {
    return {};
  }
  for (std::size_t k = 0; k < leaves.size(); ++k)
  {
    for (std::size_t j = 0; j < k; ++j)
    {
      if (leaves[j].Primitive == leaves[k].Primitive)
      {
        return {}; // (a mesh and its complement: Phi of one mesh in two leaves)
      }
    }
  }
  return leaves;
}

bool IsMeshBoolean(const CsgExpression& expression)
{
  return !MeshBooleanLeaves(expression).empty();
}

bool MeshBooleanSurfaceInCell(const CsgExpression& expression, const PrimitiveSet& primitives, const Box3& cell,
  double width, std::size_t pieceBudget, MeshBooleanSurface& surface, std::vector<CreaseSegment>* creases)
{
  surface.OnSurface.clear();
  surface.Covering.clear();
  surface.Undecided = 0;
  surface.Slack = 0.0;
  const std::vector<CsgLeaf> leaves = MeshBooleanLeaves(expression);
  if (leaves.empty())
  {
    return false;
  }
  std::vector<PolygonSet> meshSurfaces(leaves.size());
  double magnitude = 0.0;
  for (std::size_t k = 0; k < leaves.size(); ++k)
  {
    SurfaceInCell(leaves[k], primitives, cell, meshSurfaces[k]);
    magnitude = std::max(magnitude, SlackMagnitude(leaves[k], primitives, cell));
  }
  surface.Slack = RoundingSlackFor(magnitude, cell.Diagonal());
  if (creases)
  {
    creases->clear();
    CrossingCreases(meshSurfaces, *creases);
  }
  surface.OnSurface.SetSlackMagnitude(magnitude);
  surface.Covering.SetSlackMagnitude(magnitude);
  const double margin = 4.0 * surface.Slack; // (header: Rounding)
  std::vector<Piece> pending;
  for (std::size_t k = 0; k < leaves.size(); ++k)
  {
    for (const ConvexPolygon& q : meshSurfaces[k])
    {
      Piece piece;
      piece.Leaf = k;
      for (const Vec3& p : q.Points)
      {
        piece.Corners.push_back(p);
      }
      pending.push_back(piece);
    }
  }
  std::size_t decided = 0;
  std::vector<signed char> inside;
  while (!pending.empty())
  {
    const Piece piece = pending.back();
    pending.pop_back();
    ++decided;
    const PointSpan corners = SpanOf(piece.Corners);
    std::pair<std::size_t, std::size_t> nearest;
    const int near = NearPolygons(corners, piece.Leaf, meshSurfaces, margin, nearest);
    if (near == 0)
    {
      Vec3 centroid;
      for (const Vec3& p : corners)
      {
        centroid += p * (1.0 / static_cast<double>(corners.size()));
      }
      if (OnSurfaceAt(expression, primitives, leaves[piece.Leaf].Primitive, cell.Clamp(centroid), inside))
      {
        surface.OnSurface.Add(corners.begin(), corners.size());
        surface.Covering.Add(corners.begin(), corners.size());
      }
      continue;
    }
    // Room for the parts: a clipping keeps each corner once at most and adds
    // at most one per side, so its part has at most twice the corners
    // whatever the rounding does to the sides' signs (exactly, a convex
    // polygon's part has one more at most) - the strip, clipped twice, four
    // times.
    const std::size_t corners2 = 2 * piece.Corners.size();
    const bool room = !piece.Strip && piece.Cuts < MostCuts && decided + pending.size() + 3 <= pieceBudget;
    const ConvexPolygon other = meshSurfaces[nearest.first][nearest.second];
    if (room && near == 1 && other.TwiceArea > 0.0 && 2 * corners2 <= ClippedCorners::capacity())
    {
      // Near one polygon of another mesh: cut along its plane, pushed aside
      // by twice the margin both ways (header: Deciding a piece).
      const double offset = Dot(other.Normal, other.Points[0]), aside = 2.0 * margin;
      Piece above, strip, below;
      ClipToPlane(piece.Corners, above.Corners, other.Normal, offset + aside, true);
      ClipToPlane(piece.Corners, below.Corners, other.Normal, offset - aside, false);
      ClippedCorners beyondBelow;
      ClipToPlane(piece.Corners, beyondBelow, other.Normal, offset - aside, true);
      ClipToPlane(beyondBelow, strip.Corners, other.Normal, offset + aside, false);
      strip.Strip = true;
      for (Piece* part : { &above, &strip, &below })
      {
        part->Leaf = piece.Leaf;
        part->Cuts = piece.Cuts + 1;
        if (!part->Corners.empty())
        {
          pending.push_back(*part);
        }
      }
      continue;
    }
    const Box3 box = BoundsOf(corners.begin(), corners.size());
    int axis = 0;
    for (int a = 1; a < 3; ++a)
    {
      axis = box.Width(a) > box.Width(axis) ? a : axis;
    }
    if (room && box.Width(axis) > width && corners2 <= ClippedCorners::capacity())
    {
      // Near more: cut in two across its box's longest side.
      const double middle = 0.5 * (box.lo[axis] + box.hi[axis]);
      for (const bool below : { true, false })
      {
        Piece half;
        half.Leaf = piece.Leaf;
        half.Cuts = piece.Cuts + 1;
        ClipToHalfSpace(piece.Corners, half.Corners, axis, middle, below);
        if (!half.Corners.empty())
        {
          pending.push_back(half);
        }
      }
      continue;
    }
    surface.Covering.Add(corners.begin(), corners.size());
    ++surface.Undecided;
  }
  return true;
}

} // namespace tpc
