#include "RootGrid.h"

#include <algorithm>
#include <cmath>

namespace tpc
{

int MaximumSupportedDepth(const int dims[3])
{
  const int n = std::max({ dims[0], dims[1], dims[2], 1 });
  int depth = 0;
  while ((static_cast<std::uint64_t>(n) << (depth + 1)) < LatticeLimit)
  {
    ++depth;
  }
  return depth;
}

int DoublePrecisionDepth(const Box3& box, double rootSize)
{
  double largest = 0.0;
  for (int a = 0; a < 3; ++a)
  {
    largest = std::max({ largest, std::abs(box.lo[a]), std::abs(box.hi[a]) });
  }
  // largest = m 2^e with m in [0.5, 1): every coordinate's ulp is at most
  // 2^(e - 53); the spacing rootSize * 2^-depth must be at least 2^4 of it.
  int exponent = 0;
  std::frexp(largest, &exponent);
  const double ulp = std::ldexp(1.0, exponent - 53);
  int depth = 0;
  while (std::ldexp(rootSize, -(depth + 1)) >= 16.0 * ulp && depth < 1000)
  {
    ++depth;
  }
  return depth;
}

namespace
{
double LargestWidth(const Box3& domain, double tolerance)
{
  double extent = 0.0;
  for (int a = 0; a < 3; ++a)
  {
    extent = std::max(extent, domain.Width(a));
  }
  return extent > 0.0 ? extent : std::max(tolerance, 1e-12);
}
} // namespace

int ToleranceLevel(const Box3& domain, double tolerance)
{
  if (!(tolerance > 0.0))
  {
    return 0;
  }
  const double extent = LargestWidth(domain, tolerance);
  return std::max(0, static_cast<int>(std::ceil(std::log2(extent * std::sqrt(3.0) / tolerance))));
}

RootGrid MakeRootGrid(const Box3& domain, double tolerance, int maximumDepth, int placement)
{
  RootGrid grid;
  const double extent = LargestWidth(domain, tolerance);
  const double sqrt3 = std::sqrt(3.0);
  const int levels = ToleranceLevel(domain, tolerance);
  double size = extent;
  if (tolerance > 0.0 && levels <= maximumDepth)
  {
    // Level `levels` then has a diagonal of exactly the tolerance.
    size = std::max(extent, std::ldexp(tolerance / sqrt3, levels));
  }
  // A lattice aligned with the input's own numbers (a sphere of radius 0.5 at
  // (0.1, 0.2, 0.3) has many rational points) puts lattice corners at almost
  // exactly the surface; each such near-hit is a genuinely complex cell that
  // only refinement to the scale of the near-miss resolves. A lattice with a
  // generic spacing and a generic offset makes such coincidences as rare as
  // chance makes them. Deterministic: the same input gives the same grid.
  const double generic = 0.9876543210987654;
  // Further placements step the offset by golden-ratio fractions of the cell
  // at the tolerance's level: deep lattice planes then move by generic
  // fractions of their spacing.
  Vec3 shift(0.0731059, 0.0418603, 0.0586947);
  const Vec3 step(0.6180339887, 0.3819660113, 0.2360679775);
  for (int a = 0; a < 3; ++a)
  {
    shift[a] = std::fmod(shift[a] + placement * step[a], 1.0);
  }
  const double finest = std::ldexp(size, -levels);
  if (size * generic >= extent + 2.0 * finest)
  {
    size *= generic;
  }
  grid.RootSize = size;
  const Vec3 center = domain.Center();
  for (int a = 0; a < 3; ++a)
  {
    grid.Dims[a] = std::max(1, static_cast<int>(std::ceil(domain.Width(a) / size - 1e-12)));
    grid.Origin[a] = center[a] - 0.5 * grid.Dims[a] * size;
    const double offset = shift[a] * std::ldexp(size, -levels);
    if (grid.Origin[a] - offset <= domain.lo[a] &&
      grid.Origin[a] - offset + grid.Dims[a] * size >= domain.hi[a])
    {
      grid.Origin[a] -= offset;
    }
  }
  // The lattice is always as fine as supported: face refinement samples
  // below the deepest cells.
  Box3 covered;
  for (int a = 0; a < 3; ++a)
  {
    covered.lo[a] = grid.Origin[a];
    covered.hi[a] = grid.Origin[a] + grid.Dims[a] * size;
  }
  grid.MaxDepth = std::min(MaximumSupportedDepth(grid.Dims), DoublePrecisionDepth(covered, size));
  return grid;
}

} // namespace tpc
