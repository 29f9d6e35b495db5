#include "ConvexPolygons.h"

#include <algorithm>
#include <cassert>
#include <cfloat>
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
  // being freed over and over. Up to KeptAcrossSmallCells polygons, freed
  // only after RecycleAfter such uses in a row: within a level, large cells
  // come between small ones - a cell at the edge of the surface, or holding
  // a little of it - and a buffer freed for each small one came back as
  // fresh pages for the next large one: on armadillo at 1/64, 50 of the 80 ms
  // its 29 largest cells, 10 000 polygons at most, took to build S_C. The
  // cap bounds what each of a pool's sets, one per thread, may keep so:
  // about 4 MB.)
  constexpr int RecycleAfter = 64;
  constexpr std::size_t KeptAcrossSmallCells = 16384;
  if (this->Headers.capacity() > 16 * polygons + 1024)
  {
    if (++this->SmallUses > RecycleAfter || this->Headers.capacity() > KeptAcrossSmallCells)
    {
      *this = PolygonSet();
    }
  }
  else
  {
    this->SmallUses = 0;
  }
  this->clear();
}

namespace
{
/// Whether the distance may measure the polygon by its plane - the plane
/// distance inside its prism, the edges' outside - rather than by its edges
/// alone, within the rounding slack the certificates add (MeshCellError.h:
/// Rounding). The argument, with u the unit roundoff (eps / 2), m corners,
/// the Newell vector N taken about corners[0] from the differences e_i =
/// corners[i] - corners[0] (each within u of itself per component), L the
/// largest |e_i| and M the largest coordinate the slack is taken of:
/// - each cross product e_i x e_i+1 is within 4 sqrt(2) u L^2 of the exact
///   one (two products, a subtraction, the inputs' own rounding), and the
///   m - 3 additions add at most u m^2 L^2 / 2: the computed N is within
///   dN = (3 m + m^2 / 4) eps L^2 of the exact Newell vector of the stored
///   corners. Where |N| <= 2 dN the corners may be collinear - a triangle
///   clipped to a cell that it only touches along an edge, a degenerate
///   triangle - and the plane is rounding noise (with N from absolute
///   coordinates, whose cross products need not cancel, a segment got a
///   "plane" through its line, and a point on that line far beyond its ends
///   measured 0 from it).
/// - Else the computed normal is within an angle theta <= 2 dN / |N| of the
///   exact one, and for any point p passing the prism test with it the plane
///   distance is at least the true distance minus theta L, whatever p's
///   distance (p's computed plane distance is h / cos(theta) + sin(theta)
///   (q . t) for a point q of the polygon, |q - c_0| <= L, and the true one at
///   most h / cos(theta)): at most 2 dN L / |N| below, which is at most
///   4096 eps M - a quarter of RoundingSlack's 16384 ulps of M - where
///   |N| >= (3 m + m^2 / 4) L^3 / (2048 M). (From absolute coordinates the
///   error grew as M^2 / |N|: a small polygon far from the origin was
///   measured off by more than the slack. With a budget of 1024 ulps
///   instead, the decimation's long thin triangles were measured by their
///   edges and far fewer collapses certified: CGAL's joint at 1/128, 160 ->
///   472 triangles. The fuzzed worst case is 8.6 ulps.)
/// - A polygon failing either is measured by its edges: the distance to its
///   boundary, never less than its distance and more by at most its
///   inradius, at most |N| / (2 L): for a triangle as long as a cell (L
///   about M / 64) only slivers thinner than about 1 : 12 000 are.
/// - An N whose length overflows (coordinates beyond 1e77) or whose square
///   would be subnormal is not trusted either (its "unit" normal would be
///   zero, or not of unit length).
bool MeasuredByItsPlane(double twiceArea, double reach2, double magnitude, std::size_t m)
{
  const double dm = static_cast<double>(m);
  const double share = 3.0 * dm + 0.25 * dm * dm;
  return m >= 3 && std::isfinite(twiceArea) && twiceArea > 1e-150 &&
    twiceArea > 2.0 * share * DBL_EPSILON * reach2 && 2048.0 * magnitude * twiceArea >= share * reach2 * std::sqrt(reach2);
}
} // namespace

