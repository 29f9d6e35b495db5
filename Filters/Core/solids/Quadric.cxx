#include "Quadric.h"

#include "ExactSum.h"

#include <cmath>

namespace tpc
{
namespace
{
// Symmetric 3x3 matrix of the quadratic part, b and c of f = x'Ax + b'x + c.
struct QuadraticForm
{
  double A[3][3];
  double b[3];
  double c;
};

QuadraticForm ToForm(const std::array<double, 10>& a)
{
  QuadraticForm q;
  q.A[0][0] = a[0];
  q.A[1][1] = a[1];
  q.A[2][2] = a[2];
  q.A[0][1] = q.A[1][0] = 0.5 * a[3];
  q.A[1][2] = q.A[2][1] = 0.5 * a[4];
  q.A[0][2] = q.A[2][0] = 0.5 * a[5];
  q.b[0] = a[6];
  q.b[1] = a[7];
  q.b[2] = a[8];
  q.c = a[9];
  return q;
}

std::array<double, 10> FromForm(const QuadraticForm& q)
{
  return { q.A[0][0], q.A[1][1], q.A[2][2], 2.0 * q.A[0][1], 2.0 * q.A[1][2], 2.0 * q.A[0][2],
    q.b[0], q.b[1], q.b[2], q.c };
}

double Determinant(const double m[3][3])
{
  return m[0][0] * (m[1][1] * m[2][2] - m[1][2] * m[2][1]) -
    m[0][1] * (m[1][0] * m[2][2] - m[1][2] * m[2][0]) +
    m[0][2] * (m[1][0] * m[2][1] - m[1][1] * m[2][0]);
}

bool Invert(const double m[3][3], double inv[3][3])
{
  const double det = Determinant(m);
  double scale = 0.0;
  for (int i = 0; i < 3; ++i)
  {
    for (int j = 0; j < 3; ++j)
    {
      scale = std::max(scale, std::fabs(m[i][j]));
    }
  }
  if (scale == 0.0 || std::fabs(det) <= 1e-14 * scale * scale * scale)
  {
    return false;
  }
  inv[0][0] = (m[1][1] * m[2][2] - m[1][2] * m[2][1]) / det;
  inv[0][1] = (m[0][2] * m[2][1] - m[0][1] * m[2][2]) / det;
  inv[0][2] = (m[0][1] * m[1][2] - m[0][2] * m[1][1]) / det;
  inv[1][0] = (m[1][2] * m[2][0] - m[1][0] * m[2][2]) / det;
  inv[1][1] = (m[0][0] * m[2][2] - m[0][2] * m[2][0]) / det;
  inv[1][2] = (m[0][2] * m[1][0] - m[0][0] * m[1][2]) / det;
  inv[2][0] = (m[1][0] * m[2][1] - m[1][1] * m[2][0]) / det;
  inv[2][1] = (m[0][1] * m[2][0] - m[0][0] * m[2][1]) / det;
  inv[2][2] = (m[0][0] * m[1][1] - m[0][1] * m[1][0]) / det;
  return true;
}

bool PositiveDefinite(const double m[3][3])
{
  const double m2 = m[0][0] * m[1][1] - m[0][1] * m[1][0];
  return m[0][0] > 0.0 && m2 > 0.0 && Determinant(m) > 0.0;
}
} // namespace

// ---------------------------------------------------------------------------
Interval IntervalQuadric::EncloseAt(const Vec3& p) const
{
  const Interval x(p[0]), y(p[1]), z(p[2]);
  return (A[0] * x + A[3] * y + A[5] * z + A[6]) * x + (A[1] * y + A[4] * z + A[7]) * y +
    (A[2] * z + A[8]) * z + A[9];
}

Interval IntervalQuadric::EncloseTaylor(const Vec3& p, const Interval d[3]) const
{
  const Interval px(p[0]), py(p[1]), pz(p[2]);
  const Interval two(2.0);
  const Interval g0 = two * A[0] * px + A[3] * py + A[5] * pz + A[6];
  const Interval g1 = A[3] * px + two * A[1] * py + A[4] * pz + A[7];
  const Interval g2 = A[5] * px + A[4] * py + two * A[2] * pz + A[8];
  return this->EncloseAt(p) + g0 * d[0] + g1 * d[1] + g2 * d[2] + A[0] * Square(d[0]) + A[1] * Square(d[1]) +
    A[2] * Square(d[2]) + A[3] * (d[0] * d[1]) + A[4] * (d[1] * d[2]) + A[5] * (d[0] * d[2]);
}

Interval IntervalQuadric::Enclose(const Box3& box) const
{
  const Vec3 c = box.Center();
  Interval d[3];
  for (int i = 0; i < 3; ++i)
  {
    const double r = std::max(rounding::AddUp(c[i], -box.lo[i]), rounding::AddUp(box.hi[i], -c[i]));
    d[i] = Interval(-r, r);
  }
  // Centred form: f(c + d) with |d_i| <= r_i.
  const Interval taylor = this->EncloseTaylor(c, d);

  if (taylor.lo >= 0.0 || taylor.hi < 0.0)
  {
    return taylor; // decides the sign already: the only question callers ask
  }
  // Natural extension: better than the centred form on large boxes.
  const Interval x(box.lo[0], box.hi[0]), y(box.lo[1], box.hi[1]), z(box.lo[2], box.hi[2]);
  const Interval natural = A[0] * Square(x) + A[1] * Square(y) + A[2] * Square(z) +
    A[3] * (x * y) + A[4] * (y * z) + A[5] * (x * z) + A[6] * x + A[7] * y + A[8] * z + A[9];

  Interval best{ std::max(taylor.lo, natural.lo), std::min(taylor.hi, natural.hi) };
  if (best.lo >= 0.0 || best.hi < 0.0)
  {
    return best;
  }
  // Centred at the quadric's own centre m (where its gradient vanishes):
  // f(m + d) = f(m) + g(m).d + d'Qd, d ranging over the box minus m - not
  // symmetric, so a sphere's f = |d|^2 - r^2 is enclosed exactly up to
  // rounding. Both forms above lose ~ width^2 against a sphere's value
  // where it passes close to a box (near contacts, LoopsSeparated): the
  // difference between proving a gap of 1e-9 and not. Any m is valid; the
  // centre (from the coefficients' midpoints) only makes it tight.
  double q[3][3], inverse[3][3];
  const int offDiagonal[3][3] = { { 0, 3, 5 }, { 3, 1, 4 }, { 5, 4, 2 } };
  for (int i = 0; i < 3; ++i)
  {
    for (int j = 0; j < 3; ++j)
    {
      const Interval& a = A[offDiagonal[i][j]];
      q[i][j] = (i == j ? 2.0 : 1.0) * 0.5 * (a.lo + a.hi);
    }
  }
  if (!Invert(q, inverse))
  {
    return best;
  }
  Vec3 m;
  for (int i = 0; i < 3; ++i)
  {
    m[i] = 0.0;
    for (int j = 0; j < 3; ++j)
    {
      m[i] -= inverse[i][j] * 0.5 * (A[6 + j].lo + A[6 + j].hi);
    }
  }
  const Interval e[3] = { Interval(box.lo[0], box.hi[0]) - Interval(m[0]),
    Interval(box.lo[1], box.hi[1]) - Interval(m[1]), Interval(box.lo[2], box.hi[2]) - Interval(m[2]) };
  const Interval centred = this->EncloseTaylor(m, e);
  return { std::max(best.lo, centred.lo), std::min(best.hi, centred.hi) };
}

// ---------------------------------------------------------------------------
Quadric Quadric::Sphere(const Vec3& center, double radius)
{
  return Quadric({ 1, 1, 1, 0, 0, 0, -2 * center[0], -2 * center[1], -2 * center[2],
    Dot(center, center) - radius * radius });
}

Quadric Quadric::Plane(const Vec3& origin, const Vec3& normal)
{
  return Quadric({ 0, 0, 0, 0, 0, 0, normal[0], normal[1], normal[2], -Dot(normal, origin) });
}

Quadric Quadric::Cylinder(const Vec3& center, const Vec3& axis, double radius)
{
  const Vec3 u = Normalized(axis);
  QuadraticForm q{};
  for (int i = 0; i < 3; ++i)
  {
    for (int j = 0; j < 3; ++j)
    {
      q.A[i][j] = (i == j ? 1.0 : 0.0) - u[i] * u[j];
    }
  }
  double cAc = 0.0;
  for (int i = 0; i < 3; ++i)
  {
    double Ac = 0.0;
    for (int j = 0; j < 3; ++j)
    {
      Ac += q.A[i][j] * center[j];
    }
    q.b[i] = -2.0 * Ac;
    cAc += center[i] * Ac;
  }
  q.c = cAc - radius * radius;
  return Quadric(FromForm(q));
}

Quadric Quadric::Ellipsoid(const Vec3& center, const Vec3& semiAxes)
{
  std::array<double, 10> a{};
  for (int i = 0; i < 3; ++i)
  {
    const double w = 1.0 / (semiAxes[i] * semiAxes[i]);
    a[i] = w;
    a[6 + i] = -2.0 * w * center[i];
    a[9] += w * center[i] * center[i];
  }
  a[9] -= 1.0;
  return Quadric(a);
}

Quadric Quadric::Composed(const double m[16]) const
{
  const QuadraticForm q = ToForm(this->A);
  double L[3][3], t[3];
  for (int i = 0; i < 3; ++i)
  {
    for (int j = 0; j < 3; ++j)
    {
      L[i][j] = m[4 * i + j];
    }
    t[i] = m[4 * i + 3];
  }
  QuadraticForm r{};
  // A' = L^T A L
  double AL[3][3];
  for (int i = 0; i < 3; ++i)
  {
    for (int j = 0; j < 3; ++j)
    {
      AL[i][j] = q.A[i][0] * L[0][j] + q.A[i][1] * L[1][j] + q.A[i][2] * L[2][j];
    }
  }
  for (int i = 0; i < 3; ++i)
  {
    for (int j = 0; j < 3; ++j)
    {
      r.A[i][j] = L[0][i] * AL[0][j] + L[1][i] * AL[1][j] + L[2][i] * AL[2][j];
    }
  }
  // b' = L^T (2 A t + b),  c' = t'At + b't + c
  double At[3];
  for (int i = 0; i < 3; ++i)
  {
    At[i] = q.A[i][0] * t[0] + q.A[i][1] * t[1] + q.A[i][2] * t[2];
  }
  for (int j = 0; j < 3; ++j)
  {
    r.b[j] = 0.0;
    for (int i = 0; i < 3; ++i)
    {
      r.b[j] += L[i][j] * (2.0 * At[i] + q.b[i]);
    }
  }
  r.c = q.c;
  for (int i = 0; i < 3; ++i)
  {
    r.c += t[i] * At[i] + q.b[i] * t[i];
  }
  // Keep exact symmetry of the result.
  for (int i = 0; i < 3; ++i)
  {
    for (int j = i + 1; j < 3; ++j)
    {
      const double s = 0.5 * (r.A[i][j] + r.A[j][i]);
      r.A[i][j] = r.A[j][i] = s;
    }
  }
  return Quadric(FromForm(r));
}

Quadric Quadric::Scaled(double s) const
{
  std::array<double, 10> a = this->A;
  for (double& v : a)
  {
    v *= s;
  }
  return Quadric(a);
}

double Quadric::Value(const Vec3& p) const
{
  const double x = p[0], y = p[1], z = p[2];
  const auto& a = this->A;
  return (a[0] * x + a[3] * y + a[5] * z + a[6]) * x + (a[1] * y + a[4] * z + a[7]) * y +
    (a[2] * z + a[8]) * z + a[9];
}

Vec3 Quadric::Gradient(const Vec3& p) const
{
  const double x = p[0], y = p[1], z = p[2];
  const auto& a = this->A;
  return { 2 * a[0] * x + a[3] * y + a[5] * z + a[6], a[3] * x + 2 * a[1] * y + a[4] * z + a[7],
    a[5] * x + a[4] * y + 2 * a[2] * z + a[8] };
}

IntervalQuadric Quadric::AsInterval() const
{
  IntervalQuadric q;
  for (int i = 0; i < 10; ++i)
  {
    q.A[i] = Interval(this->A[i]);
  }
  return q;
}

namespace
{
/// Where the floating-point sign tests below may be trusted: the relative
/// rounding bound holds while no rounding is subnormal, and a subnormal
/// rounding (absolute, below 2.5e-324) scaled by at most two factors of
/// magnitude 1e30 stays under 4e-14 of any M above 1e-200. Coordinates,
/// radii or M outside that: the interval forms decide.
constexpr double LargestTrustedCoordinate = 1e30;
constexpr double SmallestTrustedMagnitude = 1e-200;

/// The form with coefficients `a` at (x, y, z), in floating point. Over the
/// coefficients' and coordinates' absolute values it gives the magnitude
/// M: the computed f is within gamma_12 < 1.4e-15 M of the exact value (at
/// most 12 roundings along any path; Higham, Accuracy and Stability of
/// Numerical Algorithms, 3.1), while no rounding is subnormal.
double EvaluateForm(const std::array<double, 10>& a, double x, double y, double z)
{
  return (a[0] * x + a[3] * y + a[5] * z + a[6]) * x + (a[1] * y + a[4] * z + a[7]) * y + (a[2] * z + a[8]) * z +
    a[9];
}

std::array<double, 10> AbsoluteValues(const std::array<double, 10>& a)
{
  std::array<double, 10> absolute;
  for (int i = 0; i < 10; ++i)
  {
    absolute[i] = std::fabs(a[i]);
  }
  return absolute;
}

/// The sign of the form at p where floating point proves it: f beyond 4e-14
/// of its magnitude (ample over gamma_12, EvaluateForm), in the trusted
/// range; 0 where it proves nothing.
int ProvenSign(const std::array<double, 10>& a, const Vec3& p)
{
  const double ax = std::fabs(p[0]), ay = std::fabs(p[1]), az = std::fabs(p[2]);
  if (!(ax <= LargestTrustedCoordinate && ay <= LargestTrustedCoordinate && az <= LargestTrustedCoordinate))
  {
    return 0;
  }
  const double f = EvaluateForm(a, p[0], p[1], p[2]);
  const double magnitude = EvaluateForm(AbsoluteValues(a), ax, ay, az);
  const double error = 4e-14 * magnitude;
  if (!std::isfinite(f) || !(magnitude > SmallestTrustedMagnitude))
  {
    return 0;
  }
  return f > error ? 1 : (f < -error ? -1 : 0);
}
} // namespace

int Quadric::ExactSign(const Vec3& p) const
{
  // First f in floating point against its rounding bound (ProvenSign): a
  // proven sign is the exact sign. Most points are far from the surface
  // relative to the rounding, and this is a few dozen flops where the
  // interval form below is ten interval products (the loops' separation
  // tests sign every crossing this way: a third of the plate of 100
  // ellipsoids' run at a tolerance of one diagonal).
  if (const int proven = ProvenSign(this->A, p))
  {
    return proven;
  }
  const Interval v = this->AsInterval().EncloseAt(p);
  if (v.lo > 0.0)
  {
    return 1;
  }
  if (v.hi < 0.0)
  {
    return -1;
  }
  if (v.lo == 0.0 && v.hi == 0.0)
  {
    return 0;
  }
  const auto& a = this->A;
  const double x = p[0], y = p[1], z = p[2];
  ExactSum s;
  s.AddProduct(a[0], x, x);
  s.AddProduct(a[1], y, y);
  s.AddProduct(a[2], z, z);
  s.AddProduct(a[3], x, y);
  s.AddProduct(a[4], y, z);
  s.AddProduct(a[5], x, z);
  s.AddProduct(a[6], x);
  s.AddProduct(a[7], y);
  s.AddProduct(a[8], z);
  s.Add(a[9]);
  return s.Sign();
}

Interval Quadric::Enclose(const Box3& box) const
{
  return this->AsInterval().Enclose(box);
}


bool Quadric::ChangesSignOn(const Box3& box) const
{
  for (int i = 0; i < 3; ++i)
  {
    if (!(std::fabs(box.lo[i]) <= LargestTrustedCoordinate && std::fabs(box.hi[i]) <= LargestTrustedCoordinate))
    {
      return false;
    }
  }
  bool negative = false, positive = false;
  for (int corner = 0; corner < 8; ++corner)
  {
    // (0 where the corner's sign is not proven: near underflow.)
    const int sign = ProvenSign(this->A,
      { corner & 1 ? box.hi[0] : box.lo[0], corner & 2 ? box.hi[1] : box.lo[1], corner & 4 ? box.hi[2] : box.lo[2] });
    negative = negative || sign < 0;
    positive = positive || sign > 0;
    if (negative && positive)
    {
      return true;
    }
  }
  // A box around a whole ellipsoid, or around its centre: every corner
  // outside, the centre inside (proven at construction). Without this the
  // interval forms found the sign change at ten interval products a leaf -
  // a fifth of the plate of 100 ellipsoids' run at a tolerance of one
  // diagonal went to pruning near expressions whose boxes hold them all.
  return positive && this->HasInterior && box.Contains(this->Interior);
}

namespace
{
/// The centred form of the quadric with coefficients `a` on the closed box,
/// in floating point, in [lo, hi] when it proves f's sign there; false when
/// it does not (or cannot be trusted). `absA` bounds the coefficients'
/// absolute values and their own errors: |a| for coefficients that are
/// exact, else the same expression over absolute values that gave them
/// (see EncloseStarCondition).
///
/// f(c + d) = f(c) + g.d + d'Qd over |d_i| <= r_i, c the box's centre (any
/// point would do: r_i, rounded up, bounds |x_i - c_i| on the box), is
/// within [F - T + Dn, F + T + Dp]: T = sum |g_i| r_i + sum_{i<j} |q_ij| r_i r_j,
/// Dn (Dp) the negative (positive) diagonal terms q_ii r_i^2 - what the
/// interval form gives for point coefficients. Computed in floating point,
/// the bounds are sums and products of the coefficients, c and r with at
/// most 20 roundings along any path, so each is within gamma_20 = 20u /
/// (1 - 20u) < 2.3e-15 of its exact value times the same expression over
/// absolute values, at most M (Higham 3.1); coefficients off by gamma_k
/// times absA move each term by at most gamma_k of its share of M, so for
/// k <= 10 the whole is within gamma_30 < 3.4e-15 M; 4e-14 M covers that
/// and M's own rounding. Near underflow (subnormal roundings are absolute:
/// LargestTrustedCoordinate), or without finite values, nothing is proven.
bool CentredFormDecides(
  const std::array<double, 10>& a, const std::array<double, 10>& absA, const Box3& box, double& lo, double& hi)
{
  Vec3 c, r;
  for (int i = 0; i < 3; ++i)
  {
    c[i] = 0.5 * (box.lo[i] + box.hi[i]);
    r[i] = std::max(rounding::AddUp(c[i], -box.lo[i]), rounding::AddUp(box.hi[i], -c[i]));
  }
  const double x = c[0], y = c[1], z = c[2];
  const double ax = std::fabs(x), ay = std::fabs(y), az = std::fabs(z);
  const double F = EvaluateForm(a, x, y, z), absF = EvaluateForm(absA, ax, ay, az);
  const double g[3] = { 2.0 * a[0] * x + a[3] * y + a[5] * z + a[6], a[3] * x + 2.0 * a[1] * y + a[4] * z + a[7],
    a[5] * x + a[4] * y + 2.0 * a[2] * z + a[8] };
  const double absG[3] = { 2.0 * absA[0] * ax + absA[3] * ay + absA[5] * az + absA[6],
    absA[3] * ax + 2.0 * absA[1] * ay + absA[4] * az + absA[7],
    absA[5] * ax + absA[4] * ay + 2.0 * absA[2] * az + absA[8] };
  const double cross = std::fabs(a[3]) * r[0] * r[1] + std::fabs(a[4]) * r[1] * r[2] + std::fabs(a[5]) * r[0] * r[2];
  const double absCross = absA[3] * r[0] * r[1] + absA[4] * r[1] * r[2] + absA[5] * r[0] * r[2];
  double T = cross, Dn = 0.0, Dp = 0.0, M = absF + absCross;
  for (int i = 0; i < 3; ++i)
  {
    T += std::fabs(g[i]) * r[i];
    M += absG[i] * r[i] + absA[i] * r[i] * r[i];
    (a[i] < 0.0 ? Dn : Dp) += a[i] * r[i] * r[i];
  }
  const double error = 4e-14 * M;
  lo = F - T + Dn - error;
  hi = F + T + Dp + error;
  const double largest = std::max({ ax, ay, az, r[0], r[1], r[2] });
  return std::isfinite(lo) && std::isfinite(hi) && M > SmallestTrustedMagnitude &&
    largest <= LargestTrustedCoordinate && (hi < 0.0 || lo > 0.0);
}
} // namespace

Interval Quadric::EncloseForSign(const Box3& box) const
{
  // A sign change between two corners: the whole line encloses f as well as
  // anything would, and says what any enclosure must (it holds zero).
  if (this->ChangesSignOn(box))
  {
    return { -HUGE_VAL, HUGE_VAL };
  }
  // The centred form in floating point (CentredFormDecides), else the
  // interval form. (It is the form Enclose tries first, whose outward
  // roundings stay within gamma_20 M: a box decided here is decided alike
  // there, and outputs do not change.)
  double lo = 0.0, hi = 0.0;
  if (CentredFormDecides(this->A, AbsoluteValues(this->A), box, lo, hi))
  {
    return { lo, hi };
  }
  return this->Enclose(box);
}

Interval Quadric::EncloseDerivative(const Box3& box, int axis) const
{
  // df/dx_axis is affine: its exact range is reached at box corners, and the
  // natural extension of an expression using each variable once is exact up
  // to rounding.
  const auto& a = this->A;
  const Interval x(box.lo[0], box.hi[0]), y(box.lo[1], box.hi[1]), z(box.lo[2], box.hi[2]);
  switch (axis)
  {
    case 0:
      return Interval(2 * a[0]) * x + Interval(a[3]) * y + Interval(a[5]) * z + Interval(a[6]);
    case 1:
      return Interval(a[3]) * x + Interval(2 * a[1]) * y + Interval(a[4]) * z + Interval(a[7]);
    default:
      return Interval(a[5]) * x + Interval(a[4]) * y + Interval(2 * a[2]) * z + Interval(a[8]);
  }
}

Interval Quadric::EncloseDirectionalDerivative(const Box3& box, const Vec3& d) const
{
  const auto& a = this->A;
  const Interval dx(d[0]), dy(d[1]), dz(d[2]);
  const Interval gx = Interval(2 * a[0]) * dx + Interval(a[3]) * dy + Interval(a[5]) * dz;
  const Interval gy = Interval(a[3]) * dx + Interval(2 * a[1]) * dy + Interval(a[4]) * dz;
  const Interval gz = Interval(a[5]) * dx + Interval(a[4]) * dy + Interval(2 * a[2]) * dz;
  const Interval h = Interval(a[6]) * dx + Interval(a[7]) * dy + Interval(a[8]) * dz;
  return gx * Interval(box.lo[0], box.hi[0]) + gy * Interval(box.lo[1], box.hi[1]) +
    gz * Interval(box.lo[2], box.hi[2]) + h;
}

Interval Quadric::EncloseStarCondition(
  const Box3& box, const StarWitness& witness, int sigma) const
{
  // h(x) = sigma * grad f(x) . (w x - p) is again a quadric in x. First its
  // coefficients in floating point and its centred form (CentredFormDecides)
  // where that proves h > 0 - all the star-shaped test asks: sigma = +-1
  // and w in {0, 1} are exact, 2 w a_i is exact, h_6..h_9 take at most 4
  // roundings, each within gamma_4 of the same sums over absolute values
  // (absH), which the centred form's error then covers. (The plate of 100
  // ellipsoids at 1/64: a tenth of its run verified witnesses in interval
  // arithmetic.) Else the interval form.
  const auto& a = this->A;
  {
    const double sg = static_cast<double>(sigma), W = witness.W;
    const Vec3& P = witness.P;
    std::array<double, 10> h, absH;
    for (int i = 0; i < 6; ++i)
    {
      h[i] = sg * 2.0 * W * a[i];
      absH[i] = std::fabs(h[i]);
    }
    h[6] = sg * (W * a[6] - (2.0 * a[0] * P[0] + a[3] * P[1] + a[5] * P[2]));
    h[7] = sg * (W * a[7] - (a[3] * P[0] + 2.0 * a[1] * P[1] + a[4] * P[2]));
    h[8] = sg * (W * a[8] - (a[5] * P[0] + a[4] * P[1] + 2.0 * a[2] * P[2]));
    h[9] = -(sg * (a[6] * P[0] + a[7] * P[1] + a[8] * P[2]));
    const double p0 = std::fabs(P[0]), p1 = std::fabs(P[1]), p2 = std::fabs(P[2]), w = std::fabs(W);
    absH[6] = w * std::fabs(a[6]) + 2.0 * std::fabs(a[0]) * p0 + std::fabs(a[3]) * p1 + std::fabs(a[5]) * p2;
    absH[7] = w * std::fabs(a[7]) + std::fabs(a[3]) * p0 + 2.0 * std::fabs(a[1]) * p1 + std::fabs(a[4]) * p2;
    absH[8] = w * std::fabs(a[8]) + std::fabs(a[5]) * p0 + std::fabs(a[4]) * p1 + 2.0 * std::fabs(a[2]) * p2;
    absH[9] = std::fabs(a[6]) * p0 + std::fabs(a[7]) * p1 + std::fabs(a[8]) * p2;
    double lo = 0.0, hi = 0.0;
    if ((sigma == 1 || sigma == -1) && (W == 0.0 || W == 1.0) &&
      p0 <= LargestTrustedCoordinate && p1 <= LargestTrustedCoordinate && p2 <= LargestTrustedCoordinate &&
      CentredFormDecides(h, absH, box, lo, hi) && lo > 0.0)
    {
      return { lo, hi };
    }
  }
  const Interval w(witness.W), s(static_cast<double>(sigma)), two(2.0);
  const Interval p0(witness.P[0]), p1(witness.P[1]), p2(witness.P[2]);
  const Interval a0(a[0]), a1(a[1]), a2(a[2]), a3(a[3]), a4(a[4]), a5(a[5]), a6(a[6]),
    a7(a[7]), a8(a[8]);
  IntervalQuadric h;
  h.A[0] = s * two * w * a0;
  h.A[1] = s * two * w * a1;
  h.A[2] = s * two * w * a2;
  h.A[3] = s * two * w * a3;
  h.A[4] = s * two * w * a4;
  h.A[5] = s * two * w * a5;
  h.A[6] = s * (w * a6 - (two * a0 * p0 + a3 * p1 + a5 * p2));
  h.A[7] = s * (w * a7 - (a3 * p0 + two * a1 * p1 + a4 * p2));
  h.A[8] = s * (w * a8 - (a5 * p0 + a4 * p1 + two * a2 * p2));
  h.A[9] = -(s * (a6 * p0 + a7 * p1 + a8 * p2));
  return h.Enclose(box);
}

SolidBounds Quadric::Bounds() const
{
  SolidBounds result;
  if (this->IsLinear())
  {
    // A half-space is bounded on one side only when its normal is an axis.
    int axis = -1, nonzero = 0;
    for (int i = 0; i < 3; ++i)
    {
      if (this->A[6 + i] != 0.0)
      {
        axis = i;
        ++nonzero;
      }
    }
    if (nonzero == 0)
    {
      return this->A[9] < 0.0 ? SolidBounds::Everything() : SolidBounds::Nothing();
    }
    if (nonzero == 1)
    {
      // a x + c < 0
      const double x = -this->A[9] / this->A[6 + axis];
      const double pad = 1e-12 * (std::fabs(x) + 1e-300);
      if (this->A[6 + axis] > 0.0)
      {
        result.Box.hi[axis] = x + pad;
      }
      else
      {
        result.Box.lo[axis] = x - pad;
      }
    }
    return result;
  }
  const QuadraticForm q = ToForm(this->A);
  double inv[3][3];
  if (!PositiveDefinite(q.A) || !Invert(q.A, inv))
  {
    return result; // unbounded
  }
  Vec3 x0;
  for (int i = 0; i < 3; ++i)
  {
    x0[i] = -0.5 * (inv[i][0] * q.b[0] + inv[i][1] * q.b[1] + inv[i][2] * q.b[2]);
  }
  // f = (x-x0)'A(x-x0) - k
  double k = -q.c;
  for (int i = 0; i < 3; ++i)
  {
    for (int j = 0; j < 3; ++j)
    {
      k += x0[i] * q.A[i][j] * x0[j];
    }
  }
  if (k <= 0.0)
  {
    return SolidBounds::Nothing();
  }
  for (int i = 0; i < 3; ++i)
  {
    // Small relative inflation: the box must contain the solid despite rounding.
    const double half = std::sqrt(k * inv[i][i]) * (1.0 + 1e-12) + 1e-300;
    result.Box.lo[i] = x0[i] - half;
    result.Box.hi[i] = x0[i] + half;
  }
  return result;
}

Quadric::Quadric(const std::array<double, 10>& coefficients)
  : A(coefficients)
{
  Vec3 center;
  if (this->EllipsoidCenter(center))
  {
    this->HasInterior = ProvenSign(this->A, center) < 0;
    this->Interior = center;
  }
}

bool Quadric::EllipsoidCenter(Vec3& center) const
{
  const QuadraticForm q = ToForm(this->A);
  double inv[3][3];
  if (!PositiveDefinite(q.A) || !Invert(q.A, inv))
  {
    return false;
  }
  for (int i = 0; i < 3; ++i)
  {
    center[i] = -0.5 * (inv[i][0] * q.b[0] + inv[i][1] * q.b[1] + inv[i][2] * q.b[2]);
  }
  return true;
}

} // namespace tpc
