// Creases followed by the patch (CreaseFollowing.h): the mesh's creases in a
// cell, whether a patch's creases come within reach of them, and on whole
// runs a chamfered bar whose every crease lies within the tolerance of an
// output crease (before the criterion, its chamfers' second edges were cut
// across, up to 1.6 and 2.3 tolerances away at 1/64 and 1/128).
#include "ApexRooms.h"
#include "CoreContour.h"
#include "CreaseCrossing.h"
#include "CreaseFollowing.h"
#include "MeshBuilders.h"
#include "MeshCellError.h"
#include "SceneBuilder.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <map>

using tpc::Vec3;

namespace
{
/// Two triangles sharing the edge (0,0,0)-(1,0,0), bent by `degrees` along it.
std::vector<std::array<Vec3, 3>> Hinge(double degrees)
{
  const double a = degrees * M_PI / 180.0;
  return { { Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(0.5, 1, 0) },
    { Vec3(1, 0, 0), Vec3(0, 0, 0), Vec3(0.5, -std::cos(a), std::sin(a)) } };
}

/// The edges of a triangle mesh where its triangles meet at `degrees` or more.
std::vector<std::array<Vec3, 2>> Creases(
  const std::vector<Vec3>& points, const std::vector<std::array<std::uint32_t, 3>>& triangles, double degrees)
{
  std::map<std::pair<std::uint32_t, std::uint32_t>, std::vector<Vec3>> normals;
  for (const auto& t : triangles)
  {
    const Vec3 n = tpc::Normalized(tpc::Cross(points[t[1]] - points[t[0]], points[t[2]] - points[t[0]]));
    for (int k = 0; k < 3; ++k)
    {
      normals[{ std::min(t[k], t[(k + 1) % 3]), std::max(t[k], t[(k + 1) % 3]) }].push_back(n);
    }
  }
  std::vector<std::array<Vec3, 2>> creases;
  for (const auto& [e, n] : normals)
  {
    if (n.size() == 2 && tpc::Dot(n[0], n[1]) <= std::cos(degrees * M_PI / 180.0))
    {
      creases.push_back({ points[e.first], points[e.second] });
    }
  }
  return creases;
}

/// A bar along y, 2 long, of square section 0.6 wide whose four long edges
/// are chamfered `w` deep on each side, tilted (tpctest::TiltedMesh).
tpc::MeshSolid ChamferedBar(double w)
{
  const double h = 0.3;
  const tpc::MeshSolid straight = tpctest::PrismMesh({ { h, -h + w }, { h, h - w }, { h - w, h }, { -h + w, h },
                                                       { -h, h - w }, { -h, -h + w }, { -h + w, -h }, { h - w, -h } },
    -1.0, 1.0);
  return tpctest::TiltedMesh(straight);
}
} // namespace

TEST(CreaseFollowing, CreasesInCellAreTheSharpEdgesClippedToIt)
{
  // A unit cube's mesh (its faces' diagonals are flat edges): a cell holding
  // part of one of its edges gets that part, one holding only a face none.
  tpc::PrimitiveSet prims;
  prims.Meshes.push_back(tpctest::CubeMesh({ 0, 0, 0 }, { 1, 1, 1 }));
  tpc::CsgLeaf leaf;
  leaf.Kind = tpc::PrimitiveKind::Mesh;
  const std::vector<tpc::CreaseSegment> one = tpc::CreasesInCell(leaf, prims, { { 0.5, -0.5, 0.25 }, { 1.5, 0.5, 0.75 } });
  ASSERT_EQ(one.size(), 1u);
  const double z0 = std::min(one[0].A[2], one[0].B[2]), z1 = std::max(one[0].A[2], one[0].B[2]);
  EXPECT_DOUBLE_EQ(z0, 0.25);
  EXPECT_DOUBLE_EQ(z1, 0.75);
  EXPECT_DOUBLE_EQ(one[0].A[0], 1.0);
  EXPECT_DOUBLE_EQ(one[0].A[1], 0.0);
  EXPECT_TRUE(tpc::CreasesInCell(leaf, prims, { { 0.25, 0.25, 0.9 }, { 0.75, 0.75, 1.1 } }).empty());
}

TEST(CreaseFollowing, PatchCreasesWithinReach)
{
  const tpc::CreaseSegment along{ Vec3(0.1, 0, 0), Vec3(0.9, 0, 0) };
  const tpc::CreaseSegment beside{ Vec3(0.1, 0.5, 0), Vec3(0.9, 0.5, 0) };
  // Bent by 90 degrees: the shared edge is a crease of the patch.
  EXPECT_TRUE(tpc::CreasesFollowed({ along }, Hinge(90.0), 0.01));
  EXPECT_TRUE(tpc::CreasesFollowed({ beside }, Hinge(90.0), 0.6));
  // 0.5 away: not within 0.45 (nor within 0.52, the samples needing 1/16 of
  // the reach to spare).
  EXPECT_FALSE(tpc::CreasesFollowed({ beside }, Hinge(90.0), 0.45));
  EXPECT_FALSE(tpc::CreasesFollowed({ beside }, Hinge(90.0), 0.52));
  // Bent by 20 degrees (less than a crease's 30): the patch draws no crease.
  EXPECT_FALSE(tpc::CreasesFollowed({ along }, Hinge(20.0), 0.01));
  // No crease to follow.
  EXPECT_TRUE(tpc::CreasesFollowed({}, Hinge(20.0), 0.01));
  // The two triangles walking their common edge the same way are not one
  // patch's neighbours (an inconsistent pair): no crease.
  auto flipped = Hinge(90.0);
  std::swap(flipped[1][0], flipped[1][1]);
  EXPECT_FALSE(tpc::CreasesFollowed({ along }, flipped, 0.01));
}

