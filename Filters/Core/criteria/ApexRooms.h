// Where the apex of each of a cell's loops may lie (paper 4.3, several loops
// in one cell), so that the fans around them stay apart: the extraction
// places its apexes there (LoopTriangulation.h), and the subdivision's
// prediction of a cell with several loops places its own there too
// (MeshCellError.h: Several loops), so that it predicts the fans the
// extraction will draw.
//
// A cell passes the tests with several loops only when every two are
// separated by a plane that the surface does not meet (LoopsSeparated,
// ComplexCellCriterion.h): axis-aligned, so their points' bounding boxes are
// apart along some axis, or oblique. A patch lies in the convex hull of its
// loop and apex. ApexRegion cuts the cell halfway between the boxes of every
// two loops apart along an axis; ApexRooms finds one plane between the
// points of two loops that are not, each loop below it on its own side. Each
// loop's points lie inside its own region and below its own cuts by half
// their gaps; with its apex strictly inside its region and below its cuts by
// a quarter of their gaps (InRoom), loop i's patch lies strictly on its side
// of each cut and loop j's strictly on the other: the patches of different
// loops lie strictly on opposite sides of a plane, so they do not meet.
// Every comparison is exact on the computed coordinates.
#pragma once

#include "SeparatingPlane.h"
#include "Vector3.h"

#include <cstddef>
#include <vector>

namespace tpc
{

/// Where one loop's apex may lie: strictly inside Region and below every
/// plane of Below by a quarter of its gap.
struct ApexRoom
{
  Box3 Region;
  std::vector<SeparatingPlane> Below;
};

/// The open region of `cell` where loop `i`'s apex may lie: the cell cut, for
/// every other loop whose bounding box is apart from loop i's along some axis,
/// halfway between the two boxes. Loops not apart from loop i do not cut it
/// (see ApexRooms).
Box3 ApexRegion(const std::vector<Box3>& loopBoxes, std::size_t i, const Box3& cell);

/// Each loop's room in `cell`, the loops given by their points: the whole
/// cell for a lone loop, else ApexRegion and, for every other loop whose box
/// is not apart from its own along any axis (two sheets beside a thin
/// wedge's edge, which the subdivision separated by an oblique plane,
/// LoopsSeparated), a plane between the two loops' points, the same for
/// both, each below it on its side. None found (cells stopped by a limit):
/// no cut, and the exact check of the output decides (SurfaceEmbedding.h).
std::vector<ApexRoom> ApexRooms(const std::vector<std::vector<Vec3>>& loopPoints, const Box3& cell);

/// Whether `p` lies in `room` (strictly inside its region, below each cut by
/// a quarter of its gap).
bool InRoom(const Vec3& p, const ApexRoom& room);

/// `apex` moved into `room`: pushed below its cuts to 3/8 of their gaps and
/// clamped strictly inside its region, a few rounds; `fallback` (the loop's
/// centroid, below its cuts by half their gaps) clamped there where that
/// does not settle.
Vec3 KeptInRoom(Vec3 apex, const Vec3& fallback, const ApexRoom& room);

/// `candidates` that lie in `room` (InRoom), in order.
std::vector<Vec3> InRoomOnly(const std::vector<Vec3>& candidates, const ApexRoom& room);

/// The sets of apexes to try, one per loop, from each loop's candidates in
/// order (`perLoop`): the k-th set takes each loop's k-th candidate, or its
/// last; at most `most` sets, none where a loop has no candidate.
std::vector<std::vector<Vec3>> KthApexSets(const std::vector<std::vector<Vec3>>& perLoop, std::size_t most);

/// True when `p` lies strictly inside `box` on every axis (exact comparisons).
bool StrictlyInside(const Vec3& p, const Box3& box);

/// The point of the open box nearest to `p` on each axis: `p` itself where it
/// is strictly inside, else the representable value next to the violated side
/// (or the midpoint for a box too thin to hold one).
Vec3 ClampStrictlyInside(const Vec3& p, const Box3& box);

} // namespace tpc
