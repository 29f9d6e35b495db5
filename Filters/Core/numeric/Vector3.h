// Small fixed-size geometry used everywhere in the core: points/vectors and
// closed axis-aligned boxes (a box may be degenerate: a face or an edge).
#pragma once

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <utility>

namespace tpc
{

struct Vec3
{
  double x[3] = { 0.0, 0.0, 0.0 };

  Vec3() = default;
  Vec3(double a, double b, double c)
    : x{ a, b, c }
  {
  }
  double& operator[](int i) { return x[i]; }
  double operator[](int i) const { return x[i]; }

  Vec3 operator+(const Vec3& o) const { return { x[0] + o[0], x[1] + o[1], x[2] + o[2] }; }
  Vec3 operator-(const Vec3& o) const { return { x[0] - o[0], x[1] - o[1], x[2] - o[2] }; }
  Vec3 operator*(double s) const { return { x[0] * s, x[1] * s, x[2] * s }; }
  Vec3& operator+=(const Vec3& o)
  {
    x[0] += o[0];
    x[1] += o[1];
    x[2] += o[2];
    return *this;
  }
};

inline double Dot(const Vec3& a, const Vec3& b)
{
  return a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
}

inline Vec3 Cross(const Vec3& a, const Vec3& b)
{
  return { a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0] };
}

inline double Norm(const Vec3& a)
{
  return std::sqrt(Dot(a, a));
}

inline Vec3 Normalized(const Vec3& a)
{
  const double n = Norm(a);
  return n > 0.0 ? a * (1.0 / n) : a;
}

/// A closed axis-aligned box [lo, hi]. Degenerate boxes (lo == hi on some
/// axes) describe cell faces and edges.
struct Box3
{
  Vec3 lo;
  Vec3 hi;

  Vec3 Center() const { return (lo + hi) * 0.5; }
  double Width(int axis) const { return hi[axis] - lo[axis]; }
  double Diagonal() const { return Norm(hi - lo); }
  /// The largest absolute coordinate of its corners (the scale of rounding
  /// errors in computations on points in it).
  double Magnitude() const
  {
    double m = 0.0;
    for (int a = 0; a < 3; ++a)
    {
      m = std::max({ m, std::fabs(lo[a]), std::fabs(hi[a]) });
    }
    return m;
  }
  /// The box grown on every side by `fraction` of its diagonal.
  Box3 Grown(double fraction) const
  {
    const double margin = fraction * this->Diagonal();
    Box3 b = *this;
    for (int a = 0; a < 3; ++a)
    {
      b.lo[a] -= margin;
      b.hi[a] += margin;
    }
    return b;
  }
  /// The box shrunk on each side by `fraction` of its width along that axis.
  Box3 Shrunk(double fraction) const
  {
    Box3 b = *this;
    for (int a = 0; a < 3; ++a)
    {
      const double d = fraction * this->Width(a);
      b.lo[a] += d;
      b.hi[a] -= d;
    }
    return b;
  }
  bool Contains(const Vec3& p) const
  {
    for (int a = 0; a < 3; ++a)
    {
      if (p[a] < lo[a] || p[a] > hi[a])
      {
        return false;
      }
    }
    return true;
  }
  /// The closed boxes share at least a point.
  bool Overlaps(const Box3& o) const
  {
    for (int a = 0; a < 3; ++a)
    {
      if (lo[a] > o.hi[a] || o.lo[a] > hi[a])
      {
        return false;
      }
    }
    return true;
  }
  Vec3 Clamp(const Vec3& p) const
  {
    return { std::clamp(p[0], lo[0], hi[0]), std::clamp(p[1], lo[1], hi[1]),
      std::clamp(p[2], lo[2], hi[2]) };
  }
  /// The squared distance from `p` to the box (0 inside).
  double Distance2(const Vec3& p) const
  {
    double sum = 0.0;
    for (int a = 0; a < 3; ++a)
    {
      const double gap = std::max({ 0.0, lo[a] - p[a], p[a] - hi[a] });
      sum += gap * gap;
    }
    return sum;
  }
  /// The segment from `p` to `q` meets the closed box (slabs; in floating
  /// point, so a segment a rounding outside may be said to meet it).
  bool MeetsSegment(const Vec3& p, const Vec3& q) const
  {
    double t0 = 0.0, t1 = 1.0;
    return this->SegmentWithin(p, q, t0, t1);
  }
  /// The part of the segment p + t (q - p), t in [t0, t1] = [0, 1], within
  /// the closed box (Liang-Barsky: the parameters within each slab), in `t0`
  /// and `t1`; false where there is none (then t0 and t1 are undefined).
  bool SegmentWithin(const Vec3& p, const Vec3& q, double& t0, double& t1) const
  {
    t0 = 0.0;
    t1 = 1.0;
    for (int a = 0; a < 3; ++a)
    {
      const double d = q[a] - p[a];
      if (d == 0.0)
      {
        if (p[a] < lo[a] || p[a] > hi[a])
        {
          return false;
        }
        continue;
      }
      double enter = (lo[a] - p[a]) / d, leave = (hi[a] - p[a]) / d;
      if (enter > leave)
      {
        std::swap(enter, leave);
      }
      t0 = std::max(t0, enter);
      t1 = std::min(t1, leave);
    }
    return t0 <= t1;
  }
  /// Corner `c` (bit a of c chooses hi on axis a).
  Vec3 Corner(int c) const
  {
    return { (c & 1) ? hi[0] : lo[0], (c & 2) ? hi[1] : lo[1], (c & 4) ? hi[2] : lo[2] };
  }
};

