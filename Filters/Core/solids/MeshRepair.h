// Preparing an input triangle mesh to be a solid, and saying what was wrong.
//
// The paper assumes (3) closed manifold primitives without self-intersections.
// This checks each of those on the input and repairs what can be repaired
// without guessing: exactly coincident vertices are merged, triangles that
// repeat a vertex or have no area are dropped, duplicate triangles are
// dropped, and each connected component is oriented consistently and
// outward (an inner shell of a hollow solid facing into its cavity).
// What cannot be repaired (open boundary, non-manifold edges, a
// non-orientable surface, self-intersections) is reported; the caller
// decides whether the mesh is still usable.
#pragma once

#include "MeshSolid.h"
#include "Parallel.h"
#include "Vector3.h"

#include <array>
#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

namespace tpc
{

struct MeshRepairReport
{
  std::size_t InputTriangles = 0;
  std::size_t MergedVertices = 0;       ///< vertices equal to an earlier one
  std::size_t DegenerateTriangles = 0;  ///< dropped: repeated vertex or zero area
  std::size_t DuplicateTriangles = 0;   ///< dropped: same three vertices
  std::size_t BoundaryEdges = 0;        ///< edges with one triangle (open mesh)
  std::size_t NonManifoldEdges = 0;     ///< edges with more than two triangles
  /// Vertices where the surface touches itself: two or more fans of
  /// triangles meeting only there (VertexLinks.h; counted when every edge has
  /// two triangles).
  std::int64_t PinchedVertices = 0;
  std::size_t InconsistentEdges = 0;    ///< edges two triangles walk the same way (before repair)
  std::size_t Components = 0;
  std::size_t FlippedComponents = 0;    ///< reoriented to face outward
  bool Orientable = true;
  std::size_t SelfIntersections = 0;    ///< pairs of triangles that meet improperly (capped count)
  bool SelfIntersectionsChecked = false;
  long long EulerCharacteristic = 0;
  long long Genus = -1;                 ///< of the closed manifold input, else -1
  /// Triangles the caller added to close holes before the repair (the VTK
  /// filter's FillHoles).
  std::size_t FilledHoleTriangles = 0;
  /// Input polygons not simple in their plane, fanned from a corner by the
  /// caller (PolygonTriangulation.h): the mesh stays closed, and the
  /// self-intersection test judges the fan.
  std::size_t FannedPolygons = 0;

  /// Closed (no boundary), every edge manifold and orientable: a solid.
  bool Closed() const { return BoundaryEdges == 0 && Orientable; }
  /// The paper's assumptions: closed, manifold, no self-intersections.
  bool MeetsAssumptions() const
  {
    return Closed() && NonManifoldEdges == 0 && PinchedVertices == 0 && SelfIntersectionsChecked &&
      SelfIntersections == 0;
  }
  /// Anything repaired beyond merging exactly coincident vertices (which is
  /// how many formats store a closed mesh: one copy of a corner per face).
  bool Repaired() const
  {
    return DegenerateTriangles > 0 || DuplicateTriangles > 0 || InconsistentEdges > 0 || FlippedComponents > 0 ||
      FilledHoleTriangles > 0 || FannedPolygons > 0;
  }
  /// One line per problem found, empty if none.
  std::string Describe() const;
};

/// Repairs `points` and `triangles` in place (see above) and reports.
/// Self-intersections are looked for when `checkSelfIntersections` is set
/// (at most `maxReported` are counted).
MeshRepairReport RepairMesh(std::vector<Vec3>& points,
  std::vector<std::array<std::uint32_t, 3>>& triangles, bool checkSelfIntersections = true,
  std::size_t maxReported = 100, const ParallelFor& parallelFor = SequentialFor,
  const ProgressCallback& progress = nullptr);

/// RepairMesh with the self-intersection check, and the repaired mesh as a
/// solid, sharing their work: one edge table orients the mesh and gives the
/// solid its neighbours, and the check reads the solid's triangle boxes
/// (armadillo: a tenth less time to read, and 1 200 fewer fresh pages). A
/// mesh whose triangles come in no local order is reordered along a Morton
/// curve, points and triangles renamed (MeshOrder.h). An empty solid where
/// `progress` asked to stop (`report` is then partial).
MeshSolid RepairIntoSolid(std::vector<Vec3> points, std::vector<std::array<std::uint32_t, 3>> triangles,
  MeshRepairReport& report, std::size_t maxReported = 100, const ParallelFor& parallelFor = SequentialFor,
  const ProgressCallback& progress = nullptr);

} // namespace tpc
