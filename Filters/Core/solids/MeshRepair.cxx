#include "MeshRepair.h"

#include "EmbeddedStars.h"
#include "ExactPredicates.h"
#include "MeshEdges.h"
#include "MeshOrder.h"
#include "MeshSolid.h"
#include "SelfIntersection.h"
#include "UnionFind.h"
#include "VertexLinks.h"

#include <algorithm>
#include <cstring>
#include <sstream>

namespace tpc
{
namespace
{
/// For each of `count` items, the first item equal to it (itself where none
/// comes before, or where it equals nothing, not even itself): one pass in
/// order through an open-addressing table of the first ones, at most half
/// full, probed from the top bits of hash(i) - a multiplicative hash carries
/// every bit of the key up to them. (Written out: the standard library's
/// unordered containers allocate a node per entry. The sorts these passes
/// replace were most of the merging's and the duplicates' time: 2.4 and
/// 4.3 ms of the 48 ms armadillo's repair and check took on two threads.)
template <typename Hash, typename Equal>
std::vector<std::uint32_t> FirstOfEach(std::size_t count, const Hash& hash, const Equal& equal)
{
  constexpr std::uint32_t Empty = UINT32_MAX;
  int bits = 4;
  while ((std::size_t{ 1 } << bits) < 2 * count)
  {
    ++bits;
  }
  const std::size_t mask = (std::size_t{ 1 } << bits) - 1;
  std::vector<std::uint32_t> table(mask + 1, Empty), first(count);
  for (std::uint32_t i = 0; i < count; ++i)
  {
    first[i] = i;
    if (!equal(i, i))
    {
      continue; // (equal to nothing, as a point with a NaN coordinate: kept out of the table)
    }
    for (std::size_t k = static_cast<std::size_t>(hash(i) >> (64 - bits));; k = (k + 1) & mask)
    {
      if (table[k] == Empty)
      {
        table[k] = i;
        break;
      }
      if (equal(table[k], i))
      {
        first[i] = table[k];
        break;
      }
    }
  }
  return first;
}

/// Mixes `value`'s bits into `hash` (FirstOfEach reads the top bits).
std::uint64_t MixIn(std::uint64_t hash, std::uint64_t value)
{
  return (hash ^ value) * 0x9E3779B97F4A7C15ull;
}

std::uint64_t CoordinatesHash(const Vec3& p)
{
  std::uint64_t h = 0;
  for (int a = 0; a < 3; ++a)
  {
    const double x = p[a] == 0.0 ? 0.0 : p[a]; // (-0 and +0 are one coordinate)
    std::uint64_t bits;
    std::memcpy(&bits, &x, sizeof bits);
    h = MixIn(h, bits);
  }
  return h;
}

void MergeCoincidentVertices(std::vector<Vec3>& points, std::vector<Triangle>& triangles, MeshRepairReport& r)
{
  // Each vertex maps to the first (lowest index) vertex with its coordinates;
  // the survivors keep their order, moved down in place, and where nothing
  // merges (most inputs) the triangles are left alone. (The copies this
  // replaced were most of the step: on the benchmark machine each page first
  // touched - a fault - costs about 11 us.)
  std::vector<std::uint32_t> renamed = FirstOfEach(
    points.size(), [&](std::uint32_t v) { return CoordinatesHash(points[v]); },
    [&](std::uint32_t a, std::uint32_t b) {
      const Vec3 &p = points[a], &q = points[b];
      return p[0] == q[0] && p[1] == q[1] && p[2] == q[2];
    });
  std::uint32_t kept = 0;
  for (std::uint32_t v = 0; v < points.size(); ++v)
  {
    // (A representative comes first, so it is renamed before its copies.)
    const std::uint32_t representative = renamed[v];
    if (representative == v)
    {
      points[kept] = points[v];
      renamed[v] = kept++;
    }
    else
    {
      renamed[v] = renamed[representative];
    }
  }
  r.MergedVertices += points.size() - kept;
  if (kept == points.size())
  {
    return;
  }
  points.resize(kept);
  for (Triangle& t : triangles)
  {
    for (auto& v : t)
    {
      v = renamed[v];
    }
  }
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

/// A triangle's vertex ids in increasing order: the same for the triangles
/// with the same three vertices.
Triangle SortedIds(Triangle t)
{
  std::sort(t.begin(), t.end());
  return t;
}

void DropDegenerateAndDuplicates(const std::vector<Vec3>& P, std::vector<Triangle>& triangles,
  const ParallelFor& parallelFor, MeshRepairReport& r)
{
  // (The exact area tests in parallel: most of the step's time.)
  std::vector<std::uint8_t> degenerate(triangles.size());
  parallelFor(triangles.size(), [&](std::size_t begin, std::size_t end) {
    for (std::size_t t = begin; t < end; ++t)
    {
      degenerate[t] = Degenerate(P, triangles[t]) ? 1 : 0;
    }
  });
  // Of the triangles with the same three vertices, the first is kept; a
  // degenerate one equals none, so it stays out of the table. (The ids are
  // sorted where they are compared: sorted copies of the triangles, and a
  // copy of those kept, were a third of the step - pages first touched.)
  const std::vector<std::uint32_t> first = FirstOfEach(
    triangles.size(),
    [&](std::uint32_t t) {
      const Triangle ids = SortedIds(triangles[t]);
      return MixIn(MixIn(MixIn(0, ids[0]), ids[1]), ids[2]);
    },
    [&](std::uint32_t a, std::uint32_t b) {
      return !degenerate[a] && !degenerate[b] && SortedIds(triangles[a]) == SortedIds(triangles[b]);
    });
  std::size_t kept = 0;
  for (std::size_t t = 0; t < triangles.size(); ++t)
  {
    if (degenerate[t])
    {
      ++r.DegenerateTriangles;
    }
    else if (first[t] != t)
    {
      ++r.DuplicateTriangles;
    }
    else
    {
      triangles[kept++] = triangles[t];
    }
  }
  triangles.resize(kept);
}

/// Across the edge from corner k of each triangle to the next, where that
/// edge is manifold: the triangle on the other side (else None, as
/// MeshSolid::Across answers), and whether the two walk the edge the same
/// way (one of them must then be flipped), bit k of the triangle's
/// SameDirection. (Kept apart, the triangles across are the neighbours
/// RepairIntoSolid hands on, not copied out of a per-corner record.)
struct EdgeAdjacency
{
  static constexpr std::uint32_t None = UINT32_MAX;
  std::vector<Triangle> Across;
  std::vector<std::uint8_t> SameDirection;
};

/// The triangles across each triangle's manifold edges, from the edge table;
/// counts the edges (`edges`), the boundary, non-manifold and inconsistently
/// oriented ones, and joins the triangles of each connected component.
EdgeAdjacency EdgeNeighbours(const std::vector<EdgeUse>& uses, std::size_t triangles, UnionFind& components,
  MeshRepairReport& r, long long& edges)
{
  EdgeAdjacency adjacency;
  adjacency.Across.assign(triangles, { EdgeAdjacency::None, EdgeAdjacency::None, EdgeAdjacency::None });
  adjacency.SameDirection.assign(triangles, 0);
  ForEachEdge(uses, [&](std::size_t first, std::size_t count) {
    ++edges;
    r.BoundaryEdges += count == 1 ? 1 : 0;
    r.NonManifoldEdges += count > 2 ? 1 : 0;
    for (std::size_t k = first + 1; k < first + count; ++k)
    {
      components.Join(uses[k].Triangle, uses[first].Triangle);
    }
    if (count == 2)
    {
      const EdgeUse &a = uses[first], &b = uses[first + 1];
      const bool same = a.Ascending == b.Ascending;
      r.InconsistentEdges += same ? 1 : 0;
      adjacency.Across[a.Triangle][a.Corner] = b.Triangle;
      adjacency.Across[b.Triangle][b.Corner] = a.Triangle;
      adjacency.SameDirection[a.Triangle] |= static_cast<std::uint8_t>(same ? 1 << a.Corner : 0);
      adjacency.SameDirection[b.Triangle] |= static_cast<std::uint8_t>(same ? 1 << b.Corner : 0);
    }
  });
  return adjacency;
}

/// Which triangles to flip so that across every manifold edge the two
/// triangles walk it in opposite directions: breadth-first from a seed per
/// component (kept as it is). A contradiction makes the mesh not orientable.
std::vector<bool> ConsistentFlips(const EdgeAdjacency& adjacency, MeshRepairReport& r)
{
  const std::size_t n = adjacency.Across.size();
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
      for (int k = 0; k < 3; ++k)
      {
        const std::uint32_t across = adjacency.Across[t][k];
        if (across == EdgeAdjacency::None)
        {
          continue;
        }
        const bool same = (adjacency.SameDirection[t] >> k & 1) != 0;
        const int wanted = same ? 1 - flip[t] : flip[t];
        if (flip[across] < 0)
        {
          flip[across] = wanted;
          queue.push_back(across);
        }
        else if (flip[across] != wanted)
        {
          r.Orientable = false;
        }
      }
    }
  }
  std::vector<bool> flips(n);
  for (std::size_t t = 0; t < n; ++t)
  {
    flips[t] = flip[t] == 1;
  }
  return flips;
}

/// The component of each triangle, numbered in triangle order.
std::vector<std::uint32_t> ComponentLabels(UnionFind& components, std::size_t triangles, MeshRepairReport& r)
{
  std::vector<std::uint32_t> component(triangles), label(triangles, UINT32_MAX);
  std::uint32_t count = 0;
  for (std::uint32_t t = 0; t < triangles; ++t)
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

/// Turns triangle t over, and its neighbours with it (null: none kept):
/// (a, b, c) becomes (a, c, b), whose edges 0, 1, 2 are the old 2, 1, 0.
void Flip(std::vector<Triangle>& triangles, std::vector<Triangle>* neighbours, std::size_t t)
{
  std::swap(triangles[t][1], triangles[t][2]);
  if (neighbours)
  {
    std::swap((*neighbours)[t][0], (*neighbours)[t][2]);
  }
}

/// Orients every component consistently; returns the component of each
/// triangle, and the number of edges in `edges` (flips do not change the
/// edges: the Euler characteristic is taken from this table). Where
/// `neighbours` is given, each triangle's neighbour across each edge after
/// the flips, as MeshSolid::Across answers them (the triangle across an
/// edge of exactly two, else MeshSolid::NoTriangle).
std::vector<std::uint32_t> OrientConsistently(std::vector<Triangle>& triangles, const ParallelFor& parallelFor,
  MeshRepairReport& r, long long& edges, std::vector<Triangle>* neighbours)
{
  std::vector<EdgeUse> uses;
  BuildEdgeTable(triangles.data(), triangles.size(), uses, parallelFor);
  UnionFind components(triangles.size());
  EdgeAdjacency adjacency = EdgeNeighbours(uses, triangles.size(), components, r, edges);
  std::vector<EdgeUse>().swap(uses);
  // (No edge walked twice the same way - most inputs: nothing turns, and the
  // search, which would keep every triangle, is not needed.)
  const std::vector<bool> flips =
    r.InconsistentEdges == 0 ? std::vector<bool>(triangles.size(), false) : ConsistentFlips(adjacency, r);
  if (neighbours)
  {
    static_assert(EdgeAdjacency::None == MeshSolid::NoTriangle, "the same mark for no neighbour");
    *neighbours = std::move(adjacency.Across);
  }
  for (std::size_t t = 0; t < triangles.size(); ++t)
  {
    if (flips[t])
    {
      Flip(triangles, neighbours, t);
    }
  }
  return ComponentLabels(components, triangles.size(), r);
}

/// Flips components so that each faces away from the solid: an outer shell
/// encloses positive volume, a cavity's shell negative.
void OrientOutward(const std::vector<Vec3>& P, std::vector<Triangle>& triangles,
  const std::vector<std::uint32_t>& component, MeshRepairReport& r, std::vector<Triangle>* neighbours)
{
  const std::size_t count = r.Components;
  std::vector<double> volume(count, 0.0);
  for (std::size_t t = 0; t < triangles.size(); ++t)
  {
    const Triangle& f = triangles[t];
    volume[component[t]] += Dot(P[f[0]], Cross(P[f[1]], P[f[2]])) / 6.0;
  }
  // Nesting depth from exact inside tests (parity does not depend on
  // orientation). Quadratic in the number of components: fine for the
  // handful real solids have; beyond that, assume no nesting.
  std::vector<int> depth(count, 0);
  if (count > 1 && count <= 256)
  {
    std::vector<std::vector<Triangle>> parts(count);
    for (std::size_t t = 0; t < triangles.size(); ++t)
    {
      parts[component[t]].push_back(triangles[t]);
    }
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
      Flip(triangles, neighbours, t);
    }
  }
}
} // namespace

