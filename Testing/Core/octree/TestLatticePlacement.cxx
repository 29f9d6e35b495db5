// The lattice shift ranking (LatticePlacement.h): creases lying in an axis
// plane are kept away from the lattice planes, and scenes without meshes keep
// the unshifted lattice. (End to end, CGAL's anchor.off at 1/128, whose flat
// faces lie a hair from the unshifted lattice's planes, is in the mesh suite.)
#include "BestLatticePlacement.h"
#include "LatticePlacement.h"
#include "MeshBuilders.h"

#include <gtest/gtest.h>

#include <cmath>

using tpc::Box3;
using tpc::MeshSolid;
using tpc::RootGrid;
using tpc::Vec3;

namespace
{
constexpr double Tolerance = 0.1;
constexpr int MaximumDepth = 12;

double DistanceToPlanes(double x, double origin, double spacing)
{
  double f = (x - origin) / spacing;
  f -= std::floor(f);
  return std::min(f, 1.0 - f) * spacing;
}

/// Spacing of the cells one level below the tolerance's (LatticeSpacings).
double SurfaceSpacing(const RootGrid& grid)
{
  int level = 0;
  while (grid.CellDiagonal(level) > Tolerance * (1.0 + 1e-9))
  {
    ++level;
  }
  return std::ldexp(grid.RootSize, -(level + 1));
}

/// A tetrahedron whose edge AB, along x at height z, is a ridge: both other
/// vertices lie below it.
MeshSolid RidgeTetrahedron(double z)
{
  const std::vector<Vec3> p = { { -0.5, 0.0, z }, { 0.5, 0.0, z }, { 0.0, -0.5, z - 0.5 }, { 0.0, 0.5, z - 0.5 } };
  return MeshSolid(p, { { 0, 2, 1 }, { 0, 1, 3 }, { 0, 3, 2 }, { 1, 2, 3 } });
}

const Box3 Domain{ { -1.0, -1.0, -1.0 }, { 1.0, 1.0, 1.0 } };
} // namespace

TEST(LatticePlacement, RidgeOnALatticePlaneIsMovedOffIt)
{
  const RootGrid base = tpc::MakeRootGrid(Domain, Tolerance, MaximumDepth);
  const double spacing = SurfaceSpacing(base);
  const double finest = std::ldexp(base.RootSize, -base.MaxDepth);
  // The ridge exactly on a plane of the unshifted lattice.
  const double z = base.Origin[2] + std::round((0.3 - base.Origin[2]) / spacing) * spacing;
  tpc::PrimitiveSet prims;
  prims.Meshes.push_back(RidgeTetrahedron(z));

  const tpc::LatticeCreases creases = tpc::FindLatticeCreases(prims, 4 * spacing, finest);
  // The ridge AB and the valley CD, both flat in z only; facets at 45 degrees.
  ASSERT_EQ(creases.Ridges[2].size(), 2u);
  EXPECT_TRUE(creases.Ridges[0].empty() && creases.Ridges[1].empty());
  for (const tpc::FlatCreaseEdge& e : creases.Ridges[2])
  {
    EXPECT_NEAR(e.BandPerSeparation, 0.5, 1e-12);
  }

  const std::vector<Vec3> shifts = tpc::RankLatticeShifts(prims, base, Tolerance, MaximumDepth, 3);
  ASSERT_EQ(shifts.size(), 3u);
  EXPECT_GT(shifts[0][2], 0.0); // the unshifted lattice is not the best
  for (const Vec3& s : shifts)
  {
    // Every proposal keeps the ridge well outside the unresolvable band.
    EXPECT_GT(DistanceToPlanes(z, base.Origin[2] - s[2], spacing), 8 * finest);
    for (int a = 0; a < 3; ++a)
    {
      EXPECT_GE(s[a], 0.0);
      EXPECT_LT(s[a], spacing);
    }
  }
}

TEST(LatticePlacement, FaceInAPlaneIsKeptBetweenTheDeepestPlanes)
{
  const RootGrid base = tpc::MakeRootGrid(Domain, Tolerance, MaximumDepth);
  const double deepest = std::ldexp(base.RootSize, -MaximumDepth);
  const double top = base.Origin[2] + std::round((0.4 - base.Origin[2]) / deepest) * deepest;
  tpc::PrimitiveSet prims;
  prims.Meshes.push_back(tpctest::CubeMesh({ -0.3, -0.3, -0.3 }, { 0.3, 0.3, top }));
  const std::vector<Vec3> shifts = tpc::RankLatticeShifts(prims, base, Tolerance, MaximumDepth, 1);
  ASSERT_EQ(shifts.size(), 1u);
  EXPECT_GT(DistanceToPlanes(top, base.Origin[2] - shifts[0][2], deepest), 0.4 * deepest);
}

TEST(LatticePlacement, ScenesWithoutMeshesKeepTheUnshiftedLatticeFirst)
{
  const RootGrid base = tpc::MakeRootGrid(Domain, Tolerance, MaximumDepth);
  const std::vector<Vec3> shifts = tpc::RankLatticeShifts({}, base, Tolerance, MaximumDepth, 3);
  ASSERT_EQ(shifts.size(), 3u);
  for (int a = 0; a < 3; ++a)
  {
    EXPECT_EQ(shifts[0][a], 0.0);
  }
  EXPECT_NE(shifts[1][0], shifts[2][0]);
}
