// The certified error of a cell's final patch (issue 17): the bound of
// QuadricCellError.h evaluated on the triangles and loop chords the cell
// actually drew, after crack patching and apex placement; or, where one mesh
// is the surface, MeshCellError.h's distance between those triangles and the
// mesh in the cell.
#pragma once

#include "CellPatches.h"
#include "MeshCellError.h"
#include "QuadricCellError.h"
#include "TriangleMesh.h"

namespace tpc
{

/// The cell's triangles with their vertices' positions.
std::vector<SourceTriangle> PatchTriangles(const CellPatches& patches, const TriangleMesh& mesh);

/// E_C of the cell's `patches` (crossing vertices in `mesh`, apexes local):
/// the largest triangle term over its triangles and the largest chord term
/// over the triangle edges lying in one face of the cell (the loop's chords:
/// an apex is strictly inside the cell, and Marching Cubes' fan diagonals
/// join points on no common face, LoopTriangulation.h). +inf when a chord
/// lies on a face without a monotone direction, or when E_C exceeds the
/// margin (the argument's segments must stay in the grown cell).
double CertifiedPatchError(const QuadricCellError& bound, const CellPatches& patches, const TriangleMesh& mesh);

/// E(P) of MeshCellError.h for the cell's `patches` against `surface` (S in
/// the cell): CertifiedMeshPatchError on the patch's triangles.
HausdorffEstimate CertifiedMeshCellError(const PolygonSet& surface, const CellPatches& patches,
  const TriangleMesh& mesh, double slack, double enough, double giveUp, std::size_t budget);

} // namespace tpc
