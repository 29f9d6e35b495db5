#include "ConvexPolygons.h"

#include <algorithm>
#include <cmath>
#include <utility>

namespace tpc
{

void PolygonSet::reserve(std::size_t polygons, std::size_t corners)
{
  this->Headers.reserve(polygons);
  this->Corners.reserve(corners);
  this->Inward.reserve(corners);
}

void PolygonSet::Recycle(std::size_t polygons)
{
  // (Sixteen times: cells a level apart hold about a quarter of each other's
  // surface, so a buffer is kept for two levels - freed at every level, it
  // came back as fresh pages each time; the floor keeps small sets from
  // being freed over and over.)
  if (this->Headers.capacity() > 16 * polygons + 1024)
  {
    *this = PolygonSet();
  }
  this->clear();
}

void PolygonSet::Add(const Vec3* corners, std::size_t m)
{
  Header h;
  h.First = static_cast<std::uint32_t>(this->Corners.size());
  h.Count = static_cast<std::uint32_t>(m);
  Vec3 normal;
  for (std::size_t i = 0; i < m; ++i)
  {
    normal += Cross(corners[i], corners[(i + 1) % m]);
  }
  const double length = Norm(normal);
  h.Normal = length > 0.0 ? normal * (1.0 / length) : Vec3();
  h.TwiceArea = length;
  h.Bounds = m ? BoundsOf(corners, m) : Box3{};
  h.HasInward = m >= 3 && length > 0.0;
  this->Corners.insert(this->Corners.end(), corners, corners + m);
  for (std::size_t i = 0; i < m; ++i)
  {
    this->Inward.push_back(h.HasInward ? Cross(h.Normal, corners[(i + 1) % m] - corners[i]) : Vec3());
  }
  this->Headers.push_back(h);
}

namespace
{
/// Squared distance from `p` to the segment [a, b].
double SegmentDistance2(const Vec3& p, const Vec3& a, const Vec3& b)
{
  const Vec3 ab = b - a;
  const double length2 = Dot(ab, ab);
  const double t = length2 > 0.0 ? std::clamp(Dot(p - a, ab) / length2, 0.0, 1.0) : 0.0;
  const Vec3 d = p - (a + ab * t);
  return Dot(d, d);
}
} // namespace

double SegmentDistance(const Vec3& p, const Vec3& a, const Vec3& b)
{
  return std::sqrt(SegmentDistance2(p, a, b));
}

namespace
{
/// Distance from `p` to the convex polygon with corners v[0 .. m), edge
/// normals `inward` (null when degenerate) and unit normal `normal`.
double DistanceToCorners(const Vec3& p, const Vec3* v, const Vec3* inward, std::size_t m, const Vec3& normal)
{
  if (m == 1)
  {
    return Norm(p - v[0]);
  }
  if (inward)
  {
    // Inside the polygon's prism: the distance to its plane. Outside it, the
    // nearest point of a convex polygon lies on an edge whose line has p's
    // projection on its outer side (a nearest vertex has such an edge too):
    // only those edges are measured. (Inward is normal to the polygon's
    // normal, so p's side of an edge is its projection's.)
    double d2 = HUGE_VAL;
    for (std::size_t i = 0; i < m; ++i)
    {
      if (Dot(p - v[i], inward[i]) < 0.0)
      {
        d2 = std::min(d2, SegmentDistance2(p, v[i], v[(i + 1) % m]));
      }
    }
    return d2 == HUGE_VAL ? std::fabs(Dot(p - v[0], normal)) : std::sqrt(d2);
  }
  double d2 = HUGE_VAL;
  for (std::size_t i = 0; i < m; ++i)
  {
    d2 = std::min(d2, SegmentDistance2(p, v[i], v[(i + 1) % m]));
  }
  return std::sqrt(d2);
}
} // namespace

double PolygonDistance(const Vec3& p, const ConvexPolygon& polygon)
{
  return DistanceToCorners(p, polygon.Points.First, polygon.Inward.empty() ? nullptr : polygon.Inward.First,
    polygon.Points.size(), polygon.Normal);
}

double PolygonSet::Distance(const Vec3& p, std::size_t i) const
{
  const Header& h = this->Headers[i];
  return DistanceToCorners(p, this->Corners.data() + h.First, h.HasInward ? this->Inward.data() + h.First : nullptr,
    h.Count, h.Normal);
}

bool ClipSegment(Vec3& a, Vec3& b, const Box3& box)
{
  // Liang-Barsky: the parameters of ab inside each slab.
  double t0 = 0.0, t1 = 1.0;
  const Vec3 d = b - a;
  for (int axis = 0; axis < 3; ++axis)
  {
    if (d[axis] == 0.0)
    {
      if (a[axis] < box.lo[axis] || a[axis] > box.hi[axis])
      {
        return false;
      }
      continue;
    }
    double lo = (box.lo[axis] - a[axis]) / d[axis], hi = (box.hi[axis] - a[axis]) / d[axis];
    if (lo > hi)
    {
      std::swap(lo, hi);
    }
    t0 = std::max(t0, lo);
    t1 = std::min(t1, hi);
    if (t0 > t1)
    {
      return false;
    }
  }
  const Vec3 start = a + d * t0, end = a + d * t1;
  a = start;
  b = end;
  return true;
}

} // namespace tpc
