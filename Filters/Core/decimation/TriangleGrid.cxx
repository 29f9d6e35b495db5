#include "TriangleGrid.h"

#include <cmath>

namespace tpc
{

TriangleGrid::TriangleGrid(const Vec3& origin, double width)
  : Origin(origin)
  , Width(width)
{
}

TriangleGrid::Range TriangleGrid::RangeOf(const Box3& box) const
{
  // (A box reaching a bucket's boundary is listed on both sides of it:
  // floor of the low end, floor of the high end.)
  Range r;
  for (int a = 0; a < 3; ++a)
  {
    r.Lo[a] = static_cast<std::int64_t>(std::floor((box.lo[a] - this->Origin[a]) / this->Width));
    r.Hi[a] = static_cast<std::int64_t>(std::floor((box.hi[a] - this->Origin[a]) / this->Width));
  }
  return r;
}

std::uint64_t TriangleGrid::Key(std::int64_t i, std::int64_t j, std::int64_t k)
{
  // 21 bits per axis: the caller's buckets number far fewer than 2^21 per
  // axis (wrapping would only merge buckets, never miss a triangle).
  const std::uint64_t mask = (std::uint64_t{ 1 } << 21) - 1;
  return (static_cast<std::uint64_t>(i) & mask) | ((static_cast<std::uint64_t>(j) & mask) << 21) |
    ((static_cast<std::uint64_t>(k) & mask) << 42);
}

void TriangleGrid::Insert(std::uint32_t triangle, const Box3& box)
{
  const Range r = this->RangeOf(box);
  for (std::int64_t i = r.Lo[0]; i <= r.Hi[0]; ++i)
  {
    for (std::int64_t j = r.Lo[1]; j <= r.Hi[1]; ++j)
    {
      for (std::int64_t k = r.Lo[2]; k <= r.Hi[2]; ++k)
      {
        std::vector<std::uint32_t>& bucket = this->Buckets[Key(i, j, k)];
        if (bucket.empty() || bucket.back() != triangle)
        {
          bucket.push_back(triangle);
        }
      }
    }
  }
}

} // namespace tpc
