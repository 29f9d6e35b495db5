#include "MeshRepair.h"

#include "ExactPredicates.h"
#include "MeshSolid.h"
#include "SelfIntersection.h"
#include "UnionFind.h"

#include <algorithm>
#include <numeric>
#include <sstream>

namespace tpc
{
namespace
{
using Triangle = std::array<std::uint32_t, 3>;


void MergeCoincidentVertices(std::vector<Vec3>& points, std::vector<Triangle>& triangles, MeshRepairReport& r)
{
  std::vector<std::uint32_t> order(points.size());
  std::iota(order.begin(), order.end(), 0u);
  auto less = [&](std::uint32_t a, std::uint32_t b) {
    const Vec3 &p = points[a], &q = points[b];
    return p[0] != q[0] ? p[0] < q[0] : (p[1] != q[1] ? p[1] < q[1] : (p[2] != q[2] ? p[2] < q[2] : a < b));
  };
  std::sort(order.begin(), order.end(), less);
  // Each vertex maps to the first (lowest index) vertex with its coordinates;
  // the survivors keep their order.
  std::vector<std::uint32_t> representative(points.size());
  for (std::size_t i = 0; i < order.size(); ++i)
  {
    const Vec3& p = points[order[i]];
    const bool same = i > 0 && p[0] == points[order[i - 1]][0] && p[1] == points[order[i - 1]][1] &&
      p[2] == points[order[i - 1]][2];
    representative[order[i]] = same ? representative[order[i - 1]] : order[i];
  }
  std::vector<std::uint32_t> remap(points.size());
  std::vector<Vec3> merged;
  for (std::uint32_t v = 0; v < points.size(); ++v)
  {
    if (representative[v] == v)
    {
      remap[v] = static_cast<std::uint32_t>(merged.size());
      merged.push_back(points[v]);
    }
    else
    {
      ++r.MergedVertices;
    }
  }
  for (std::uint32_t v = 0; v < points.size(); ++v)
  {
    remap[v] = remap[representative[v]];
  }
  for (Triangle& t : triangles)
  {
    for (auto& v : t)
    {
      v = remap[v];
    }
  }
  points.swap(merged);
}

bool Degenerate(const std::vector<Vec3>& P, const Triangle& t)
{
  if (t[0] == t[1] || t[1] == t[2] || t[0] == t[2])
  {
    return true;
  }
  for (int k = 0; k < 3; ++k)
  {
    const int u = (k + 1) % 3, v = (k + 2) % 3;
    if (Orient2D(P[t[0]][u], P[t[0]][v], P[t[1]][u], P[t[1]][v], P[t[2]][u], P[t[2]][v]) != 0)
    {
      return false;
    }
  }
  return true; // collinear in every projection: no area
}

void DropDegenerateAndDuplicates(const std::vector<Vec3>& P, std::vector<Triangle>& triangles, MeshRepairReport& r)
{
  std::vector<Triangle> kept;
  std::vector<std::pair<Triangle, std::size_t>> sorted;
  for (const Triangle& t : triangles)
  {
    if (Degenerate(P, t))
    {
      ++r.DegenerateTriangles;
      continue;
    }
    Triangle s = t;
    std::sort(s.begin(), s.end());
    sorted.emplace_back(s, kept.size());
    kept.push_back(t);
  }
  std::sort(sorted.begin(), sorted.end());
  std::vector<bool> drop(kept.size(), false);
  for (std::size_t i = 1; i < sorted.size(); ++i)
  {
    if (sorted[i].first == sorted[i - 1].first)
    {
      drop[sorted[i].second] = true;
      ++r.DuplicateTriangles;
    }
  }
  triangles.clear();
  for (std::size_t i = 0; i < kept.size(); ++i)
  {
    if (!drop[i])
    {
      triangles.push_back(kept[i]);
    }
  }
}

struct EdgeUse
{
  std::uint64_t Key; // (min vertex << 32) | max vertex
  std::uint32_t Triangle;
  int Direction; // +1 if the triangle walks min -> max
};

std::vector<EdgeUse> EdgeUses(const std::vector<Triangle>& triangles)
{
  std::vector<EdgeUse> uses;
  uses.reserve(3 * triangles.size());
  for (std::uint32_t t = 0; t < triangles.size(); ++t)
  {
    for (int k = 0; k < 3; ++k)
    {
      const std::uint32_t a = triangles[t][k], b = triangles[t][(k + 1) % 3];
      uses.push_back({ (static_cast<std::uint64_t>(std::min(a, b)) << 32) | std::max(a, b), t, a < b ? 1 : -1 });
    }
  }
  std::sort(uses.begin(), uses.end(), [](const EdgeUse& x, const EdgeUse& y) { return x.Key < y.Key; });
  return uses;
}

/// Orients every component consistently; returns the component of each triangle.
std::vector<std::uint32_t> OrientConsistently(std::vector<Triangle>& triangles, MeshRepairReport& r)
{
  const std::vector<EdgeUse> uses = EdgeUses(triangles);
  const std::size_t n = triangles.size();
  std::vector<std::vector<std::pair<std::uint32_t, int>>> neighbors(n); // (triangle, +1 same direction)
  UnionFind components(n);
  for (std::size_t i = 0; i < uses.size();)
  {
    std::size_t j = i;
    while (j < uses.size() && uses[j].Key == uses[i].Key)
    {
      ++j;
    }
    const std::size_t count = j - i;
    if (count == 1)
    {
      ++r.BoundaryEdges;
    }
    else if (count > 2)
    {
      ++r.NonManifoldEdges;
    }
    for (std::size_t a = i; a < j; ++a)
    {
      components.Join(uses[a].Triangle, uses[i].Triangle);
    }
    if (count == 2)
    {
      const bool same = uses[i].Direction == uses[i + 1].Direction;
      r.InconsistentEdges += same ? 1 : 0;
      neighbors[uses[i].Triangle].emplace_back(uses[i + 1].Triangle, same ? 1 : -1);
      neighbors[uses[i + 1].Triangle].emplace_back(uses[i].Triangle, same ? 1 : -1);
    }
    i = j;
  }
  // Breadth-first flips: across a manifold edge the two triangles must walk
  // it in opposite directions.
  std::vector<int> flip(n, -1);
  std::vector<std::uint32_t> queue;
  for (std::uint32_t seed = 0; seed < n; ++seed)
  {
    if (flip[seed] >= 0)
    {
      continue;
    }
    flip[seed] = 0;
    queue.assign(1, seed);
    for (std::size_t q = 0; q < queue.size(); ++q)
    {
      const std::uint32_t t = queue[q];
      for (const auto& nb : neighbors[t])
      {
        const int wanted = nb.second > 0 ? 1 - flip[t] : flip[t];
        if (flip[nb.first] < 0)
        {
          flip[nb.first] = wanted;
          queue.push_back(nb.first);
        }
        else if (flip[nb.first] != wanted)
        {
          r.Orientable = false;
        }
      }
    }
  }
  for (std::size_t t = 0; t < n; ++t)
  {
    if (flip[t] == 1)
    {
      std::swap(triangles[t][1], triangles[t][2]);
    }
  }
  std::vector<std::uint32_t> component(n);
  std::vector<std::uint32_t> label(n, UINT32_MAX);
  std::uint32_t count = 0;
  for (std::uint32_t t = 0; t < n; ++t)
  {
    const std::uint32_t root = components.Find(t);
    if (label[root] == UINT32_MAX)
    {
      label[root] = count++;
    }
    component[t] = label[root];
  }
  r.Components = count;
  return component;
}

/// Flips components so that each faces away from the solid: an outer shell
/// encloses positive volume, a cavity's shell negative.
void OrientOutward(const std::vector<Vec3>& P, std::vector<Triangle>& triangles,
  const std::vector<std::uint32_t>& component, MeshRepairReport& r)
{
  const std::size_t count = r.Components;
  std::vector<std::vector<Triangle>> parts(count);
  std::vector<double> volume(count, 0.0);
  for (std::size_t t = 0; t < triangles.size(); ++t)
  {
    const Triangle& f = triangles[t];
    parts[component[t]].push_back(f);
    volume[component[t]] += Dot(P[f[0]], Cross(P[f[1]], P[f[2]])) / 6.0;
  }
  // Nesting depth from exact inside tests (parity does not depend on
  // orientation). Quadratic in the number of components: fine for the
  // handful real solids have; beyond that, assume no nesting.
  std::vector<int> depth(count, 0);
  if (count > 1 && count <= 256)
  {
    std::vector<MeshSolid> solids;
    for (const auto& part : parts)
    {
      solids.emplace_back(P, part);
    }
    for (std::size_t i = 0; i < count; ++i)
    {
      const Vec3& probe = P[parts[i].front()[0]];
      for (std::size_t j = 0; j < count; ++j)
      {
        depth[i] += (j != i && solids[j].IsInside(probe)) ? 1 : 0;
      }
    }
  }
  std::vector<bool> flip(count, false);
  for (std::size_t i = 0; i < count; ++i)
  {
    flip[i] = (volume[i] > 0.0) != (depth[i] % 2 == 0);
    r.FlippedComponents += flip[i] ? 1 : 0;
  }
  for (std::size_t t = 0; t < triangles.size(); ++t)
  {
    if (flip[component[t]])
    {
      std::swap(triangles[t][1], triangles[t][2]);
    }
  }
}
} // namespace

MeshRepairReport RepairMesh(std::vector<Vec3>& points, std::vector<Triangle>& triangles,
  bool checkSelfIntersections, std::size_t maxReported, const ParallelFor& parallelFor,
  const ProgressCallback& progress)
{
  // Progress after each step (a 1M-triangle mesh takes a few tenths of a
  // second per step); the exact self-intersection test is most of the work.
  auto stop = [&progress](double f) { return progress && progress(f); };
  MeshRepairReport r;
  r.InputTriangles = triangles.size();
  MergeCoincidentVertices(points, triangles, r);
  if (stop(0.03))
  {
    return r;
  }
  DropDegenerateAndDuplicates(points, triangles, r);
  if (triangles.empty() || stop(0.06))
  {
    return r;
  }
  const std::vector<std::uint32_t> component = OrientConsistently(triangles, r);
  if (stop(0.08))
  {
    return r;
  }
  if (r.Orientable)
  {
    OrientOutward(points, triangles, component, r);
  }
  if (stop(0.1))
  {
    return r;
  }
  if (checkSelfIntersections)
  {
    r.SelfIntersections =
      CountSelfIntersections(points, triangles, maxReported, parallelFor, ProgressRange(progress, 0.1, 0.95));
    r.SelfIntersectionsChecked = true;
    if (stop(0.95))
    {
      return r;
    }
  }
  // Topology of the input surface.
  std::vector<bool> used(points.size(), false);
  for (const Triangle& t : triangles)
  {
    for (auto v : t)
    {
      used[v] = true;
    }
  }
  const long long vertices = std::count(used.begin(), used.end(), true);
  const std::vector<EdgeUse> uses = EdgeUses(triangles);
  long long edges = 0;
  for (std::size_t i = 0; i < uses.size(); ++i)
  {
    edges += (i == 0 || uses[i].Key != uses[i - 1].Key) ? 1 : 0;
  }
  r.EulerCharacteristic = vertices - edges + static_cast<long long>(triangles.size());
  if (r.Closed() && r.NonManifoldEdges == 0)
  {
    const long long twice = 2 * static_cast<long long>(r.Components) - r.EulerCharacteristic;
    r.Genus = twice >= 0 && twice % 2 == 0 ? twice / 2 : -1;
  }
  return r;
}

std::string MeshRepairReport::Describe() const
{
  std::ostringstream s;
  if (MergedVertices)
  {
    s << MergedVertices << " duplicate vertices merged; ";
  }
  if (DegenerateTriangles)
  {
    s << DegenerateTriangles << " degenerate triangles dropped; ";
  }
  if (DuplicateTriangles)
  {
    s << DuplicateTriangles << " duplicate triangles dropped; ";
  }
  if (InconsistentEdges)
  {
    s << "inconsistent orientation repaired (" << InconsistentEdges << " edges); ";
  }
  if (FlippedComponents)
  {
    s << FlippedComponents << " component(s) turned to face outward; ";
  }
  if (BoundaryEdges)
  {
    s << "open: " << BoundaryEdges << " boundary edges; ";
  }
  if (NonManifoldEdges)
  {
    s << NonManifoldEdges << " non-manifold edges; ";
  }
  if (!Orientable)
  {
    s << "not orientable; ";
  }
  if (SelfIntersections)
  {
    s << (SelfIntersections >= 100 ? "at least " : "") << SelfIntersections
      << " self-intersecting triangle pairs; ";
  }
  std::string out = s.str();
  if (out.size() >= 2)
  {
    out.resize(out.size() - 2);
  }
  return out;
}

} // namespace tpc
