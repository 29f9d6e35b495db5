// Why a cell of the adaptive octree was subdivided (paper 5.3), and the state
// of each cell. Values are stable: they are written to the vtkHyperTreeGrid
// output (cell data "SplitReason", "CellState") and documented in
// vtkTopologyPreservingContour.h.
#pragma once

#include <cstdint>

namespace tpc
{

enum class SplitReason : std::uint8_t
{
  None = 0,               ///< not split (a leaf that passed, or never needed tests)
  ComplexVoxel = 1,       ///< surface may meet the voxel but its corners show no sign change
  ComplexFace = 2,        ///< surface may meet a face whose corners show no sign change
  ComplexEdge = 3,        ///< an edge is (or may be) crossed more than once
  FaceAmbiguity = 4,      ///< alternating corner signs around a face
  VoxelAmbiguity = 5,     ///< two body-diagonal corners differ from the six others
  NotStarShapedVoxel = 6, ///< no witness found for the solid restricted to the voxel
  NotStarShapedFace = 7,  ///< no witness found for the solid restricted to a face
  HausdorffSize = 8,      ///< cell on the surface larger than the tolerance, with no certified
                          ///< error within it (QuadricCellError.h, MeshCellError.h) and not
                          ///< a plane section
  LimitReached = 9,       ///< leaf kept because of MaximumDepth/MaximumNumberOfCells
                          ///< while a criterion still failed
  SurfacesTooClose = 10,  ///< leaf kept while a criterion failed: two surfaces face
                          ///< each other closer than the finest cell throughout it
  PatchNotEmbedded = 11,  ///< cell whose patch met another patch improperly in the exact
                          ///< embedding check of the output (SurfaceEmbedding.h): split when
                          ///< the subdivision ran again (CellRepair.h), or a leaf so marked
                          ///< where no repair round could split it
  CreaseNotFollowed = 12, ///< cell of one mesh larger than the tolerance whose fan would
                          ///< not draw one of its creases, around its apex or a point of
                          ///< a crease (CreaseFollowing.h): its fan within the tolerance of
                          ///< the mesh, or no fan following them (asked first:
                          ///< MeshCellError.h, Creases first)
  PatchNotCertified = 13  ///< cell larger than the tolerance whose final patch (after crack
                          ///< patching) a run found beyond the tolerance or could not
                          ///< certify: split when the subdivision ran again (CellRepair.h)
};

const char* SplitReasonName(SplitReason r);

enum class CellState : std::uint8_t
{
  Inside = 0,     ///< leaf proven entirely inside the solid
  Outside = 1,    ///< leaf proven entirely outside the solid
  Surface = 2,    ///< leaf meeting the surface, MC-compatible (all tests passed)
  Unresolved = 3, ///< leaf meeting the surface where a limit stopped refinement
  Refined = 4,    ///< inner node
  Exact = 5       ///< leaf whose patch is its one input mesh clipped to it (ExactCell.h)
};

const char* CellStateName(CellState s);

/// One past the largest value of each enum (to list their names).
constexpr int SplitReasonCount = 14;
constexpr int CellStateCount = 6;

} // namespace tpc
