// Where each of a cell's loops may have its apex (ApexRooms.h): regions cut
// halfway between loops apart along an axis, oblique cuts between loops that
// are not, and apexes moved into their rooms so that the patches of
// different loops lie strictly on opposite sides of a plane.
#include "ApexRooms.h"

#include <gtest/gtest.h>

#include <cmath>
#include <vector>

using tpc::Box3;
using tpc::Vec3;

namespace
{
const Box3 Cell{ { 0, 0, 0 }, { 1, 1, 1 } };

/// Whether every point of `a` lies strictly below `plane` and every point of
/// `b` strictly above it.
bool Separates(const tpc::SeparatingPlane& plane, const std::vector<Vec3>& a, const std::vector<Vec3>& b)
{
  for (const Vec3& p : a)
  {
    if (!(tpc::Dot(plane.Normal, p) < plane.Offset))
    {
      return false;
    }
  }
  for (const Vec3& p : b)
  {
    if (!(tpc::Dot(plane.Normal, p) > plane.Offset))
    {
      return false;
    }
  }
  return true;
}
} // namespace

TEST(ApexRooms, LoopsApartAlongAnAxisCutTheCellHalfwayBetweenThem)
{
  // Two loops whose boxes are apart along x: each apex region is cut halfway
  // between them, so their fans lie on opposite sides of that plane.
  const std::vector<Box3> boxes = { { { 0, 0, 0 }, { 0.2, 1, 1 } }, { { 0.6, 0, 0 }, { 1, 1, 1 } } };
  const Box3 left = tpc::ApexRegion(boxes, 0, Cell), right = tpc::ApexRegion(boxes, 1, Cell);
  EXPECT_DOUBLE_EQ(left.hi[0], 0.4);
  EXPECT_DOUBLE_EQ(right.lo[0], 0.4);
  EXPECT_EQ(left.lo[0], 0.0);
  EXPECT_EQ(right.hi[0], 1.0);
  // Overlapping boxes (a cell stopped by a limit) do not cut each other.
  const std::vector<Box3> overlapping = { { { 0, 0, 0 }, { 0.7, 1, 1 } }, { { 0.6, 0, 0 }, { 1, 1, 1 } } };
  const Box3 whole = tpc::ApexRegion(overlapping, 0, Cell);
  EXPECT_EQ(whole.hi[0], 1.0);
}

TEST(ApexRooms, ALoneLoopHasTheWholeCell)
{
  const std::vector<tpc::ApexRoom> rooms = tpc::ApexRooms({ { Vec3(0, 0.5, 0.5), Vec3(1, 0.5, 0.5), Vec3(0.5, 1, 0) } }, Cell);
  ASSERT_EQ(rooms.size(), 1u);
  EXPECT_EQ(rooms[0].Below.size(), 0u);
  for (int a = 0; a < 3; ++a)
  {
    EXPECT_EQ(rooms[0].Region.lo[a], Cell.lo[a]);
    EXPECT_EQ(rooms[0].Region.hi[a], Cell.hi[a]);
  }
  // Strictly inside: the cell's faces are not in the room.
  EXPECT_TRUE(tpc::InRoom(Vec3(0.5, 0.5, 0.5), rooms[0]));
  EXPECT_FALSE(tpc::InRoom(Vec3(0.0, 0.5, 0.5), rooms[0]));
}

