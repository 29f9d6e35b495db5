// The lattice shift ranking (LatticePlacement.h): creases lying in an axis
// plane are kept away from the lattice planes, and scenes without meshes keep
// the unshifted lattice. (End to end, CGAL's anchor.off at 1/128, whose flat
// faces lie a hair from the unshifted lattice's planes, is in the mesh suite.)
#include "BestLatticePlacement.h"
#include "LatticePlacement.h"
#include "MeshBuilders.h"
#include "MeshEdges.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <tuple>

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

TEST(LatticePlacement, EachAxisIsRankedOnItsOwnAndRetriesMoveEveryAxis)
{
  // A box whose top and right faces lie on deepest planes of the unshifted
  // lattice: flat along z and along x. The penalty sums one term per axis,
  // so each axis's shifts are ranked on their own: the first shift's term
  // along each axis is within LatticeNearTie of the least of that axis's
  // LatticeShiftsPerAxis shifts, the k-th's no more than the later ones' (up
  // to the same tie), and every retry moves the lattice along every axis.
  const RootGrid base = tpc::MakeRootGrid(Domain, Tolerance, MaximumDepth);
  const double deepest = std::ldexp(base.RootSize, -MaximumDepth);
  const auto onPlane = [&](double x, int a) {
    return base.Origin[a] + std::round((x - base.Origin[a]) / deepest) * deepest;
  };
  const double top = onPlane(0.4, 2), right = onPlane(0.35, 0);
  tpc::PrimitiveSet prims;
  prims.Meshes.push_back(tpctest::CubeMesh({ -0.3, -0.3, -0.3 }, { right, 0.3, top }));
  const std::vector<Vec3> shifts = tpc::RankLatticeShifts(prims, base, Tolerance, MaximumDepth, 3);
  ASSERT_EQ(shifts.size(), 3u);

  const tpc::LatticeSpacings spacings = tpc::LatticeSpacingsOf(base, Tolerance, MaximumDepth);
  EXPECT_EQ(spacings.Deepest, deepest);
  EXPECT_EQ(spacings.Surface, SurfaceSpacing(base));
  const tpc::LatticeCreases creases = tpc::FindLatticeCreases(prims, 4.0 * spacings.Surface, spacings.Finest);
  ASSERT_FALSE(creases.InPlane[0].empty());
  ASSERT_FALSE(creases.InPlane[2].empty());
  const double tie = 1.0 + tpc::LatticeNearTie;
  for (int a = 0; a < 3; ++a)
  {
    const auto penalty = [&](double shift) {
      return tpc::LatticeAxisPenalty(creases, a, base.Origin[a] - shift, spacings);
    };
    double least = HUGE_VAL;
    for (std::size_t k = 0; k < tpc::LatticeShiftsPerAxis; ++k)
    {
      least = std::min(least, penalty(tpc::LatticeAxisShift(k, a, spacings.Surface)));
    }
    EXPECT_LE(penalty(shifts[0][a]), tie * least) << "axis " << a;
    for (std::size_t k = 1; k < shifts.size(); ++k)
    {
      EXPECT_LE(penalty(shifts[k - 1][a]), tie * penalty(shifts[k][a])) << "axis " << a << ", shift " << k;
      for (std::size_t l = 0; l < k; ++l)
      {
        EXPECT_NE(shifts[k][a], shifts[l][a]) << "axis " << a << ", shifts " << l << " and " << k;
      }
    }
  }
  // The faces kept between the deepest planes, along both of their axes.
  EXPECT_GT(DistanceToPlanes(top, base.Origin[2] - shifts[0][2], deepest), 0.4 * deepest);
  EXPECT_GT(DistanceToPlanes(right, base.Origin[0] - shifts[0][0], deepest), 0.4 * deepest);
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

TEST(LatticePlacement, CreasesAreEveryPairOfAnEdgesTriangles)
{
  // FindLatticeCreases reads the mesh's neighbours, and the pairs of uses of
  // an edge of more than two triangles apart: the creases must be those of
  // every edge table's pair of uses (by triangle number), whatever the
  // order. Two cubes sharing the edge x = y = 1 (four triangles on it), with
  // vertices merged and triangles shuffled, and a cube alone.
  const MeshSolid a = tpctest::CubeMesh({ 0, 0, 0 }, { 1, 1, 1 });
  const MeshSolid b = tpctest::CubeMesh({ 1, 1, 0 }, { 2, 2, 1 });
  std::vector<Vec3> points = a.Points();
  std::vector<std::array<std::uint32_t, 3>> triangles = a.Triangles();
  for (const auto& t : b.Triangles())
  {
    std::array<std::uint32_t, 3> merged{};
    for (int k = 0; k < 3; ++k)
    {
      const Vec3& p = b.Points()[t[k]];
      std::uint32_t id = 0;
      while (id < points.size() && tpc::Norm(points[id] - p) != 0.0)
      {
        ++id;
      }
      if (id == points.size())
      {
        points.push_back(p);
      }
      merged[k] = id;
    }
    triangles.push_back(merged);
  }
  std::reverse(triangles.begin(), triangles.end());
  std::swap(triangles[3], triangles[17]);
  using Lists = std::vector<std::vector<std::tuple<double, double, double, double>>>;
  const auto collect = [](const tpc::LatticeCreases& creases, Lists& lists) {
    for (int axis = 0; axis < 3; ++axis)
    {
      for (const auto* list : { &creases.Ridges[axis], &creases.InPlane[axis] })
      {
        for (const tpc::FlatCreaseEdge& e : *list)
        {
          lists[list == &creases.Ridges[axis] ? axis : 3 + axis].emplace_back(
            e.Lo, e.Hi, e.Length, e.BandPerSeparation);
        }
      }
    }
  };
  for (const bool twoCubes : { true, false })
  {
    tpc::PrimitiveSet prims;
    // (Tilted: every edge a ridge or valley along some axis.)
    prims.Meshes.push_back(tpctest::TiltedMesh(twoCubes ? MeshSolid(points, triangles) : a));
    const MeshSolid& mesh = prims.Meshes.front();
    // The reference: every edge table's pair of uses.
    std::vector<tpc::EdgeUse> uses;
    tpc::BuildEdgeTable(mesh.Triangles().data(), mesh.Triangles().size(), uses);
    tpc::PrimitiveSet one;
    Lists expected(6), found(6);
    int paired = 0;
    tpc::ForEachEdge(uses, [&](std::size_t first, std::size_t count) {
      for (std::size_t k = first; k + 1 < first + count; k += 2)
      {
        // A mesh of the two triangles alone has exactly this pair's crease.
        const auto& t1 = mesh.Triangles()[uses[k].Triangle];
        const auto& t2 = mesh.Triangles()[uses[k + 1].Triangle];
        one.Meshes.assign(1, MeshSolid(mesh.Points(), { t1, t2 }));
        collect(tpc::FindLatticeCreases(one, 2.0, 1e-9), expected);
        ++paired;
      }
    });
    collect(tpc::FindLatticeCreases(prims, 2.0, 1e-9), found);
    for (int list = 0; list < 6; ++list)
    {
      std::sort(expected[list].begin(), expected[list].end());
      std::sort(found[list].begin(), found[list].end());
      EXPECT_EQ(found[list], expected[list]) << (twoCubes ? "two cubes" : "a cube") << ", list " << list;
    }
    EXPECT_EQ(paired, twoCubes ? 36 : 18);
    std::size_t entries = 0;
    for (const auto& list : expected)
    {
      entries += list.size();
    }
    EXPECT_GE(entries, static_cast<std::size_t>(paired)); // (each pair makes a crease)
  }
}
