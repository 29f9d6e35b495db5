// An oracle for the tests: the topology of the exact Boolean of two closed
// triangle meshes, computed independently of the core by CGAL's corefinement
// (Polygon Mesh Processing) on a kernel with exact constructions - as
// Testing/Reference/CsgReference.cxx computed Data/CsgReference.csv, here for
// meshes made at run time (Testing/Fuzz/FuzzBooleans.cxx). CGAL is GPL: it
// is linked into test programs only, never into the product.
#pragma once

#include "CgalHausdorff.h"

namespace tpcoracle
{

enum class BooleanOperation
{
  Union,
  Intersection,
  Difference ///< the first mesh's solid minus the second's
};

struct BooleanTopology
{
  /// False where there is no reference to compare with: an operand is not a
  /// closed manifold triangle mesh free of self-intersections, or the
  /// Boolean's boundary is not an embedded 2-manifold (the operands touch
  /// at a point or along an edge: CGAL refuses such a result, or it has a
  /// pinched vertex, or it touches itself).
  bool Valid = false;
  /// The two meshes' surfaces meet (CGAL's do_intersect on the surfaces):
  /// the Boolean has an intersection curve, not only whole components.
  bool SurfacesMeet = false;
  long long Components = 0;
  /// Total genus of the boundary: (2 Components - Euler characteristic) / 2.
  long long Genus = 0;
  /// The Boolean's boundary (corefined exactly, its points then rounded to
  /// the nearest doubles), for a distance to it (CgalHausdorff.h).
  TriangleSoup Surface;
  /// False when TPC_SKIP_CGAL_ORACLE is set (CgalEmbedding.h: under
  /// valgrind CGAL's interval filters give wrong answers).
  bool Checked = true;
};

/// The components and genus of the boundary of A op B, A and B the solids
/// bounded by the two meshes (each oriented here to bound its volume).
BooleanTopology ExactBooleanTopology(const TriangleSoup& a, const TriangleSoup& b, BooleanOperation operation);

} // namespace tpcoracle