namespace
{
/// Progress after each step of the repair (a 1M-triangle mesh takes a few
/// tenths of a second per step; the exact self-intersection test is most of
/// the work).
constexpr double MergedAt = 0.03, DroppedAt = 0.06, OrientedAt = 0.08, OutwardAt = 0.1, CheckedAt = 0.95;

/// The repairs (merging, dropping, orienting), each step's progress
/// reported; false when asked to stop. `edges`: the number of edges;
/// `neighbours` (if given): as OrientConsistently gives them.
bool Repair(std::vector<Vec3>& points, std::vector<Triangle>& triangles, const ParallelFor& parallelFor,
  const ProgressCallback& progress, MeshRepairReport& r, long long& edges, std::vector<Triangle>* neighbours)
{
  auto stop = [&progress](double f) { return progress && progress(f); };
  r.InputTriangles = triangles.size();
  MergeCoincidentVertices(points, triangles, r);
  if (stop(MergedAt))
  {
    return false;
  }
  DropDegenerateAndDuplicates(points, triangles, parallelFor, r);
  if (triangles.empty() || stop(DroppedAt))
  {
    return false;
  }
  const std::vector<std::uint32_t> component = OrientConsistently(triangles, parallelFor, r, edges, neighbours);
  if (stop(OrientedAt))
  {
    return false;
  }
  if (r.Orientable)
  {
    OrientOutward(points, triangles, component, r, neighbours);
  }
  return !stop(OutwardAt);
}

/// The input surface's topology: Euler characteristic, pinched vertices,
/// and the genus where the surface is a closed manifold. `stars`: proven of
/// these triangles, whose links they have looked at (null: none).
void CountTopology(const std::vector<Vec3>& points, const std::vector<Triangle>& triangles, long long edges,
  const EmbeddedStars* stars, const ParallelFor& parallelFor, MeshRepairReport& r)
{
  std::vector<bool> used(points.size(), false);
  for (const Triangle& t : triangles)
  {
    for (auto v : t)
    {
      used[v] = true;
    }
  }
  const long long vertices = std::count(used.begin(), used.end(), true);
  r.EulerCharacteristic = vertices - edges + static_cast<long long>(triangles.size());
  if (r.Closed() && r.NonManifoldEdges == 0)
  {
    if (stars)
    {
      stars->CountNonManifoldVertices(r.PinchedVertices, parallelFor);
    }
    else
    {
      CountNonManifoldVertices(triangles.data(), triangles.size(), points.size(), r.PinchedVertices, parallelFor);
    }
    if (r.PinchedVertices == 0)
    {
      r.Genus = GenusFromEuler(static_cast<std::int64_t>(r.Components), r.EulerCharacteristic);
    }
  }
}
} // namespace

