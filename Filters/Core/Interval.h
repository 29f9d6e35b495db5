// Interval arithmetic with rigorous outward rounding.
//
// Every operation returns an interval that contains the exact real result for
// all real operands in the input intervals. Rounding is emulated with
// error-free transformations (TwoSum, FMA-based TwoProduct): a bound is moved
// one ulp outward only when the floating-point operation was inexact, so exact
// results (frequent on dyadic lattices: a plane through lattice points gives
// exactly [0, 0]) stay exact. Hand-written rather than taken from Boost.Interval
// because that library switches the FPU rounding mode, which is slow, not
// thread-friendly, and fragile under optimizing compilers; this version is
// deterministic and needs only IEEE-754 round-to-nearest.
//
// The core must be compiled without -ffast-math and with -ffp-contract=off.
#pragma once

#include <algorithm>
#include <cmath>
#include <limits>

namespace tpc
{
namespace rounding
{
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
  return SumError(a, b, s) < 0.0 ? std::nextafter(s, -HUGE_VAL) : s;
}

inline double AddUp(double a, double b)
{
  const double s = a + b;
  if (!std::isfinite(s))
  {
    return std::isnan(s) ? std::numeric_limits<double>::infinity() : s;
  }
  return SumError(a, b, s) > 0.0 ? std::nextafter(s, HUGE_VAL) : s;
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
    // Near underflow the FMA residual is unreliable; widen conservatively.
    return std::nextafter(std::nextafter(p, -HUGE_VAL), -HUGE_VAL);
  }
  return std::fma(a, b, -p) < 0.0 ? std::nextafter(p, -HUGE_VAL) : p;
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
    return std::nextafter(std::nextafter(p, HUGE_VAL), HUGE_VAL);
  }
  return std::fma(a, b, -p) > 0.0 ? std::nextafter(p, HUGE_VAL) : p;
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
  // Fast paths for the frequent sign-definite cases would save little here;
  // the four-product form is simple and always correct.
  const double l1 = rounding::MulDown(a.lo, b.lo), l2 = rounding::MulDown(a.lo, b.hi);
  const double l3 = rounding::MulDown(a.hi, b.lo), l4 = rounding::MulDown(a.hi, b.hi);
  const double h1 = rounding::MulUp(a.lo, b.lo), h2 = rounding::MulUp(a.lo, b.hi);
  const double h3 = rounding::MulUp(a.hi, b.lo), h4 = rounding::MulUp(a.hi, b.hi);
  return { std::min(std::min(l1, l2), std::min(l3, l4)),
    std::max(std::max(h1, h2), std::max(h3, h4)) };
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
