// The patches of the surface cells (paper 4.3): each loop of a cell spanned
// inside the cell (LoopTriangulation.h), an exact cell's polygons fanned in
// their planes, and the output written once from them.
#pragma once

#include "AdaptiveOctree.h"
#include "BoundaryLoops.h"
#include "CrossingVertices.h"
#include "Parallel.h"
#include "QuadricCellError.h"
#include "TriangleMesh.h"

#include <cstdint>
#include <vector>

namespace tpc
{

/// The triangles of one cell; vertex ids with LocalFlag set index Apexes,
/// the others are crossing vertices.
struct CellPatches
{
  static constexpr std::uint32_t LocalFlag = 1u << 31;
  std::vector<Vec3> Apexes;
  std::vector<Triangle> Triangles;
};

/// Spans every loop of leaf `node` (LoopTriangulation.h), each apex in its
/// own loop's room in the cell (ApexRooms.h); `mesh` holds the crossing
/// vertices. `surface`: the cell's error is certified (QuadricCellError.h),
/// its apexes go on the surface where they can. `meshApexes`: the apexes a
/// prediction was made with, one per loop (MeshCellError.h,
/// MeshBooleanCellError.h): each loop is fanned around its own, moved into
/// its room (a lone loop around the lone apex; with several, each around
/// the apex nearest its room, if no two loops take the same).
void TriangulateCell(const BoundaryLoopSet& loops, const OctreeNode& node, const CsgExpression& expression,
  const PrimitiveSet& primitives, const RootGrid& grid, const CrossingVertices& vertices, const TriangleMesh& mesh,
  CellPatches& out, const QuadricCellError* surface = nullptr, const std::vector<Vec3>* meshApexes = nullptr);

/// A cell of one loop spanned by Marching Cubes' fan from one of its points
/// (k - 2 triangles where the apex fan takes k): from a point on a mesh edge
/// (MeshEdgeFanPoint) when the loop holds one - `fromMeshEdge` says so -
/// else from any point where the surface is smooth along the loop
/// (LoopFanPoint; a fan from a point off the crease would cut across the
/// crease that the apex fan keeps sharp); false when the loop allows none.
/// The caller certifies its error (MeshCellError.h) before using it.
bool TriangulateCellFromLoopPoint(const BoundaryLoopSet& loops, const OctreeNode& node, const RootGrid& grid,
  const CrossingVertices& vertices, const TriangleMesh& mesh, CellPatches& out, bool& fromMeshEdge);

/// An exact cell's polygons (ExactCell.h), each a triangle or a fan around
/// its centroid (in its triangle's plane: the polygon is convex, and its
/// inserted tile-side points are collinear with their neighbours).
void TriangulateExactCell(
  const BoundaryLoopSet& polygons, const CrossingVertices& vertices, const TriangleMesh& mesh, CellPatches& out);

/// Writes the patches into `mesh` once, count -> prefix sum -> write: each
/// cell's apexes (with their normals, the area-weighted mean of their fans)
/// after the crossing vertices and the earlier cells' apexes, its triangles
/// after the earlier cells' triangles, each with its cell (`cells`, node
/// indices). The patches are released as they are written. False when
/// `progress` asked to stop.
bool WritePatches(std::vector<CellPatches>& patches, const std::vector<std::uint32_t>& cells, TriangleMesh& mesh,
  const ParallelFor& parallelFor, const ProgressCallback& progress);

} // namespace tpc