MeshRepairReport RepairMesh(std::vector<Vec3>& points, std::vector<Triangle>& triangles,
  bool checkSelfIntersections, std::size_t maxReported, const ParallelFor& parallelFor,
  const ProgressCallback& progress)
{
  MeshRepairReport r;
  long long edges = 0;
  if (!Repair(points, triangles, parallelFor, progress, r, edges, nullptr))
  {
    return r;
  }
  if (checkSelfIntersections)
  {
    r.SelfIntersections = CountSelfIntersections(
      points, triangles, maxReported, parallelFor, ProgressRange(progress, OutwardAt, CheckedAt));
    r.SelfIntersectionsChecked = true;
    if (progress && progress(CheckedAt))
    {
      return r;
    }
  }
  CountTopology(points, triangles, edges, nullptr, parallelFor, r);
  return r;
}

MeshSolid RepairIntoSolid(std::vector<Vec3> points, std::vector<Triangle> triangles, MeshRepairReport& report,
  std::size_t maxReported, const ParallelFor& parallelFor, const ProgressCallback& progress)
{
  report = MeshRepairReport();
  long long edges = 0;
  std::vector<Triangle> neighbours;
  if (!Repair(points, triangles, parallelFor, progress, report, edges, &neighbours))
  {
    // (Asked to stop, or nothing left: a solid of no triangles.)
    return triangles.empty() ? MeshSolid(std::move(points), {}, {}, parallelFor) : MeshSolid();
  }
  // (The cells read it in runs: MeshOrder.h.)
  if (!InLocalOrder(points, triangles))
  {
    OrderAlongMortonCurve(points, triangles, neighbours, MeshSolid::NoTriangle, parallelFor);
  }
  MeshSolid solid(std::move(points), std::move(triangles), std::move(neighbours), parallelFor);
  // (The stars serve the check and the pinched vertices' count.)
  const EmbeddedStars stars(solid.Points().data(), solid.Points().size(), solid.Triangles().data(),
    solid.Triangles().size(), parallelFor);
  report.SelfIntersections =
    CountSelfIntersections(solid, stars, maxReported, parallelFor, ProgressRange(progress, OutwardAt, CheckedAt));
  report.SelfIntersectionsChecked = true;
  if (progress && progress(CheckedAt))
  {
    return MeshSolid();
  }
  CountTopology(solid.Points(), solid.Triangles(), edges, &stars, parallelFor, report);
  return solid;
}

std::string MeshRepairReport::Describe() const
{
  std::ostringstream s;
  if (FilledHoleTriangles)
  {
    s << "holes filled with " << FilledHoleTriangles << " triangles; ";
  }
  if (FannedPolygons)
  {
    s << FannedPolygons << " polygons folded over themselves fanned from a corner; ";
  }
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
  if (PinchedVertices)
  {
    s << PinchedVertices << " vertices where the surface touches itself; ";
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
