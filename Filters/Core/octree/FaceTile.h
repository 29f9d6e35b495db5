// The tiles of a cell face: a face is one tile, or - where face refinement
// sampled it finer (FaceRefinement.h) - the rectangles it was split into.
#pragma once

#include "RootGrid.h"

#include <algorithm>
#include <cstdint>
#include <vector>

namespace tpc
{

/// A rectangular tile [U0, U1] x [V0, V1] of a face, in lattice units of the
/// face's (u, v) axes, u = axis + 1, v = axis + 2 (mod 3).
struct FaceTile
{
  LatticeIndex U0 = 0, V0 = 0, U1 = 1, V1 = 1;
};

inline bool operator==(const FaceTile& a, const FaceTile& b)
{
  return a.U0 == b.U0 && a.V0 == b.V0 && a.U1 == b.U1 && a.V1 == b.V1;
}

/// Whether tile a lies in tile b.
inline bool TileWithin(const FaceTile& a, const FaceTile& b)
{
  return b.U0 <= a.U0 && a.U1 <= b.U1 && b.V0 <= a.V0 && a.V1 <= b.V1;
}

/// Whether the interiors of tiles a and b are disjoint.
inline bool TilesApart(const FaceTile& a, const FaceTile& b)
{
  return a.U1 <= b.U0 || b.U1 <= a.U0 || a.V1 <= b.V0 || b.V1 <= a.V0;
}

/// Two tilings of one face (by the two cells sharing it): where every tile
/// of one either nests with or lies apart from every tile of the other -
/// both refine one tiling by splitting some of its tiles, as face refinement
/// and chord refinement (MeshCellError.h) do, each split decided by its tile
/// alone - `kept` becomes the tiles of either that hold no smaller tile of
/// the other: a tiling that refines both, so each cell's final loop holds
/// its own loop's points (its prediction's premise). Else `kept` stays.
/// Independent of which came first; `kept` is unchanged when `other` adds
/// nothing.
inline void MergeFaceTilings(std::vector<FaceTile>& kept, const std::vector<FaceTile>& other)
{
  for (const FaceTile& a : kept)
  {
    for (const FaceTile& b : other)
    {
      if (!TileWithin(a, b) && !TileWithin(b, a) && !TilesApart(a, b))
      {
        return;
      }
    }
  }
  const auto holdsSmaller = [](const FaceTile& t, const std::vector<FaceTile>& tiles) {
    return std::any_of(tiles.begin(), tiles.end(), [&](const FaceTile& s) { return TileWithin(s, t) && !(s == t); });
  };
  std::vector<FaceTile> merged;
  for (const FaceTile& t : kept)
  {
    if (!holdsSmaller(t, other))
    {
      merged.push_back(t);
    }
  }
  const std::size_t fromKept = merged.size();
  for (const FaceTile& t : other)
  {
    if (!holdsSmaller(t, kept) && std::find(merged.begin(), merged.begin() + static_cast<std::ptrdiff_t>(fromKept), t) ==
        merged.begin() + static_cast<std::ptrdiff_t>(fromKept))
    {
      merged.push_back(t);
    }
  }
  if (merged.size() != kept.size() || fromKept != kept.size())
  {
    // (In one order whatever came first: tiles sorted by their low corner.)
    std::sort(merged.begin(), merged.end(), [](const FaceTile& a, const FaceTile& b) {
      return a.V0 != b.V0 ? a.V0 < b.V0 : a.U0 != b.U0 ? a.U0 < b.U0 : a.V1 != b.V1 ? a.V1 < b.V1 : a.U1 < b.U1;
    });
    kept = std::move(merged);
  }
}

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
