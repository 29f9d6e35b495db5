// The tiles of a cell face: a face is one tile, or - where face refinement
// sampled it finer (FaceRefinement.h) - the rectangles it was split into.
#pragma once

#include "RootGrid.h"

#include <cstdint>

namespace tpc
{

/// A rectangular tile [U0, U1] x [V0, V1] of a face, in lattice units of the
/// face's (u, v) axes, u = axis + 1, v = axis + 2 (mod 3).
struct FaceTile
{
  LatticeIndex U0 = 0, V0 = 0, U1 = 1, V1 = 1;
};

/// Corner c (bit 0: U1, bit 1: V1) of a tile lying in the plane axis = plane.
inline PointKey TileCorner(int axis, LatticeIndex plane, const FaceTile& t, int c)
{
  LatticeIndex p[3];
  p[axis] = plane;
  p[(axis + 1) % 3] = (c & 1) ? t.U1 : t.U0;
  p[(axis + 2) % 3] = (c & 2) ? t.V1 : t.V0;
  return MakePointKey(p[0], p[1], p[2]);
}

/// A tile as a crossing's key (a bend's or a CSG crease's, BoundaryLoops.h):
/// its low corner and its plane's axis, plus one (never zero).
inline LatticeKey TileKey(int axis, LatticeIndex plane, const FaceTile& t)
{
  return WithAxis(TileCorner(axis, plane, t, 0), axis) + 1;
}
/// The plane axis of a TileKey, and its low corner.
inline int TileKeyAxis(LatticeKey key)
{
  return AxisOf(key - 1);
}
inline void TileKeyCorner(LatticeKey key, LatticeIndex corner[3])
{
  SplitPointKey(PointOf(key - 1), corner);
}

/// The closed box of a tile lying in the plane axis = plane (flat along
/// axis), in world coordinates.
inline Box3 TileBox(const RootGrid& grid, int axis, LatticeIndex plane, const FaceTile& t)
{
  const int u = (axis + 1) % 3, v = (axis + 2) % 3;
  Box3 box;
  box.lo[axis] = box.hi[axis] = grid.Coordinate(axis, plane);
  box.lo[u] = grid.Coordinate(u, t.U0);
  box.hi[u] = grid.Coordinate(u, t.U1);
  box.lo[v] = grid.Coordinate(v, t.V0);
  box.hi[v] = grid.Coordinate(v, t.V1);
  return box;
}

} // namespace tpc
