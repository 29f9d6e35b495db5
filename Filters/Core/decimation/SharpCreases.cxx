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

/// min over segments of max(d(a, s), d(b, s)): the distance to the segments
/// over all of ab is at most this (convexity, header).
double UpperOver(const Vec3& a, const Vec3& b, const std::vector<EdgeSegment>& segments)
{
  double upper = HUGE_VAL;
  for (const EdgeSegment& s : segments)
  {
    upper = std::min(upper, std::max(SegmentDistance(a, s.A, s.B), SegmentDistance(b, s.A, s.B)));
  }
  return upper;
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
    if (UpperOver(piece.A, piece.B, after) <= reach)
    {
      continue;
    }
    for (const Vec3& end : { piece.A, piece.B })
    {
      if (DistanceToSegments(end, removed) <= reach && DistanceToSegments(end, after) > reach)
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
