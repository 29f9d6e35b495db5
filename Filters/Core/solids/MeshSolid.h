// A closed, outward-oriented triangle mesh as a solid (paper 5.1-5.3, 6.4).
//
// Inside/outside is decided exactly: the parity of crossings of a ray from
// the point, with the exact predicates of ExactPredicates.h. Every query
// point q stands for q + (eps, eps^2, eps^3) (one symbolic perturbation for
// all queries), so rays through edges and vertices are counted once and
// consistently, and a point on the surface is classified like the points just
// beside it in that direction. This is guaranteed correct for closed meshes - unlike signs from closest features, which fail
// on real parts (vtkImplicitPolyDataDistance finds hundreds of spurious
// components on a genus-11 mesh). Crossings of axis-aligned segments use the
// same rule, so "how many times does this lattice edge cross the surface" is
// exact too.
//
// Cells keep the list of triangles overlapping them (the paper's 6.4): a
// conservative triangle/box test filters a parent's list for each child.
//
// Each triangle's unit normal and its neighbour across each edge are kept
// from the start (one edge table): the crease tests (CreaseCrossing.h,
// CreaseFollowing.h) ask, for every face tile and every cell of the
// surface, which listed triangles meet at an angle. Computed per cell, that
// was sorting the cell's edges and normalizing the normals each time
// (CreasesInCell alone 3 % of armadillo at 1/64, now 0.5 %; the whole run
// 0.97-0.98x, outputs unchanged).
#pragma once

#include "Parallel.h"
#include "ReleasableArray.h"
#include "Vector3.h"

#include <array>
#include <cstdint>
#include <vector>

namespace tpc
{

using TriangleList = std::vector<std::uint32_t>;

/// The coordinates a mesh's floating-point geometry is trusted with. Its
/// exact predicates hold for doubles whose products neither overflow nor
/// underflow (ExactSum.h), and the distances, normals and certificates
/// built on them (ConvexPolygons.cxx, PolygonHausdorff.cxx,
/// MeshCellError.cxx) take up to fourth powers of lengths: |N|^2 of a
/// Newell vector is a sum of fourth powers of coordinate differences, which
/// overflows once coordinates reach about 1e76, and lengths as short as the
/// lattice's finest spacing (2^-41 of the domain) raised to the fourth
/// power become subnormal - losing the relative rounding bound every
/// certificate rests on - once the mesh is below about 1e-62 across.
/// Measured (CGAL's fandisk scaled, 1/32): the same surface from 1e-70 to
/// 1e77, the input itself at 1e-80 and 1e100 (every cell exact), a broken
/// one at 1e150 (flagged) and none at 1e-150, where the repair also found
/// self-intersections that are not there. A mesh is refused with a margin
/// of 1e16 above (coordinates up to 1e60 in magnitude) and 1e12 below (a
/// box at least 1e-50 across). (The box bounds coordinates, not their
/// differences: a triangle whose Newell vector falls below 1e-150 is
/// measured by its edges, squares of lengths - ConvexPolygons.cxx,
/// MeasuredByItsPlane.)
constexpr double LargestTrustedMeshCoordinate = 1e60;
constexpr double SmallestTrustedMeshDiagonal = 1e-50;
/// Whether a mesh with this box is within the trusted range.
bool WithinTrustedMeshRange(const Box3& bounds);

class MeshSolid
{
public:
  MeshSolid() = default;
  /// Triangles must form a closed surface oriented outward (see MeshRepair.h).
  MeshSolid(std::vector<Vec3> points, std::vector<std::array<std::uint32_t, 3>> triangles,
    const ParallelFor& parallelFor = SequentialFor);
  /// The same with each triangle's neighbour across each edge given, as
  /// Across() answers them (RepairIntoSolid's, from the edge table its
  /// repair builds anyway: a second table was a tenth of reading armadillo);
  /// found anew where there is not one entry per triangle.
  MeshSolid(std::vector<Vec3> points, std::vector<std::array<std::uint32_t, 3>> triangles,
    std::vector<std::array<std::uint32_t, 3>> neighbours, const ParallelFor& parallelFor = SequentialFor);

