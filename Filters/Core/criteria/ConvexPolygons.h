// Convex planar polygons, stored flat, and the distance to one (the surface
// in a cell where one mesh is the surface, S_C of MeshCellError.h, and the
// targets of PolygonHausdorff.h's branch and bound).
//
// Why flat: S_C is built for every cell a prediction or a certificate
// examines, from up to thousands of clipped triangles. A polygon holding its
// corners and edge normals in two vectors of its own cost two heap blocks
// each; one holding them inline (room for 12 corners) cost none but twice
// the memory, and this virtual machine's page faults (about 15 us a page)
// made that slower. A PolygonSet keeps every polygon's corners in one array
// and its edge normals in another, with a header per polygon: three
// allocations per set, about 240 bytes per triangle, and half the
// instructions building S_C took with a vector per polygon (armadillo at
// 1/64: 0.51 G -> 0.26 G).
#pragma once

#include "BoundedVector.h"
#include "Vector3.h"

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <initializer_list>
#include <vector>

namespace tpc
{

/// The corners of a triangle being clipped by a box, on the stack: at most
/// 9 (each side adds at most one corner to a convex polygon). Rounding can
/// add one more only where an interpolated corner lands an ulp beyond its
/// edge's ends along another axis and a later side passes exactly there;
/// 32 is far beyond what that can reach. (The polygons are then copied into
/// a PolygonSet, which has no such bound.)
using ClippedCorners = BoundedVector<Vec3, 32>;

/// The part of the polygon `points` with x[axis] <= value (`below`) or >=
/// value (Sutherland-Hodgman) in `out`; new points get exactly x[axis] =
/// value.
template <std::size_t Capacity>
void ClipToHalfSpace(const BoundedVector<Vec3, Capacity>& points, BoundedVector<Vec3, Capacity>& out, int axis,
  double value, bool below)
{
  out.clear();
  const std::size_t m = points.size();
  const auto kept = [&](const Vec3& p) { return below ? p[axis] <= value : p[axis] >= value; };
  for (std::size_t i = 0; i < m; ++i)
  {
    const Vec3& a = points[i];
    const Vec3& b = points[(i + 1) % m];
    if (kept(a))
    {
      out.push_back(a);
    }
    if (kept(a) != kept(b) && m > 1)
    {
      const double t = (value - a[axis]) / (b[axis] - a[axis]);
      Vec3 p = a + (b - a) * t;
      p[axis] = value;
      out.push_back(p);
    }
  }
}

/// The polygon `points` clipped to the closed box (possibly degenerate), in
/// place: a convex polygon gains at most one corner per side (and rounding
/// rarely one more: ClippedCorners), so Capacity must exceed its count by 6
/// and some. A side the polygon lies within is skipped, one it lies beyond
/// empties it: what clipping would give, without building it (most triangles
/// of a cell cross no side or one).
template <std::size_t Capacity>
void ClipToBox(BoundedVector<Vec3, Capacity>& points, const Box3& box)
{
  BoundedVector<Vec3, Capacity> clipped;
  for (int axis = 0; axis < 3 && !points.empty(); ++axis)
  {
    double lo = points[0][axis], hi = lo;
    for (const Vec3& p : points)
    {
      lo = std::min(lo, p[axis]);
      hi = std::max(hi, p[axis]);
    }
    if (lo > box.hi[axis] || hi < box.lo[axis])
    {
      points.clear();
      return;
    }
    if (hi > box.hi[axis])
    {
      ClipToHalfSpace(points, clipped, axis, box.hi[axis], true);
      points = clipped;
    }
    if (lo < box.lo[axis] && !points.empty())
    {
      ClipToHalfSpace(points, clipped, axis, box.lo[axis], false);
      points = clipped;
    }
  }
}

/// A run of points in a PolygonSet (a polygon's corners, or its edges'
/// inward normals).
struct PointSpan
{
  const Vec3* First = nullptr;
  std::size_t Count = 0;

