// Exact geometric predicates on double coordinates: the sign of 2-D and 3-D
// orientation determinants. A floating-point filter, then an interval
// evaluation, decide almost always; when they cannot, the determinant is
// expanded into products of coordinates (2-D) or of the differences' rounded
// values and rounding errors (3-D) and summed exactly (ExactSum.h). These decide every inside/outside and
// crossing question about meshes, so two cells asking about the same point
// or segment always get the same answer.
#pragma once

#include "Vector3.h"

#include <cfloat>
#include <cmath>

namespace tpc
{

namespace predicates
{
// Floating-point filters with Shewchuk's a-priori error bounds ("Adaptive
// Precision Floating-Point Arithmetic and Fast Robust Geometric Predicates",
// 1997, the bounds ccwerrboundA and o3derrboundA): when |det| exceeds the
// bound, its sign is exact. Several times cheaper than the interval filter
// (no rounding-mode arithmetic), which stays as the second stage. Products
// below MinimumMagnitude could have underflowed: those go to the next stage.
constexpr double Epsilon = 1.1102230246251565e-16; // 2^-53
constexpr double Orient2DBound = (3.0 + 16.0 * Epsilon) * Epsilon;
constexpr double Orient3DBound = (7.0 + 56.0 * Epsilon) * Epsilon;
constexpr double MinimumMagnitude = 1e-200;

/// Orient2D where its filter cannot decide: the interval, then the exact
/// stage.
int Orient2DBeyondFilter(double au, double av, double bu, double bv, double cu, double cv);

/// Orient3D where its filter cannot decide.
int Orient3DBeyondFilter(const Vec3& a, const Vec3& b, const Vec3& c, const Vec3& d);

/// The filter of a 3 x 3 determinant with rows (ax, ay, az), (bx, by, bz),
/// (cx, cy, cz): its sign, or 0 where the filter cannot decide.
inline int FilteredDeterminantSign(
  double ax, double ay, double az, double bx, double by, double bz, double cx, double cy, double cz)
{
  const double bxcy = bx * cy, cxby = cx * by, cxay = cx * ay, axcy = ax * cy, axby = ax * by, bxay = bx * ay;
  const double det = az * (bxcy - cxby) + bz * (cxay - axcy) + cz * (axby - bxay);
  const double permanent = (std::abs(bxcy) + std::abs(cxby)) * std::abs(az) +
    (std::abs(cxay) + std::abs(axcy)) * std::abs(bz) + (std::abs(axby) + std::abs(bxay)) * std::abs(cz);
  if (!(permanent >= MinimumMagnitude && permanent <= DBL_MAX)) // (a NaN, infinite, or may have underflowed)
  {
    return 0;
  }
  const double bound = Orient3DBound * permanent;
  return det > bound ? 1 : det < -bound ? -1 : 0;
}
} // namespace predicates

/// Sign of (b - a) x (c - a) for 2-D points given by (u, v) pairs:
/// +1 counter-clockwise, -1 clockwise, 0 collinear. The filter, on
/// (a - c) x (b - c), the same determinant, inline: it decides almost every
/// call, which then costs no call (the predicate is called from most of the
/// core's tests: 3.5 % of the turbine's instructions at 1/64 went to it).
inline int Orient2D(double au, double av, double bu, double bv, double cu, double cv)
{
  const double left = (au - cu) * (bv - cv), right = (av - cv) * (bu - cu);
  const double det = left - right;
  const double sum = std::abs(left) + std::abs(right);
  if (sum >= predicates::MinimumMagnitude && sum <= DBL_MAX) // (not a NaN, finite)
  {
    const double bound = predicates::Orient2DBound * sum;
    if (det > bound)
    {
      return 1;
    }
    if (det < -bound)
    {
      return -1;
    }
  }
  return predicates::Orient2DBeyondFilter(au, av, bu, bv, cu, cv);
}

/// Sign of det[a - d, b - d, c - d] = n . (a - d) with n = (b - a) x (c - a):
/// +1 when d is on the side opposite to n (behind the triangle a, b, c),
/// -1 in front, 0 coplanar. The filter inline, as Orient2D's (Orient3D was
/// 2.7 % of the turbine's instructions at 1/64, its out-of-line stages
/// another 2.5 %).
inline int Orient3D(const Vec3& a, const Vec3& b, const Vec3& c, const Vec3& d)
{
  const int filtered = predicates::FilteredDeterminantSign(a[0] - d[0], a[1] - d[1], a[2] - d[2], b[0] - d[0],
    b[1] - d[1], b[2] - d[2], c[0] - d[0], c[1] - d[1], c[2] - d[2]);
  return filtered ? filtered : predicates::Orient3DBeyondFilter(a, b, c, d);
}

/// Sign of n . u with n = (b - a) x (c - a): which way the triangle faces
/// relative to the direction u.
int FacingSign(const Vec3& a, const Vec3& b, const Vec3& c, const Vec3& u);

} // namespace tpc
