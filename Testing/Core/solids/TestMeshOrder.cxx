// The order of an input mesh's triangles in memory (MeshOrder.h): a mesh in
// no local order (its triangles shuffled, as a scan's come) is reordered
// along a Morton curve - the same triangles, each oriented as it was, their
// neighbours renamed with them - and a mesh in a local order is kept as it
// is, by RepairIntoSolid too.
#include "MeshBuilders.h"
#include "MeshOrder.h"
#include "MeshRepair.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>

using tpc::Vec3;
using Tris = std::vector<std::array<std::uint32_t, 3>>;

namespace
{
/// Each triangle as its corners' coordinates from its least corner on (its
/// orientation kept), sorted: the mesh whatever its points' and triangles'
/// names.
std::vector<std::array<double, 9>> Geometry(const std::vector<Vec3>& points, const Tris& triangles)
{
  std::vector<std::array<double, 9>> geometry;
  for (const auto& t : triangles)
  {
    std::array<std::array<double, 9>, 3> rotations;
    for (int r = 0; r < 3; ++r)
    {
      for (int c = 0; c < 3; ++c)
      {
        for (int a = 0; a < 3; ++a)
        {
          rotations[r][3 * c + a] = points[t[(r + c) % 3]][a];
        }
      }
    }
    geometry.push_back(*std::min_element(rotations.begin(), rotations.end()));
  }
  std::sort(geometry.begin(), geometry.end());
  return geometry;
}

/// A sphere of 5 120 triangles, its triangles shuffled.
void ShuffledSphere(std::vector<Vec3>& points, Tris& triangles)
{
  const tpc::MeshSolid sphere = tpctest::SphereMesh({ 0.1, -0.2, 0.3 }, 1.0, 4);
  points = sphere.Points();
  triangles = sphere.Triangles();
  std::mt19937 random(7);
  std::shuffle(triangles.begin(), triangles.end(), random);
}

Tris Neighbours(const tpc::MeshSolid& mesh)
{
  Tris neighbours(mesh.Triangles().size());
  for (std::uint32_t t = 0; t < neighbours.size(); ++t)
  {
    for (int k = 0; k < 3; ++k)
    {
      neighbours[t][k] = mesh.Across(t, k);
    }
  }
  return neighbours;
}
} // namespace

TEST(MeshOrder, AMeshInNoLocalOrderIsReorderedAlongAMortonCurve)
{
  const tpc::MeshSolid sphere = tpctest::SphereMesh({ 0.1, -0.2, 0.3 }, 1.0, 4);
  EXPECT_TRUE(tpc::InLocalOrder(sphere.Points(), sphere.Triangles()));
  std::vector<Vec3> points;
  Tris triangles;
  ShuffledSphere(points, triangles);
  ASSERT_FALSE(tpc::InLocalOrder(points, triangles));
  Tris neighbours = Neighbours(tpc::MeshSolid(points, triangles));
  points.push_back(Vec3(5, 6, 7)); // (no triangle uses it)
  const auto before = Geometry(points, triangles);
  tpc::OrderAlongMortonCurve(points, triangles, neighbours, tpc::MeshSolid::NoTriangle);
  EXPECT_TRUE(tpc::InLocalOrder(points, triangles));
  EXPECT_EQ(Geometry(points, triangles), before);
  ASSERT_EQ(points.size(), sphere.Points().size() + 1);
  EXPECT_EQ(points.back()[0], 5.0);
  EXPECT_EQ(points.back()[2], 7.0);
  // The points in the order the triangles first use them; the neighbours
  // those of the reordered mesh.
  std::uint32_t named = 0;
  for (const auto& t : triangles)
  {
    for (const std::uint32_t v : t)
    {
      ASSERT_LE(v, named) << "a point named before its first use";
      named = std::max(named, v + 1);
    }
  }
  EXPECT_EQ(named, sphere.Points().size());
  EXPECT_EQ(neighbours, Neighbours(tpc::MeshSolid(points, triangles)));
  // Consecutive triangles near each other, as along a Morton curve: a jump
  // of a tenth of the sphere's diameter is rare (330 of 5 119; shuffled,
  // 5 076 are), the median jump about an edge (0.08; 1.4 shuffled).
  std::vector<double> jumps;
  for (std::size_t k = 0; k + 1 < triangles.size(); ++k)
  {
    jumps.push_back(tpc::Norm(points[triangles[k][0]] - points[triangles[k + 1][0]]));
  }
  EXPECT_LT(std::count_if(jumps.begin(), jumps.end(), [](double j) { return j > 0.2; }), 512);
  std::nth_element(jumps.begin(), jumps.begin() + jumps.size() / 2, jumps.end());
  EXPECT_LT(jumps[jumps.size() / 2], 0.1);
}

TEST(MeshOrder, PointsNotANumberLeaveTheCurveOverTheOthers)
{
  // A triangle with a NaN corner (the core takes what it is given: the VTK
  // layer refuses non-finite points) keeps every other triangle's code on
  // the finite centroids' box; the renaming stays a permutation.
  std::vector<Vec3> points;
  Tris triangles;
  ShuffledSphere(points, triangles);
  points.push_back(Vec3(std::nan(""), 0.0, 0.0));
  triangles.push_back({ 0, 1, static_cast<std::uint32_t>(points.size() - 1) });
  Tris none;
  tpc::OrderAlongMortonCurve(points, triangles, none, tpc::MeshSolid::NoTriangle);
  EXPECT_TRUE(none.empty());
  std::vector<int> uses(points.size(), 0);
  for (const auto& t : triangles)
  {
    for (const std::uint32_t v : t)
    {
      ASSERT_LT(v, points.size());
      uses[v] = 1;
    }
  }
  EXPECT_EQ(std::count(uses.begin(), uses.end(), 1), static_cast<long>(points.size()));
  triangles.pop_back(); // (somewhere in the order; the sphere's alone are tested above)
  std::vector<double> jumps;
  for (std::size_t k = 0; k + 1 < triangles.size(); ++k)
  {
    jumps.push_back(tpc::Norm(points[triangles[k][0]] - points[triangles[k + 1][0]]));
  }
  std::nth_element(jumps.begin(), jumps.begin() + jumps.size() / 2, jumps.end());
  EXPECT_LT(jumps[jumps.size() / 2], 0.1);
}

TEST(MeshOrder, RepairIntoSolidReordersOnlyAMeshInNoLocalOrder)
{
  const tpc::MeshSolid sphere = tpctest::SphereMesh({ 0.1, -0.2, 0.3 }, 1.0, 4);
  tpc::MeshRepairReport report;
  const tpc::MeshSolid kept = tpc::RepairIntoSolid(sphere.Points(), sphere.Triangles(), report);
  EXPECT_EQ(kept.Triangles(), sphere.Triangles());
  std::vector<Vec3> points;
  Tris triangles;
  ShuffledSphere(points, triangles);
  const tpc::MeshSolid reordered = tpc::RepairIntoSolid(points, triangles, report);
  EXPECT_TRUE(report.MeetsAssumptions()) << report.Describe();
  EXPECT_EQ(report.Genus, 0);
  EXPECT_TRUE(tpc::InLocalOrder(reordered.Points(), reordered.Triangles()));
  EXPECT_EQ(Geometry(reordered.Points(), reordered.Triangles()), Geometry(points, triangles));
  // (Its neighbours are the repair's, renamed: as the solid's own table.)
  EXPECT_EQ(Neighbours(reordered), Neighbours(tpc::MeshSolid(reordered.Points(), reordered.Triangles())));
}
