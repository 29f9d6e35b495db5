#include "TopologyReport.h"

#include "MeshEdges.h"
#include "UnionFind.h"
#include "VertexLinks.h"

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
    !CountNonManifoldVertices(mesh.Triangles.data(), mesh.Triangles.size(), mesh.Points.size(),
      r.NonManifoldVertices, parallelFor, ProgressRange(progress, 0.6, 1.0)))
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
