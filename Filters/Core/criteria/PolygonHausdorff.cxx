#include "PolygonHausdorff.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <queue>
#include <utility>

namespace tpc
{
namespace
{
/// Distance between two boxes (0 when they overlap).
double BoxDistance(const Box3& a, const Box3& b)
{
  double sum = 0.0;
  for (int k = 0; k < 3; ++k)
  {
    const double gap = std::max({ 0.0, a.lo[k] - b.hi[k], b.lo[k] - a.hi[k] });
    sum += gap * gap;
  }
  return std::sqrt(sum);
}

Box3 BoundsOf(const Vec3* points, std::size_t count)
{
  Box3 box{ points[0], points[0] };
  for (std::size_t i = 1; i < count; ++i)
  {
    for (int k = 0; k < 3; ++k)
    {
      box.lo[k] = std::min(box.lo[k], points[i][k]);
      box.hi[k] = std::max(box.hi[k], points[i][k]);
    }
  }
  return box;
}

struct Piece
{
  SourceTriangle Vertices;
  std::vector<std::uint32_t> Candidates; ///< the targets that may be nearest to one of its points
  double Upper = HUGE_VAL;
  bool operator<(const Piece& o) const { return this->Upper < o.Upper; }
};

/// Distance from a point to a box (0 inside).
double PointBoxDistance(const Vec3& p, const Box3& b)
{
  double sum = 0.0;
  for (int k = 0; k < 3; ++k)
  {
    const double gap = std::max({ 0.0, b.lo[k] - p[k], p[k] - b.hi[k] });
    sum += gap * gap;
  }
  return std::sqrt(sum);
}

/// The piece's bound ((1) and (2) of the header) from the targets among
/// `candidates` that may be nearest to one of its points (box distance within
/// `parentUpper`); raises `lower` to its vertices' distances. Targets are
/// visited nearest box first, and a distance is computed only where it may
/// lower a vertex's nearest distance or the single-target bound (box
/// distances are lower bounds of distances), so both stay exact.
void Evaluate(Piece& piece, const std::vector<std::uint32_t>& candidates, double parentUpper,
  const std::vector<ConvexPolygon>& targets, double& lower, std::vector<std::pair<double, std::uint32_t>>& order)
{
  const Box3 box = BoundsOf(piece.Vertices.data(), 3);
  order.clear();
  for (const std::uint32_t t : candidates)
  {
    const double d = BoxDistance(box, targets[t].Bounds);
    if (d <= parentUpper)
    {
      order.emplace_back(d, t);
    }
  }
  std::sort(order.begin(), order.end());
  double nearest[3] = { HUGE_VAL, HUGE_VAL, HUGE_VAL };
  double single = HUGE_VAL;
  for (const auto& [boxDistance, t] : order)
  {
    if (boxDistance >= single && boxDistance >= nearest[0] && boxDistance >= nearest[1] &&
      boxDistance >= nearest[2])
    {
      break; // (sorted: no later target can lower either)
    }
    const ConvexPolygon& target = targets[t];
    // Whether this target may give a smaller single-target bound: then all
    // three distances are needed, until one reaches the current bound.
    bool improvesSingle = boxDistance < single;
    double farthest = 0.0;
    for (int i = 0; i < 3; ++i)
    {
      const bool improvesNearest = PointBoxDistance(piece.Vertices[i], target.Bounds) < nearest[i];
      if (!improvesNearest && !improvesSingle)
      {
        continue;
      }
      const double d = PolygonDistance(piece.Vertices[i], target);
      nearest[i] = std::min(nearest[i], d);
      farthest = std::max(farthest, d);
      improvesSingle = improvesSingle && farthest < single;
    }
    if (improvesSingle)
    {
      single = farthest; // (all three computed, their maximum below the bound)
    }
  }
  const Vec3 centroid = (piece.Vertices[0] + piece.Vertices[1] + piece.Vertices[2]) * (1.0 / 3.0);
  double radius = 0.0, vertexMax = 0.0;
  for (int i = 0; i < 3; ++i)
  {
    radius = std::max(radius, Norm(piece.Vertices[i] - centroid));
    vertexMax = std::max(vertexMax, nearest[i]);
  }
  piece.Upper = std::min(single, vertexMax + radius);
  lower = std::max(lower, vertexMax == HUGE_VAL ? 0.0 : vertexMax);
  piece.Candidates.clear();
  for (const auto& [boxDistance, t] : order)
  {
    if (boxDistance <= piece.Upper)
    {
      piece.Candidates.push_back(t);
    }
  }
}
} // namespace

ConvexPolygon MakeConvexPolygon(std::vector<Vec3> points)
{
  ConvexPolygon polygon;
  polygon.Points = std::move(points);
  Vec3 normal;
  const std::size_t m = polygon.Points.size();
  for (std::size_t i = 0; i < m; ++i)
  {
    normal += Cross(polygon.Points[i], polygon.Points[(i + 1) % m]);
  }
  const double length = Norm(normal);
  polygon.Normal = length > 0.0 ? normal * (1.0 / length) : Vec3();
  polygon.Bounds = m ? BoundsOf(polygon.Points.data(), m) : Box3{};
  return polygon;
}

double SegmentDistance(const Vec3& p, const Vec3& a, const Vec3& b)
{
  const Vec3 ab = b - a;
  const double length2 = Dot(ab, ab);
  const double t = length2 > 0.0 ? std::clamp(Dot(p - a, ab) / length2, 0.0, 1.0) : 0.0;
  return Norm(p - (a + ab * t));
}

double PolygonDistance(const Vec3& p, const ConvexPolygon& polygon)
{
  const std::vector<Vec3>& v = polygon.Points;
  const std::size_t m = v.size();
  if (m == 1)
  {
    return Norm(p - v[0]);
  }
  const Vec3& n = polygon.Normal;
  if (m >= 3 && Dot(n, n) > 0.0)
  {
    // Inside the polygon's prism: the distance to its plane.
    const double height = Dot(p - v[0], n);
    const Vec3 q = p - n * height;
    bool inside = true;
    for (std::size_t i = 0; i < m && inside; ++i)
    {
      inside = Dot(Cross(v[(i + 1) % m] - v[i], q - v[i]), n) >= 0.0;
    }
    if (inside)
    {
      return std::fabs(height);
    }
  }
  double d = HUGE_VAL;
  for (std::size_t i = 0; i < m; ++i)
  {
    d = std::min(d, SegmentDistance(p, v[i], v[(i + 1) % m]));
  }
  return d;
}

HausdorffEstimate OneSidedHausdorff(const std::vector<SourceTriangle>& sources,
  const std::vector<ConvexPolygon>& targets, double enough, double giveUp, std::size_t budget)
{
  HausdorffEstimate estimate;
  if (sources.empty())
  {
    return estimate;
  }
  std::vector<std::uint32_t> all(targets.size());
  for (std::uint32_t t = 0; t < all.size(); ++t)
  {
    all[t] = t;
  }
  std::priority_queue<Piece> pieces;
  std::vector<std::pair<double, std::uint32_t>> order; // (scratch of Evaluate)
  for (const SourceTriangle& s : sources)
  {
    Piece piece{ s, {}, HUGE_VAL };
    Evaluate(piece, all, HUGE_VAL, targets, estimate.Lower, order);
    pieces.push(std::move(piece));
  }
  std::size_t evaluated = sources.size();
  while (evaluated < budget && estimate.Lower <= giveUp)
  {
    const double top = pieces.top().Upper;
    // (Within 10 % of the lower bound is close enough only below giveUp: the
    // caller needs a proof under it.)
    if (top <= std::min(enough, giveUp) || (top <= 1.1 * estimate.Lower && top <= giveUp) || top == HUGE_VAL)
    {
      break;
    }
    const Piece parent = pieces.top();
    pieces.pop();
    const SourceTriangle& v = parent.Vertices;
    const Vec3 m01 = (v[0] + v[1]) * 0.5, m12 = (v[1] + v[2]) * 0.5, m20 = (v[2] + v[0]) * 0.5;
    for (const SourceTriangle& child :
      { SourceTriangle{ v[0], m01, m20 }, SourceTriangle{ m01, v[1], m12 }, SourceTriangle{ m20, m12, v[2] },
        SourceTriangle{ m01, m12, m20 } })
    {
      Piece piece{ child, {}, HUGE_VAL };
      Evaluate(piece, parent.Candidates, parent.Upper, targets, estimate.Lower, order);
      piece.Upper = std::min(piece.Upper, parent.Upper); // (the child lies in its parent)
      pieces.push(std::move(piece));
    }
    evaluated += 4;
  }
  estimate.Upper = pieces.top().Upper;
  return estimate;
}

} // namespace tpc
