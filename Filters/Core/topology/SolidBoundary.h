// Whether a closed, consistently oriented, embedded surface is the boundary
// of a solid with its normals pointing out of it - the "outward" of the
// guarantee (README, What TopologyGuaranteed = 1 promises).
//
// Each component C of such a surface bounds one region (Jordan-Brouwer), and
// its normals point out of that region everywhere or nowhere (the set where
// they do is open and closed in a connected surface): C's signed volume is
// positive or negative accordingly. The components bound a solid with the
// normals pointing out of it exactly when each C points out of its own
// region where it lies inside an even number of the other components (a
// shell, or an island in a void) and into it where it lies inside an odd
// number (a void): sign of the volume = (-1)^depth. An inside-out component
// - a void left outside the solid, a small solid turned over - breaks it,
// which the counts (components, genus, closed, manifold, oriented) do not
// see.
//
// The extraction orients every patch with the solid on its inner side (each
// loop's segments cut off the runs of inside points in the order the tiles
// are walked, BoundaryLoops.h), and the decimation keeps the side of every
// component (CertifiedDecimation.h, Embedding); this checks both on the
// surface itself.
//
// Depth: the parity of the crossings of the ray along +x from a vertex of C
// with the other components' triangles, exact (MeshSolid::CrossingsAlongX;
// the vertex lies on no other component's triangle, the surface being
// embedded). Volume: sum over C's triangles of det(a - o, b - o, c - o) / 6
// in floating point about a vertex o of C, with an error bound
// (SolidBoundary.cxx); a component whose volume is within it of 0 is
// undecided, and counts as not outward.
#pragma once

#include "Parallel.h"
#include "TriangleMesh.h"

#include <cstddef>
#include <cstdint>

namespace tpc
{

/// The volume closed triangles enclose (six times it), summed about the
/// first vertex added, with a bound on its rounding error (SolidBoundary.cxx).
class EnclosedVolume
{
public:
  void Add(const Vec3* points, const Triangle& t);
  /// +1 or -1, or 0 when the sum is within its rounding bound of 0.
  int Sign() const;
  /// The vertex the determinants are taken about.
  std::uint32_t Origin() const { return this->Base; }

private:
  std::uint32_t Base = 0;
  bool Started = false;
  double Six = 0.0;
  double Magnitudes = 0.0; ///< sum of the determinants' terms' absolute values
  double Reach = 0.0;      ///< sum of the first corners' |x - o|_1 (underflow errors scale with it)
  std::size_t Count = 0;
};

struct OutwardReport
{
  std::int64_t Components = 0;
  std::int64_t InsideOut = 0; ///< oriented against their depth
  std::int64_t Undecided = 0; ///< volume within its rounding bound of 0
  bool Outward() const { return this->InsideOut == 0 && this->Undecided == 0; }
};

/// The check above, on `mesh` (closed, consistently oriented, embedded: what
/// it says of anything else means nothing).
OutwardReport CheckOutward(const TriangleMesh& mesh, const ParallelFor& parallelFor = SequentialFor);

} // namespace tpc
