#include "TopologyReport.h"

#include "UnionFind.h"

#include <algorithm>
#include <numeric>
#include <sstream>
#include <vector>

namespace tpc
{
namespace
{
} // namespace

TopologyReport ComputeTopologyReport(
  const TriangleMesh& mesh, const ParallelFor& parallelFor, const ProgressCallback& progress)
{
  auto stop = [&progress](double f) { return progress && progress(f); };
  TopologyReport r;
  const std::size_t nv = mesh.Points.size();
  std::vector<bool> used(nv, false);
  // Directed half-edges (from, to, triangle).
  struct HalfEdge
  {
    std::uint32_t A, B;
  };
  std::vector<HalfEdge> half;
  half.reserve(3 * mesh.Triangles.size());
  UnionFind uf(nv);
  for (const auto& t : mesh.Triangles)
  {
    if ((half.size() & 0xFFFFF) == 0 && stop(0.2 * static_cast<double>(half.size()) / (3.0 * mesh.Triangles.size())))
    {
      return r;
    }
    if (t[0] == t[1] || t[1] == t[2] || t[0] == t[2])
    {
      ++r.DegenerateTriangles;
    }
    for (int k = 0; k < 3; ++k)
    {
      used[t[k]] = true;
      half.push_back({ t[k], t[(k + 1) % 3] });
    }
    uf.Join(t[0], t[1]);
    uf.Join(t[1], t[2]);
    const Vec3& p0 = mesh.Points[t[0]];
    r.SignedVolume += Dot(p0, Cross(mesh.Points[t[1]], mesh.Points[t[2]])) / 6.0;
  }
  r.Faces = static_cast<std::int64_t>(mesh.Triangles.size());
  r.Vertices = std::count(used.begin(), used.end(), true);

  // Undirected edges with their use counts in each direction.
  std::vector<std::pair<std::uint64_t, int>> edges; // key, +1 for a<b direction, -1 otherwise
  edges.reserve(half.size());
  for (const HalfEdge& h : half)
  {
    const std::uint32_t lo = std::min(h.A, h.B), hi = std::max(h.A, h.B);
    edges.emplace_back((static_cast<std::uint64_t>(lo) << 32) | hi, h.A < h.B ? 1 : -1);
  }
  if (!ParallelSort(edges, std::less<>(), parallelFor, ProgressRange(progress, 0.2, 0.6)))
  {
    return r;
  }
  bool oriented = true;
  for (std::size_t i = 0; i < edges.size();)
  {
    std::size_t j = i;
    int forward = 0, backward = 0;
    while (j < edges.size() && edges[j].first == edges[i].first)
    {
      (edges[j].second > 0 ? forward : backward)++;
      ++j;
    }
    const std::size_t count = j - i;
    ++r.Edges;
    if (count == 1)
    {
      ++r.BoundaryEdges;
    }
    else if (count > 2)
    {
      ++r.NonManifoldEdges;
    }
    if (count == 2 && forward != 1)
    {
      oriented = false;
    }
    i = j;
  }
  r.EulerCharacteristic = r.Vertices - r.Edges + r.Faces;

  // Components (over used vertices).
  std::vector<bool> root(nv, false);
  for (std::size_t v = 0; v < nv; ++v)
  {
    if (used[v])
    {
      root[uf.Find(static_cast<std::uint32_t>(v))] = true;
    }
  }
  r.Components = std::count(root.begin(), root.end(), true);

  // Vertex links: in a closed manifold, the triangles around a vertex form
  // one cycle; count vertices whose fan splits into several.
  if (r.BoundaryEdges == 0 && r.NonManifoldEdges == 0)
  {
    std::vector<std::uint32_t> start(nv + 1, 0);
    for (const auto& t : mesh.Triangles)
    {
      for (int k = 0; k < 3; ++k)
      {
        ++start[t[k] + 1];
      }
    }
    std::partial_sum(start.begin(), start.end(), start.begin());
    std::vector<std::uint32_t> fill(start.begin(), start.end() - 1), incident(start.back());
    for (std::uint32_t ti = 0; ti < mesh.Triangles.size(); ++ti)
    {
      for (int k = 0; k < 3; ++k)
      {
        incident[fill[mesh.Triangles[ti][k]]++] = ti;
      }
    }
    for (std::size_t v = 0; v < nv; ++v)
    {
      if ((v & 0x3FFFF) == 0 && stop(0.6 + 0.4 * static_cast<double>(v) / static_cast<double>(nv)))
      {
        return r;
      }
      const std::uint32_t b = start[v], e = start[v + 1];
      if (b == e)
      {
        continue;
      }
      // The link edges (opposite vertex pairs) must form a single cycle.
      std::vector<std::uint32_t> others;
      for (std::uint32_t k = b; k < e; ++k)
      {
        const auto& t = mesh.Triangles[incident[k]];
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
          others.push_back(o[0]);
          others.push_back(o[1]);
        }
      }
      std::vector<std::uint32_t> distinct(others);
      std::sort(distinct.begin(), distinct.end());
      distinct.erase(std::unique(distinct.begin(), distinct.end()), distinct.end());
      UnionFind link(distinct.size());
      auto idx = [&](std::uint32_t x) {
        return static_cast<std::uint32_t>(
          std::lower_bound(distinct.begin(), distinct.end(), x) - distinct.begin());
      };
      std::size_t groups = distinct.size();
      for (std::size_t k = 0; k + 1 < others.size(); k += 2)
      {
        groups -= link.Join(idx(others[k]), idx(others[k + 1])) ? 1 : 0;
      }
      // A closed fan of m triangles has m distinct link vertices in one cycle.
      if (groups != 1 || distinct.size() != static_cast<std::size_t>(e - b))
      {
        ++r.NonManifoldVertices;
      }
    }
  }
  r.Closed = r.Faces > 0 && r.BoundaryEdges == 0;
  r.Manifold = r.Closed && r.NonManifoldEdges == 0 && r.NonManifoldVertices == 0 &&
    r.DegenerateTriangles == 0;
  r.Oriented = r.Manifold && oriented;
  if (r.Manifold && r.Oriented)
  {
    const std::int64_t twiceGenus = 2 * r.Components - r.EulerCharacteristic;
    r.Genus = twiceGenus >= 0 && twiceGenus % 2 == 0 ? twiceGenus / 2 : -1;
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