  /// Across() where an edge is not used by exactly two triangles.
  static constexpr std::uint32_t NoTriangle = 0xFFFFFFFFu;

  const std::vector<Vec3>& Points() const { return this->Vertices; }
  const std::vector<std::array<std::uint32_t, 3>>& Triangles() const { return this->Faces; }
  std::size_t TriangleCount() const { return this->Faces.size(); }
  const Box3& Bounds() const { return this->Box; }

  /// Exact: inside the (symbolically perturbed) solid.
  bool IsInside(const Vec3& p) const;
  /// Exact: how many of the triangles t with counts(t) the ray from p along
  /// +x (along -x: `backward`) crosses, p perturbed as in IsInside (so its
  /// parity over a closed surface's triangles says whether p is inside that
  /// surface, whichever way the ray goes; the triangles' orientation does
  /// not matter - turning one over turns every sign its crossing test reads
  /// - so this holds for any closed triangles, outward or not).
  template <typename Counts>
  int CrossingsAlongX(const Vec3& p, const Counts& counts, bool backward = false) const;

  /// Exact number of crossings of the surface by the segment from `a` to `b`,
  /// which differ only along `axis` (a[axis] < b[axis]), among `triangles`
  /// (which must include every triangle meeting the segment).
  int CountCrossings(const Vec3& a, const Vec3& b, int axis, const TriangleList& triangles) const;
  /// When that segment crosses the surface exactly once: the crossing, on the
  /// crossed triangle's plane (floating point), in `point`, and that
  /// triangle in `crossed` (if given). False otherwise.
  bool CrossingPoint(const Vec3& a, const Vec3& b, int axis, const TriangleList& triangles, Vec3& point,
    std::uint32_t* crossed = nullptr) const;
  /// Every crossing of that segment (those CountCrossings counts): the
  /// coordinate along `axis` where it meets the crossed triangle's plane
  /// (floating point, not ordered), appended to `coordinates`. False where a
  /// crossed triangle's plane gives no point (PlaneCrossing: it holds the
  /// segment, which the perturbation decides, or rounding puts the point
  /// outside it).
  bool CrossingCoordinates(
    const Vec3& a, const Vec3& b, int axis, const TriangleList& triangles, std::vector<double>& coordinates) const;

  /// The triangles of `candidates` that may meet the closed box (a
  /// conservative separating-axis test: never drops a triangle that does).
  void Overlapping(const Box3& box, const TriangleList& candidates, TriangleList& out) const;
  /// All triangles that may meet the box.
  TriangleList Overlapping(const Box3& box) const;

