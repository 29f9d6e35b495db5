#include "LocalHeights.h"

#include "BoundedVector.h"

#include <algorithm>
#include <array>
#include <cfloat>
#include <cmath>
#include <cstdint>

namespace tpc
{
namespace
{
/// The slope limit of the local heights' bound (header): a
/// triangle's normal N has N . n >= |N| / SteepLimit.
constexpr double SteepLimit = 16.0;

/// Whether a triangle of normal `normal` (any length) is steep enough along
/// `n` for the local heights (header).
bool SteepAlong(const Vec3& normal, const Vec3& n)
{
  const double along = Dot(normal, n);
  return along > 0.0 && SteepLimit * along >= Norm(normal);
}

/// Coordinates in the orthonormal frame (E1, E2, N), N = n: across n, then
/// the height along it. (E1 x E2 = N: a triangle facing along n turns
/// counterclockwise in (s, t).)
struct HeightFrame
{
  Vec3 E1, E2, N;

  explicit HeightFrame(const Vec3& n)
    : N(n)
  {
    int least = 0; // (the axis least along n, crossed with it)
    for (int a = 1; a < 3; ++a)
    {
      least = std::fabs(n[a]) < std::fabs(n[least]) ? a : least;
    }
    Vec3 axis(0.0, 0.0, 0.0);
    axis[least] = 1.0;
    this->E1 = Normalized(Cross(n, axis));
    this->E2 = Cross(n, this->E1);
  }
  Vec3 Of(const Vec3& p) const { return Vec3(Dot(p, this->E1), Dot(p, this->E2), Dot(p, this->N)); }
};

/// A convex polygon's corners in a HeightFrame, cut by half-spaces. (A cut
/// adds a corner at most, and rounding on a near-degenerate polygon rarely
/// one more: a cut that would pass the capacity makes the bound give up.)
using FrameCorners = BoundedVector<Vec3, 48>;

/// The (s, t) box of some corners.
struct Shadow
{
  double Lo[2] = { HUGE_VAL, HUGE_VAL }, Hi[2] = { -HUGE_VAL, -HUGE_VAL };

  void Hold(const Vec3& p)
  {
    for (int a = 0; a < 2; ++a)
    {
      this->Lo[a] = std::min(this->Lo[a], p[a]);
      this->Hi[a] = std::max(this->Hi[a], p[a]);
    }
  }
  bool Meets(const Shadow& other) const
  {
    return !(this->Lo[0] > other.Hi[0] || other.Lo[0] > this->Hi[0] || this->Lo[1] > other.Hi[1] ||
      other.Lo[1] > this->Hi[1]);
  }
};

/// The half-space Normal . x <= Offset of frame coordinates (a half-plane of
/// (s, t) where Normal[2] = 0).
struct HalfSpace
{
  Vec3 Normal;
  double Offset;
};

/// `points` cut to `half`, every coordinate carried along each edge (the
/// heights are affine there); false where the cut would pass the capacity,
/// or a corner's side is NaN.
bool CutTo(FrameCorners& points, const HalfSpace& half)
{
  // (Most cuts keep all or nothing: those are told first.)
  const std::size_t m = points.size();
  std::array<double, FrameCorners::capacity()> beyond;
  std::size_t in = 0;
  for (std::size_t i = 0; i < m; ++i)
  {
    beyond[i] = Dot(half.Normal, points[i]) - half.Offset;
    if (std::isnan(beyond[i]))
    {
      return false; // (nothing is proven of a NaN corner or side)
    }
    in += beyond[i] <= 0.0 ? 1 : 0;
  }
  if (in == m)
  {
    return true;
  }
  if (in == 0)
  {
    points.clear();
    return true;
  }
  FrameCorners kept;
  for (std::size_t i = 0; i < m; ++i)
  {
    const Vec3& p = points[i];
    const Vec3& q = points[(i + 1) % m];
    const double dp = beyond[i], dq = beyond[(i + 1) % m];
    const bool inP = dp <= 0.0, crosses = inP != (dq <= 0.0);
    if (kept.size() + (inP ? 1 : 0) + (crosses ? 1 : 0) > kept.capacity())
    {
      return false;
    }
    if (inP)
    {
      kept.push_back(p);
    }
    if (crosses)
    {
      kept.push_back(p + (q - p) * (dp / (dp - dq)));
    }
  }
  points = kept;
  return true;
}

/// `points` cut to every half-space of `halves`; false where a cut gives up.
template <typename HalfSpaces>
bool CutToAll(FrameCorners& points, const HalfSpaces& halves)
{
  for (const HalfSpace& half : halves)
  {
    if (points.empty())
    {
      return true;
    }
    if (!CutTo(points, half))
    {
      return false;
    }
  }
  return true;
}

/// The largest of `value` over `corners` (0 where there are none; +inf for
/// a NaN).
template <typename Value>
double LargestAt(const FrameCorners& corners, const Value& value)
{
  double largest = 0.0;
  for (const Vec3& p : corners)
  {
    const double v = value(p);
    largest = v <= largest ? largest : (std::isnan(v) ? HUGE_VAL : v);
  }
  return largest;
}

/// A triangle of P in the frame: its corners, its shadow's box and sides,
/// and its plane (Normal . (x - Corners[0]) = 0, Normal[2] > 0).
struct FrameTriangle
{
  std::array<Vec3, 3> Corners;
  Shadow Box;
  std::array<HalfSpace, 3> Sides;
  Vec3 Normal;

