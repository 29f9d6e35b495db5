// Exact cells (ExactCell.h, issue 14): which cells keep their input mesh as
// their patch instead of being split - the criterion the subdivision applies;
// the extraction (ExactCell.h) clips the mesh to them.
#pragma once

#include "CsgExpression.h"

#include <cstddef>

namespace tpc
{

/// When a cell of one mesh that fails the tests keeps the mesh instead of
/// being split. Its patch has about as many triangles as the cell lists, a
/// sampled cell about four: keeping the mesh where the cell lists many would
/// bring back the input's density (a coarse remesh would not be coarse),
/// while most creases resolve within a few more levels. So, once the cell is
/// as small as the tolerance asks: when it lists at most ExactCellTriangles
/// triangles (the size of one more level's patches), or when refinement
/// cannot help (`hopeless`: two sheets closer than the finest cell, a limit,
/// or ExactCellLevelsBelowTolerance levels below the tolerance's cells - a
/// wedge of a few degrees, a crease a hair from a lattice line).
constexpr std::size_t ExactCellTriangles = 8;
/// Face refinement levels a cell that would keep its mesh tries (instead of
/// FaceRefinementLevels): a face that does not pass within them fails, and
/// the cell keeps the mesh rather than spend thousands of samples on it.
constexpr int ExactCellFaceRefinementLevels = 2;
constexpr int ExactCellLevelsBelowTolerance = 3;
bool KeepsTheMesh(const CsgExpression& expression, bool toleranceSize, bool hopeless);

/// The mesh leaf when `expression` is a lone mesh leaf with its triangle
/// list (the cell's surface is that mesh's), else null.
const CsgLeaf* LoneMeshLeaf(const CsgExpression& expression);

/// The scene is one mesh (remeshing): where exact cells are used. (Elsewhere
/// a cell of one mesh could border a cell stopped by a limit, whose sampled
/// loop cannot follow the mesh's exact trace.)
bool IsOneMesh(const CsgExpression& expression);

} // namespace tpc
