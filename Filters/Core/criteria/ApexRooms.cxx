#include "ApexRooms.h"

#include <algorithm>
#include <cmath>

namespace tpc
{

Box3 ApexRegion(const std::vector<Box3>& loopBoxes, std::size_t i, const Box3& cell)
{
  Box3 region = cell;
  const Box3& own = loopBoxes[i];
  for (std::size_t j = 0; j < loopBoxes.size(); ++j)
  {
    if (j == i)
    {
      continue;
    }
    const Box3& other = loopBoxes[j];
    // The axis with the widest gap between the two boxes, if any.
    int axis = -1;
    double gap = 0.0, cut = 0.0;
    bool below = false;
    for (int a = 0; a < 3; ++a)
    {
      const double up = other.lo[a] - own.hi[a], down = own.lo[a] - other.hi[a];
      if (up > gap || down > gap)
      {
        axis = a;
        below = up > down;
        gap = std::max(up, down);
        cut = below ? 0.5 * (own.hi[a] + other.lo[a]) : 0.5 * (other.hi[a] + own.lo[a]);
      }
    }
    if (axis >= 0)
    {
      (below ? region.hi[axis] : region.lo[axis]) =
        below ? std::min(region.hi[axis], cut) : std::max(region.lo[axis], cut);
    }
  }
  return region;
}

std::vector<ApexRoom> ApexRooms(const std::vector<std::vector<Vec3>>& loopPoints, const Box3& cell)
{
  if (loopPoints.size() == 1)
  {
    return { ApexRoom{ cell, {} } };
  }
  std::vector<Box3> boxes;
  for (const std::vector<Vec3>& loop : loopPoints)
  {
    // (An empty loop - none is traced - has an empty box, apart from none.)
    boxes.push_back(loop.empty() ? Box3{ { HUGE_VAL, HUGE_VAL, HUGE_VAL }, { -HUGE_VAL, -HUGE_VAL, -HUGE_VAL } }
                                 : BoundsOf(loop.data(), loop.size()));
  }
  std::vector<ApexRoom> rooms;
  for (std::size_t i = 0; i < loopPoints.size(); ++i)
  {
    rooms.push_back({ ApexRegion(boxes, i, cell), {} });
  }
  // One plane per pair of loops whose boxes overlap, each loop below it on
  // its own side (the header's argument needs the same plane for both).
  for (std::size_t i = 0; i < loopPoints.size(); ++i)
  {
    for (std::size_t j = i + 1; j < loopPoints.size(); ++j)
    {
      SeparatingPlane plane;
      if (boxes[i].Overlaps(boxes[j]) && FindSeparatingPlane(loopPoints[i], loopPoints[j], plane))
      {
        rooms[i].Below.push_back(plane);
        rooms[j].Below.push_back({ plane.Normal * -1.0, -plane.Offset, plane.Gap });
      }
    }
  }
  return rooms;
}

bool InRoom(const Vec3& p, const ApexRoom& room)
{
  for (const SeparatingPlane& plane : room.Below)
  {
    if (!(Dot(plane.Normal, p) < plane.Offset - 0.25 * plane.Gap))
    {
      return false;
    }
  }
  return StrictlyInside(p, room.Region);
}

Vec3 KeptInRoom(Vec3 apex, const Vec3& fallback, const ApexRoom& room)
{
  for (int round = 0; round < 4 && !InRoom(apex, room); ++round)
  {
    for (const SeparatingPlane& plane : room.Below)
    {
      const double excess = Dot(plane.Normal, apex) - (plane.Offset - 0.375 * plane.Gap);
      if (excess > 0.0)
      {
        apex = apex - plane.Normal * excess;
      }
    }
    apex = ClampStrictlyInside(apex, room.Region);
  }
  return InRoom(apex, room) ? apex : ClampStrictlyInside(fallback, room.Region);
}

std::vector<Vec3> InRoomOnly(const std::vector<Vec3>& candidates, const ApexRoom& room)
{
  std::vector<Vec3> in;
  for (const Vec3& p : candidates)
  {
    if (InRoom(p, room))
    {
      in.push_back(p);
    }
  }
  return in;
}

std::vector<std::vector<Vec3>> KthApexSets(const std::vector<std::vector<Vec3>>& perLoop, std::size_t most)
{
  std::size_t tries = 0;
  for (const std::vector<Vec3>& candidates : perLoop)
  {
    if (candidates.empty())
    {
      return {};
    }
    tries = std::max(tries, candidates.size());
  }
  std::vector<std::vector<Vec3>> sets;
  for (std::size_t k = 0; k < std::min(tries, most); ++k)
  {
    sets.emplace_back();
    for (const std::vector<Vec3>& candidates : perLoop)
    {
      sets.back().push_back(candidates[std::min(k, candidates.size() - 1)]);
    }
  }
  return sets;
}

bool StrictlyInside(const Vec3& p, const Box3& box)
{
  for (int a = 0; a < 3; ++a)
  {
    if (!(p[a] > box.lo[a] && p[a] < box.hi[a]))
    {
      return false;
    }
  }
  return true;
}

Vec3 ClampStrictlyInside(const Vec3& p, const Box3& box)
{
  Vec3 q = p;
  for (int a = 0; a < 3; ++a)
  {
    const double lo = std::nextafter(box.lo[a], HUGE_VAL), hi = std::nextafter(box.hi[a], -HUGE_VAL);
    q[a] = lo <= hi ? std::clamp(p[a], lo, hi) : 0.5 * (box.lo[a] + box.hi[a]);
  }
  return q;
}

} // namespace tpc
