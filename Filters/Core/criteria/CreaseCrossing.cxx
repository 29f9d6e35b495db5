#include "CreaseCrossing.h"

#include "FaceDecisionCache.h"
#include "MeshArrangement.h"

#include <algorithm>
#include <cmath>
#include <tuple>
#include <vector>

namespace tpc
{
namespace
{
/// A triangle edge crossing the open tile: its vertices (smaller first), the
/// triangle and the triangle's third vertex.
struct EdgeUseOnTile
{
  std::uint32_t A = 0, B = 0, Triangle = 0, Opposite = 0;
  bool operator<(const EdgeUseOnTile& o) const { return std::tie(A, B, Triangle) < std::tie(o.A, o.B, o.Triangle); }
};

/// Whether the mesh's crossing X of the plane x_axis = plane through edge
/// (a, b) lies in the open tile (exact, MeshArrangement.h).
bool InsideTile(const MeshArrangement& arrangement, const ArrangementPoint& x, int axis, const FaceTile& tile)
{
  const int u = (axis + 1) % 3, v = (axis + 2) % 3;
  return arrangement.Side(x, u, tile.U0) > 0 && arrangement.Side(x, u, tile.U1) < 0 &&
    arrangement.Side(x, v, tile.V0) > 0 && arrangement.Side(x, v, tile.V1) < 0;
}

/// The triangles of `triangles` whose bounds meet `tileBox`, the tile's
/// closed box. (A triangle strictly apart from it, in doubles, stays apart
/// from it under the infinitesimal perturbation: no exact test needs it.)
void NearTile(const MeshSolid& mesh, const TriangleList& triangles, const Box3& tileBox, TriangleList& near)
{
  near.clear();
  for (const std::uint32_t t : triangles)
  {
    if (mesh.TriangleBounds(t).Overlaps(tileBox))
    {
      near.push_back(t);
    }
  }
}

/// Whether an edge of one of `triangles` bends by a crease tile's angle or
/// more (the cosine between its two triangles' normals at most
/// `creaseCosine`) and its box meets `tileBox`, the tile's: an edge crossing
/// the tile with such a bend has that box, so without one the tile is no
/// crease tile - decided before any exact test, comparing the same two
/// normals as the crease test below, and by the mesh and the tile alone
/// (whatever else each cell lists near the tile, both cells sharing it find
/// its crease edges). (An edge strictly apart from the tile's box in doubles
/// stays apart from the tile under the perturbation, as a triangle does:
/// NearTile.) The edge's box, not its triangles': on a scan a tile often has
/// a triangle near it whose other edge bends that much far from it
/// (armadillo at 1/64: 2.5 % fewer side tests, 1 % of the instructions).
bool MayHoldCrease(const MeshSolid& mesh, const TriangleList& triangles, const Box3& tileBox, double creaseCosine)
{
  for (const std::uint32_t t : triangles)
  {
    for (int k = 0; k < 3; ++k)
    {
      const std::uint32_t other = mesh.Across(t, k);
      if (other != MeshSolid::NoTriangle && Dot(mesh.Normal(t), mesh.Normal(other)) <= creaseCosine)
      {
        const Vec3 ends[2] = { mesh.Vertex(t, k), mesh.Vertex(t, (k + 1) % 3) };
        if (BoundsOf(ends, 2).Overlaps(tileBox))
        {
          return true;
        }
      }
    }
  }
  return false;
}

/// The edges of `triangles` (those near the tile) crossing the open tile,
/// each use once, sorted. Whether an edge's crossing lies in the open tile is
/// a question of the edge alone (EdgeOnPlane orders its ends), asked once for
/// both its uses: the uses crossing the plane are sorted first, so that the
/// two of an edge are side by side. (Asked of each use, those exact tests
/// were 1.6 % of armadillo's instructions at 1/64.)
std::vector<EdgeUseOnTile> EdgesOnTile(
  const MeshArrangement& arrangement, const TriangleList& triangles, int axis, LatticeIndex plane, const FaceTile& tile)
{
  const MeshSolid& mesh = arrangement.Mesh();
  std::vector<EdgeUseOnTile> crossing;
  for (const std::uint32_t t : triangles)
  {
    const auto& ids = mesh.Triangles()[t];
    int side[3];
    for (int k = 0; k < 3; ++k)
    {
      side[k] = arrangement.Side(ArrangementPoint::Vertex(ids[k]), axis, plane);
    }
    for (int k = 0; k < 3; ++k)
    {
      const std::uint32_t a = ids[k], b = ids[(k + 1) % 3];
      if (side[k] != side[(k + 1) % 3])
      {
        crossing.push_back({ std::min(a, b), std::max(a, b), t, ids[(k + 2) % 3] });
      }
    }
  }
  std::sort(crossing.begin(), crossing.end());
  std::vector<EdgeUseOnTile> uses;
  for (std::size_t i = 0; i < crossing.size();)
  {
    std::size_t j = i + 1;
    while (j < crossing.size() && crossing[j].A == crossing[i].A && crossing[j].B == crossing[i].B)
    {
      ++j;
    }
    if (InsideTile(arrangement, ArrangementPoint::EdgeOnPlane(crossing[i].A, crossing[i].B, axis, plane), axis, tile))
    {
      uses.insert(uses.end(), crossing.begin() + static_cast<std::ptrdiff_t>(i),
        crossing.begin() + static_cast<std::ptrdiff_t>(j));
    }
    i = j;
  }
  return uses;
}

/// The two triangles of each edge crossing the tile, or empty when an edge
/// has not exactly two there (then no crease tile).
bool Paired(const std::vector<EdgeUseOnTile>& uses)
{
  for (std::size_t i = 0; i < uses.size(); i += 2)
  {
    if (i + 1 >= uses.size() || uses[i + 1].A != uses[i].A || uses[i + 1].B != uses[i].B ||
      (i + 2 < uses.size() && uses[i + 2].A == uses[i].A && uses[i + 2].B == uses[i].B))
    {
      return false;
    }
  }
  return true;
}

/// The trace from the crease edge `start` through triangle `triangle`: the
/// crossings of the edges it passes inside the tile, then the crossing of the
/// edge where it leaves the tile (outside it).
std::vector<Vec3> WalkTrace(const MeshArrangement& arrangement, const std::vector<EdgeUseOnTile>& uses,
  std::uint32_t triangle, std::uint32_t a, std::uint32_t b, int axis, LatticeIndex plane)
{
  const MeshSolid& mesh = arrangement.Mesh();
  std::vector<Vec3> trace;
  for (std::size_t step = 0; step <= uses.size(); ++step)
  {
    // The triangle's other edge crossing the plane: from its third vertex
    // to whichever of a, b lies on the other side.
    const auto& ids = mesh.Triangles()[triangle];
    std::uint32_t c = ids[0];
    for (const std::uint32_t id : ids)
    {
      c = id != a && id != b ? id : c;
    }
    const int sideC = arrangement.Side(ArrangementPoint::Vertex(c), axis, plane);
    const std::uint32_t d = arrangement.Side(ArrangementPoint::Vertex(a), axis, plane) != sideC ? a : b;
    const std::uint32_t lo = std::min(c, d), hi = std::max(c, d);
    trace.push_back(arrangement.Position(ArrangementPoint::EdgeOnPlane(lo, hi, axis, plane)));
    const auto next = std::find_if(uses.begin(), uses.end(),
      [&](const EdgeUseOnTile& u) { return u.A == lo && u.B == hi && u.Triangle != triangle; });
    if (next == uses.end())
    {
      return trace; // left the tile
    }
    triangle = next->Triangle;
    a = lo;
    b = hi;
  }
  return {}; // (a cycle: not a tile's arc)
}
} // namespace

std::optional<CreaseTile> CreaseOnTile(const CsgLeaf& leaf, const PrimitiveSet& primitives, const RootGrid& grid,
  int axis, LatticeIndex plane, const FaceTile& tile)
{
  const MeshSolid& mesh = primitives.Meshes[leaf.Primitive];
  const double creaseCosine = std::cos(CreaseTileAngleDegrees * M_PI / 180.0);
  thread_local TriangleList near; // (scratch: called for every tile of every cell)
  const Box3 tileBox = TileBox(grid, axis, plane, tile);
  NearTile(mesh, *leaf.Triangles, tileBox, near);
  if (!MayHoldCrease(mesh, near, tileBox, creaseCosine))
  {
    return std::nullopt;
  }
  const MeshArrangement arrangement(mesh, grid);
  const std::vector<EdgeUseOnTile> uses = EdgesOnTile(arrangement, near, axis, plane, tile);
  if (!Paired(uses))
  {
    return std::nullopt;
  }
  // The sharpest crease: the smallest cosine, ties broken by the edge's
  // vertices (a total order, so a sub-tile holding it picks it too).
  const EdgeUseOnTile* sharpest = nullptr;
  double sharpestCosine = 2.0;
  for (std::size_t i = 0; i < uses.size(); i += 2)
  {
    const EdgeUseOnTile &p = uses[i], &q = uses[i + 1];
    const double cosine = Dot(mesh.Normal(p.Triangle), mesh.Normal(q.Triangle));
    if (std::isnan(cosine))
    {
      return std::nullopt; // (non-finite coordinates: no angle; a degenerate
                           // triangle's zero normal gives 0, a right angle)
    }
    if (cosine > creaseCosine)
    {
      continue; // a bend of one of the trace's halves
    }
    if (!sharpest || cosine < sharpestCosine ||
      (cosine == sharpestCosine && std::tie(p.A, p.B) < std::tie(sharpest->A, sharpest->B)))
    {
      sharpest = &uses[i];
      sharpestCosine = cosine;
    }
  }
  std::optional<CreaseTile> crease;
  if (sharpest)
  {
    const EdgeUseOnTile &p = sharpest[0], &q = sharpest[1];
    CreaseTile found;
    found.X.Kind = CrossingKind::MeshEdge;
    found.X.Key = PlaneKey(axis, plane);
    found.X.Tile = leaf.Primitive;
    found.X.Partner = (static_cast<std::uint64_t>(p.A) << 32) | p.B;
    found.Position = arrangement.Position(ArrangementPoint::EdgeOnPlane(p.A, p.B, axis, plane));
    // Strictly inside the tile as computed too (a position rounded onto a
    // tile side would put the two chords along it): decided for x alone -
    // its position is on the side of every lattice plane the exact tests
    // say - so that a tile and its sub-tiles decide alike.
    if (!arrangement.PlacedAsDecided(ArrangementPoint::EdgeOnPlane(p.A, p.B, axis, plane), found.Position))
    {
      return std::nullopt;
    }
    found.Sides[0] = WalkTrace(arrangement, uses, p.Triangle, p.A, p.B, axis, plane);
    found.Sides[1] = WalkTrace(arrangement, uses, q.Triangle, p.A, p.B, axis, plane);
    if (found.Sides[0].empty() || found.Sides[1].empty())
    {
      return std::nullopt;
    }
    crease = std::move(found);
  }
  return crease;
}

std::optional<CreaseTile> DecideCreaseTile(FaceDecisionCache* cache, const CsgLeaf& leaf,
  const PrimitiveSet& primitives, const RootGrid& grid, int axis, LatticeIndex plane, const FaceTile& tile)
{
  return cache ? cache->DecideCrease(leaf, primitives, grid, axis, plane, tile)
               : CreaseOnTile(leaf, primitives, grid, axis, plane, tile);
}

} // namespace tpc