TEST(CreaseFollowing, ACellsFanMovesItsApexOntoACreaseItMissed)
{
  // A roof in the unit cell: planes z = 0.6 - 1.5 |x - 0.5| meeting at the
  // ridge x = 0.5, z = 0.6 (112 degrees), crossing the bottom face at x =
  // 0.1 and 0.9; its loop runs through the ridge's crossings of the faces y =
  // 0 and y = 1. A fan around a point below the ridge cuts across it; the fan
  // around the ridge's point nearest that apex is the roof itself.
  const tpc::Box3 cell{ { 0, 0, 0 }, { 1, 1, 1 } };
  tpc::PolygonSet surface;
  surface.Add({ Vec3(0.1, 0, 0), Vec3(0.5, 0, 0.6), Vec3(0.5, 1, 0.6), Vec3(0.1, 1, 0) });
  surface.Add({ Vec3(0.5, 0, 0.6), Vec3(0.9, 0, 0), Vec3(0.9, 1, 0), Vec3(0.5, 1, 0.6) });
  const std::vector<tpc::CreaseSegment> ridge{ { Vec3(0.5, 0, 0.6), Vec3(0.5, 1, 0.6) } };
  tpc::AdaptiveOctree::MeshCellPrediction prediction;
  prediction.Loops = { { Vec3(0.1, 0, 0), Vec3(0.5, 0, 0.6), Vec3(0.9, 0, 0), Vec3(0.9, 1, 0), Vec3(0.5, 1, 0.6),
    Vec3(0.1, 1, 0) } };
  prediction.Apexes = { Vec3(0.5, 0.5, 0.3) };
  prediction.Delta = 0.01;
  const double tolerance = 0.1, reach = 0.1, slack = 1e-12;
  ASSERT_FALSE(tpc::CreasesFollowed(ridge, tpc::ApexFan(prediction.Loops[0], prediction.Apexes[0]), reach));
  // (A delta at the tolerance leaves no room: nothing changes.)
  tpc::AdaptiveOctree::MeshCellPrediction noRoom = prediction;
  noRoom.Delta = tolerance;
  EXPECT_FALSE(tpc::PredictCreaseApex(surface, cell, ridge, reach, slack, tolerance, noRoom));
  EXPECT_EQ(tpc::Norm(noRoom.Apexes[0] - prediction.Apexes[0]), 0.0);
  ASSERT_TRUE(tpc::PredictCreaseApex(surface, cell, ridge, reach, slack, tolerance, prediction));
  EXPECT_NEAR(tpc::Norm(prediction.Apexes[0] - Vec3(0.5, 0.5, 0.6)), 0.0, 1e-15);
  EXPECT_TRUE(tpc::CreasesFollowed(ridge, tpc::ApexFan(prediction.Loops[0], prediction.Apexes[0]), reach));
  // (The roof itself: no distance attained; the bound is the first proof
  // under the tolerance, as the prediction's.)
  EXPECT_LT(prediction.Attained, 1e-9);
  EXPECT_LE(prediction.OwnFanError, tolerance - prediction.Delta);
  EXPECT_NEAR(prediction.Bound, prediction.OwnFanError + prediction.Delta, 1e-15);
  // Every crease must be followed: with a second one no fan around a point
  // of either draws, the cell keeps its apex (and splits).
  std::vector<tpc::CreaseSegment> two = ridge;
  two.push_back({ Vec3(0.2, 0.3, 0.15), Vec3(0.2, 0.7, 0.15) });
  tpc::AdaptiveOctree::MeshCellPrediction missed;
  missed.Loops = prediction.Loops;
  missed.Apexes = { Vec3(0.5, 0.5, 0.3) };
  missed.Delta = 0.01;
  EXPECT_FALSE(tpc::PredictCreaseApex(surface, cell, two, reach, slack, tolerance, missed));
  EXPECT_EQ(tpc::Norm(missed.Apexes[0] - Vec3(0.5, 0.5, 0.3)), 0.0);
}

