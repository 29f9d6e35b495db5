// The link of each vertex of an indexed triangle mesh: on a closed surface
// whose every edge has two triangles, a vertex is a manifold point exactly
// when its triangles form one cycle around it. A bow tie - two fans meeting
// at one vertex, the surface touching itself there - has two. The topology
// report counts such vertices on the output, mesh repair on the input (a
// solid whose boundary pinches at a vertex is not a closed 2-manifold, and
// the self-intersection test cannot see it: the two fans share the vertex).
#pragma once

#include "Parallel.h"
#include "TriangleMesh.h"

#include <cstddef>
#include <cstdint>
#include <vector>

namespace tpc
{

/// The triangles around each vertex: those of vertex v are Incident[Start[v]]
/// to Incident[Start[v + 1] - 1], in triangle order (a triangle repeating v
/// listed once per repetition): counted, prefix-summed, written.
struct VertexTriangles
{
  std::vector<std::size_t> Start;
  std::vector<std::uint32_t> Incident;

  VertexTriangles(const Triangle* triangles, std::size_t triangleCount, std::size_t vertexCount);
  std::size_t Count(std::size_t v) const { return this->Start[v + 1] - this->Start[v]; }
  const std::uint32_t* Of(std::size_t v) const { return this->Incident.data() + this->Start[v]; }
};

/// Counts into `count` the vertices (of `vertexCount`) whose triangles among
/// the `triangleCount` at `triangles` do not form one cycle around them
/// (meant for meshes whose every edge has two triangles), the vertices'
/// links checked in parallel. False when `progress` asked to stop (`count`
/// is then partial).
bool CountNonManifoldVertices(const Triangle* triangles, std::size_t triangleCount, std::size_t vertexCount,
  std::int64_t& count, const ParallelFor& parallelFor = SequentialFor, const ProgressCallback& progress = nullptr);

/// The same with the table `around` of those triangles, passing over the
/// vertices v with knownOneCycle[v] != 0 (null: none), whose triangles the
/// caller has found to form one cycle (EmbeddedStars.h).
bool CountNonManifoldVertices(const Triangle* triangles, const VertexTriangles& around,
  const std::uint8_t* knownOneCycle, std::int64_t& count, const ParallelFor& parallelFor = SequentialFor,
  const ProgressCallback& progress = nullptr);

} // namespace tpc