  double HeightAt(const Vec3& x) const
  {
    const Vec3& c = this->Corners[0];
    return c[2] - (this->Normal[0] * (x[0] - c[0]) + this->Normal[1] * (x[1] - c[1])) / this->Normal[2];
  }
};

/// The face of `cell` holding both `a` and `b` - its axis, and its side in
/// `side` - or -1 where no face holds both within `near`, or two do (a chord
/// along an edge).
int SharedFace(const Vec3& a, const Vec3& b, const Box3& cell, double near, double& side)
{
  int face = -1;
  for (int axis = 0; axis < 3; ++axis)
  {
    for (double at : { cell.lo[axis], cell.hi[axis] })
    {
      if (std::fabs(a[axis] - at) <= near && std::fabs(b[axis] - at) <= near)
      {
        if (face >= 0)
        {
          return -1;
        }
        face = axis;
        side = at;
      }
    }
  }
  return face;
}

/// A chord c = [a, b] as the local heights see it (header):
/// its ends and direction in the frame; where its face is known, the unit
/// vectors Across (in the face's plane, across c) and Out (the face's
/// normal), and the range [Low, High] of Across . (w - a) over the points
/// w of its arc and refining polylines (0 in it); and the rectangle of the
/// (s, t) plane holding R_c, widened by the slack, with its box.
struct ChordView
{
  Vec3 A, B;
  /// Where the face is known, c's ends put on its plane (within `near` of
  /// A and B) and the unit vector from one to the other: the line the arc's
  /// points are read across; else A, B and c's direction.
  Vec3 FlatA, FlatB, Along;
  bool OnFace = false;
  Vec3 Across, Out;
  double Low = 0.0, High = 0.0;
  std::array<HalfSpace, 4> Rectangle;
  Shadow Box;
};

/// The rectangle of the (s, t) plane aligned with the shadow of the chord
/// from `a` to `b` (frame coordinates) holding every point of `region`
/// (frame coordinates) widened by `reach`, into `chord`.
void RectangleAround(const Vec3& a, const Vec3& b, const FrameCorners& region, double reach, ChordView& chord)
{
  const double ds = b[0] - a[0], dt = b[1] - a[1], length = std::hypot(ds, dt);
  const double us = length > 0.0 ? ds / length : 1.0, ut = length > 0.0 ? dt / length : 0.0;
  double lo[2] = { HUGE_VAL, HUGE_VAL }, hi[2] = { -HUGE_VAL, -HUGE_VAL }; // (along u, along u's normal w)
  for (const Vec3& p : region)
  {
    const double along = us * p[0] + ut * p[1], side = -ut * p[0] + us * p[1];
    lo[0] = std::min(lo[0], along - reach);
    hi[0] = std::max(hi[0], along + reach);
    lo[1] = std::min(lo[1], side - reach);
    hi[1] = std::max(hi[1], side + reach);
  }
  chord.Rectangle = { HalfSpace{ Vec3(us, ut, 0.0), hi[0] }, HalfSpace{ Vec3(-us, -ut, 0.0), -lo[0] },
    HalfSpace{ Vec3(-ut, us, 0.0), hi[1] }, HalfSpace{ Vec3(ut, -us, 0.0), -lo[1] } };
  for (double along : { lo[0], hi[0] })
  {
    for (double side : { lo[1], hi[1] })
    {
      chord.Box.Hold(Vec3(us * along - ut * side, ut * along + us * side, 0.0));
    }
  }
}

/// The chord from `a` to `b` (world coordinates) with reach `delta` in
/// `cell` (header). Where a face of the cell holds both
/// ends (within `near`), its arc and refining polylines lie in that face,
/// in the cell, within delta of c: in the region a + alpha Along + beta
/// Across, -delta <= alpha <= |c| + delta, Low <= beta <= High - Low and
/// High the range of beta over S_C's part on the face within delta of c's
/// box, which holds the arc (and the polylines' corners), clamped to
/// [-delta, delta] - and R_c is the shadow of that region's part in the
/// cell. Else R_c is the chord's shadow widened by delta.
ChordView ViewOf(const HeightFrame& frame, const PolygonSet& surface, const Vec3& a, const Vec3& b,
  const Box3& cell, double near, double delta, double slack)
{
  ChordView chord;
  chord.A = chord.FlatA = frame.Of(a);
  chord.B = chord.FlatB = frame.Of(b);
  const double length = Norm(b - a);
  const Vec3 along = frame.Of(length > 0.0 ? (b - a) * (1.0 / length) : Vec3(0.0, 0.0, 0.0));
  chord.Along = along;
  double side = 0.0;
  int face = length > 0.0 ? SharedFace(a, b, cell, near, side) : -1;
  // (Its ends put on the face's plane: a and b lie within `near` of it, so
  // the chord's direction in the plane is read from them only where the
  // chord is long against that.)
  Vec3 flatA = a, flatB = b;
  if (face >= 0)
  {
    flatA[face] = flatB[face] = side;
    face = Norm(flatB - flatA) > 1024.0 * near ? face : -1;
  }
  FrameCorners region;
  if (face >= 0)
  {
    Vec3 out(0.0, 0.0, 0.0);
    out[face] = 1.0;
    const Vec3 inPlane = Normalized(flatB - flatA);
    const Vec3 across = Normalized(Cross(out, inPlane));
    chord.OnFace = true;
    chord.FlatA = frame.Of(flatA);
    chord.FlatB = frame.Of(flatB);
    chord.Along = frame.Of(inPlane);
    chord.Out = frame.Of(out);
    chord.Across = frame.Of(across);
    // (S_C's corners clipped to the cell lie on its faces exactly.)
    Box3 trace = cell;
    for (int axis = 0; axis < 3; ++axis)
    {
      trace.lo[axis] = axis == face ? side : std::max(cell.lo[axis], std::min(a[axis], b[axis]) - delta - slack);
      trace.hi[axis] = axis == face ? side : std::min(cell.hi[axis], std::max(a[axis], b[axis]) + delta + slack);
    }
    // (The largest over S_C's clipped corners: 0 where none, as c's own.)
    const double high = LargestOverClippedCorners(surface, trace, [&](const Vec3& p) { return Dot(across, p - a); });
    const double low = -LargestOverClippedCorners(surface, trace, [&](const Vec3& p) { return Dot(across, a - p); });
    chord.Low = std::max(low - slack, -delta);
    chord.High = std::min(high + slack, delta);
    const double reach = delta + near; // (the flattened ends moved by `near` at most)
    BoundedVector<Vec3, 16> corners{ flatA - inPlane * reach + across * chord.Low,
      flatB + inPlane * reach + across * chord.Low, flatB + inPlane * reach + across * chord.High,
      flatA - inPlane * reach + across * chord.High };
    Box3 within = cell; // (open along the face's axis: the corners are on its plane up to rounding)
    within.lo[face] = -HUGE_VAL;
    within.hi[face] = HUGE_VAL;
    ClipToBox(corners, within);
    for (const Vec3& p : corners)
    {
      region.push_back(frame.Of(p));
    }
  }
  if (region.empty())
  {
    chord.OnFace = false;
    chord.FlatA = chord.A;
    chord.FlatB = chord.B;
    chord.Along = along;
    region.push_back(chord.A);
    region.push_back(chord.B);
    RectangleAround(chord.A, chord.B, region, delta + slack, chord);
  }
  else
  {
    RectangleAround(chord.A, chord.B, region, slack, chord);
  }
  return chord;
}

/// The largest over `corners` (frame coordinates) cut to R_c of a bound of
/// the distance from their points to the far side - S_C's points to P's,
/// P's to S_C's (header) - in three parts: beyond a (the
/// distance to a, a loop point on both), beyond b (to b), and between
/// (points whose nearest point u of c's line - c put on its face's plane,
/// FlatA to FlatB - is on c: the far side's point w there - on the arc, or
/// on a refining polyline, both in that plane - has w - u = beta Across,
/// Low <= beta <= High, so |x - w| <= sqrt((Out . (x - FlatA))^2 + max over
/// beta of (Across . (x - FlatA) - beta)^2), convex; with no face known,
/// d(x, c) + delta). `farSideOnC`: the far side holds c itself (S_C's points
/// against the own loops' P): there d(x, c).
double FarthestOver(const FrameCorners& corners, const ChordView& chord, double delta, bool farSideOnC)
{
  const double alongA = Dot(chord.Along, chord.FlatA), alongB = Dot(chord.Along, chord.FlatB);
  const HalfSpace beyondA{ chord.Along, alongA }, beforeB{ chord.Along, alongB };
  const HalfSpace afterA{ chord.Along * -1.0, -alongA }, beyondB{ chord.Along * -1.0, -alongB };
  FrameCorners inR = corners;
  if (!CutToAll(inR, chord.Rectangle))
  {
    return HUGE_VAL;
  }
  if (inR.empty())
  {
    return 0.0;
  }
  double largest = 0.0;
  for (const std::pair<HalfSpace, Vec3>& beyond : { std::pair{ beyondA, chord.A }, std::pair{ beyondB, chord.B } })
  {
    FrameCorners part = inR;
    if (!CutTo(part, beyond.first))
    {
      return HUGE_VAL;
    }
    const Vec3& end = beyond.second; // (named outside the lambda: C++17 lambdas capture no bindings)
    largest = std::max(largest, LargestAt(part, [&](const Vec3& x) { return Norm(x - end); }));
  }
  FrameCorners between = inR;
  if (!CutTo(between, afterA) || !CutTo(between, beforeB))
  {
    return HUGE_VAL;
  }
  const auto toFarSide = [&](const Vec3& x) {
    if (farSideOnC)
    {
      return SegmentDistance(x, chord.A, chord.B);
    }
    if (!chord.OnFace)
    {
      return SegmentDistance(x, chord.A, chord.B) + delta;
    }
    const double out = Dot(chord.Out, x - chord.FlatA), across = Dot(chord.Across, x - chord.FlatA);
    const double apart = std::max(std::fabs(across - chord.Low), std::fabs(across - chord.High));
    return std::sqrt(out * out + apart * apart);
  };
  const double viaC = LargestAt(between, toFarSide);
  const double viaEnds = std::min(LargestAt(between, [&](const Vec3& x) { return Norm(x - chord.A); }),
    LargestAt(between, [&](const Vec3& x) { return Norm(x - chord.B); }));
  return std::max(largest, std::min(viaC, viaEnds));
}

/// S_C and P in a HeightFrame: P's triangles; S_C's corners, polygon i's from
/// First[i] to First[i + 1], and each polygon's shadow box.
struct FramedCell
{
  std::vector<FrameTriangle> Fan;
  std::vector<Vec3> Corners;
  std::vector<std::size_t> First{ 0 };
  std::vector<Shadow> Shadows;

