// Where an input mesh meets the lattice, decided exactly (for exact cells,
// ExactCell.h): the mesh's vertices, the points where its edges cross
// lattice planes and where its triangles cross lattice lines, and on which
// side of a lattice plane each of them lies.
//
// The mesh is MeshSolid's perturbed solid: every lattice point q stands for
// q + d, d = (eps, eps^2, eps^3), which is the mesh moved by -d against the
// unperturbed lattice. Every side test is decided for that mesh, so no point
// is ever on a lattice plane, and the answers agree with MeshSolid's signs
// and crossing counts (the same perturbed solid). Each test is an exact
// predicate (ExactPredicates.h); where it is zero, the first non-zero term of
// its expansion in eps decides:
//
// - vertex p against the plane x_a = c: the sign of p_a - c; when zero, the
//   moved vertex p - d is below (-1).
// - the crossing X of edge (p, q) with the plane x_b = e, against x_a = c:
//   X_a - c = D / (q_b - p_b) with D = (p_a - c)(q_b - p_b) + (e - p_b)(q_a - p_a)
//   (a 2-D orientation of p, q and (e, c) in the (b, a) plane). Moving the
//   mesh by -d moves X along a by d_b (q_a - p_a) / (q_b - p_b) - d_a: when
//   D = 0, the term of lower power of eps decides - the first if b < a (and
//   q_a != p_a), otherwise -d_a (below).
// - the crossing Y of triangle (A, B, C), normal n = (B - A) x (C - A), with
//   the lattice line through Z along a, against Z_a: Y_a - Z_a = n.(A - Z) / n_a.
//   Moving the mesh adds -n.d / n_a: when n.(A - Z) = 0 the first non-zero
//   of n_x, n_y, n_z decides (its sign, against n_a's). n_a != 0 whenever
//   such a crossing is made (a line parallel to the triangle never crosses it).
//
// Positions are computed once per point from the mesh and the lattice alone
// (an edge's crossing from its lower-numbered vertex), so every cell that
// meets a point places it at the same coordinates, exactly on its lattice
// plane or line. PlacedAsDecided says whether a position lies strictly on
// the side of every lattice plane that the exact tests say (rounding may put
// a point on or past a plane it is before): a property of the point alone,
// the same for every tile and sub-tile holding it (CreaseCrossing.h).
#pragma once

#include "MeshSolid.h"
#include "RootGrid.h"

#include <cstdint>
#include <vector>

namespace tpc
{

/// A point of the arrangement of one mesh with the lattice.
struct ArrangementPoint
{
  enum class Kind : std::uint8_t
  {
    MeshVertex,     ///< vertex A
    EdgeOnPlane,    ///< edge (A, B), A < B, on the plane x_Axis = Lattice[Axis]
    TriangleOnLine  ///< triangle A on the line along Axis through Lattice (Lattice[Axis] unused)
  };
  Kind PointKind = Kind::MeshVertex;
  std::uint32_t A = 0, B = 0;
  int Axis = 0;
  LatticeIndex Lattice[3] = { 0, 0, 0 };

  static ArrangementPoint Vertex(std::uint32_t v);
  static ArrangementPoint EdgeOnPlane(std::uint32_t a, std::uint32_t b, int axis, LatticeIndex coordinate);
  static ArrangementPoint TriangleOnLine(std::uint32_t t, int freeAxis, const LatticeIndex lattice[3]);
  /// The point's coordinate on `axis` is a lattice coordinate (it lies on
  /// that lattice plane): the coordinate, else -1.
  std::int64_t FixedCoordinate(int axis) const;
};

/// A vertex of a triangle clipped to a box, and what the polygon edge from
/// it to the next vertex lies on: an edge of the triangle (0, 1, 2: from its
/// vertex k to k + 1) or a face of the box (FaceSupport + f, CubeTopology.h).
struct ClippedVertex
{
  static constexpr int FaceSupport = 3;
  ArrangementPoint Point;
  int Support = 0;
};

class MeshArrangement
{
public:
  MeshArrangement(const MeshSolid& mesh, const RootGrid& grid);

  /// -1 or +1: `p` is below or above the lattice plane x_axis = coordinate
  /// (never on it; not asked of a point lying on that very plane).
  int Side(const ArrangementPoint& p, int axis, LatticeIndex coordinate) const;
  Vec3 Position(const ArrangementPoint& p) const;
  /// Whether `position` (p's, as computed) lies strictly between the two
  /// lattice planes of the finest level that p lies between by the exact
  /// side tests, on every axis p is not fixed on; then it is on the decided
  /// side of every lattice plane.
  bool PlacedAsDecided(const ArrangementPoint& p, const Vec3& position) const;

  /// Triangle t clipped to the closed lattice box [lo, hi] (Sutherland and
  /// Hodgman, with the exact side tests), in t's orientation; empty when
  /// they do not meet.
  std::vector<ClippedVertex> ClipTriangle(std::uint32_t t, const LatticeIndex lo[3], const LatticeIndex hi[3]) const;

  /// The segment triangle t draws on the lattice plane x_axis = plane inside
  /// the rectangle [lo[0], hi[0]] x [lo[1], hi[1]] of the plane's (u, v) axes
  /// (u = axis + 1, v = axis + 2), oriented as BoundaryLoops orients chords:
  /// the solid on its right seen from the side `outward` (+1: from above).
  /// `sigma` -1 means the solid is the mesh's complement. False when t does
  /// not meet the rectangle.
  bool TraceOnRectangle(std::uint32_t t, int axis, LatticeIndex plane, const LatticeIndex lo[2],
    const LatticeIndex hi[2], int outward, int sigma, ArrangementPoint& from, ArrangementPoint& to) const;

  /// For two points of a straight segment starting at `from`: true when `a`
  /// comes before the point where the segment crosses the lattice plane
  /// x_axisB = coordinateB (`a` and `from` not on that plane).
  bool Before(const ArrangementPoint& from, const ArrangementPoint& a, int axisB, LatticeIndex coordinateB) const;

  const MeshSolid& Mesh() const { return this->Solid; }
  const RootGrid& Lattice() const { return this->Grid; }

private:
  int VertexSide(const Vec3& p, int axis, double c) const;
  int EdgeSide(const ArrangementPoint& p, int axis, double c) const;
  int TriangleSide(const ArrangementPoint& p, int axis, double c) const;

  const MeshSolid& Solid;
  const RootGrid& Grid;
};

} // namespace tpc
