#include "QuadricCellError.h"

#include "Interval.h"

#include <algorithm>
#include <cmath>

namespace tpc
{
namespace
{
/// Distances and squared lengths are computed in floating point; this
/// relative allowance covers their few ulps of rounding many times over.
constexpr double RoundingAllowance = 1.0 + 1e-12;

/// The leaf's quadric with its sign: sigma * f.
Quadric SignedQuadric(const Quadric& q, int sigma)
{
  if (sigma > 0)
  {
    return q;
  }
  std::array<double, 10> a = q.Coefficients();
  for (double& v : a)
  {
    v = -v;
  }
  return Quadric(a);
}

/// Encloses grad f(p) . d (interval arithmetic on exact inputs).
Interval EncloseDirectionalDerivative(const Quadric& q, const Vec3& p, const Vec3& d)
{
  const Box3 point{ p, p };
  return q.EncloseDerivative(point, 0) * Interval(d[0]) + q.EncloseDerivative(point, 1) * Interval(d[1]) +
    q.EncloseDerivative(point, 2) * Interval(d[2]);
}

/// A proven lower bound of grad f . d over the box (affine: its minimum is at
/// a corner). A flat box (a face) repeats corners, harmlessly.
double MinimumRise(const Quadric& q, const Box3& box, const Vec3& d)
{
  double lowest = HUGE_VAL;
  for (int c = 0; c < 8; ++c)
  {
    const Vec3 corner{ (c & 1) ? box.hi[0] : box.lo[0], (c & 2) ? box.hi[1] : box.lo[1],
      (c & 4) ? box.hi[2] : box.lo[2] };
    lowest = std::min(lowest, EncloseDirectionalDerivative(q, corner, d).lo);
  }
  return lowest;
}

/// An upper bound of the spectral norm of A (half the Hessian): the smaller
/// of the largest absolute row sum (the spectral norm of a symmetric matrix is
/// at most its infinity norm) and the Frobenius norm, rounded up.
double CurvatureBound(const Quadric& q)
{
  const auto& c = q.Coefficients();
  // A = [[c0, c3/2, c5/2], [c3/2, c1, c4/2], [c5/2, c4/2, c2]] (halving is exact).
  const double a[3][3] = { { c[0], 0.5 * c[3], 0.5 * c[5] }, { 0.5 * c[3], c[1], 0.5 * c[4] },
    { 0.5 * c[5], 0.5 * c[4], c[2] } };
  double rows = 0.0, frobenius = 0.0;
  for (int i = 0; i < 3; ++i)
  {
    double row = 0.0;
    for (int j = 0; j < 3; ++j)
    {
      row += std::fabs(a[i][j]);
      frobenius += a[i][j] * a[i][j];
    }
    rows = std::max(rows, row);
  }
  return std::min(rows, std::sqrt(frobenius)) * RoundingAllowance;
}

double SquaredNorm(const Vec3& v)
{
  return Dot(v, v);
}

/// Upper bound of |f(p)| (the quadric's enclosure over the point).
double FieldMagnitude(const Quadric& q, const Vec3& p)
{
  return q.Enclose(Box3{ p, p }).Magnitude();
}

/// Squared radius of the smallest ball holding the triangle: half its longest
/// side where the triangle is right or obtuse (or degenerate), else its
/// circumradius.
double SmallestBallRadiusSquared(const Vec3& a, const Vec3& b, const Vec3& c)
{
  const double ab = SquaredNorm(b - a), bc = SquaredNorm(c - b), ca = SquaredNorm(a - c);
  const double longest = std::max({ ab, bc, ca });
  if (2.0 * longest >= ab + bc + ca) // (longest^2 >= sum of the others': not acute)
  {
    return 0.25 * longest;
  }
  const double twiceArea2 = SquaredNorm(Cross(b - a, c - a));
  if (!(twiceArea2 > 0.0))
  {
    return 0.25 * longest;
  }
  // R = |ab| |bc| |ca| / (4 area) = |ab| |bc| |ca| / (2 |(b-a) x (c-a)|).
  return std::min(ab * bc * ca / (4.0 * twiceArea2), 0.25 * (ab + bc + ca));
}

/// The face's rectangle (flat box) of the cell.
Box3 FaceBox(const Box3& cell, int face)
{
  Box3 f = cell;
  const int axis = face / 2;
  (face % 2 ? f.lo : f.hi)[axis] = (face % 2 ? cell.hi : cell.lo)[axis];
  return f;
}
} // namespace

std::optional<QuadricCellError> BoundQuadricCell(const CsgExpressionPtr& cellExpression,
  const CsgExpressionPtr& sceneExpression, const PrimitiveSet& primitives, const Box3& cell, double margin)
{
  if (!cellExpression || !sceneExpression || !(margin > 0.0))
  {
    return std::nullopt;
  }
  const CsgExpression::Node& root = cellExpression->NodeAt(cellExpression->Root());
  if (root.NodeKind != CsgExpression::Node::Kind::Leaf || root.LeafData.Kind != PrimitiveKind::Quadric)
  {
    return std::nullopt; // (cheap exit: the expression pruned to C already has more)
  }
  QuadricCellError bound;
  bound.Cell = cell;
  bound.Margin = margin;
  // (Rounded outward: C+ holds the cell grown by the margin exactly.)
  Box3 grown = cell;
  for (int a = 0; a < 3; ++a)
  {
    grown.lo[a] = std::nextafter(cell.lo[a] - margin, -HUGE_VAL);
    grown.hi[a] = std::nextafter(cell.hi[a] + margin, HUGE_VAL);
  }
  const CsgExpression::Pruned there = CsgExpression::Prune(sceneExpression, grown, primitives);
  if (there.Sign != RegionSign::Mixed)
  {
    return std::nullopt;
  }
  const CsgExpression::Node& leaf = there.Expression->NodeAt(there.Expression->Root());
  if (leaf.NodeKind != CsgExpression::Node::Kind::Leaf || leaf.LeafData.Kind != PrimitiveKind::Quadric)
  {
    return std::nullopt; // another primitive within the margin
  }
  bound.Field = SignedQuadric(primitives.Quadrics[leaf.LeafData.Primitive], leaf.LeafData.Sigma);
  bound.Direction = Normalized(bound.Field.Gradient(cell.Center()));
  bound.Rise = MinimumRise(bound.Field, grown, bound.Direction);
  if (!(bound.Rise > 0.0))
  {
    return std::nullopt;
  }
  bound.Curvature = CurvatureBound(bound.Field);
  for (int face = 0; face < 6; ++face)
  {
    const Box3 rectangle = FaceBox(cell, face);
    if (!bound.Field.Enclose(rectangle).ContainsZero())
    {
      bound.FaceRise[face] = HUGE_VAL; // carries no chord
      continue;
    }
    Vec3 m = bound.Field.Gradient(rectangle.Center());
    m[face / 2] = 0.0;
    const double length = Norm(m);
    bound.FaceDirection[face] = length > 0.0 ? m * (1.0 / length) : Vec3();
    bound.FaceRise[face] = length > 0.0 ? std::max(0.0, MinimumRise(bound.Field, rectangle, bound.FaceDirection[face])) : 0.0;
  }
  return bound;
}

double PredictedCellError(const QuadricCellError& bound)
{
  const Vec3 w = bound.Cell.hi - bound.Cell.lo;
  const double diagonal2 = SquaredNorm(w) * RoundingAllowance;
  double error = bound.Curvature * 0.25 * diagonal2 / bound.Rise;
  for (int face = 0; face < 6; ++face)
  {
    if (bound.FaceRise[face] == HUGE_VAL)
    {
      continue;
    }
    if (!(bound.FaceRise[face] > 0.0))
    {
      return HUGE_VAL;
    }
    const int axis = face / 2;
    const double faceDiagonal2 = (diagonal2 - w[axis] * w[axis]) * RoundingAllowance;
    error = std::max(
      error, bound.Curvature * 0.25 * faceDiagonal2 * (1.0 / bound.Rise + 1.0 / bound.FaceRise[face]));
  }
  return error * RoundingAllowance;
}

double TriangleError(const QuadricCellError& bound, const Vec3& a, const Vec3& b, const Vec3& c)
{
  const double vertices =
    std::max({ FieldMagnitude(bound.Field, a), FieldMagnitude(bound.Field, b), FieldMagnitude(bound.Field, c) });
  const double spread = bound.Curvature * SmallestBallRadiusSquared(a, b, c) * RoundingAllowance;
  return (vertices + spread) / bound.Rise * RoundingAllowance;
}

double ChordError(const QuadricCellError& bound, int face, const Vec3& a, const Vec3& b)
{
  const double rise = bound.FaceRise[face];
  if (!(rise > 0.0) || rise == HUGE_VAL) // (no chord was expected on a face missing S)
  {
    return HUGE_VAL;
  }
  const double ends = std::max(FieldMagnitude(bound.Field, a), FieldMagnitude(bound.Field, b));
  const double sag = bound.Curvature * 0.25 * SquaredNorm(b - a) * RoundingAllowance;
  return (ends + sag) * (1.0 / bound.Rise + 1.0 / rise) * RoundingAllowance;
}

std::optional<Vec3> SurfacePointAlongDirection(const QuadricCellError& bound, const Vec3& p, const Box3& region)
{
  // The stretch of the line p + t n inside the region.
  double t0 = -HUGE_VAL, t1 = HUGE_VAL;
  for (int a = 0; a < 3; ++a)
  {
    const double d = bound.Direction[a];
    if (d == 0.0)
    {
      if (p[a] <= region.lo[a] || p[a] >= region.hi[a])
      {
        return std::nullopt;
      }
      continue;
    }
    const double s0 = (region.lo[a] - p[a]) / d, s1 = (region.hi[a] - p[a]) / d;
    t0 = std::max(t0, std::min(s0, s1));
    t1 = std::min(t1, std::max(s0, s1));
  }
  if (!(t0 < t1))
  {
    return std::nullopt;
  }
  // f increases along n: the root, if any, is where the exact sign changes.
  double lo = t0, hi = t1;
  if (bound.Field.ExactSign(p + bound.Direction * lo) >= 0 || bound.Field.ExactSign(p + bound.Direction * hi) <= 0)
  {
    return std::nullopt;
  }
  for (int i = 0; i < 80 && hi - lo > 0.0; ++i)
  {
    const double mid = 0.5 * (lo + hi);
    if (mid <= lo || mid >= hi)
    {
      break;
    }
    (bound.Field.ExactSign(p + bound.Direction * mid) < 0 ? lo : hi) = mid;
  }
  return p + bound.Direction * (0.5 * (lo + hi));
}

} // namespace tpc