void PolygonSet::Add(const Vec3* corners, std::size_t m)
{
  Header h;
  h.First = static_cast<std::uint32_t>(this->Corners.size());
  h.Count = static_cast<std::uint32_t>(m);
  // The Newell vector about the first corner (header: MeasuredByItsPlane).
  Vec3 normal;
  double reach2 = 0.0;
  if (m >= 2)
  {
    Vec3 previous = corners[1] - corners[0];
    reach2 = Dot(previous, previous);
    for (std::size_t i = 2; i < m; ++i)
    {
      const Vec3 e = corners[i] - corners[0];
      reach2 = std::max(reach2, Dot(e, e));
      normal += Cross(previous, e);
      previous = e;
    }
  }
  const double length = Norm(normal);
  h.Normal = length > 0.0 ? normal * (1.0 / length) : Vec3();
  h.TwiceArea = length;
  h.Bounds = m ? BoundsOf(corners, m) : Box3{};
  // (The box's magnitude is the corners' largest coordinate.)
  h.HasInward = MeasuredByItsPlane(length, reach2, std::max(h.Bounds.Magnitude(), this->SlackMagnitude), m);
  assert(this->Inward.size() == this->Corners.size() && "Inward is parallel to Corners");
  this->Corners.insert(this->Corners.end(), corners, corners + m);
  // (Sized once and written in place, the next corner without a division:
  // S_C is built for every cell tested, a few hundred thousand polygons.
  // Zeros for a polygon measured by its edges.)
  this->Inward.resize(this->Corners.size());
  if (h.HasInward)
  {
    Vec3* inward = this->Inward.data() + h.First;
    for (std::size_t i = 0; i < m; ++i)
    {
      inward[i] = Cross(h.Normal, corners[i + 1 < m ? i + 1 : 0] - corners[i]);
    }
  }
  this->Headers.push_back(h);
}

void PolygonSet::AddCopy(const PolygonSet& from, std::size_t i)
{
  assert(this->SlackMagnitude == from.SlackMagnitude && "Add would measure it against another magnitude");
  Header h = from.Headers[i];
  const std::size_t first = h.First;
  h.First = static_cast<std::uint32_t>(this->Corners.size());
  this->Corners.insert(this->Corners.end(), from.Corners.begin() + static_cast<std::ptrdiff_t>(first),
    from.Corners.begin() + static_cast<std::ptrdiff_t>(first + h.Count));
  this->Inward.insert(this->Inward.end(), from.Inward.begin() + static_cast<std::ptrdiff_t>(first),
    from.Inward.begin() + static_cast<std::ptrdiff_t>(first + h.Count));
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
  double t0 = 0.0, t1 = 1.0;
  if (!box.SegmentWithin(a, b, t0, t1))
  {
    return false;
  }
  const Vec3 d = b - a;
  const Vec3 start = a + d * t0, end = a + d * t1;
  a = start;
  b = end;
  return true;
}

namespace
{
/// The Newell vector of the polygon: its normal, of length twice its area.
Vec3 NewellVector(const PointSpan& p)
{
  Vec3 n;
  for (std::size_t i = 1; i + 1 < p.size(); ++i)
  {
    n += Cross(p[i] - p[0], p[i + 1] - p[0]);
  }
  return n;
}

/// The polygon's edges (a segment has one).
std::size_t EdgeCount(const PointSpan& p)
{
  return p.size() == 2 ? 1 : p.size() < 2 ? 0 : p.size();
}

Vec3 Edge(const PointSpan& p, std::size_t i)
{
  return p[(i + 1) % p.size()] - p[i];
}

/// The least and largest Dot(axis, x) over the corners `p`.
void ExtentAlong(const Vec3& axis, const PointSpan& p, double& lo, double& hi)
{
  lo = HUGE_VAL;
  hi = -HUGE_VAL;
  for (const Vec3& x : p)
  {
    const double d = Dot(axis, x);
    lo = std::min(lo, d);
    hi = std::max(hi, d);
  }
}

/// Whether the projections of `q` on `axis`, of length `length`, and [pLo,
/// pHi], p's, are more than `margin` times `length` apart.
bool ApartAlong(const Vec3& axis, double length, double pLo, double pHi, const PointSpan& q, double margin)
{
  double qLo, qHi;
  ExtentAlong(axis, q, qLo, qHi);
  const double gap = margin * length;
  return qLo - pHi > gap || pLo - qHi > gap;
}

/// Whether the projections of `p` and `q` on `axis` are more than `margin`
/// times |axis| apart.
bool ApartAlong(const Vec3& axis, const PointSpan& p, const PointSpan& q, double margin)
{
  const double length = Norm(axis);
  if (!(length > 0.0))
  {
    return false;
  }
  double pLo, pHi;
  ExtentAlong(axis, p, pLo, pHi);
  return ApartAlong(axis, length, pLo, pHi, q, margin);
}

/// Whether the normals of `p` (prepared) and `q` separate them by more than
/// `margin`.
bool NormalsApart(const PolygonOnItsNormal& p, const PointSpan& q, double margin)
{
  return (p.Length > 0.0 && ApartAlong(p.Normal, p.Length, p.Lo, p.Hi, q, margin)) ||
    ApartAlong(NewellVector(q), p.Points, q, margin);
}

/// Whether the cross product of an edge of `p` and one of `q` separates them
/// by more than `margin`.
bool EdgeCrossProductsApart(const PointSpan& p, const PointSpan& q, double margin)
{
  for (std::size_t i = 0; i < EdgeCount(p); ++i)
  {
    for (std::size_t k = 0; k < EdgeCount(q); ++k)
    {
      if (ApartAlong(Cross(Edge(p, i), Edge(q, k)), p, q, margin))
      {
        return true;
      }
    }
  }
  return false;
}
} // namespace

