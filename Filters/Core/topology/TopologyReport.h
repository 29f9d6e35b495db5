// Topology of a triangle mesh, computed on the mesh alone (the independent
// oracle for every test): Euler characteristic V - E + F, connected
// components, genus, and the checks the guarantee is about - closed (every
// edge has two triangles), manifold (and every vertex link is one cycle),
// consistently oriented, and outward (positive enclosed volume).
#pragma once

#include "Parallel.h"
#include "TriangleMesh.h"

#include <cstdint>
#include <string>

namespace tpc
{

struct TopologyReport
{
  std::int64_t Vertices = 0; ///< vertices used by triangles
  std::int64_t Edges = 0;
  std::int64_t Faces = 0;
  std::int64_t EulerCharacteristic = 0;
  std::int64_t Components = 0;
  /// Sum of the genera of the components; -1 if not a closed orientable surface.
  std::int64_t Genus = -1;
  std::int64_t BoundaryEdges = 0;     ///< edges with one triangle
  std::int64_t NonManifoldEdges = 0;  ///< edges with more than two triangles
  std::int64_t NonManifoldVertices = 0;
  std::int64_t DegenerateTriangles = 0; ///< triangles repeating a vertex index
  bool Closed = false;
  bool Manifold = false;
  bool Oriented = false;
  double SignedVolume = 0.0;

  std::string ToString() const;
};

/// The edge sort runs in parallel; `progress` is asked between the steps
/// and through the vertex links, and stops the count early (a partial
/// report) when it asks to abort.
TopologyReport ComputeTopologyReport(const TriangleMesh& mesh, const ParallelFor& parallelFor = SequentialFor,
  const ProgressCallback& progress = nullptr);

} // namespace tpc
