// Marching-Cubes-like extraction on the adaptive grid with crack patching
// (paper 4.3).
//
// Crack patching as one idea: in an MC-compatible cell the exact surface is a
// disk (Lemma 3) whose boundary is a loop on the cell's faces. Each leaf that
// meets the surface walks its six faces at the finest resolution present on
// them - every lattice corner of every leaf touching the face or its edges -
// so a face shared with smaller neighbours is split exactly as they split it.
// On each tile of a face, every run of inside points along the tile's boundary
// is cut off by one segment between the two crossings that bound the run;
// the segments chain into the disk's boundary loop, which is triangulated as
// a fan around an apex strictly inside the cell - or, where the surface is
// smooth in the cell, as Marching Cubes does, by a fan from one of the loop's
// own points - so that the surface is embedded by construction
// (LoopTriangulation.h). Both cells
// sharing a tile compute the same segments from the same points, and a
// crossing is identified by the finest lattice sub-edge that contains it, so
// no crack can appear and every edge of the output has exactly two
// triangles - whether or not the cell passed the tests (cells stopped by a
// limit still give a closed manifold, only without the topology guarantee).
// Edge crossings are found on the exact field by root finding, not by linear
// interpolation. An exact cell's patch is its input mesh clipped to it, and
// its neighbours draw the mesh's exact trace on the tiles they share with it
// (ExactCell.h).
#pragma once

#include "AdaptiveOctree.h"
#include "Parallel.h"
#include "TopologyPreservingSubdivision.h"
#include "TriangleMesh.h"

namespace tpc
{

struct ExtractionResult
{
  TriangleMesh Mesh;
  /// Cells whose boundary crossings did not close into loops (never expected;
  /// reported rather than hidden).
  std::size_t InconsistentCells = 0;
  /// Cells that may hold surface (passed, or stopped by a limit) without a
  /// patch: no crossings on their boundary (a complex voxel left by a limit).
  /// The surface there, if any, is missing from the mesh, so no Hausdorff
  /// bound holds.
  std::size_t CellsWithoutPatch = 0;
  /// `progress` asked to stop: the mesh is incomplete.
  bool Aborted = false;
};

ExtractionResult ExtractSurface(const AdaptiveOctree& octree, const ImplicitScene& scene,
  const ParallelFor& parallelFor = SequentialFor, const ProgressCallback& progress = nullptr);

} // namespace tpc
