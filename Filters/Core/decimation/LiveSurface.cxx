#include "LiveSurface.h"

#include "SelfIntersection.h"

#include <algorithm>
#include <cmath>
#include <iterator>

namespace tpc
{
namespace
{

Triangle Replaced(Triangle t, std::uint32_t v, std::uint32_t u)
{
  for (std::uint32_t& x : t)
  {
    x = x == v ? u : x;
  }
  return t;
}

/// The vertex of `t` that is neither a nor b.
std::uint32_t Opposite(const Triangle& t, std::uint32_t a, std::uint32_t b)
{
  for (const std::uint32_t x : t)
  {
    if (x != a && x != b)
    {
      return x;
    }
  }
  return t[0];
}

} // namespace

Box3 GrownBy(Box3 box, double margin)
{
  for (int a = 0; a < 3; ++a)
  {
    box.lo[a] -= margin;
    box.hi[a] += margin;
  }
  return box;
}

Box3 Union(Box3 a, const Box3& b)
{
  for (int k = 0; k < 3; ++k)
  {
    a.lo[k] = std::min(a.lo[k], b.lo[k]);
    a.hi[k] = std::max(a.hi[k], b.hi[k]);
  }
  return a;
}

Box3 BoxOf(const Vec3* points, const std::vector<Triangle>& triangles)
{
  Box3 box = TriangleBox(points, triangles.front());
  for (const Triangle& t : triangles)
  {
    box = Union(box, TriangleBox(points, t));
  }
  return box;
}

std::vector<std::pair<std::uint32_t, std::uint32_t>> EdgesOf(const std::vector<Triangle>& triangles)
{
  std::vector<std::pair<std::uint32_t, std::uint32_t>> edges;
  for (const Triangle& t : triangles)
  {
    for (int k = 0; k < 3; ++k)
    {
      edges.emplace_back(std::min(t[k], t[(k + 1) % 3]), std::max(t[k], t[(k + 1) % 3]));
    }
  }
  std::sort(edges.begin(), edges.end());
  edges.erase(std::unique(edges.begin(), edges.end()), edges.end());
  return edges;
}

LiveSurface::LiveSurface(const TriangleMesh& mesh, const ReleasableArray<std::int32_t>& labels,
  double featureAngle, double bucketWidth)
  : P(mesh.Points.data())
  , Triangles(mesh.Triangles.begin(), mesh.Triangles.end())
  , Alive(mesh.Triangles.size(), 1)
  , Around(mesh.Points.size())
  , Grid(mesh.Points.empty() ? Vec3() : BoundsOf(mesh.Points.data(), mesh.Points.size()).lo, bucketWidth)
  , Labels(labels)
  , CosFeatureAngle(std::cos(featureAngle * M_PI / 180.0))
{
  for (std::uint32_t t = 0; t < this->Triangles.size(); ++t)
  {
    for (const std::uint32_t v : this->Triangles[t])
    {
      this->Around[v].push_back(t);
    }
    this->Grid.Insert(t, TriangleBox(this->P, this->Triangles[t]));
  }
}

std::vector<std::uint32_t> LiveSurface::Neighbours(std::uint32_t v) const
{
  std::vector<std::uint32_t> n;
  for (const std::uint32_t t : this->Around[v])
  {
    for (const std::uint32_t x : this->Triangles[t])
    {
      if (x != v)
      {
        n.push_back(x);
      }
    }
  }
  std::sort(n.begin(), n.end());
  n.erase(std::unique(n.begin(), n.end()), n.end());
  return n;
}

std::vector<std::uint32_t> LiveSurface::EdgeTriangles(std::uint32_t a, std::uint32_t b) const
{
  std::vector<std::uint32_t> both;
  for (const std::uint32_t t : this->Around[a])
  {
    if (Holds(this->Triangles[t], b))
    {
      both.push_back(t);
    }
  }
  return both;
}

bool LiveSurface::IsFeature(std::uint32_t a, std::uint32_t b) const
{
  const std::vector<std::uint32_t> both = this->EdgeTriangles(a, b);
  if (both.size() != 2)
  {
    return true; // (not an edge of a closed manifold: never moved)
  }
  return this->Bent(this->Normal(this->Triangles[both[0]]), this->LabelOf(both[0]),
    this->Normal(this->Triangles[both[1]]), this->LabelOf(both[1]));
}

bool LiveSurface::Describe(Collapse& c) const
{
  for (const std::uint32_t t : this->Around[c.From])
  {
    if (Holds(this->Triangles[t], c.To))
    {
      c.Vanishing.push_back(t);
    }
    else
    {
      c.Kept.push_back(t);
      c.Made.push_back(Replaced(this->Triangles[t], c.From, c.To));
    }
  }
  return c.Vanishing.size() == 2 && !c.Kept.empty();
}

std::vector<Triangle> LiveSurface::StarOf(const Collapse& c) const
{
  std::vector<Triangle> star;
  for (const std::vector<std::uint32_t>* part : { &c.Vanishing, &c.Kept })
  {
    for (const std::uint32_t t : *part)
    {
      star.push_back(this->Triangles[t]);
    }
  }
  return star;
}

bool LiveSurface::EdgeAfter(const Collapse& c, std::uint32_t x, std::uint32_t y, bool& bent) const
{
  std::vector<Vec3> normals;
  std::vector<std::int32_t> labels;
  for (std::size_t j = 0; j < c.Made.size(); ++j)
  {
    if (Holds(c.Made[j], x) && Holds(c.Made[j], y))
    {
      normals.push_back(this->Normal(c.Made[j]));
      labels.push_back(this->LabelOf(c.Kept[j]));
    }
  }
  for (const std::uint32_t o : this->Around[x])
  {
    if (!Holds(this->Triangles[o], c.From) && Holds(this->Triangles[o], y))
    {
      normals.push_back(this->Normal(this->Triangles[o]));
      labels.push_back(this->LabelOf(o));
    }
  }
  bent = normals.size() == 2 && this->Bent(normals[0], labels[0], normals[1], labels[1]);
  return normals.size() == 2;
}

bool LiveSurface::LinkConditionHolds(const Collapse& c) const
{
  const std::uint32_t w1 = Opposite(this->Triangles[c.Vanishing[0]], c.From, c.To);
  const std::uint32_t w2 = Opposite(this->Triangles[c.Vanishing[1]], c.From, c.To);
  if (w1 == w2)
  {
    return false;
  }
  const std::vector<std::uint32_t> a = this->Neighbours(c.From), b = this->Neighbours(c.To);
  std::vector<std::uint32_t> common;
  std::set_intersection(a.begin(), a.end(), b.begin(), b.end(), std::back_inserter(common));
  if (common.size() != 2)
  {
    return false;
  }
  // (The one edge both links could share: w1 w2, when both triangles
  // From w1 w2 and To w1 w2 exist - a tetrahedron.)
  auto hasTriangle = [this, w1, w2](std::uint32_t x) {
    for (const std::uint32_t t : this->Around[x])
    {
      if (Holds(this->Triangles[t], w1) && Holds(this->Triangles[t], w2))
      {
        return true;
      }
    }
    return false;
  };
  return !(hasTriangle(c.From) && hasTriangle(c.To));
}

bool LiveSurface::KeepsShape(const Collapse& c) const
{
  for (std::size_t i = 0; i < c.Made.size(); ++i)
  {
    const Triangle& t = c.Made[i];
    if (TriangleIsDegenerate(this->P[t[0]], this->P[t[1]], this->P[t[2]]) ||
      !(Dot(this->Normal(t), this->Normal(this->Triangles[c.Kept[i]])) > 0.0))
    {
      return false;
    }
  }
  return true;
}

void LiveSurface::Apply(const Collapse& c)
{
  for (const std::uint32_t t : c.Vanishing)
  {
    this->Alive[t] = 0;
    for (const std::uint32_t x : this->Triangles[t])
    {
      if (x != c.From)
      {
        std::vector<std::uint32_t>& around = this->Around[x];
        around.erase(std::find(around.begin(), around.end(), t));
      }
    }
  }
  for (std::size_t i = 0; i < c.Kept.size(); ++i)
  {
    const std::uint32_t t = c.Kept[i];
    this->Triangles[t] = c.Made[i];
    this->Around[c.To].push_back(t);
    this->Grid.Insert(t, TriangleBox(this->P, c.Made[i]));
  }
  this->Around[c.From].clear();
}

} // namespace tpc