/// The mean of `count` points (the origin for none).
inline Vec3 MeanOf(const Vec3* points, std::size_t count)
{
  Vec3 sum;
  for (std::size_t i = 0; i < count; ++i)
  {
    sum += points[i];
  }
  return count == 0 ? sum : sum * (1.0 / static_cast<double>(count));
}

/// The box of `count` >= 1 points (their exact minima and maxima).
inline Box3 BoundsOf(const Vec3* points, std::size_t count)
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

/// Splits a box at its midpoint along its non-degenerate axes (8 pieces for a
/// voxel, 4 for a face, 2 for an edge); returns how many pieces were written.
inline int SplitBox(const Box3& box, Box3 pieces[8])
{
  int axes[3], count = 0;
  for (int a = 0; a < 3; ++a)
  {
    if (box.hi[a] > box.lo[a])
    {
      axes[count++] = a;
    }
  }
  for (int piece = 0; piece < (1 << count); ++piece)
  {
    Box3& sub = pieces[piece];
    sub = box;
    for (int k = 0; k < count; ++k)
    {
      const int a = axes[k];
      const double mid = 0.5 * (box.lo[a] + box.hi[a]);
      ((piece >> k) & 1 ? sub.lo[a] : sub.hi[a]) = mid;
    }
  }
  return 1 << count;
}

/// Bounding box of a solid. Unbounded directions hold -inf/+inf.
struct SolidBounds
{
  bool Empty = false; ///< the solid is provably empty
  Box3 Box{ { -HUGE_VAL, -HUGE_VAL, -HUGE_VAL }, { HUGE_VAL, HUGE_VAL, HUGE_VAL } };

  bool Bounded() const
  {
    for (int a = 0; a < 3; ++a)
    {
      if (!std::isfinite(Box.lo[a]) || !std::isfinite(Box.hi[a]))
      {
        return false;
      }
    }
    return true;
  }
  static SolidBounds Everything() { return SolidBounds{}; }
  static SolidBounds Nothing()
  {
    SolidBounds b;
    b.Empty = true;
    return b;
  }
  /// Union: hull of the boxes.
  static SolidBounds Hull(const SolidBounds& a, const SolidBounds& b)
  {
    if (a.Empty)
    {
      return b;
    }
    if (b.Empty)
    {
      return a;
    }
    SolidBounds r;
    for (int i = 0; i < 3; ++i)
    {
      r.Box.lo[i] = std::min(a.Box.lo[i], b.Box.lo[i]);
      r.Box.hi[i] = std::max(a.Box.hi[i], b.Box.hi[i]);
    }
    return r;
  }
  /// Intersection: overlap of the boxes.
  static SolidBounds Overlap(const SolidBounds& a, const SolidBounds& b)
  {
    if (a.Empty || b.Empty)
    {
      return Nothing();
    }
    SolidBounds r;
    for (int i = 0; i < 3; ++i)
    {
      r.Box.lo[i] = std::max(a.Box.lo[i], b.Box.lo[i]);
      r.Box.hi[i] = std::min(a.Box.hi[i], b.Box.hi[i]);
      if (r.Box.lo[i] > r.Box.hi[i])
      {
        return Nothing();
      }
    }
    return r;
  }
};

} // namespace tpc
