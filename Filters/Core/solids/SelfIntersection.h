// Self-intersection detection for triangle meshes, with exact predicates.
//
// Two triangles meet improperly when they intersect anywhere except along
// the edge or at the vertex they share. Candidate pairs come from a uniform
// grid over the triangles' bounding boxes; each pair is decided exactly
// (Orient3D/Orient2D), coplanar pairs included.
#pragma once

#include "Parallel.h"
#include "Vector3.h"

#include <array>
#include <cstddef>
#include <cstdint>
#include <vector>

namespace tpc
{

class EmbeddedStars;
class MeshSolid;

/// Number of improperly meeting triangle pairs, counting at most `limit`
/// (the candidate pairs are tested in parallel; the count does not depend on
/// the number of threads). Both counts report progress over the candidate
/// pairs and stop early when it asks to (Parallel.h).
std::size_t CountSelfIntersections(const std::vector<Vec3>& points,
  const std::vector<std::array<std::uint32_t, 3>>& triangles, std::size_t limit = 100,
  const ParallelFor& parallelFor = SequentialFor, const ProgressCallback& progress = nullptr);

/// The same for the triangles of `mesh`, with the boxes it keeps of them
/// (not a second copy) and `stars`, proven of them (EmbeddedStars.h: the
/// caller keeps them for the pinched vertices' count).
std::size_t CountSelfIntersections(const MeshSolid& mesh, const EmbeddedStars& stars, std::size_t limit = 100,
  const ParallelFor& parallelFor = SequentialFor, const ProgressCallback& progress = nullptr);

/// Number of triangle pairs, one from each mesh, that lie in one plane and
/// meet (exact), with opposite windings (`facingEachOther`) or the same
/// winding, counting at most `limit`. In a union or an intersection, faces
/// facing each other make the two surfaces meet without crossing - a
/// tangential contact (paper 5.3.3) spread over an area, which no refinement
/// resolves; a difference complements its subtracted solids, and there flush
/// faces (the same winding) are the contact.
std::size_t CountCoincidentFaces(const std::vector<Vec3>& pointsA,
  const std::vector<std::array<std::uint32_t, 3>>& trianglesA, const std::vector<Vec3>& pointsB,
  const std::vector<std::array<std::uint32_t, 3>>& trianglesB, bool facingEachOther, std::size_t limit = 100,
  const ParallelFor& parallelFor = SequentialFor, const ProgressCallback& progress = nullptr);

/// Exact: do triangles t1 and t2 of a mesh meet anywhere but in the vertices
/// or the edge they share (by index)? Identical triangles always do.
bool TrianglesMeetImproperly(const Vec3* points, const std::array<std::uint32_t, 3>& t1,
  const std::array<std::uint32_t, 3>& t2);

/// Exact: do the closed triangles (a, b, c) and (d, e, f), which share no
/// vertex, intersect?
bool TrianglesIntersect(const Vec3& a, const Vec3& b, const Vec3& c, const Vec3& d, const Vec3& e,
  const Vec3& f);

/// Exact: are a, b and c collinear (the triangle has no area)?
bool TriangleIsDegenerate(const Vec3& a, const Vec3& b, const Vec3& c);

/// Exact: does the closed segment pq meet the closed triangle abc?
bool SegmentMeetsTriangle(const Vec3& p, const Vec3& q, const Vec3& a, const Vec3& b, const Vec3& c);

} // namespace tpc
