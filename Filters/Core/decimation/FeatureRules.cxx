#include "FeatureRules.h"

#include "ConvexPolygons.h"

namespace tpc
{

bool MovesAlongFeatures(const LiveSurface& surface, const Collapse& c)
{
  std::size_t features = 0;
  bool towardsTo = false;
  for (const std::uint32_t w : surface.Neighbours(c.From))
  {
    if (surface.IsFeature(c.From, w))
    {
      ++features;
      towardsTo |= w == c.To;
    }
  }
  return features == 0 || (features == 2 && towardsTo);
}

bool MakesNoFeature(const LiveSurface& surface, const Collapse& c)
{
  for (const Triangle& t : c.Made)
  {
    for (int k = 0; k < 3; ++k)
    {
      const std::uint32_t x = t[k], y = t[(k + 1) % 3];
      bool bent = false;
      if (!surface.EdgeAfter(c, x, y, bent))
      {
        return false; // (never in a closed manifold after a collapse the link condition allows)
      }
      if (!bent)
      {
        continue;
      }
      // A feature now: it must be the image of one before (From's edges
      // become To's).
      const std::uint32_t z = x == c.To ? y : (y == c.To ? x : c.From);
      const bool before = z == c.From ? surface.IsFeature(x, y)
                                      : surface.IsFeature(c.From, z) ||
          (surface.EdgeTriangles(c.To, z).size() == 2 && surface.IsFeature(c.To, z));
      if (!before)
      {
        return false;
      }
    }
  }
  return true;
}

bool KeepsFeatures(const LiveSurface& surface, const Collapse& c)
{
  // (Images: From's edges become To's; the vanishing triangles' edges To w
  // too, whose other triangle changes.)
  for (const std::vector<std::uint32_t>* part : { &c.Kept, &c.Vanishing })
  {
    for (const std::uint32_t t : *part)
    {
      const Triangle& old = surface.Triangles[t];
      for (int k = 0; k < 3; ++k)
      {
        const std::uint32_t u = old[k], v = old[(k + 1) % 3];
        const std::uint32_t x = u == c.From ? c.To : u, y = v == c.From ? c.To : v;
        if (x != y && surface.IsFeature(u, v) && !surface.IsFeatureAfter(c, x, y))
        {
          return false;
        }
      }
    }
  }
  return true;
}

SharpCreaseRule::SharpCreaseRule(const Vec3& origin, double bucketWidth)
  : Grid(origin, bucketWidth)
{
}

SharpCreaseRule::SharpCreaseRule(const MeshSolid& mesh, const Vec3& origin, double bucketWidth)
  : Sharp(SharpEdges(mesh, SharpCreaseAngle))
  , Grid(origin, bucketWidth)
{
  for (std::uint32_t k = 0; k < this->Sharp.size(); ++k)
  {
    const Vec3 ends[2] = { this->Sharp[k].A, this->Sharp[k].B };
    this->Grid.Insert(k, BoundsOf(ends, 2));
  }
}

bool SharpCreaseRule::KeepsFollowed(const LiveSurface& surface, const Collapse& c, double tolerance, double slack,
  VisitMarks& creaseMarks, VisitMarks& triangleMarks) const
{
  if (this->Sharp.empty())
  {
    return true;
  }
  // Removed: feature edges of the star that are not feature edges after
  // (gone, or no longer bent). Only edges with a triangle in the star change
  // (SharpCreases.h); most collapses remove none.
  // (An edge of From's is gone: removed if it was a feature.)
  std::vector<EdgeSegment> removed;
  for (const auto& [x, y] : EdgesOf(surface.StarOf(c)))
  {
    const bool now = x != c.From && y != c.From && surface.IsFeatureAfter(c, x, y);
    if (!now && surface.IsFeature(x, y))
    {
      removed.push_back({ surface.P[x], surface.P[y] });
    }
  }
  if (removed.empty())
  {
    return true;
  }
  // The sharp creases within reach of a removed edge, and the feature edges
  // after within reach of those (from the triangles there).
  const double reach = tolerance - slack;
  std::vector<Vec3> ends;
  for (const EdgeSegment& e : removed)
  {
    ends.insert(ends.end(), { e.A, e.B });
  }
  const Box3 region = GrownBy(BoundsOf(ends.data(), ends.size()), tolerance);
  std::vector<EdgeSegment> pieces;
  creaseMarks.Start(this->Sharp.size());
  this->Grid.ForEachListed(region, [&](std::uint32_t k) {
    if (creaseMarks.First(k))
    {
      EdgeSegment piece = this->Sharp[k];
      if (ClipSegment(piece.A, piece.B, region))
      {
        pieces.push_back(piece);
      }
    }
  });
  if (pieces.empty())
  {
    return true;
  }
  std::vector<Triangle> near = c.Made;
  surface.ForEachOther(
    c, GrownBy(region, tolerance), triangleMarks, [&](std::uint32_t o) { near.push_back(surface.Triangles[o]); });
  std::vector<EdgeSegment> after;
  for (const auto& [x, y] : EdgesOf(near))
  {
    if (surface.IsFeatureAfter(c, x, y))
    {
      after.push_back({ surface.P[x], surface.P[y] });
    }
  }
  for (const EdgeSegment& piece : pieces)
  {
    if (!StaysFollowed(piece.A, piece.B, removed, after, reach))
    {
      return false;
    }
  }
  return true;
}

} // namespace tpc
