#include "SharpCreases.h"

#include "ConvexPolygons.h"

#include <algorithm>
#include <cmath>

namespace tpc
{

std::vector<EdgeSegment> SharpEdges(const MeshSolid& mesh, double degrees)
{
  const double cosine = std::cos(degrees * M_PI / 180.0);
  std::vector<EdgeSegment> sharp;
  const auto& triangles = mesh.Triangles();
  for (std::uint32_t t = 0; t < triangles.size(); ++t)
  {
    for (int k = 0; k < 3; ++k)
    {
      const std::uint32_t other = mesh.Across(t, k);
      // (Each edge once, from its lower-numbered triangle.)
      if (other != MeshSolid::NoTriangle && t < other && Dot(mesh.Normal(t), mesh.Normal(other)) <= cosine)
      {
        sharp.push_back({ mesh.Points()[triangles[t][k]], mesh.Points()[triangles[t][(k + 1) % 3]] });
      }
    }
  }
  return sharp;
}

double DistanceToSegments(const Vec3& p, const std::vector<EdgeSegment>& segments)
{
  double nearest = HUGE_VAL;
  for (const EdgeSegment& s : segments)
  {
    nearest = std::min(nearest, SegmentDistance(p, s.A, s.B));
  }
  return nearest;
}

namespace
{

/// Whether one segment lies within `reach` of both a and b - then, by
/// convexity (header), of all of ab. (Stops at the first: only whether
/// one does matters.)
bool OneFollowsAll(const Vec3& a, const Vec3& b, const std::vector<EdgeSegment>& segments, double reach)
{
  for (const EdgeSegment& s : segments)
  {
    if (SegmentDistance(a, s.A, s.B) <= reach && SegmentDistance(b, s.A, s.B) <= reach)
    {
      return true;
    }
  }
  return false;
}

/// Whether a segment lies within `reach` of p.
bool AnyWithin(const Vec3& p, const std::vector<EdgeSegment>& segments, double reach)
{
  for (const EdgeSegment& s : segments)
  {
    if (SegmentDistance(p, s.A, s.B) <= reach)
    {
      return true;
    }
  }
  return false;
}

} // namespace

bool StaysFollowed(const Vec3& a, const Vec3& b, const std::vector<EdgeSegment>& removed,
  const std::vector<EdgeSegment>& after, double reach, std::size_t budget)
{
  if (removed.empty())
  {
    return true;
  }
  std::vector<EdgeSegment> pieces{ { a, b } };
  std::size_t examined = 0;
  while (!pieces.empty())
  {
    const EdgeSegment piece = pieces.back();
    pieces.pop_back();
    if (++examined > budget)
    {
      return false;
    }
    // (The removed edges, a few, before the edges after, often hundreds:
    // either test settles the piece.)
    const Vec3 middle = (piece.A + piece.B) * 0.5;
    if (DistanceToSegments(middle, removed) - 0.5 * Norm(piece.B - piece.A) > reach)
    {
      continue; // (no removed edge within reach of the piece)
    }
    if (OneFollowsAll(piece.A, piece.B, after, reach))
    {
      continue;
    }
    for (const Vec3& end : { piece.A, piece.B })
    {
      if (AnyWithin(end, removed, reach) && !AnyWithin(end, after, reach))
      {
        return false;
      }
    }
    pieces.push_back({ piece.A, middle });
    pieces.push_back({ middle, piece.B });
  }
  return true;
}

} // namespace tpc
