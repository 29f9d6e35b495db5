#include "VertexLinks.h"

#include "BucketStarts.h"
#include "UnionFind.h"

#include <algorithm>
#include <atomic>
#include <numeric>
#include <vector>

namespace tpc
{
namespace
{
/// Whether the triangles around vertex `v` (listed in `fan`) form one closed
/// cycle: their link edges (the opposite vertex pairs) join m distinct link
/// vertices into one cycle for a fan of m triangles. (Scratch kept per
/// thread: three allocations per vertex were most of the test.)
bool HasOneCycleLink(const Triangle* triangles, std::uint32_t v, const std::uint32_t* fan, std::size_t m)
{
  thread_local std::vector<std::uint32_t> link, distinct;
  thread_local UnionFind joined(0);
  link.clear(); // pairs of opposite vertices
  for (std::size_t k = 0; k < m; ++k)
  {
    const Triangle& t = triangles[fan[k]];
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
  distinct.assign(link.begin(), link.end());
  std::sort(distinct.begin(), distinct.end());
  distinct.erase(std::unique(distinct.begin(), distinct.end()), distinct.end());
  auto index = [&](std::uint32_t x) {
    return static_cast<std::uint32_t>(std::lower_bound(distinct.begin(), distinct.end(), x) - distinct.begin());
  };
  joined.Reset(distinct.size());
  std::size_t groups = distinct.size();
  for (std::size_t k = 0; k + 1 < link.size(); k += 2)
  {
    groups -= joined.Join(index(link[k]), index(link[k + 1])) ? 1 : 0;
  }
  return groups == 1 && distinct.size() == m;
}

} // namespace

VertexTriangles::VertexTriangles(const Triangle* triangles, std::size_t triangleCount, std::size_t vertexCount)
  : Start(vertexCount + 1, 0)
{
  for (std::size_t t = 0; t < triangleCount; ++t)
  {
    for (const std::uint32_t v : triangles[t])
    {
      ++this->Start[v + 1];
    }
  }
  std::partial_sum(this->Start.begin(), this->Start.end(), this->Start.begin());
  this->Incident.resize(this->Start.back());
  for (std::size_t t = 0; t < triangleCount; ++t)
  {
    for (const std::uint32_t v : triangles[t])
    {
      this->Incident[this->Start[v]++] = static_cast<std::uint32_t>(t);
    }
  }
  RestoreBucketStarts(this->Start);
}

bool CountNonManifoldVertices(const Triangle* triangles, std::size_t triangleCount, std::size_t vertexCount,
  std::int64_t& count, const ParallelFor& parallelFor, const ProgressCallback& progress)
{
  return CountNonManifoldVertices(
    triangles, VertexTriangles(triangles, triangleCount, vertexCount), nullptr, count, parallelFor, progress);
}

bool CountNonManifoldVertices(const Triangle* triangles, const VertexTriangles& around,
  const std::uint8_t* knownOneCycle, std::int64_t& count, const ParallelFor& parallelFor,
  const ProgressCallback& progress)
{
  const std::size_t nv = around.Start.size() - 1;
  // (A sum: the same count for any number of threads.)
  std::atomic<std::int64_t> pinched{ 0 };
  const bool done = ChunkedFor(nv, std::size_t(1) << 18, parallelFor, [&](std::size_t begin, std::size_t end) {
    std::int64_t here = 0;
    for (std::size_t v = begin; v < end; ++v)
    {
      const std::size_t m = around.Count(v);
      here += m > 0 && !(knownOneCycle && knownOneCycle[v]) &&
        !HasOneCycleLink(triangles, static_cast<std::uint32_t>(v), around.Of(v), m);
    }
    pinched += here;
  }, progress);
  count += pinched;
  return done;
}

} // namespace tpc