  /// Unit outward normal of triangle t (zero when degenerate, NaN with
  /// non-finite coordinates).
  const Vec3& Normal(std::uint32_t t) const { return this->Normals[t]; }
  /// The other triangle of triangle t's edge k (from its corner k to corner
  /// k + 1), or NoTriangle when that edge has not exactly two triangles.
  std::uint32_t Across(std::uint32_t t, int k) const { return this->Neighbours[t][k]; }
  /// Every edge between exactly two triangles (with the repair's consistent
  /// orientation, MeshRepair.h: the mesh is a closed oriented surface).
  bool EveryEdgeHasTwoTriangles() const { return this->Closed; }
  /// Signed distance to the nearest of `triangles` (sign from that triangle's
  /// side; for placing vertices only - topology never uses it).
  double ApproximateSignedDistance(const Vec3& p, const TriangleList& triangles, std::uint32_t* nearest = nullptr) const;
  /// The box of triangle t's vertices (their exact minima and maxima).
  const Box3& TriangleBounds(std::uint32_t t) const { return this->FaceBoxes[t]; }
  /// Those boxes, one per triangle.
  const ReleasableArray<Box3>& TriangleBoxes() const { return this->FaceBoxes; }
  /// Vertex k (0..2) of triangle t.
  const Vec3& Vertex(std::uint32_t t, int k) const { return this->Vertices[this->Faces[t][k]]; }

private:
  /// Normals, boxes and the ray-casting grid, from the vertices and faces.
  void Index(const ParallelFor& parallelFor);
  /// Whether the segment from a to b (differing along `axis` only, a at or
  /// below b), or without b the ray from a along +axis (-axis: `backward`),
  /// crosses triangle t, a and b perturbed as in IsInside.
  bool Crosses(std::uint32_t t, const Vec3& a, const Vec3* b, int axis, bool backward = false) const;
  /// Where the segment from a to b (differing along `axis` only) meets
  /// triangle t's plane: its coordinate along `axis`, in `coordinate`; false
  /// where the segment lies in the plane, or rounding puts the point outside
  /// the segment.
  bool PlaneCrossing(std::uint32_t t, const Vec3& a, const Vec3& b, int axis, double& coordinate) const;
  /// The ray-casting grid's column (0: along y, 1: along z) of a coordinate.
  int GridColumn(int k, double coordinate) const;
  /// The ray-casting grid's cell holding p's (y, z).
  std::size_t RayCell(const Vec3& p) const;
  /// Calls `crossed(t)` for each triangle of `triangles` the segment crosses.
  template <typename Crossed>
  void ForEachCrossing(const Vec3& a, const Vec3& b, int axis, const TriangleList& triangles,
    const Crossed& crossed) const;

  std::vector<Vec3> Vertices;
  std::vector<std::array<std::uint32_t, 3>> Faces;
  // (Filled by a parallel loop: ReleasableArray::resize_for_overwrite.)
  ReleasableArray<Box3> FaceBoxes;
  ReleasableArray<Vec3> Normals;
  /// Every edge between exactly two triangles (IsInside may cast its ray
  /// either way).
  bool Closed = false;
  /// Each triangle's exact sign of its normal's component along each axis
  /// (Orient2D of its corners seen along that axis): read by every crossing
  /// test (Crosses), made once.
  ReleasableArray<std::array<std::int8_t, 3>> AxisFacing;
  std::vector<std::array<std::uint32_t, 3>> Neighbours;
  Box3 Box;
  // Ray-casting index: a uniform grid over the (y, z) extent; each cell lists
  // the triangles whose (y, z) bounding box overlaps it.
  int GridSize[2] = { 1, 1 };
  double GridOrigin[2] = { 0, 0 };
  double GridStep[2] = { 1, 1 };
  std::vector<std::uint32_t> GridStart;
  std::vector<std::uint32_t> GridTriangles;
};

template <typename Counts>
int MeshSolid::CrossingsAlongX(const Vec3& p, const Counts& counts, bool backward) const
{
  if (this->Faces.empty() || (backward ? !(p[0] >= this->Box.lo[0]) : !(p[0] <= this->Box.hi[0])) ||
    p[1] < this->Box.lo[1] || p[1] > this->Box.hi[1] || p[2] < this->Box.lo[2] || p[2] > this->Box.hi[2])
  {
    return 0;
  }
  const std::size_t cell = this->RayCell(p);
  int crossings = 0;
  for (std::uint32_t i = this->GridStart[cell]; i < this->GridStart[cell + 1]; ++i)
  {
    const std::uint32_t t = this->GridTriangles[i];
    const Box3& b = this->FaceBoxes[t];
    if ((backward ? b.lo[0] > p[0] : b.hi[0] < p[0]) || p[1] < b.lo[1] || p[1] > b.hi[1] || p[2] < b.lo[2] ||
      p[2] > b.hi[2] || !counts(t))
    {
      continue;
    }
    crossings += this->Crosses(t, p, nullptr, 0, backward) ? 1 : 0;
  }
  return crossings;
}

} // namespace tpc
