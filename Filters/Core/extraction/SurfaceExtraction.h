// Marching-Cubes-like extraction on the adaptive grid with crack patching
// (paper 4.3), in four passes over the leaves that meet the surface (passed
// the tests, were stopped by a limit, or are exact):
//
// 1. each leaf's boundary loops, from the samples on its faces at the finest
//    resolution present there - the same samples its neighbours see, so no
//    crack can appear and every output edge has two triangles, whether or not
//    the cell passed the tests (CrackPatching.h, BoundaryLoops.h);
// 2. one vertex per distinct crossing, found on the exact field by root
//    finding and placed strictly inside its lattice sub-edge
//    (CrossingVertices.h);
// 3. each loop's patch: a fan around an apex strictly inside the cell, or
//    Marching Cubes' fan from one of the loop's points - where the surface is
//    smooth along the loop, or from a mesh edge's point such as a crease's
//    crossing - embedded by construction (LoopTriangulation.h,
//    CellPatches.h); an exact cell's patch is its input mesh clipped to it,
//    and its neighbours draw the mesh's exact trace on the tiles they share
//    with it (ExactCell.h);
// 4. the output written once: counted per cell, prefix-summed, written in
//    parallel (CellPatches.h).
#pragma once

#include "AdaptiveOctree.h"
#include "CsgExpression.h"
#include "Parallel.h"
#include "TriangleMesh.h"

#include <cstdint>
#include <utility>
#include <vector>

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
  /// The largest two-sided Hausdorff bound of the error-bounded cells
  /// (QuadricCellError.h, MeshCellError.h), each certified on its final patch
  /// (CertifiedError.h), or its diagonal where that is smaller or the
  /// certificate failed.
  double CertifiedBound = 0.0;
  /// Error-bounded cells larger than the tolerance whose certificate failed
  /// (their diagonal counts, which exceeds the tolerance).
  std::size_t UncertifiedCells = 0;
  /// Own cells larger than the tolerance whose first certificate their
  /// final loops' chords, measured on the final tiles, settled without a
  /// branch and bound (FinalChordsCellError, CertifiedError.h) - mostly where
  /// those loops no longer refine the cell's own, and no other bound held.
  std::size_t FinalChordCells = 0;
  /// Each own error-bounded cell's certified error (node index, E_C; +inf
  /// where the certificate failed), in node order.
  std::vector<std::pair<std::uint32_t, double>> CellErrors;
  /// `progress` asked to stop: the mesh is incomplete.
  bool Aborted = false;
};

ExtractionResult ExtractSurface(const AdaptiveOctree& octree, const ImplicitScene& scene,
  const ParallelFor& parallelFor = SequentialFor, const ProgressCallback& progress = nullptr);

} // namespace tpc
