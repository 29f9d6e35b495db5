// Two cells' tilings of the face they share merged into one that refines
// both (FaceTile.h), whichever came first.
#include "FaceTile.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <vector>

namespace
{
using tpc::FaceTile;

/// The area of the tiles, and whether they cover [0, 8]^2 without overlap
/// (brute force over the unit squares).
bool TilesTheSquare(const std::vector<FaceTile>& tiles)
{
  for (tpc::LatticeIndex u = 0; u < 8; ++u)
  {
    for (tpc::LatticeIndex v = 0; v < 8; ++v)
    {
      const FaceTile unit{ u, v, u + 1, v + 1 };
      const auto holding = std::count_if(
        tiles.begin(), tiles.end(), [&](const FaceTile& t) { return tpc::TileWithin(unit, t); });
      if (holding != 1)
      {
        return false;
      }
    }
  }
  return true;
}

/// Whether every tile of `coarse` is a union of tiles of `fine`.
bool Refines(const std::vector<FaceTile>& fine, const std::vector<FaceTile>& coarse)
{
  return std::all_of(fine.begin(), fine.end(), [&](const FaceTile& f) {
    return std::any_of(coarse.begin(), coarse.end(), [&](const FaceTile& c) { return tpc::TileWithin(f, c); });
  });
}

std::vector<FaceTile> Sorted(std::vector<FaceTile> tiles)
{
  std::sort(tiles.begin(), tiles.end(), [](const FaceTile& a, const FaceTile& b) {
    return std::tie(a.V0, a.U0, a.V1, a.U1) < std::tie(b.V0, b.U0, b.V1, b.U1);
  });
  return tiles;
}
} // namespace

TEST(FaceTile, MergedTilingsRefineBothWhicheverCameFirst)
{
  // A face split in four (at 3, 5: face refinement splits where the signs
  // say, not only at midpoints); one cell split the lower left quarter
  // again, the other the upper right one, and it further.
  const std::vector<FaceTile> base{ { 0, 0, 3, 5 }, { 3, 0, 8, 5 }, { 0, 5, 3, 8 }, { 3, 5, 8, 8 } };
  std::vector<FaceTile> a{ { 3, 0, 8, 5 }, { 0, 5, 3, 8 }, { 3, 5, 8, 8 }, { 0, 0, 1, 2 }, { 1, 0, 3, 2 },
    { 0, 2, 1, 5 }, { 1, 2, 3, 5 } };
  std::vector<FaceTile> b{ { 0, 0, 3, 5 }, { 3, 0, 8, 5 }, { 0, 5, 3, 8 }, { 3, 5, 5, 6 }, { 5, 5, 8, 6 },
    { 3, 6, 5, 8 }, { 5, 6, 6, 7 }, { 6, 6, 8, 7 }, { 5, 7, 6, 8 }, { 6, 7, 8, 8 } };
  ASSERT_TRUE(TilesTheSquare(base) && TilesTheSquare(a) && TilesTheSquare(b));
  std::vector<FaceTile> ab = a, ba = b;
  tpc::MergeFaceTilings(ab, b);
  tpc::MergeFaceTilings(ba, a);
  EXPECT_TRUE(TilesTheSquare(ab));
  EXPECT_TRUE(Refines(ab, a) && Refines(ab, b));
  EXPECT_EQ(ab.size(), 4u + 3u + 6u); // (the finest of both, nothing finer)
  EXPECT_EQ(Sorted(ab), Sorted(ba));

  // The same tiling again, or a coarser one: unchanged, order and all.
  std::vector<FaceTile> same = a;
  tpc::MergeFaceTilings(same, base);
  EXPECT_EQ(same, a);
  tpc::MergeFaceTilings(same, a);
  EXPECT_EQ(same, a);

  // Tilings that do not nest (split at other points): the first stays.
  std::vector<FaceTile> other{ { 0, 0, 4, 4 }, { 4, 0, 8, 4 }, { 0, 4, 4, 8 }, { 4, 4, 8, 8 } };
  std::vector<FaceTile> kept = a;
  tpc::MergeFaceTilings(kept, other);
  EXPECT_EQ(kept, a);
}