bool PolygonsApart(const PointSpan& p, const PointSpan& q, double margin)
{
  if (p.empty() || q.empty())
  {
    return true;
  }
  for (int a = 0; a < 3; ++a)
  {
    Vec3 axis;
    axis[a] = 1.0;
    if (ApartAlong(axis, p, q, margin))
    {
      return true;
    }
  }
  return NormalsApart(OnItsNormal(p), q, margin) || EdgeCrossProductsApart(p, q, margin);
}

PolygonOnItsNormal OnItsNormal(const PointSpan& p)
{
  PolygonOnItsNormal prepared;
  prepared.Points = p;
  prepared.Normal = NewellVector(p);
  prepared.Length = Norm(prepared.Normal);
  ExtentAlong(prepared.Normal, p, prepared.Lo, prepared.Hi);
  return prepared;
}

bool PolygonsApartBesideTheirBoxes(const PointSpan& p, const ConvexPolygon& q, double margin)
{
  return PolygonsApartBesideTheirBoxes(OnItsNormal(p), q, margin);
}

bool PolygonsApartBesideTheirBoxes(const PolygonOnItsNormal& prepared, const ConvexPolygon& q, double margin)
{
  const PointSpan& p = prepared.Points;
  if (p.empty() || q.Points.empty())
  {
    return true;
  }
  if (NormalsApart(prepared, q.Points, margin))
  {
    return true;
  }
  // Meshes' polygons near one another mostly cross, and crossing polygons
  // have no separating axis: found so in one pass over each instead of a
  // projection of both on every pair of their edges. Only where q's plane
  // is known within the rounding (Inward: MeasuredByItsPlane) - collinear
  // corners' "plane" is rounding noise, whose section would be clipped by
  // its sides alone, without ends - so that p's section, clipped to q, is a
  // point both share up to rounding: the axes could not separate them by
  // the margin either, and the answer is theirs.
  Vec3 a, b;
  if (!q.Inward.empty() && SectionByPlane(p, q.Normal, Dot(q.Normal, q.Points[0]), a, b) &&
    ClipSegmentToPolygon(q, a, b))
  {
    return false;
  }
  return EdgeCrossProductsApart(p, q.Points, margin);
}

bool SectionByPlane(const PointSpan& q, const Vec3& n, double offset, Vec3& a, Vec3& b)
{
  int found = 0;
  const std::size_t m = q.size();
  for (std::size_t i = 0; i < m && found < 2; ++i)
  {
    const Vec3 &x = q[i], &y = q[(i + 1) % m];
    const double sx = Dot(n, x) - offset, sy = Dot(n, y) - offset;
    if ((sx < 0.0) != (sy < 0.0))
    {
      (found++ == 0 ? a : b) = x + (y - x) * (sx / (sx - sy));
    }
  }
  return found == 2;
}

bool ClipSegmentToPolygon(const ConvexPolygon& p, Vec3& a, Vec3& b)
{
  double t0 = 0.0, t1 = 1.0;
  const std::size_t m = p.Points.size();
  for (std::size_t i = 0; i < m; ++i)
  {
    // (A polygon of a set measured by its plane has its sides' inward
    // normals made already, PolygonSet::Add, the same product.)
    const Vec3 inward = p.Inward.empty() ? Cross(p.Normal, p.Points[(i + 1) % m] - p.Points[i]) : p.Inward[i];
    const double da = Dot(inward, a - p.Points[i]), db = Dot(inward, b - p.Points[i]);
    if (da < 0.0 && db < 0.0)
    {
      return false;
    }
    if (da < 0.0 || db < 0.0)
    {
      const double t = da / (da - db);
      if (da < 0.0)
      {
        t0 = std::max(t0, t); // (enters the polygon's side at t)
      }
      else
      {
        t1 = std::min(t1, t); // (leaves it)
      }
    }
  }
  if (!(t0 < t1))
  {
    return false;
  }
  const Vec3 d = b - a;
  b = a + d * t1;
  a = a + d * t0;
  return true;
}

} // namespace tpc
