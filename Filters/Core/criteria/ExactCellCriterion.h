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
/// or ExactCellLevelsBelowTolerance levels below the cells of
/// ExactCellReferenceSize - a wedge of a few degrees, a crease a hair from a
/// lattice line).
constexpr std::size_t ExactCellTriangles = 8;
/// Face refinement levels a cell that would keep its mesh tries (instead of
/// FaceRefinementLevels): a face that does not pass within them fails, and
/// the cell keeps the mesh rather than spend thousands of samples on it.
constexpr int ExactCellFaceRefinementLevels = 2;
constexpr int ExactCellLevelsBelowTolerance = 3;
/// The cell size those levels are counted from: the tolerance, or an eighth
/// of the surface's diagonal (`surfaceDiagonal`; 0: unknown) where that is
/// smaller. A cell that fails the tests is hopeless for what is in it at a
/// point - a wedge, a near contact, a crease by a lattice line - not for its
/// size beside the tolerance; but where the tolerance is as large as the
/// surface itself, three levels below it a cell holds a whole finger of a
/// scan (or at 64 diagonals, a whole model): it would keep hundreds or all
/// of the mesh's triangles, where a few more levels of the tests give a
/// coarse remesh - the armadillo at a tolerance of half its diagonal came
/// out as 9 152 triangles and at 1/8 as 4 214, and at 64 diagonals as the
/// input's 52 000 after 30 s (one cell kept the whole mesh and checked it
/// against itself). Counted from an eighth of the diagonal, the level where
/// a failing cell keeps the mesh whatever it lists is the same at every
/// tolerance above it. (A cell as small as the tolerance asks that lists at
/// most ExactCellTriangles keeps them from the tolerance's own level, as
/// before: a small patch whatever refinement would find - counted from the
/// reference too, CGAL's tetrahedron at half its diagonal came out as 570
/// triangles instead of 118; over CGAL's 84 valid demo meshes at 1/2,
/// 104 624 triangles before, 88 834 now.)
double ExactCellReferenceSize(double tolerance, double surfaceDiagonal);
bool KeepsTheMesh(const CsgExpression& expression, bool toleranceSize, bool hopeless);

/// The mesh leaf when `expression` is a lone mesh leaf with its triangle
/// list (the cell's surface is that mesh's), else null.
const CsgLeaf* LoneMeshLeaf(const CsgExpression& expression);

/// The scene is one mesh (remeshing): where exact cells are used. (Elsewhere
/// a cell of one mesh could border a cell stopped by a limit, whose sampled
/// loop cannot follow the mesh's exact trace.)
bool IsOneMesh(const CsgExpression& expression);

} // namespace tpc
