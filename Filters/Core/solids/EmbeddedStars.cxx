#include "EmbeddedStars.h"

#include "ExactPredicates.h"
#include "VertexLinks.h"

#include <algorithm>
#include <cmath>

namespace tpc
{
namespace
{
/// (i) of the header: the link of v as one cycle w_1 .. w_m in `cycle`, from
/// the m triangles at `fan`; false where it is not one.
bool LinkCycle(const Triangle* triangles, std::uint32_t v, const std::uint32_t* fan, std::size_t m,
  std::vector<std::pair<std::uint32_t, std::uint32_t>>& edges, std::vector<std::uint32_t>& cycle)
{
  if (m < 3)
  {
    return false;
  }
  edges.clear();
  for (std::size_t k = 0; k < m; ++k)
  {
    const Triangle& t = triangles[fan[k]];
    const int c = t[0] == v ? 0 : t[1] == v ? 1 : 2;
    const std::uint32_t a = t[(c + 1) % 3], b = t[(c + 2) % 3];
    if (a == v || b == v || a == b)
    {
      return false; // (v twice, or a triangle without area by its ids)
    }
    edges.emplace_back(a, b);
  }
  std::sort(edges.begin(), edges.end());
  for (std::size_t k = 1; k < m; ++k)
  {
    if (edges[k].first == edges[k - 1].first)
    {
      return false; // two link edges leave one vertex
    }
  }
  // Each vertex leaves once: following the edges from the first, m steps
  // return to it exactly when they make one cycle through all m.
  cycle.clear();
  std::uint32_t at = edges[0].first;
  for (std::size_t step = 0; step < m; ++step)
  {
    const auto next = std::lower_bound(edges.begin(), edges.end(), std::make_pair(at, std::uint32_t{ 0 }));
    if (next == edges.end() || next->first != at || (step > 0 && at == edges[0].first))
    {
      return false;
    }
    cycle.push_back(at);
    at = next->second;
  }
  return at == edges[0].first;
}

/// (ii) and (iii) of the header for the cycle around `v`, dropping `axis`.
bool WindsOnceProjected(const Vec3* points, std::uint32_t v, const std::vector<std::uint32_t>& cycle, int axis)
{
  const int u = (axis + 1) % 3, w = (axis + 2) % 3;
  const Vec3& p = points[v];
  const auto orient = [&](std::uint32_t a, std::uint32_t b) {
    return Orient2D(p[u], p[w], points[a][u], points[a][w], points[b][u], points[b][w]);
  };
  const std::size_t m = cycle.size();
  const int s = orient(cycle[0], cycle[1]);
  if (s == 0)
  {
    return false;
  }
  for (std::size_t i = 1; i < m; ++i)
  {
    if (orient(cycle[i], cycle[(i + 1) % m]) != s)
    {
      return false;
    }
  }
  // The first wedge never holds d (it starts there), the last always does
  // (it ends there): any other wedge holding it is a second turn.
  for (std::size_t i = 1; i + 1 < m; ++i)
  {
    if (s * orient(cycle[i], cycle[0]) > 0 && s * orient(cycle[0], cycle[i + 1]) >= 0)
    {
      return false;
    }
  }
  return true;
}

/// Whether v's star, whose link is the one cycle `cycle` ((i) of the
/// header), is proven embedded by a projection, trying the axes in the
/// order the star's area vector favours.
bool WindsOnceInSomeProjection(const Vec3* points, std::uint32_t v, const std::vector<std::uint32_t>& cycle)
{
  const std::size_t m = cycle.size();
  const Vec3& p = points[v];
  Vec3 area;
  for (std::size_t i = 0; i < m; ++i)
  {
    area += Cross(points[cycle[i]] - p, points[cycle[(i + 1) % m]] - p);
  }
  for (const std::uint32_t c : cycle)
  {
    for (int a = 0; a < 3; ++a)
    {
      if (!std::isfinite(points[c][a]) || !std::isfinite(p[a]))
      {
        return false;
      }
    }
  }
  // (Largest first; each axis is tried in turn anyway. A NaN from huge
  // coordinates counts as 0, so that the order is a strict one.)
  double weight[3];
  for (int a = 0; a < 3; ++a)
  {
    weight[a] = std::isnan(area[a]) ? 0.0 : std::fabs(area[a]);
  }
  int axes[3] = { 0, 1, 2 };
  std::sort(axes, axes + 3, [&](int a, int b) { return weight[a] > weight[b]; });
  for (const int axis : axes)
  {
    if (WindsOnceProjected(points, v, cycle, axis))
    {
      return true;
    }
  }
  return false;
}
} // namespace

EmbeddedStars::EmbeddedStars(const Vec3* points, std::size_t vertexCount, const Triangle* triangles,
  std::size_t count, const ParallelFor& parallelFor)
  : Triangles(triangles)
  , Around(triangles, count, vertexCount)
  , Link(vertexCount, NotOneCycle)
{
  parallelFor(vertexCount, [&](std::size_t begin, std::size_t end) {
    std::vector<std::pair<std::uint32_t, std::uint32_t>> edges;
    std::vector<std::uint32_t> cycle;
    for (std::size_t v = begin; v < end; ++v)
    {
      const auto u = static_cast<std::uint32_t>(v);
      if (LinkCycle(triangles, u, this->Around.Of(v), this->Around.Count(v), edges, cycle))
      {
        this->Link[v] = WindsOnceInSomeProjection(points, u, cycle) ? ProvenStar : OneCycle;
      }
    }
  });
}

std::size_t EmbeddedStars::ProvenCount() const
{
  return static_cast<std::size_t>(std::count(this->Link.begin(), this->Link.end(), std::uint8_t{ ProvenStar }));
}

bool EmbeddedStars::CountNonManifoldVertices(
  std::int64_t& count, const ParallelFor& parallelFor, const ProgressCallback& progress) const
{
  static_assert(NotOneCycle == 0, "the vertices known to be manifold points are those marked nonzero");
  return tpc::CountNonManifoldVertices(this->Triangles, this->Around, this->Link.data(), count, parallelFor, progress);
}

} // namespace tpc
