// Boundary-loop tracing (BoundaryLoops.h) on hand-made cell boundaries: the
// loops the surface draws on a cell's faces, from exact signs at the
// samples, with every crossing named by its finest lattice sub-edge.
#include "BoundaryLoops.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <functional>
#include <vector>

using tpc::CellBoundary;
using tpc::Crossing;
using tpc::FaceTile;

namespace
{
constexpr std::uint32_t S = 8; ///< the cell's size, lattice units (base at the origin)
using Sign = std::function<bool(std::uint32_t, std::uint32_t, std::uint32_t)>;

/// Face f's single tile, or its `n` x `n` sub-tiles.
std::vector<FaceTile> FaceTiles(int f, std::uint32_t n = 1)
{
  std::vector<FaceTile> tiles;
  const std::uint32_t step = S / n;
  for (std::uint32_t j = 0; j < n; ++j)
  {
    for (std::uint32_t i = 0; i < n; ++i)
    {
      tiles.push_back({ i * step, j * step, (i + 1) * step, (j + 1) * step });
    }
  }
  (void)f;
  return tiles;
}

/// The cell [0, S]^3 with one tile per face and a sample at every lattice
/// point of spacing `spacing` on its boundary (S: the corners only).
CellBoundary Boundary(const Sign& inside, std::uint32_t spacing = S)
{
  CellBoundary b;
  b.Size = S;
  for (int f = 0; f < 6; ++f)
  {
    b.Tiles[f] = FaceTiles(f);
    b.Across[f].assign(b.Tiles[f].size(), -1);
  }
  for (std::uint32_t z = 0; z <= S; z += spacing)
  {
    for (std::uint32_t y = 0; y <= S; y += spacing)
    {
      for (std::uint32_t x = 0; x <= S; x += spacing)
      {
        const bool onBoundary = x == 0 || y == 0 || z == 0 || x == S || y == S || z == S;
        if (onBoundary)
        {
          b.Points.emplace_back(tpc::MakePointKey(x, y, z), inside(x, y, z));
        }
      }
    }
  }
  return b;
}

std::vector<std::uint32_t> Sorted(std::vector<std::uint32_t> v)
{
  std::sort(v.begin(), v.end());
  return v;
}

/// The crossing on the sub-edge from (x, y, z) along `axis` to `upper`.
Crossing SubEdge(std::uint32_t x, std::uint32_t y, std::uint32_t z, int axis, std::uint32_t upper)
{
  Crossing c;
  c.Key = (tpc::MakePointKey(x, y, z) << 2) | static_cast<std::uint64_t>(axis);
  c.Upper = upper;
  return c;
}

bool Holds(const tpc::BoundaryLoopSet& loops, const Crossing& c)
{
  return std::any_of(loops.Crossings.begin(), loops.Crossings.end(),
    [&](const Crossing& k) { return k.SameVertex(c) && k.Upper == c.Upper; });
}
} // namespace

TEST(BoundaryLoops, OneCornerInsideGivesOneTriangle)
{
  CellBoundary b = Boundary([](std::uint32_t x, std::uint32_t y, std::uint32_t z) { return x + y + z == 0; });
  const tpc::BoundaryLoopSet loops = tpc::TraceBoundaryLoops(b);
  EXPECT_TRUE(loops.Consistent);
  ASSERT_EQ(loops.LoopSizes, std::vector<std::uint32_t>{ 3 });
  for (int axis = 0; axis < 3; ++axis)
  {
    EXPECT_TRUE(Holds(loops, SubEdge(0, 0, 0, axis, S))) << axis;
  }
}

