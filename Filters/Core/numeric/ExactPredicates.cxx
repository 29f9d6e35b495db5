#include "ExactPredicates.h"

#include "ExactSum.h"
#include "Interval.h"

#include <cmath>

namespace tpc
{
namespace
{
/// A matrix entry x - y (y = 0 for a plain value).
struct Difference
{
  double X, Y;
};

/// Exact sign of the 3x3 determinant of differences where the floating-point
/// filter (predicates::FilteredDeterminantSign) could not decide: an
/// interval filter, then the exact sum.
int SignOfDeterminantBeyondFilter(const Difference m[3][3])
{
  static const int perms[6][3] = { { 0, 1, 2 }, { 1, 2, 0 }, { 2, 0, 1 }, { 0, 2, 1 }, { 2, 1, 0 },
    { 1, 0, 2 } };
  static const int parity[6] = { 1, 1, 1, -1, -1, -1 };
  Interval det(0.0);
  for (int p = 0; p < 6; ++p)
  {
    Interval term(static_cast<double>(parity[p]));
    for (int r = 0; r < 3; ++r)
    {
      const Difference& d = m[r][perms[p][r]];
      term = term * (Interval(d.X) - Interval(d.Y));
    }
    det += term;
  }
  if (det.lo > 0.0)
  {
    return 1;
  }
  if (det.hi < 0.0)
  {
    return -1;
  }
  if (det.lo == 0.0 && det.hi == 0.0)
  {
    return 0;
  }
  // Each difference x - y as its rounded value plus its exact rounding
  // error (TwoSum: x - y == head + tail exactly); the determinant is linear in
  // each entry, so each product of three differences expands into eight
  // products of heads and tails, every one of them summed exactly. Nearby
  // coordinates subtract exactly (Sterbenz): their tails are zero and drop
  // out, which leaves one product per permutation instead of eight (the
  // exact stage runs on coplanar pieces of flat faces, a few per cent of a
  // run on a CAD part).
  double head[3][3], tail[3][3];
  for (int r = 0; r < 3; ++r)
  {
    for (int c = 0; c < 3; ++c)
    {
      head[r][c] = m[r][c].X - m[r][c].Y;
      tail[r][c] = rounding::SumError(m[r][c].X, -m[r][c].Y, head[r][c]);
    }
  }
  ExactSum sum;
  for (int p = 0; p < 6; ++p)
  {
    const int c0 = perms[p][0], c1 = perms[p][1], c2 = perms[p][2];
    for (int choice = 0; choice < 8; ++choice)
    {
      const double f0 = (choice & 1) ? tail[0][c0] : head[0][c0];
      const double f1 = (choice & 2) ? tail[1][c1] : head[1][c1];
      const double f2 = (choice & 4) ? tail[2][c2] : head[2][c2];
      if (f0 != 0.0 && f1 != 0.0 && f2 != 0.0)
      {
        sum.AddProduct(parity[p] * f0, f1, f2);
      }
    }
  }
  return sum.Sign();
}

/// Exact sign of the 3x3 determinant of differences.
int SignOfDeterminant(const Difference m[3][3])
{
  const auto value = [&](int r, int c) { return m[r][c].X - m[r][c].Y; };
  const int filtered = predicates::FilteredDeterminantSign(
    value(0, 0), value(0, 1), value(0, 2), value(1, 0), value(1, 1), value(1, 2), value(2, 0), value(2, 1), value(2, 2));
  return filtered ? filtered : SignOfDeterminantBeyondFilter(m);
}
} // namespace

int predicates::Orient2DBeyondFilter(double au, double av, double bu, double bv, double cu, double cv)
{
  const Interval det = (Interval(bu) - Interval(au)) * (Interval(cv) - Interval(av)) -
    (Interval(bv) - Interval(av)) * (Interval(cu) - Interval(au));
  if (det.lo > 0.0)
  {
    return 1;
  }
  if (det.hi < 0.0)
  {
    return -1;
  }
  if (det.lo == 0.0 && det.hi == 0.0)
  {
    return 0;
  }
  // (bu - au)(cv - av) - (bv - av)(cu - au); the au*av terms cancel.
  ExactSum sum;
  sum.AddProduct(bu, cv);
  sum.AddProduct(-bu, av);
  sum.AddProduct(-au, cv);
  sum.AddProduct(-bv, cu);
  sum.AddProduct(bv, au);
  sum.AddProduct(av, cu);
  return sum.Sign();
}

int predicates::Orient3DBeyondFilter(const Vec3& a, const Vec3& b, const Vec3& c, const Vec3& d)
{
  // Four points in one axis plane (faces of cells, axis-aligned faces of CAD
  // parts) are coplanar: the determinant is exactly zero, which the filters
  // cannot certify and the exact stage would compute at length.
  for (int k = 0; k < 3; ++k)
  {
    if (a[k] == d[k] && b[k] == d[k] && c[k] == d[k])
    {
      return 0;
    }
  }
  const Difference m[3][3] = { { { a[0], d[0] }, { a[1], d[1] }, { a[2], d[2] } },
    { { b[0], d[0] }, { b[1], d[1] }, { b[2], d[2] } },
    { { c[0], d[0] }, { c[1], d[1] }, { c[2], d[2] } } };
  return SignOfDeterminantBeyondFilter(m); // (the inline filter could not decide)
}

int FacingSign(const Vec3& a, const Vec3& b, const Vec3& c, const Vec3& u)
{
  // n . u = det[b - a, c - a, u]
  const Difference m[3][3] = { { { b[0], a[0] }, { b[1], a[1] }, { b[2], a[2] } },
    { { c[0], a[0] }, { c[1], a[1] }, { c[2], a[2] } },
    { { u[0], 0.0 }, { u[1], 0.0 }, { u[2], 0.0 } } };
  return SignOfDeterminant(m);
}

} // namespace tpc
