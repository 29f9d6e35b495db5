// Which triangles may meet a box: a uniform grid of buckets over the
// triangles' bounding boxes that the decimation updates as it goes
// (CertifiedDecimation.h: every collapse checks its new triangles against
// all others whose boxes overlap theirs).
//
// A triangle is listed in every bucket its box overlaps. A triangle whose
// vertices change is listed again under its new box; its old listings stay
// (removing them would cost a search per bucket), so a query may name a
// triangle that no longer overlaps the box, or is gone, or twice - the caller
// checks each candidate's current box, whether it is alive, and visits each
// once (Stamp). What a query never misses: every live triangle whose current
// box overlaps the queried box, since it was listed under that box.
#pragma once

#include "Vector3.h"

#include <cstdint>
#include <unordered_map>
#include <vector>

namespace tpc
{

class TriangleGrid
{
public:
  /// Buckets of width `width` from `origin` (width > 0).
  TriangleGrid(const Vec3& origin, double width);

  void Insert(std::uint32_t triangle, const Box3& box);

  /// Calls visit(triangle) for every triangle listed in a bucket that `box`
  /// overlaps (with repeats, see the header).
  template <typename Visit>
  void ForEachListed(const Box3& box, Visit&& visit) const
  {
    const Range r = this->RangeOf(box);
    for (std::int64_t i = r.Lo[0]; i <= r.Hi[0]; ++i)
    {
      for (std::int64_t j = r.Lo[1]; j <= r.Hi[1]; ++j)
      {
        for (std::int64_t k = r.Lo[2]; k <= r.Hi[2]; ++k)
        {
          const auto bucket = this->Buckets.find(Key(i, j, k));
          if (bucket != this->Buckets.end())
          {
            for (const std::uint32_t t : bucket->second)
            {
              visit(t);
            }
          }
        }
      }
    }
  }

private:
  struct Range
  {
    std::int64_t Lo[3];
    std::int64_t Hi[3];
  };
  Range RangeOf(const Box3& box) const;
  static std::uint64_t Key(std::int64_t i, std::int64_t j, std::int64_t k);

  Vec3 Origin;
  double Width;
  std::unordered_map<std::uint64_t, std::vector<std::uint32_t>> Buckets;
};

} // namespace tpc