TEST(BoundaryLoops, OppositeCornersGiveTwoLoopsAndAFaceGivesAQuad)
{
  CellBoundary corners = Boundary([](std::uint32_t x, std::uint32_t y, std::uint32_t z) {
    return (x == 0 && y == 0 && z == 0) || (x == S && y == S && z == S);
  });
  const tpc::BoundaryLoopSet two = tpc::TraceBoundaryLoops(corners);
  EXPECT_TRUE(two.Consistent);
  EXPECT_EQ(Sorted(two.LoopSizes), (std::vector<std::uint32_t>{ 3, 3 }));
  CellBoundary slab = Boundary([](std::uint32_t, std::uint32_t, std::uint32_t z) { return z == 0; });
  const tpc::BoundaryLoopSet quad = tpc::TraceBoundaryLoops(slab);
  EXPECT_TRUE(quad.Consistent);
  ASSERT_EQ(quad.LoopSizes, std::vector<std::uint32_t>{ 4 });
  for (const std::uint32_t x : { 0u, S })
  {
    for (const std::uint32_t y : { 0u, S })
    {
      EXPECT_TRUE(Holds(quad, SubEdge(x, y, 0, 2, S)));
    }
  }
}

TEST(BoundaryLoops, AmbiguousFaceIsCutAroundEachInsideCorner)
{
  // Corners (0,0,0) and (S,S,0) of the face z = 0 inside: each run of inside
  // samples is cut off on its own (two loops, never a tube).
  CellBoundary b = Boundary([](std::uint32_t x, std::uint32_t y, std::uint32_t z) {
    return z == 0 && x == y && (x == 0 || x == S);
  });
  const tpc::BoundaryLoopSet loops = tpc::TraceBoundaryLoops(b);
  EXPECT_TRUE(loops.Consistent);
  EXPECT_EQ(Sorted(loops.LoopSizes), (std::vector<std::uint32_t>{ 3, 3 }));
}

TEST(BoundaryLoops, FinerSamplesOnAFaceNameTheCrossingBySubEdge)
{
  // The face x = 0 is tiled by a finer neighbour's four faces; its samples
  // lie on the cell's edges too, so the faces sharing those edges cross
  // them on the same sub-edges (crack patching).
  const Sign inside = [](std::uint32_t x, std::uint32_t y, std::uint32_t z) { return 4 * (x + y + z) < S; };
  CellBoundary b = Boundary(inside, S / 2);
  b.Tiles[0] = FaceTiles(0, 2);
  b.Across[0].assign(4, -1);
  const tpc::BoundaryLoopSet loops = tpc::TraceBoundaryLoops(b);
  EXPECT_TRUE(loops.Consistent);
  ASSERT_EQ(loops.LoopSizes, std::vector<std::uint32_t>{ 3 });
  EXPECT_TRUE(Holds(loops, SubEdge(0, 0, 0, 1, S / 2)));
  EXPECT_TRUE(Holds(loops, SubEdge(0, 0, 0, 2, S / 2)));
  EXPECT_TRUE(Holds(loops, SubEdge(0, 0, 0, 0, S / 2)));
  // A face whose tiles leave a hole where the loop passes: the segments no
  // longer close (a crack would open there).
  b.Tiles[0].erase(b.Tiles[0].begin());
  b.Across[0].pop_back();
  EXPECT_FALSE(tpc::TraceBoundaryLoops(b).Consistent);
}

TEST(BoundaryLoops, RunOnATileSideIsBent)
{
  // Only the midpoint of the edge y = z = 0 inside (a cell stopped by a
  // limit: the side is crossed twice). The segment cutting that run off
  // would lie on the side's line: it is bent through the tile instead, on
  // both faces sharing the side, and the loop still closes.
  CellBoundary b = Boundary(
    [](std::uint32_t x, std::uint32_t y, std::uint32_t z) { return x == S / 2 && y == 0 && z == 0; }, S / 2);
  const tpc::BoundaryLoopSet loops = tpc::TraceBoundaryLoops(b);
  EXPECT_TRUE(loops.Consistent);
  ASSERT_EQ(loops.LoopSizes.size(), 1u);
  const auto bends = std::count_if(loops.Crossings.begin(), loops.Crossings.end(),
    [](const Crossing& c) { return c.Kind == tpc::CrossingKind::Bend; });
  EXPECT_EQ(bends, 2);
  EXPECT_EQ(loops.LoopSizes[0], 4u);
}
