// An oracle for the tests, independent of the core's own exact checks
// (SurfaceEmbedding.h, SolidBoundary.h): CGAL's self-intersection test on a
// triangle mesh with its own vertex ids, an exact count of vertices at the
// coordinates of another, and whether the mesh bounds a volume. CGAL is
// GPL: it is linked into test programs only, never into the product.
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <vector>

namespace tpcoracle
{

struct EmbeddingVerdict
{
  std::size_t SelfIntersectingPairs = 0; ///< CGAL::Polygon_mesh_processing::self_intersections
  std::size_t CoincidentVertices = 0;    ///< vertices with the coordinates of an earlier one
  bool PolygonMesh = true;               ///< CGAL took the triangles as one oriented manifold mesh
  /// Every component oriented as its nesting asks - outward at an even
  /// nesting level - by CGAL's volume_connected_components (its orientation
  /// and nesting tests). Decided only for a closed polygon mesh free of
  /// self-intersections (VolumeChecked).
  bool Outward = false;
  bool VolumeChecked = false;
  /// False when TPC_SKIP_CGAL_ORACLE is set: under valgrind, which does not
  /// emulate the rounding modes CGAL's interval filters switch to, CGAL's
  /// predicates give wrong answers.
  bool Checked = true;

  bool Embedded() const { return this->SelfIntersectingPairs == 0 && this->CoincidentVertices == 0; }
};

/// CGAL with exact constructions: do triangles (p[t1[0]], p[t1[1]],
/// p[t1[2]]) and (p[t2[0]], ...) meet anywhere but in the vertex or the edge
/// they share by index? (The intersection computed exactly and compared.)
bool TrianglePairMeetsImproperly(const std::vector<std::array<double, 3>>& points,
  const std::array<std::uint32_t, 3>& t1, const std::array<std::uint32_t, 3>& t2);

EmbeddingVerdict CheckEmbeddingWithCgal(
  const std::vector<std::array<double, 3>>& points, const std::vector<std::array<std::uint32_t, 3>>& triangles);

} // namespace tpcoracle
