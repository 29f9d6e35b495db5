// Exact geometric predicates on double coordinates: the sign of 2-D and 3-D
// orientation determinants. A floating-point filter, then an interval
// evaluation, decide almost always; when they cannot, the determinant is
// expanded into products of coordinates (2-D) or of the differences' rounded
// values and rounding errors (3-D) and summed exactly (ExactSum.h). These decide every inside/outside and
// crossing question about meshes, so two cells asking about the same point
// or segment always get the same answer.
#pragma once

#include "Vector3.h"

namespace tpc
{

/// Sign of (b - a) x (c - a) for 2-D points given by (u, v) pairs:
/// +1 counter-clockwise, -1 clockwise, 0 collinear.
int Orient2D(double au, double av, double bu, double bv, double cu, double cv);

/// Sign of det[a - d, b - d, c - d] = n . (a - d) with n = (b - a) x (c - a):
/// +1 when d is on the side opposite to n (behind the triangle a, b, c),
/// -1 in front, 0 coplanar.
int Orient3D(const Vec3& a, const Vec3& b, const Vec3& c, const Vec3& d);

/// Sign of n . u with n = (b - a) x (c - a): which way the triangle faces
/// relative to the direction u.
int FacingSign(const Vec3& a, const Vec3& b, const Vec3& c, const Vec3& u);

} // namespace tpc