  std::size_t size() const { return this->Count; }
  bool empty() const { return this->Count == 0; }
  const Vec3& operator[](std::size_t i) const { return this->First[i]; }
  const Vec3* begin() const { return this->First; }
  const Vec3* end() const { return this->First + this->Count; }
  const Vec3& front() const { return this->First[0]; }
  const Vec3& back() const { return this->First[this->Count - 1]; }
};

/// A convex polygon in a plane (vertices in order; a segment or a point when
/// degenerate): a view of a PolygonSet's polygon, valid while the set is
/// unchanged.
struct ConvexPolygon
{
  PointSpan Points;
  /// Unit, from the vertex order (Newell, about the first corner); zero
  /// only where the Newell vector is exactly zero: collinear corners that
  /// are not binary fractions give a unit normal of rounding noise, weighted
  /// by TwiceArea (of rounding size) where it is read (MeshCellApex), and
  /// never used to measure a distance (Inward is empty then).
  Vec3 Normal;
  double TwiceArea = 0.0; ///< the Newell vector's length
  Box3 Bounds;
  /// Normal x (edge from Points[i] to Points[i + 1]): points into the polygon
  /// within its plane (empty where the polygon is measured by its edges:
  /// collinear corners, or a plane not known within the rounding slack,
  /// ConvexPolygons.cxx: MeasuredByItsPlane).
  PointSpan Inward;
};

/// Convex planar polygons, stored flat (header).
class PolygonSet
{
public:
  /// Room for `polygons` polygons with `corners` corners in all.
  void reserve(std::size_t polygons, std::size_t corners);
  /// No polygons; the memory stays for the next ones.
  void clear()
  {
    this->Headers.clear();
    this->Corners.clear();
    this->Inward.clear();
  }
  /// No polygons, and room for `polygons` more: the memory stays unless it
  /// has been far more than that many times in a row (a set reused from cell
  /// to cell, ScratchPool.h, keeps what the first levels' large cells needed
  /// only while cells that large come).
  void Recycle(std::size_t polygons);
  /// Adds the polygon with corners `corners` (convex, planar, in order):
  /// its normal, area, box and edges' inward normals.
  void Add(const Vec3* corners, std::size_t count);
  void Add(std::initializer_list<Vec3> corners) { this->Add(corners.begin(), corners.size()); }
  /// Adds polygon `i` of `from` as `from` holds it: its corners, normal,
  /// area, box and inward normals copied rather than measured again (what Add
  /// would compute, where this set has `from`'s slack magnitude; S_C's sheets
  /// are cut out of S_C so, MeshCellError.h).
  void AddCopy(const PolygonSet& from, std::size_t i);
  /// The largest coordinate M the caller's rounding slack is taken of
  /// (MeshCellError.h: Rounding) - the polygons added after are measured by
  /// their planes wherever that is within a quarter of the slack
  /// (ConvexPolygons.cxx, MeasuredByItsPlane). Without it (0, and after
  /// Recycle frees the memory) each polygon's own largest coordinate stands
  /// in: never larger, so the test is only stricter.
  void SetSlackMagnitude(double magnitude) { this->SlackMagnitude = magnitude; }
  double GetSlackMagnitude() const { return this->SlackMagnitude; }

  std::size_t size() const { return this->Headers.size(); }
  bool empty() const { return this->Headers.empty(); }
  /// Polygons it has room for without allocating.
  std::size_t capacity() const { return this->Headers.capacity(); }
  ConvexPolygon operator[](std::size_t i) const;
  /// PolygonDistance(p, (*this)[i]), without making the view (the branch
  /// and bound measures millions).
  double Distance(const Vec3& p, std::size_t i) const;
  /// (*this)[i].Bounds, without making the view (loops that test the box
  /// first, and mostly stop there).
  const Box3& Bounds(std::size_t i) const { return this->Headers[i].Bounds; }

  /// Iteration yields the polygons by value (views).
  class Iterator
  {
  public:
    Iterator(const PolygonSet* set, std::size_t i)
      : Set(set)
      , Index(i)
    {
    }
    ConvexPolygon operator*() const { return (*this->Set)[this->Index]; }
    Iterator& operator++()
    {
      ++this->Index;
      return *this;
    }
    bool operator!=(const Iterator& o) const { return this->Index != o.Index; }