TEST(ApexRooms, SheetsBesideAWedgeAreCutObliquelyAndTheirApexesKeptApart)
{
  // The two sheets beside a thin wedge's edge, parallel to no axis: their
  // loops' boxes overlap on every axis, so each room is cut by a plane
  // between the two loops' points. An apex placed beyond it - where the
  // least squares put it between the sheets - moves below it by at least a
  // quarter of its gap, and a patch in the hull of its loop and apex then
  // lies strictly on its side.
  const std::vector<Vec3> lower{ Vec3(0, 0.1, 0.05), Vec3(1, 0.5, 0.45), Vec3(1, 0.9, 0.85), Vec3(0, 0.5, 0.45) };
  const std::vector<Vec3> upper{ Vec3(0, 0.1, 0.25), Vec3(1, 0.5, 0.65), Vec3(1, 0.9, 1.0), Vec3(0, 0.5, 0.65) };
  const std::vector<tpc::ApexRoom> rooms = tpc::ApexRooms({ lower, upper }, Cell);
  ASSERT_EQ(rooms.size(), 2u);
  ASSERT_EQ(rooms[0].Below.size(), 1u);
  ASSERT_EQ(rooms[1].Below.size(), 1u);
  EXPECT_TRUE(Separates(rooms[0].Below[0], lower, upper));
  EXPECT_TRUE(Separates(rooms[1].Below[0], upper, lower));
  // One plane for both, each loop below it on its own side (the embedding
  // argument needs the same plane).
  for (int a = 0; a < 3; ++a)
  {
    EXPECT_EQ(rooms[1].Below[0].Normal[a], -rooms[0].Below[0].Normal[a]);
  }
  EXPECT_EQ(rooms[1].Below[0].Offset, -rooms[0].Below[0].Offset);
  EXPECT_EQ(rooms[1].Below[0].Gap, rooms[0].Below[0].Gap);
  const Vec3 between(0.5, 0.5, 0.55); // (on neither sheet: between them)
  const Vec3 low = tpc::KeptInRoom(between, Vec3(0.5, 0.5, 0.45), rooms[0]);
  const Vec3 high = tpc::KeptInRoom(between, Vec3(0.5, 0.5, 0.65), rooms[1]);
  EXPECT_TRUE(tpc::InRoom(low, rooms[0]));
  EXPECT_TRUE(tpc::InRoom(high, rooms[1]));
  EXPECT_FALSE(tpc::InRoom(low, rooms[1]));
  EXPECT_FALSE(tpc::InRoom(high, rooms[0]));
  std::vector<Vec3> lowHull = lower, highHull = upper;
  lowHull.push_back(low);
  highHull.push_back(high);
  EXPECT_TRUE(Separates(rooms[0].Below[0], lowHull, highHull));
  // An apex already in its room stays where it is.
  EXPECT_EQ(tpc::Norm(tpc::KeptInRoom(low, Vec3(), rooms[0]) - low), 0.0);
}

TEST(ApexRooms, AnApexThatCannotSettleFallsBackOnItsLoopsCentroid)
{
  // A room no point holds (a cut below the whole region - only from a cell
  // stopped by a limit, whose loops need not be separated): the apex falls
  // back on the loop's centroid clamped strictly inside the region, and the
  // exact check of the output decides (SurfaceEmbedding.h).
  const tpc::ApexRoom room{ Cell, { tpc::SeparatingPlane{ Vec3(1, 0, 0), -0.5, 0.1 } } };
  const Vec3 kept = tpc::KeptInRoom(Vec3(0.5, 0.5, 0.5), Vec3(0.25, 0.25, 0.25), room);
  EXPECT_EQ(tpc::Norm(kept - Vec3(0.25, 0.25, 0.25)), 0.0);
  EXPECT_FALSE(tpc::InRoom(kept, room));
  // A centroid on the region's side is moved strictly inside it.
  const Vec3 clamped = tpc::KeptInRoom(Vec3(0.5, 0.5, 0.5), Vec3(0.0, 0.25, 1.0), room);
  EXPECT_EQ(clamped[0], std::nextafter(0.0, 1.0));
  EXPECT_EQ(clamped[2], std::nextafter(1.0, 0.0));
}

TEST(ApexRooms, TheKthSetTakesEachLoopsKthCandidateOrItsLast)
{
  const std::vector<std::vector<Vec3>> perLoop{ { Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(2, 0, 0) },
    { Vec3(0, 1, 0) } };
  const std::vector<std::vector<Vec3>> sets = tpc::KthApexSets(perLoop, 8);
  ASSERT_EQ(sets.size(), 3u);
  for (std::size_t k = 0; k < sets.size(); ++k)
  {
    ASSERT_EQ(sets[k].size(), 2u);
    EXPECT_EQ(sets[k][0][0], static_cast<double>(k));
    EXPECT_EQ(sets[k][1][1], 1.0); // (the second loop's only candidate)
  }
  EXPECT_EQ(tpc::KthApexSets(perLoop, 2).size(), 2u);
  // A loop without a candidate: no set.
  EXPECT_TRUE(tpc::KthApexSets({ { Vec3(0, 0, 0) }, {} }, 8).empty());
  // Candidates outside a room are left out, in order.
  const tpc::ApexRoom room{ Cell, {} };
  const std::vector<Vec3> in = tpc::InRoomOnly({ Vec3(0.5, 0.5, 0.5), Vec3(0, 0.5, 0.5), Vec3(0.25, 0.5, 0.5) }, room);
  ASSERT_EQ(in.size(), 2u);
  EXPECT_EQ(in[1][0], 0.25);
}
