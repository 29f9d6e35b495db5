// The topology preserving subdivision (paper 5.3): refine an octree until
// every cell that meets the surface is MC-compatible (not complex, star-shaped
// w.r.t. its voxel and faces) and no larger than the Hausdorff tolerance.
//
// Breadth-first, one level at a time: each level is a parallel loop over the
// cells that still meet the surface. Cells whose pruned expression has a
// definite sign are leaves at once, whatever their size - the work follows the
// surface, not the volume. MaximumDepth and MaximumNumberOfCells only stop
// runaway refinement (tangential contact never passes the tests, 5.3.3); cells
// stopped by them are marked Unresolved and the result says the guarantee is
// lost. So are cells where two surfaces face each other closer than the
// finest cell (touching solids), once they are as small as the tolerance asks:
// refining them grows like an area and never succeeds (FacingSurfaces.h).
// Surface cells whose surface is a plane section stay as large as the tests
// allow (error-driven acceptance, PlanarCell.h). Where a cell is split, and
// why: SplitDecision.h.
//
// Each level runs four passes (TopologyPreservingSubdivision.cxx): the exact
// signs at corners not seen before, each evaluated once; the tests of every
// cell, in parallel; each cell's fate, in cell order; the children of the
// split cells with their parent's expression pruned to them.
#pragma once

#include "AdaptiveOctree.h"
#include "CellRepair.h"
#include "CsgExpression.h"
#include "Parallel.h"

#include <array>
#include <cstddef>
#include <functional>
#include <vector>

namespace tpc
{

struct SubdivisionParameters
{
  /// Absolute two-sided Hausdorff bound: every surface cell's diagonal is <= it.
  double HausdorffTolerance = 0.01;
  int MaximumDepth = 12;
  std::size_t MaximumNumberOfCells = 20000000;
  /// Cells whose surface is one input mesh and that fail the tests at the
  /// tolerance's size (or at a limit) keep the mesh itself as their patch
  /// (ExactCell.h) instead of refining. For scenes of one closed mesh that
  /// meets the paper's assumptions (remeshing).
  bool ExactCells = false;
  /// The diagonal of the mesh's box (with ExactCells): "levels below the
  /// tolerance" are counted from at most an eighth of it
  /// (ExactCellCriterion.h: ExactCellLevelsBelowTolerance). 0: from the
  /// tolerance alone.
  double SurfaceDiagonal = 0.0;
  /// Proven failures first: oversized cells of one mesh whose fans would
  /// stray beyond the tolerance split before their tests (MeshCellError.h:
  /// Spokes), and a prediction whose fan has a point too far from the mesh,
  /// or whose fans follow the cell's creases around no apex, fails before
  /// its branch and bound (Probes, Creases first). Off only to check that this
  /// changes no cell's fate - proven, but for the spokes of a cell of
  /// several sheets that may pass with several loops, which guess
  /// (MeshCellError.h: Spokes; a split is always allowed).
  bool ProvenFailuresFirst = true;
  /// Chords refined: a cell of one mesh larger than the tolerance whose
  /// prediction failed with chords far from the trace is predicted again
  /// with those chords' tiles split (MeshCellError.h: Chords refined). Off to
  /// measure without it, or to test what it would hide.
  bool RefineChords = true;
  /// A piece of a split run (ForestPartition.h): the role of each tree of
  /// the root grid; skipped trees stay empty roots. Empty: every tree.
  std::vector<TreeRole> TreeRoles;
  /// Cells split before their tests, named by an earlier run on the same
  /// lattice whose final surface found them wanting (CellRepair.h).
  CellsToSplit SplitFirst;
};

struct SubdivisionResult
{
  AdaptiveOctree Octree;
  bool Aborted = false;
  bool DepthLimitReached = false;
  bool CellLimitReached = false;
  std::size_t SurfaceCells = 0;
  std::size_t UnresolvedCells = 0;
  /// Of those, cells stopped because two surfaces face each other closer
  /// than the finest cell there (FacingSurfaces.h).
  std::size_t FacingSurfaceCells = 0;
  /// Of those, cells where the two surfaces lie in one plane: solids touching
  /// along a face, which no other lattice placement separates.
  std::size_t TouchingSurfaceCells = 0;
  std::size_t RefinedFaces = 0; ///< faces sampled finer than their cell (FaceRefinement.h)
  /// Surface cells accepted larger than the tolerance as plane sections
  /// (PlanarCell.h).
  std::size_t PlanarSurfaceCells = 0;
  /// Cells whose patch is the input mesh clipped to them (ExactCell.h).
  std::size_t ExactCells = 0;
  /// Surface cells whose error is certified on their patch
  /// (QuadricCellError.h, MeshCellError.h), of any size; of those, larger
  /// than the tolerance.
  std::size_t ErrorBoundedCells = 0;
  std::size_t OversizedErrorBoundedCells = 0;
  /// Cells split for their size before their tests (Spokes), or whose
  /// prediction failed before its branch and bound (Probes), or whose fans
  /// could follow no crease apex (Creases first); ProvenFailuresFirst.
  std::size_t SpokeSplitCells = 0;
  std::size_t ProbeSplitCells = 0;
  std::size_t CreaseSplitCells = 0;
  /// Surface cells accepted on a prediction over finer chords (RefineChords).
  std::size_t ChordRefinedCells = 0;
  /// The proven two-sided Hausdorff bound between the exact surface and the
  /// extracted one over the leaves other than error-bounded cells (those are
  /// certified on their patches: ExtractionResult::CertifiedBound): the
  /// largest diagonal of a surface or unresolved leaf (both surfaces lie in
  /// it), where plane sections count the finest lattice cell's diagonal
  /// (their patch is exact up to rounding).
  double HausdorffBound = 0.0;
  /// Number of cells split for each SplitReason (and leaves left unresolved
  /// with that failing test, in UnresolvedByReason).
  std::array<std::size_t, SplitReasonCount> SplitsByReason{};
  std::array<std::size_t, SplitReasonCount> UnresolvedByReason{};
};

/// The subdivision of `scene` over the root grid `grid` (one lattice
/// placement; BestLatticePlacement.h tries several).
SubdivisionResult RunTopologyPreservingSubdivision(const ImplicitScene& scene,
  const RootGrid& grid, const SubdivisionParameters& parameters,
  const ParallelFor& parallelFor = SequentialFor, const ProgressCallback& progress = nullptr);

} // namespace tpc