  private:
    const PolygonSet* Set;
    std::size_t Index;
  };
  Iterator begin() const { return { this, 0 }; }
  Iterator end() const { return { this, this->size() }; }

private:
  struct Header
  {
    std::uint32_t First = 0; ///< in Corners and Inward
    std::uint32_t Count = 0;
    bool HasInward = false;
    Vec3 Normal;
    double TwiceArea = 0.0;
    Box3 Bounds;
  };
  std::vector<Header> Headers;
  std::vector<Vec3> Corners;
  std::vector<Vec3> Inward; ///< parallel to Corners (zeros for a polygon measured by its edges)
  double SlackMagnitude = 0.0;
  int SmallUses = 0; ///< Recycle's uses in a row far below the capacity
};

inline ConvexPolygon PolygonSet::operator[](std::size_t i) const
{
  // (Inline: the branch and bound makes a view per distance it measures.)
  const Header& h = this->Headers[i];
  ConvexPolygon q;
  q.Points = { this->Corners.data() + h.First, h.Count };
  q.Normal = h.Normal;
  q.TwiceArea = h.TwiceArea;
  q.Bounds = h.Bounds;
  q.Inward = h.HasInward ? PointSpan{ this->Inward.data() + h.First, h.Count } : PointSpan{};
  return q;
}

/// Distance from `p` to the segment [a, b].
double SegmentDistance(const Vec3& p, const Vec3& a, const Vec3& b);

/// Clips the segment [a, b] to the closed box (Liang-Barsky), in place;
/// false when they do not meet.
bool ClipSegment(Vec3& a, Vec3& b, const Box3& box);

/// Distance from `p` to the polygon (its interior included).
double PolygonDistance(const Vec3& p, const ConvexPolygon& polygon);

/// The largest `value(x)` over the corners x of `set`'s polygons clipped to
/// `box` (0 where none meets it): where `value` is convex, its largest over
/// the set's part in the box (the chord deviations, MeshCellError.h).
template <typename Value>
double LargestOverClippedCorners(const PolygonSet& set, const Box3& box, const Value& value)
{
  double largest = 0.0;
  for (std::size_t i = 0; i < set.size(); ++i)
  {
    if (set.Bounds(i).Overlaps(box))
    {
      // (S_C's polygons have at most ClippedCorners' corners; one more per
      // side of the box, and some.)
      BoundedVector<Vec3, 2 * ClippedCorners::capacity()> clipped;
      for (const Vec3& p : set[i].Points)
      {
        clipped.push_back(p);
      }
      ClipToBox(clipped, box);
      for (const Vec3& p : clipped)
      {
        largest = std::max(largest, value(p));
      }
    }
  }
  return largest;
}

/// Whether the convex polygons `p` and `q` (corners in order) are proven
/// more than `margin` apart: their projections on some axis - the
/// coordinate axes, their normals, the cross products of their edges - are
/// more than `margin` times the axis's length apart (separating axes, as
/// for convex polytopes; coplanar polygons, which need axes in their plane,
/// are never found apart so). Each projection is computed within a few
/// ulps of the coordinates times the axis's length: the caller's margin
/// must exceed that (MeshBooleanSurface.h: Rounding).
bool PolygonsApart(const PointSpan& p, const PointSpan& q, double margin);
/// The same test on every axis but the coordinate axes, for polygons whose
/// boxes the caller found within `margin` of each other (there those axes
/// cannot separate them); `q` a polygon of a set, whose plane, where it is
/// known within the rounding, also tells crossing polygons at once.
bool PolygonsApartBesideTheirBoxes(const PointSpan& p, const ConvexPolygon& q, double margin);

/// A polygon with its Newell vector (its normal, of length twice its area),
/// that vector's length and the polygon's extent along it: what the test
/// below needs of p on p's own normal, found once for a polygon tested
/// against many (MeshBooleanSurface.cxx, NearPolygons: a piece against every
/// polygon of the other meshes in reach; found once a pair, they cost joint
/// minus knot 0.8 % more instructions).
struct PolygonOnItsNormal
{
  PointSpan Points;
  Vec3 Normal;
  double Length = 0.0;
  double Lo = 0.0, Hi = 0.0;
};
PolygonOnItsNormal OnItsNormal(const PointSpan& p);
/// PolygonsApartBesideTheirBoxes for `p` prepared: the same answer.
bool PolygonsApartBesideTheirBoxes(const PolygonOnItsNormal& p, const ConvexPolygon& q, double margin);

/// The part of polygon `q` (corners in order) in the plane Dot(n, x) =
/// `offset` (`n` a unit normal): the segment between the points where its
/// sides cross the plane, in `a` and `b`; false where it does not reach
/// across.
bool SectionByPlane(const PointSpan& q, const Vec3& n, double offset, Vec3& a, Vec3& b);

/// The segment [a, b] clipped to convex polygon `p` within its plane (both
/// in it up to rounding), in place; false where nothing is left.
bool ClipSegmentToPolygon(const ConvexPolygon& p, Vec3& a, Vec3& b);

} // namespace tpc
