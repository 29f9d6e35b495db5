// The cell of a uniform grid that holds a coordinate, along one axis.
#pragma once

#include <cmath>

namespace tpc
{

/// floor(offset / step) clamped to [0, count - 1], clamped in double before
/// the conversion: a coordinate billions of steps outside the grid (a query
/// box around a Bounds far larger than the mesh) must clamp to the last
/// cell, where converting first overflows the int (undefined; in practice
/// INT_MIN, clamped to the first cell: a box around the whole mesh found no
/// triangle, and the root cell holding it was taken as empty - an empty
/// surface, guaranteed). NaN gives 0. Monotone in the offset (division by a
/// positive step, floor and clamping never reorder two offsets).
inline int ClampedGridIndex(double offset, double step, int count)
{
  const double cell = std::floor(offset / step);
  if (!(cell > 0.0))
  {
    return 0;
  }
  return cell >= static_cast<double>(count - 1) ? count - 1 : static_cast<int>(cell);
}

} // namespace tpc
