#include "CreasePoint.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace tpc
{
namespace
{
/// x moved by x -= step(x) until a move is below 1e-14 `scale` or a few
/// units in the last place of x, whichever is coarser (far from the origin
/// the last steps are rounding noise) - then x; nothing when a step fails or
/// exceeds `scale`, or after 30 steps.
template <typename Step>
std::optional<Vec3> Settle(Vec3 x, double scale, const Step& step)
{
  for (int k = 0; k < 30; ++k)
  {
    const std::optional<Vec3> move = step(x);
    if (!move || !(Norm(*move) <= scale))
    {
      return std::nullopt;
    }
    x = x - *move;
    const double size = std::max({ std::fabs(x[0]), std::fabs(x[1]), std::fabs(x[2]) });
    if (Norm(*move) <= std::max(1e-14 * scale, 8.0 * std::numeric_limits<double>::epsilon() * size))
    {
      return x;
    }
  }
  return std::nullopt;
}
} // namespace

std::optional<Vec3> OntoCrease(
  const CsgLeaf& p, const CsgLeaf& q, const PrimitiveSet& primitives, const Vec3& start, double scale)
{
  return Settle(start, scale, [&](const Vec3& x) -> std::optional<Vec3> {
    const double f = LeafValue(p, primitives, x), g = LeafValue(q, primitives, x);
    const Vec3 df = LeafGradient(p, primitives, x), dg = LeafGradient(q, primitives, x);
    // J J^T for J's rows df, dg; the step is -J^T (J J^T)^-1 (f, g).
    const double a = Dot(df, df), b = Dot(df, dg), d = Dot(dg, dg), det = a * d - b * b;
    if (!(det > 1e-6 * a * d))
    {
      return std::nullopt; // (nearly) tangent surfaces: no crease to follow
    }
    return df * ((d * f - b * g) / det) + dg * ((a * g - b * f) / det);
  });
}

std::optional<Vec3> OntoCorner(const CsgLeaf leaves[3], const PrimitiveSet& primitives, const Vec3& start, double scale)
{
  return Settle(start, scale, [&](const Vec3& x) -> std::optional<Vec3> {
    Vec3 rows[3];
    double values[3];
    for (int k = 0; k < 3; ++k)
    {
      values[k] = LeafValue(leaves[k], primitives, x);
      rows[k] = LeafGradient(leaves[k], primitives, x);
    }
    // Cramer's rule: J move = values, J's rows the gradients.
    const double det = Dot(rows[0], Cross(rows[1], rows[2]));
    if (!(std::fabs(det) > 1e-3 * Norm(rows[0]) * Norm(rows[1]) * Norm(rows[2])))
    {
      return std::nullopt;
    }
    return (Cross(rows[1], rows[2]) * values[0] + Cross(rows[2], rows[0]) * values[1] +
             Cross(rows[0], rows[1]) * values[2]) *
      (1.0 / det);
  });
}

} // namespace tpc
