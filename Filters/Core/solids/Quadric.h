// The implicit primitive of the core: a polynomial of degree <= 2,
//   f(x,y,z) = a0 x^2 + a1 y^2 + a2 z^2 + a3 xy + a4 yz + a5 xz
//            + a6 x + a7 y + a8 z + a9,
// (vtkQuadric's coefficient order). Spheres, ellipsoids, cylinders, planes and
// any affine image of them are quadrics; a box is an intersection of six planes.
// The solid is {f < 0}; f = 0 counts as outside everywhere (one rule for corner
// signs, tests and extraction, see CsgExpression.h).
//
// Besides value and gradient it offers what the paper's tests need, all
// conservative (proven, never sampled): an interval enclosure of f over a box
// (paper 5.1, the max-norm "does the surface meet this box" question), of a
// partial derivative (complex edge, 5.3.1), and of the star-shaped condition
// grad f(x) . (w x - p) (5.4), plus the exact sign of f at a point.
#pragma once

#include "Interval.h"
#include "Vector3.h"

#include <array>

namespace tpc
{

/// A quadric with interval coefficients: used to enclose expressions derived
/// from a quadric (the star-shaped condition is itself quadratic in x) whose
/// coefficients carry rounding errors.
struct IntervalQuadric
{
  std::array<Interval, 10> A{};

  /// Enclosure of the polynomial over a closed box: a second-order Taylor
  /// (centred) form, intersected with the natural interval extension when the
  /// former does not decide the sign.
  Interval Enclose(const Box3& box) const;
  /// Enclosure of the polynomial at a single point.
  Interval EncloseAt(const Vec3& p) const;
  /// Second-order Taylor form at p: f(p + d) = f(p) + g(p).d + d'Qd, with d
  /// ranging over the intervals `d` (exact for a quadric, up to rounding).
  Interval EncloseTaylor(const Vec3& p, const Interval d[3]) const;
};

/// A homogeneous witness point for the star-shaped test: a finite point p
/// (W = 1) or a point at infinity in direction -P (W = 0). A point at infinity
/// stands for parallel rays; the paper's ray argument holds unchanged.
struct StarWitness
{
  Vec3 P;
  double W = 1.0;
};

class Quadric
{
public:
  Quadric() = default;
  explicit Quadric(const std::array<double, 10>& coefficients);

  static Quadric Sphere(const Vec3& center, double radius);
  /// Half-space n.(x - origin) < 0 (outside is the side the normal points to).
  static Quadric Plane(const Vec3& origin, const Vec3& normal);
  /// Infinite cylinder around the line through `center` with direction `axis`.
  static Quadric Cylinder(const Vec3& center, const Vec3& axis, double radius);
  /// Axis-aligned ellipsoid with the given semi-axes.
  static Quadric Ellipsoid(const Vec3& center, const Vec3& semiAxes);

  const std::array<double, 10>& Coefficients() const { return this->A; }

  /// f(M x) for an affine map M given as a row-major 4x4 matrix (the way a
  /// vtkImplicitFunction applies its Transform before evaluating).
  Quadric Composed(const double matrix[16]) const;
  /// The same zero set and sign with coefficients scaled by s > 0.
  Quadric Scaled(double s) const;

  double Value(const Vec3& p) const;
  Vec3 Gradient(const Vec3& p) const;
  /// Exact sign of f at p (-1, 0, +1). (Exact while no product of two or
  /// three of its numbers underflows, ExactSum.h: at subnormal coordinates
  /// a value of about 1e-324 may read as 0.)
  int ExactSign(const Vec3& p) const;

  Interval Enclose(const Box3& box) const;
  /// An enclosure of f on the closed box for deciding its sign: the whole
  /// line where f provably changes sign on it (ChangesSignOn); the centred
  /// form in floating point, with a bound of its rounding errors, where that
  /// excludes zero (most other boxes, at a fraction of the interval
  /// arithmetic's cost); else Enclose. So it excludes zero wherever Enclose
  /// does.
  Interval EncloseForSign(const Box3& box) const;
  /// Whether f is provably positive at one corner of the closed box and
  /// negative at another corner or at an ellipsoid's centre inside it
  /// (floating point with a bound of its rounding errors): then no
  /// enclosure can give it one sign there.
  bool ChangesSignOn(const Box3& box) const;
  /// Enclosure of df/dx_axis over the box.
  Interval EncloseDerivative(const Box3& box, int axis) const;
  /// Encloses grad f . d over the box: an affine function of x, written
  /// G . x + h with G = 2 A d (A half the Hessian) and h = b . d, so its
  /// natural extension uses each coordinate once and is exact up to
  /// rounding, in one evaluation where its corners took eight.
  Interval EncloseDirectionalDerivative(const Box3& box, const Vec3& d) const;
  /// Enclosure of sigma * grad f(x) . (w x - p) over the box.
  Interval EncloseStarCondition(const Box3& box, const StarWitness& witness, int sigma) const;

  /// Bounding box of the solid {f < 0}; unbounded unless it is an ellipsoid.
  SolidBounds Bounds() const;
  /// Centre of an ellipsoid (only meaningful when the solid is bounded).
  bool EllipsoidCenter(Vec3& center) const;
  /// True when f has no quadratic terms (a half-space).
  bool IsLinear() const { return this->A[0] == 0 && this->A[1] == 0 && this->A[2] == 0 && this->A[3] == 0 && this->A[4] == 0 && this->A[5] == 0; }

private:
  IntervalQuadric AsInterval() const;

  std::array<double, 10> A{};
  /// An ellipsoid's centre where f is proven negative there (ChangesSignOn:
  /// a box holding it and a corner proven positive changes sign, though no
  /// corner is negative - a box around a whole ellipsoid).
  Vec3 Interior;
  bool HasInterior = false;
};

} // namespace tpc
