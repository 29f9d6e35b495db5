// Interval arithmetic with rigorous outward rounding.
//
// Every operation returns an interval that contains the exact real result for
// all real operands in the input intervals. Rounding is emulated with
// error-free transformations (TwoSum; FMA TwoProduct where the compiler
// targets FMA): a bound is moved one ulp outward only when the operation may
// have been inexact, so exact results (a plane through lattice points gives
// exactly [0, 0]) stay exact. Hand-written rather than taken from Boost.Interval
// because that library switches the FPU rounding mode, which is slow, not
// thread-friendly, and fragile under optimizing compilers; this version is
// deterministic and needs only IEEE-754 round-to-nearest.
//
// The core must be compiled without -ffast-math and with -ffp-contract=off.
#pragma once

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <limits>

namespace tpc
{
namespace rounding
{
/// The neighbouring doubles of a finite x, by stepping its bit pattern
/// (std::nextafter is a library call, too slow for the inner loops).
inline double NextUp(double x)
{
  if (x == 0.0)
  {
    return std::numeric_limits<double>::denorm_min();
  }
  std::uint64_t bits;
  std::memcpy(&bits, &x, sizeof bits);
  bits = x > 0.0 ? bits + 1 : bits - 1;
  std::memcpy(&x, &bits, sizeof bits);
  return x;
}

inline double NextDown(double x)
{
  return -NextUp(-x);
}

/// Exact error of a + b (a + b == s + err), Knuth's TwoSum.
inline double SumError(double a, double b, double s)
{
  const double bb = s - a;
  return (a - (s - bb)) + (b - bb);
}

inline double AddDown(double a, double b)
{
  const double s = a + b;
  if (!std::isfinite(s))
  {
    return std::isnan(s) ? -std::numeric_limits<double>::infinity() : s;
  }
  return SumError(a, b, s) < 0.0 ? NextDown(s) : s;
}

inline double AddUp(double a, double b)
{
  const double s = a + b;
  if (!std::isfinite(s))
  {
    return std::isnan(s) ? std::numeric_limits<double>::infinity() : s;
  }
  return SumError(a, b, s) > 0.0 ? NextUp(s) : s;
}

/// Sign of the rounding error of p = fl(a * b): +1 if the exact product is
/// larger, -1 if smaller, 0 if exact; 2 when it cannot be told cheaply (then
/// both bounds are widened). With FMA hardware this is exact; otherwise
/// products by a power of two (axis-aligned planes, halvings) are known exact.
inline int ProductError(double a, double b, double p)
{
#if defined(__FMA__)
  const double e = __builtin_fma(a, b, -p);
  return e > 0.0 ? 1 : (e < 0.0 ? -1 : 0);
#else
  (void)p;
  std::uint64_t ba, bb;
  std::memcpy(&ba, &a, sizeof ba);
  std::memcpy(&bb, &b, sizeof bb);
  const std::uint64_t mantissa = (std::uint64_t(1) << 52) - 1;
  return ((ba & mantissa) == 0 || (bb & mantissa) == 0) ? 0 : 2;
#endif
}

inline double MulDown(double a, double b)
{
  const double p = a * b;
  if (!std::isfinite(p))
  {
    return std::isnan(p) ? -std::numeric_limits<double>::infinity() : p;
  }
  if (a == 0.0 || b == 0.0)
  {
    return 0.0; // exact: keeps [0, 0] exact
  }
  if (std::fabs(p) < 1e-290)
  {
    // Near underflow the error terms are unreliable; widen conservatively.
    return NextDown(NextDown(p));
  }
  const int e = ProductError(a, b, p);
  return e == -1 || e == 2 ? NextDown(p) : p;
}

inline double MulUp(double a, double b)
{
  const double p = a * b;
  if (!std::isfinite(p))
  {
    return std::isnan(p) ? std::numeric_limits<double>::infinity() : p;
  }
  if (a == 0.0 || b == 0.0)
  {
    return 0.0;
  }
  if (std::fabs(p) < 1e-290)
  {
    return NextUp(NextUp(p));
  }
  const int e = ProductError(a, b, p);
  return e == 1 || e == 2 ? NextUp(p) : p;
}
} // namespace rounding

struct Interval
{
  double lo = 0.0;
  double hi = 0.0;

