// Exact cells (issue 14): where sampling cannot decide, the input mesh itself.
//
// When the surface in a cell is one closed input mesh (the cell's pruned
// expression is a lone mesh leaf) and the cell still fails the paper's tests
// a few levels below the tolerance's size - a sliver thinner than any
// lattice, a sharp wedge, two sheets closer than the finest cell - refining
// further would cost cells by the million and may never succeed. But there the exact surface is known:
// it is the mesh's triangles clipped to the cell. Such a cell keeps exactly
// that as its patch, so
// - its topology is the input's (nothing is decided by samples), and its
//   Hausdorff distance to the exact surface is rounding-level;
// - the patch is embedded as the input is (the clipped polygons are pieces of
//   its triangles, triangulated in their own planes);
// - it fits its neighbours: every polygon edge on a face of the cell is split
//   where a tile side crosses it, and every vertex is named by what it is in
//   the arrangement of the mesh with the lattice (MeshArrangement.h): a mesh
//   vertex, a mesh edge on a lattice plane, or a triangle on a lattice
//   sub-edge - by the sub-edge alone when it is crossed once, as sampled
//   cells name that crossing. A neighbour that is not exact draws the exact
//   trace of the mesh on each tile it shares with an exact cell instead of its
//   sampled chord (ExactTileSegments), so both sides of every tile meet along
//   the same vertices. Such a neighbour passed the tests, so the surface in
//   it is still a disk (Lemma 3) bounded by its loop: its tiles' exact arcs
//   straightened where it is sampled, exact where it touches an exact cell.
// Every decision is exact (the perturbed solid of MeshSolid.h), so all cells
// agree on every crossing; the output is checked exactly as well
// (SurfaceEmbedding.h).
#pragma once

#include "BoundaryLoops.h"
#include "CsgExpression.h"
#include "ExactCellCriterion.h"
#include "RootGrid.h"

#include <cstdint>
#include <vector>

namespace tpc
{

/// The polygons of an exact cell: its listed triangles clipped to it and
/// split where tile sides cross them, in the solid's outward orientation;
/// each vertex a Crossing shared with every cell that meets it.
struct ExactPolygons
{
  std::vector<Crossing> Vertices; ///< the polygons, concatenated
  std::vector<std::uint32_t> Sizes;
};

ExactPolygons ClipToExactCell(const CellBoundary& boundary, const CsgLeaf& leaf, const PrimitiveSet& primitives,
  const RootGrid& grid);

/// A tile of a cell that is not exact, shared with an exact cell whose mesh
/// leaf is `Leaf`.
struct ExactTile
{
  int Face = 0;
  std::size_t Tile = 0;
  const CsgLeaf* Leaf = nullptr;
};

/// The segments the mesh draws on each of `tiles`, oriented as BoundaryLoops
/// orients its chords, appended to boundary.ExactSegments; the tiles are
/// marked exact (their samples give no segments).
void AddExactTileSegments(CellBoundary& boundary, const std::vector<ExactTile>& tiles, const PrimitiveSet& primitives,
  const RootGrid& grid);

/// Position of a crossing that exact cells name (kinds SubEdgeTriangle,
/// MeshEdge, MeshVertex), the same for every cell.
Vec3 ExactCrossingPosition(const Crossing& c, const PrimitiveSet& primitives, const RootGrid& grid);

} // namespace tpc