  FrameCorners Polygon(std::size_t i) const
  {
    FrameCorners p;
    for (std::size_t j = this->First[i]; j < this->First[i + 1]; ++j)
    {
      p.push_back(this->Corners[j]);
    }
    return p;
  }
};

/// P's triangles in `frame`, into `cell`; false where one is not steep
/// enough (header).
bool FrameFan(const HeightFrame& frame, const std::vector<SourceTriangle>& patch, FramedCell& cell)
{
  cell.Fan.resize(patch.size());
  for (std::size_t i = 0; i < patch.size(); ++i)
  {
    FrameTriangle& f = cell.Fan[i];
    for (int k = 0; k < 3; ++k)
    {
      f.Corners[k] = frame.Of(patch[i][k]);
      f.Box.Hold(f.Corners[k]);
    }
    f.Normal = Cross(f.Corners[1] - f.Corners[0], f.Corners[2] - f.Corners[0]);
    if (!SteepAlong(f.Normal, Vec3(0.0, 0.0, 1.0)))
    {
      return false;
    }
    for (int k = 0; k < 3; ++k) // (counterclockwise: inside is left of each side)
    {
      const Vec3 &p = f.Corners[k], &q = f.Corners[(k + 1) % 3];
      const Vec3 outward(q[1] - p[1], p[0] - q[0], 0.0);
      f.Sides[k] = HalfSpace{ outward, Dot(outward, p) };
    }
  }
  return true;
}

/// S_C's polygons in `frame`, into `cell`; false where a triangle they are
/// clipped from is not steep enough (header), or one has more corners than
/// the cuts leave room for.
bool FrameSurface(const HeightFrame& frame, const MeshSolid& mesh, const TriangleList& surfaceTriangles,
  const PolygonSet& surface, FramedCell& cell)
{
  cell.Corners.reserve(4 * surface.size());
  cell.Shadows.resize(surface.size());
  for (std::size_t i = 0; i < surface.size(); ++i)
  {
    const std::uint32_t t = surfaceTriangles[i];
    const Vec3 &a = mesh.Vertex(t, 0), &b = mesh.Vertex(t, 1), &c = mesh.Vertex(t, 2);
    // (S_C's polygons have at most ClippedCorners' corners: room for the cuts.)
    static_assert(FrameCorners::capacity() >= ClippedCorners::capacity() + 8);
    if (!SteepAlong(Cross(b - a, c - a), frame.N) || surface[i].Points.size() > ClippedCorners::capacity())
    {
      return false;
    }
    for (const Vec3& p : surface[i].Points)
    {
      cell.Corners.push_back(frame.Of(p));
      cell.Shadows[i].Hold(cell.Corners.back());
    }
    cell.First.push_back(cell.Corners.size());
  }
  return true;
}

/// G (header): each polygon of S_C cut to each triangle of P it may meet;
/// +inf where a cut gives up or G passes `giveUp`.
double HeightGap(const FramedCell& cell, double giveUp)
{
  double largest = 0.0;
  for (std::size_t i = 0; i < cell.Shadows.size(); ++i)
  {
    for (const FrameTriangle& f : cell.Fan)
    {
      if (!cell.Shadows[i].Meets(f.Box))
      {
        continue;
      }
      FrameCorners cut = cell.Polygon(i);
      if (!CutToAll(cut, f.Sides))
      {
        return HUGE_VAL;
      }
      largest = std::max(largest, LargestAt(cut, [&](const Vec3& x) { return std::fabs(x[2] - f.HeightAt(x)); }));
      if (!(largest <= giveUp))
      {
        return HUGE_VAL;
      }
    }
  }
  return largest;
}

/// max(D_S, D_P) (header) over the own chords `chords`; +inf where none is
/// given, a cut gives up or a term passes `giveUp`.
double ChordTerms(const HeightFrame& frame, const PolygonSet& surface, const FramedCell& cell,
  const OwnChords& chords, double slack, double giveUp)
{
  // (The chords must be P's boundary, or what it refines: none, no bound.)
  if (std::all_of(chords.Loops->begin(), chords.Loops->end(), [](const auto& loop) { return loop.empty(); }))
  {
    return HUGE_VAL;
  }
  // (Loop points lie on their faces up to an ulp or so: a chord's face is
  // read within 64 of them.)
  const double onFace = 64.0 * DBL_EPSILON * chords.Cell.Magnitude();
  double largest = 0.0;
  std::size_t k = 0;
  for (const std::vector<Vec3>& loop : *chords.Loops)
  {
    for (std::size_t j = 0; j < loop.size(); ++j, ++k)
    {
      const double delta = chords.Deltas ? (k < chords.Deltas->size() ? (*chords.Deltas)[k] : HUGE_VAL) : chords.Delta;
      if (!(delta < giveUp))
      {
        return HUGE_VAL;
      }
      const ChordView chord = ViewOf(frame, surface, loop[j], loop[(j + 1) % loop.size()], chords.Cell, onFace,
        delta, slack);
      for (std::size_t i = 0; i < cell.Shadows.size() && largest <= giveUp; ++i)
      {
        largest = cell.Shadows[i].Meets(chord.Box)
          ? std::max(largest, FarthestOver(cell.Polygon(i), chord, delta, !chords.Refined))
          : largest;
      }
      for (const FrameTriangle& f : cell.Fan)
      {
        const FrameCorners triangle{ f.Corners[0], f.Corners[1], f.Corners[2] };
        largest = largest <= giveUp && f.Box.Meets(chord.Box)
          ? std::max(largest, FarthestOver(triangle, chord, delta, false))
          : largest;
      }
      if (!(largest <= giveUp))
      {
        return HUGE_VAL;
      }
    }
  }
  return largest;
}
} // namespace

double LocalHeightsBound(const MeshSolid& mesh, const TriangleList& surfaceTriangles, const PolygonSet& surface,
  const std::vector<SourceTriangle>& patch, const OwnChords& chords, const Vec3& n, double slack, double giveUp)
{
  const HeightFrame frame(n);
  FramedCell cell;
  if (!FrameFan(frame, patch, cell) || !FrameSurface(frame, mesh, surfaceTriangles, surface, cell))
  {
    return HUGE_VAL;
  }
  const double gap = HeightGap(cell, giveUp);
  return gap <= giveUp ? std::max(gap, ChordTerms(frame, surface, cell, chords, slack, giveUp)) : HUGE_VAL;
}

} // namespace tpc
