// The closed curves that the surface draws on a cell's boundary, traced from
// exact signs at sample points (paper 4.2-4.3, generalized to sampled faces).
//
// A cell's six faces are tiled by rectangles (the faces of finer neighbours,
// or of a face refinement). Each tile's boundary polygon holds every sample
// point lying on it, in counter-clockwise order as seen from outside the cell.
// Every run of inside points along a tile's polygon is cut off by one segment
// from the crossing entering the run to the crossing leaving it; the
// segments chain into loops. When every tile is MC-compatible (the surface
// meets it in at most one arc whose ends are the sign changes), the loops are
// exactly the curves of E on the cell boundary. A crossing is identified by
// the lattice sub-edge that holds it; the same rule on both sides of a face
// gives both cells the same segments, which is what makes the extraction
// crack-free.
#pragma once

#include "FaceTile.h"
#include "RootGrid.h"

#include <cstdint>
#include <optional>
#include <vector>

namespace tpc
{

/// What a vertex of the extracted surface is.
enum class CrossingKind : std::uint8_t
{
  /// The one surface crossing on the lattice sub-edge from `Key >> 2` along
  /// axis `Key & 3` to coordinate `Upper` (LowerInside: the sign at its
  /// lower end).
  SubEdge = 0,
  /// In a cell stopped by a limit a tile side can hold a whole run of inside
  /// samples (crossed twice); the segment cutting that run off would lie on
  /// the side's line, shared by every tile around it, and the mesh would stop
  /// being manifold. Such a segment is bent through a vertex of its own tile
  /// instead: Tile identifies the tile, Key and Partner are the run's two
  /// crossings (smaller key first). Cells that passed the tests never have one.
  Bend = 1,
  /// Exact cells (ExactCell.h): the crossing of sub-edge Key (as for
  /// SubEdge) by triangle Partner of mesh Tile, where the sub-edge is crossed
  /// more than once.
  SubEdgeTriangle = 2,
  /// Exact cells: where the edge Partner (its two vertex ids, smaller in the
  /// high half) of mesh Tile meets the lattice plane Key (PlaneKey).
  MeshEdge = 3,
  /// Exact cells: vertex Key of mesh Tile, inside the cell.
  MeshVertex = 4,
  /// Where two leaves' crease (quadrics, or a mesh with a mesh or a quadric)
  /// crosses a face tile (CsgCreaseCrossing.h):
  /// Tile names the tile as for a bend, Key and Partner its far corner's
  /// coordinates along the plane's two axes.
  CsgCrease = 5
};

/// A lattice plane as a key: axis in the top bits, lattice coordinate below.
inline LatticeKey PlaneKey(int axis, LatticeIndex coordinate)
{
  return (static_cast<LatticeKey>(axis) << 64) | coordinate;
}
inline int PlaneAxis(LatticeKey plane)
{
  return static_cast<int>(plane >> 64);
}
inline LatticeIndex PlaneCoordinate(LatticeKey plane)
{
  return static_cast<LatticeIndex>(plane);
}

/// A vertex of the extracted surface: identified by (Kind, Key, Tile,
/// Partner); Upper and LowerInside describe a sub-edge crossing.
struct Crossing
{
  LatticeKey Key = 0;
  LatticeKey Tile = 0;
  LatticeKey Partner = 0;
  LatticeIndex Upper = 0;
  CrossingKind Kind = CrossingKind::SubEdge;
  bool LowerInside = false;

  bool SameVertex(const Crossing& o) const
  {
    return Kind == o.Kind && Key == o.Key && Tile == o.Tile && Partner == o.Partner;
  }
  bool operator<(const Crossing& o) const
  {
    if (Kind != o.Kind)
    {
      return Kind < o.Kind;
    }
    if (Key != o.Key)
    {
      return Key < o.Key;
    }
    return Tile != o.Tile ? Tile < o.Tile : Partner < o.Partner;
  }
};

/// A crease tile (CreaseCrossing.h, CsgCreaseCrossing.h): the crossing x
/// its chord is drawn through. For a mesh's crease also x's position and the
/// trace's two halves from x: the mesh edges' crossings inside the tile, in
/// order, then the crossing just outside it (the half's last segment leaves
/// the tile through a or b); a CSG crease has X only (placed with the cell,
/// CsgCreaseCrossing.h).
struct CreaseTile
{
  Crossing X;
  Vec3 Position;
  std::vector<Vec3> Sides[2];
};

/// The samples on a cell's boundary.
struct CellBoundary
{
  LatticeIndex Base[3] = { 0, 0, 0 }; ///< low corner, lattice units
  LatticeIndex Size = 1;              ///< edge length, lattice units
  std::vector<FaceTile> Tiles[6];      ///< tiles of face f (see CubeTopology.h)
  /// Per tile of face f: the leaf on its other side (an octree node index,
  /// -1 outside the grid).
  std::vector<std::int64_t> Across[6];
  /// Every sample point on the boundary with its exact sign (any order,
  /// duplicates allowed; Trace sorts them).
  std::vector<std::pair<PointKey, bool>> Points;
  /// Per tile of face f: 1 where the surface on it is drawn exactly
  /// (ExactCell.h: a tile of an exact cell), its segments in ExactSegments;
  /// 0 (or empty) where they come from the samples.
  std::vector<std::uint8_t> ExactTile[6];
  std::vector<std::pair<Crossing, Crossing>> ExactSegments;
  /// Per tile of face f (or empty): the crease that the tile's chord is
  /// drawn through, where it has one: a mesh's sharpest edge on it
  /// (CreaseCrossing.h) or two leaves' crease (CsgCreaseCrossing.h).
  std::vector<std::optional<CreaseTile>> Creases[6];
};

struct BoundaryLoopSet
{
  std::vector<Crossing> Crossings; ///< the loops, concatenated, in order
  std::vector<std::uint32_t> LoopSizes;
  bool Consistent = true; ///< every crossing starts and ends exactly one segment
};

BoundaryLoopSet TraceBoundaryLoops(CellBoundary& boundary);

/// Each loop's crossings, in order.
std::vector<std::vector<Crossing>> EachLoop(const BoundaryLoopSet& loops);

/// Faces of the cell with low corner `base` and edge `size` (lattice units)
/// that a loop's crossing lies on: bit f (CubeTopology.h numbering); all six
/// for a bend (never a fan point), none for a mesh vertex inside an exact
/// cell, its tile's face for a CSG crease.
unsigned CrossingFaces(const Crossing& c, const LatticeIndex base[3], LatticeIndex size);

} // namespace tpc
