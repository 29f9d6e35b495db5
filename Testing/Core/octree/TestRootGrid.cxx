// The root grid's lattice: 42-bit coordinates packed into 128-bit keys, as
// deep as the doubles of the coordinates allow (RootGrid.h).
#include "RootGrid.h"

#include <gtest/gtest.h>

#include <cmath>
#include <random>

using tpc::LatticeIndex;

TEST(RootGrid, KeysRoundTripEveryCoordinateOfTheLattice)
{
  std::mt19937_64 random(11);
  const LatticeIndex last = tpc::LatticeLimit - 1;
  for (int k = 0; k < 10000; ++k)
  {
    LatticeIndex p[3] = { random() & last, random() & last, random() & last };
    if (k < 8)
    {
      for (int a = 0; a < 3; ++a)
      {
        p[a] = (k >> a) & 1 ? last : 0; // the lattice's corners
      }
    }
    LatticeIndex q[3];
    tpc::SplitPointKey(tpc::MakePointKey(p[0], p[1], p[2]), q);
    EXPECT_EQ(q[0], p[0]);
    EXPECT_EQ(q[1], p[1]);
    EXPECT_EQ(q[2], p[2]);
    const int axis = k % 3;
    const tpc::LatticeKey subEdge = tpc::WithAxis(tpc::MakePointKey(p[0], p[1], p[2]), axis);
    EXPECT_EQ(tpc::AxisOf(subEdge), axis);
    EXPECT_TRUE(tpc::PointOf(subEdge) == tpc::MakePointKey(p[0], p[1], p[2]));
    // The line along `axis` forgets the coordinate along it, and only it.
    LatticeIndex moved[3] = { p[0], p[1], p[2] };
    moved[axis] = random() & last;
    EXPECT_TRUE(tpc::LineKey(p, axis) == tpc::LineKey(moved, axis));
    moved[(axis + 1) % 3] ^= 1;
    EXPECT_FALSE(tpc::LineKey(p, axis) == tpc::LineKey(moved, axis));
  }
}

TEST(RootGrid, LatticeReachesTwoToTheMinus40OfTheRootCell)
{
  const tpc::Box3 domain{ { -0.5, -0.2, -0.3 }, { 0.5, 0.3, 0.4 } };
  for (const double tolerance : { 1.0 / 32, 1.0 / 128, 1e-4 })
  {
    const tpc::RootGrid grid = tpc::MakeRootGrid(domain, tolerance, 40);
    EXPECT_GE(grid.MaxDepth, 40) << tolerance;
    // The deepest lattice points stay distinct, ordered doubles at both ends
    // of every axis.
    for (int a = 0; a < 3; ++a)
    {
      const LatticeIndex end = static_cast<LatticeIndex>(grid.Dims[a]) << grid.MaxDepth;
      for (const LatticeIndex i : { LatticeIndex(0), end / 3, end - 2 })
      {
        EXPECT_LT(grid.Coordinate(a, i), grid.Coordinate(a, i + 1));
        EXPECT_LT(grid.Coordinate(a, i + 1), grid.Coordinate(a, i + 2));
      }
    }
  }
}

TEST(RootGrid, DepthStopsWhereTheDoublesRunOut)
{
  // Far from the origin, a small part leaves fewer bits below its size: the
  // lattice stops where its spacing would fall under 16 ulps.
  const tpc::Box3 nearOrigin{ { 0, 0, 0 }, { 1, 1, 1 } };
  const tpc::Box3 farAway{ { 1e6, 1e6, 1e6 }, { 1e6 + 1, 1e6 + 1, 1e6 + 1 } };
  EXPECT_GE(tpc::DoublePrecisionDepth(nearOrigin, 1.0), 47);
  const int far = tpc::DoublePrecisionDepth(farAway, 1.0);
  EXPECT_LT(far, 40);
  EXPECT_GE(far, 24);
  const double ulp = std::nextafter(1e6 + 1, 2e6) - (1e6 + 1);
  EXPECT_GE(std::ldexp(1.0, -far), 16 * ulp);
  EXPECT_LT(std::ldexp(1.0, -(far + 1)), 16 * ulp);
  const tpc::RootGrid grid = tpc::MakeRootGrid(farAway, 1e-3, 40);
  EXPECT_LE(grid.MaxDepth, far + 1);
  for (int a = 0; a < 3; ++a)
  {
    const LatticeIndex end = static_cast<LatticeIndex>(grid.Dims[a]) << grid.MaxDepth;
    EXPECT_LT(grid.Coordinate(a, end - 1), grid.Coordinate(a, end));
  }
}