TEST(CreaseFollowing, CreaseApexSetsTakeEachLoopsCreasePointsInItsRoom)
{
  // One loop: CreaseApexes' points, in order, one set each (as the fan of a
  // lone loop has always tried them).
  const tpc::Box3 cell{ { 0, 0, 0 }, { 1, 1, 1 } };
  const std::vector<tpc::CreaseSegment> creases{ { Vec3(0.2, 0, 0.3), Vec3(0.2, 1, 0.3) },
    { Vec3(0.8, 0, 0.7), Vec3(0.8, 1, 0.7) } };
  const std::vector<Vec3> lower{ Vec3(0, 0, 0.2), Vec3(0.4, 0, 0.4), Vec3(0.4, 1, 0.4), Vec3(0, 1, 0.2) };
  const std::vector<Vec3> upper{ Vec3(0.6, 0, 0.6), Vec3(1, 0, 0.8), Vec3(1, 1, 0.8), Vec3(0.6, 1, 0.6) };
  const std::vector<Vec3> one = tpc::CreaseApexes(cell, creases, Vec3(0.3, 0.5, 0.3));
  const std::vector<std::vector<Vec3>> sets = tpc::CreaseApexSets(cell, creases, { lower }, { Vec3(0.3, 0.5, 0.3) });
  ASSERT_EQ(sets.size(), one.size());
  for (std::size_t k = 0; k < one.size(); ++k)
  {
    ASSERT_EQ(sets[k].size(), 1u);
    EXPECT_EQ(tpc::Norm(sets[k][0] - one[k]), 0.0);
  }
  // Two loops, apart along x (the cell is cut at x = 0.5): each takes the
  // point of the crease in its own room, never the other's.
  const std::vector<std::vector<Vec3>> two =
    tpc::CreaseApexSets(cell, creases, { lower, upper }, { Vec3(0.3, 0.5, 0.3), Vec3(0.7, 0.5, 0.7) });
  ASSERT_FALSE(two.empty());
  const std::vector<tpc::ApexRoom> rooms = tpc::ApexRooms({ lower, upper }, cell);
  for (const std::vector<Vec3>& set : two)
  {
    ASSERT_EQ(set.size(), 2u);
    EXPECT_TRUE(tpc::InRoom(set[0], rooms[0]));
    EXPECT_TRUE(tpc::InRoom(set[1], rooms[1]));
  }
  EXPECT_NEAR(two[0][0][0], 0.2, 1e-15);
  EXPECT_NEAR(two[0][1][0], 0.8, 1e-15);
  // No crease point for either loop: no set (the loops' own fans are the
  // ones that missed).
  EXPECT_TRUE(tpc::CreaseApexSets(cell, {}, { lower, upper }, { Vec3(0.3, 0.5, 0.3), Vec3(0.7, 0.5, 0.7) }).empty());
}

TEST(CreaseFollowing, ChamferedBarsCreasesLieWithinTheToleranceOfOutputCreases)
{
  // Chamfers 1-3 tolerances wide: each face tile crossed by both edges of a
  // chamfer is drawn through one of them, and a large cell's fan then cut the
  // other, up to 1.6 and 2.3 tolerances away at 1/64 and 1/128 before cells
  // were required to follow their creases (1 192 and 1 710 triangles; now
  // 1 370 and 2 244, at most 0.94 tolerances away: a cell whose apex fan
  // misses a crease is fanned around a point of a crease where that follows,
  // and 11 and 27 cells split for a crease - 1 860 and 2 790 triangles, 41
  // and 71 cells, with apex fans only).
  for (const double relative : { 1.0 / 64, 1.0 / 128 })
  {
    const tpc::MeshSolid bar = ChamferedBar(0.05);
    tpctest::SceneBuilder b;
    b.Finish(b.Mesh(bar));
    const tpctest::ContourRun r = tpctest::Contour(b.Scene, bar.Bounds(), relative);
    EXPECT_TRUE(r.Guaranteed);
    EXPECT_EQ(r.Report.Genus, 0);
    const auto input = Creases(bar.Points(), bar.Triangles(), tpc::FollowedCreaseDegrees);
    const auto output = Creases(r.Extraction.Mesh.Points.ToVector(), r.Extraction.Mesh.Triangles.ToVector(), 30.0);
    ASSERT_EQ(input.size(), 24u); // (8 long edges, 8 around each end)
    double worst = 0.0;
    for (const auto& e : input)
    {
      for (int k = 0; k <= 200; ++k)
      {
        const Vec3 p = e[0] + (e[1] - e[0]) * (k / 200.0);
        double nearest = HUGE_VAL;
        for (const auto& o : output)
        {
          nearest = std::min(nearest, tpc::SegmentDistance(p, o[0], o[1]));
        }
        worst = std::max(worst, nearest);
      }
    }
    const auto& splits = r.Subdivision.SplitsByReason;
    std::cout << "chamfered bar at 1/" << std::lround(1.0 / relative) << ": " << r.Extraction.Mesh.Triangles.size()
              << " triangles, worst crease " << worst / r.Tolerance << " tolerance from an output crease, "
              << splits[static_cast<int>(tpc::SplitReason::CreaseNotFollowed)] << " cells split to follow creases\n";
    EXPECT_LE(worst, r.Tolerance);
    EXPECT_GT(splits[static_cast<int>(tpc::SplitReason::CreaseNotFollowed)], 0u);
  }
}
