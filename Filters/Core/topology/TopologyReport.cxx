#include "TopologyReport.h"

#include "MeshEdges.h"
#include "UnionFind.h"

#include <algorithm>
#include <numeric>
#include <sstream>
#include <vector>

namespace tpc
{
namespace
{
/// Pass 1 - faces: F, the used vertices V, degenerate triangles, the signed
/// volume, and the components (joined along each triangle's edges). False
/// when `progress` asked to stop.
bool CountFaces(const TriangleMesh& mesh, TopologyReport& r, UnionFind& parts, std::vector<bool>& used,
  const ProgressCallback& progress)
{
  const std::size_t n = mesh.Triangles.size();
  for (std::size_t i = 0; i < n; ++i)
  {
    if ((i & 0x3FFFF) == 0 && progress && progress(static_cast<double>(i) / static_cast<double>(n)))
    {
      return false;
    }
    const Triangle& t = mesh.Triangles[i];
    if (t[0] == t[1] || t[1] == t[2] || t[0] == t[2])
    {
      ++r.DegenerateTriangles;
    }
    used[t[0]] = used[t[1]] = used[t[2]] = true;
    parts.Join(t[0], t[1]);
    parts.Join(t[1], t[2]);
    r.SignedVolume += Dot(mesh.Points[t[0]], Cross(mesh.Points[t[1]], mesh.Points[t[2]])) / 6.0;
  }
  r.Faces = static_cast<std::int64_t>(n);
  r.Vertices = std::count(used.begin(), used.end(), true);
  std::vector<bool> root(used.size(), false);
  for (std::size_t v = 0; v < used.size(); ++v)
  {
    if (used[v])
    {
      root[parts.Find(static_cast<std::uint32_t>(v))] = true;
    }
  }
  r.Components = std::count(root.begin(), root.end(), true);
  return true;
}

/// Pass 2 - edges, from the edge table: E, boundary and non-manifold edges;
/// returns whether every edge of two triangles is walked once each way
/// (consistent orientation).
bool CountEdges(const std::vector<EdgeUse>& uses, TopologyReport& r)
{
  bool oriented = true;
  ForEachEdge(uses, [&](std::size_t first, std::size_t count) {
    ++r.Edges;
    r.BoundaryEdges += count == 1 ? 1 : 0;
    r.NonManifoldEdges += count > 2 ? 1 : 0;
    oriented = oriented && (count != 2 || uses[first].Ascending != uses[first + 1].Ascending);
  });
  return oriented;
}

/// Whether the triangles around vertex `v` (listed in `fan`) form one closed
/// cycle: their link edges (the opposite vertex pairs) join m distinct link
/// vertices into one cycle for a fan of m triangles.
bool HasOneCycleLink(const TriangleMesh& mesh, std::uint32_t v, const std::uint32_t* fan, std::size_t m)
{
  std::vector<std::uint32_t> link; // pairs of opposite vertices
  for (std::size_t k = 0; k < m; ++k)
  {
    const Triangle& t = mesh.Triangles[fan[k]];
    std::uint32_t o[2], n = 0;
    for (int c = 0; c < 3; ++c)
    {
      if (t[c] != v)
      {
        o[n++] = t[c];
      }
    }
    if (n == 2)
    {
      link.push_back(o[0]);
      link.push_back(o[1]);
    }
  }
  std::vector<std::uint32_t> distinct(link);
  std::sort(distinct.begin(), distinct.end());
  distinct.erase(std::unique(distinct.begin(), distinct.end()), distinct.end());
  auto index = [&](std::uint32_t x) {
    return static_cast<std::uint32_t>(std::lower_bound(distinct.begin(), distinct.end(), x) - distinct.begin());
  };
  UnionFind joined(distinct.size());
  std::size_t groups = distinct.size();
  for (std::size_t k = 0; k + 1 < link.size(); k += 2)
  {
    groups -= joined.Join(index(link[k]), index(link[k + 1])) ? 1 : 0;
  }
  return groups == 1 && distinct.size() == m;
}

/// Pass 3 - vertices (on a mesh whose every edge has two triangles): the
/// vertices whose triangles do not form one cycle around them (a bow tie:
/// two fans meeting at a point). False when `progress` asked to stop.
bool CountNonManifoldVertices(const TriangleMesh& mesh, TopologyReport& r, const ProgressCallback& progress)
{
  // The triangles around each vertex: counted, prefix-summed, written.
  const std::size_t nv = mesh.Points.size();
  std::vector<std::uint32_t> start(nv + 1, 0);
  for (const Triangle& t : mesh.Triangles)
  {
    for (const std::uint32_t v : t)
    {
      ++start[v + 1];
    }
  }
  std::partial_sum(start.begin(), start.end(), start.begin());
  std::vector<std::uint32_t> fill(start.begin(), start.end() - 1), incident(start.back());
  for (std::uint32_t t = 0; t < mesh.Triangles.size(); ++t)
  {
    for (const std::uint32_t v : mesh.Triangles[t])
    {
      incident[fill[v]++] = t;
    }
  }
  for (std::uint32_t v = 0; v < nv; ++v)
  {
    if ((v & 0x3FFFF) == 0 && progress && progress(static_cast<double>(v) / static_cast<double>(nv)))
    {
      return false;
    }
    const std::size_t m = start[v + 1] - start[v];
    if (m > 0 && !HasOneCycleLink(mesh, v, incident.data() + start[v], m))
    {
      ++r.NonManifoldVertices;
    }
  }
  return true;
}
} // namespace

TopologyReport ComputeTopologyReport(
  const TriangleMesh& mesh, const ParallelFor& parallelFor, const ProgressCallback& progress)
{
  TopologyReport r;
  UnionFind parts(mesh.Points.size());
  std::vector<bool> used(mesh.Points.size(), false);
  std::vector<EdgeUse> uses;
  if (!CountFaces(mesh, r, parts, used, ProgressRange(progress, 0.0, 0.2)) ||
    !BuildEdgeTable(mesh.Triangles.data(), mesh.Triangles.size(), uses, parallelFor, ProgressRange(progress, 0.2, 0.6)))
  {
    return r;
  }
  const bool oriented = CountEdges(uses, r);
  std::vector<EdgeUse>().swap(uses);
  r.EulerCharacteristic = r.Vertices - r.Edges + r.Faces;
  if (r.BoundaryEdges == 0 && r.NonManifoldEdges == 0 &&
    !CountNonManifoldVertices(mesh, r, ProgressRange(progress, 0.6, 1.0)))
  {
    return r;
  }
  r.Closed = r.Faces > 0 && r.BoundaryEdges == 0;
  r.Manifold = r.Closed && r.NonManifoldEdges == 0 && r.NonManifoldVertices == 0 && r.DegenerateTriangles == 0;
  r.Oriented = r.Manifold && oriented;
  if (r.Manifold && r.Oriented)
  {
    r.Genus = GenusFromEuler(r.Components, r.EulerCharacteristic);
  }
  return r;
}

std::string TopologyReport::ToString() const
{
  std::ostringstream s;
  s << "components " << Components << ", genus " << Genus << ", Euler characteristic "
    << EulerCharacteristic << " (V " << Vertices << ", E " << Edges << ", F " << Faces << ")"
    << ", closed " << (Closed ? "yes" : "no") << ", manifold " << (Manifold ? "yes" : "no")
    << ", oriented " << (Oriented ? "yes" : "no");
  return s.str();
}

} // namespace tpc