  constexpr Interval() = default;
  constexpr Interval(double v)
    : lo(v)
    , hi(v)
  {
  }
  constexpr Interval(double l, double h)
    : lo(l)
    , hi(h)
  {
  }

  bool Contains(double v) const { return lo <= v && v <= hi; }
  bool ContainsZero() const { return lo <= 0.0 && 0.0 <= hi; }
  double Width() const { return hi - lo; }
  /// Largest magnitude of a member.
  double Magnitude() const { return std::max(std::fabs(lo), std::fabs(hi)); }
};

inline Interval operator+(const Interval& a, const Interval& b)
{
  return { rounding::AddDown(a.lo, b.lo), rounding::AddUp(a.hi, b.hi) };
}

inline Interval operator-(const Interval& a)
{
  return { -a.hi, -a.lo };
}

inline Interval operator-(const Interval& a, const Interval& b)
{
  return { rounding::AddDown(a.lo, -b.hi), rounding::AddUp(a.hi, -b.lo) };
}

inline Interval operator*(const Interval& a, const Interval& b)
{
  using rounding::MulDown;
  using rounding::MulUp;
  // The nine sign cases: two rounded products each, except when both straddle zero.
  if (a.lo >= 0.0)
  {
    if (b.lo >= 0.0)
    {
      return { MulDown(a.lo, b.lo), MulUp(a.hi, b.hi) };
    }
    if (b.hi <= 0.0)
    {
      return { MulDown(a.hi, b.lo), MulUp(a.lo, b.hi) };
    }
    return { MulDown(a.hi, b.lo), MulUp(a.hi, b.hi) };
  }
  if (a.hi <= 0.0)
  {
    if (b.lo >= 0.0)
    {
      return { MulDown(a.lo, b.hi), MulUp(a.hi, b.lo) };
    }
    if (b.hi <= 0.0)
    {
      return { MulDown(a.hi, b.hi), MulUp(a.lo, b.lo) };
    }
    return { MulDown(a.lo, b.hi), MulUp(a.lo, b.lo) };
  }
  if (b.lo >= 0.0)
  {
    return { MulDown(a.lo, b.hi), MulUp(a.hi, b.hi) };
  }
  if (b.hi <= 0.0)
  {
    return { MulDown(a.hi, b.lo), MulUp(a.lo, b.lo) };
  }
  return { std::min(MulDown(a.lo, b.hi), MulDown(a.hi, b.lo)),
    std::max(MulUp(a.lo, b.lo), MulUp(a.hi, b.hi)) };
}

inline Interval& operator+=(Interval& a, const Interval& b)
{
  a = a + b;
  return a;
}

/// Range of x*x for x in a (tighter than a*a when a straddles zero).
inline Interval Square(const Interval& a)
{
  if (a.lo >= 0.0)
  {
    return { rounding::MulDown(a.lo, a.lo), rounding::MulUp(a.hi, a.hi) };
  }
  if (a.hi <= 0.0)
  {
    return { rounding::MulDown(a.hi, a.hi), rounding::MulUp(a.lo, a.lo) };
  }
  const double m = std::max(-a.lo, a.hi);
  return { 0.0, rounding::MulUp(m, m) };
}

inline Interval Hull(const Interval& a, const Interval& b)
{
  return { std::min(a.lo, b.lo), std::max(a.hi, b.hi) };
}

inline Interval Min(const Interval& a, const Interval& b)
{
  return { std::min(a.lo, b.lo), std::min(a.hi, b.hi) };
}

inline Interval Max(const Interval& a, const Interval& b)
{
  return { std::max(a.lo, b.lo), std::max(a.hi, b.hi) };
}

} // namespace tpc
