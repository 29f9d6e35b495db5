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
// refining them grows like an area and never succeeds (FacingSurfaces.h). Surface cells whose surface is a plane section stay as large as the
// tests allow (error-driven acceptance, PlanarCell.h).
#pragma once

#include "AdaptiveOctree.h"
#include "CsgExpression.h"
#include "Parallel.h"

#include <array>
#include <cstddef>
#include <functional>
#include <vector>

namespace tpc
{

/// The solid to contour: primitives combined by a CSG expression.
struct ImplicitScene
{
  PrimitiveSet Primitives;
  CsgExpressionPtr Expression;
};

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
  /// A piece of a split run (ForestPartition.h): the role of each tree of
  /// the root grid; skipped trees stay empty roots. Empty: every tree.
  std::vector<TreeRole> TreeRoles;
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
  std::size_t RefinedFaces = 0; ///< faces sampled finer than their cell (FaceRefinement.h)
  /// Surface cells accepted larger than the tolerance as plane sections
  /// (PlanarCell.h).
  std::size_t PlanarSurfaceCells = 0;
  /// Cells whose patch is the input mesh clipped to them (ExactCell.h).
  std::size_t ExactCells = 0;
  /// The proven two-sided Hausdorff bound between the exact surface and the
  /// extracted one: the largest diagonal of a surface or unresolved leaf (both
  /// surfaces lie in it), where plane sections count the finest lattice
  /// cell's diagonal (their patch is exact up to rounding).
  double HausdorffBound = 0.0;
  /// Number of cells split for each SplitReason (and leaves left unresolved
  /// with that failing test, in UnresolvedByReason).
  std::array<std::size_t, SplitReasonCount> SplitsByReason{};
  std::array<std::size_t, SplitReasonCount> UnresolvedByReason{};
};

/// The level at which cells covering `domain` (its largest width, as the root
/// size) have a diagonal of at most `tolerance`: where the Hausdorff size
/// test stops refining (0 for a non-positive tolerance).
int ToleranceLevel(const Box3& domain, double tolerance);

/// Chooses the root grid: cubic root cells covering `domain`, sized so that
/// some level has cells whose diagonal is exactly the tolerance (no finer
/// than needed), and the finest lattice the keys support. `placement` picks
/// one of several generic lattice offsets (see LatticePlacements).
RootGrid MakeRootGrid(const Box3& domain, double hausdorffTolerance, int maximumDepth, int placement = 0);

/// How many lattice placements a driver may try. A surface feature that lies
/// almost exactly on the lattice (a crease a hair from a lattice plane or
/// line: it meets it in a sliver thinner than the finest lattice spacing)
/// cannot be resolved on that lattice, but moves away on another placement
/// (LatticePlacement.h); a genuine degeneracy (tangent contact) fails on
/// every placement.
constexpr int LatticePlacements = 3;

/// Largest MaximumDepth the lattice supports for a root grid of `dims`.
int MaximumSupportedDepth(const int dims[3]);

SubdivisionResult RunTopologyPreservingSubdivision(const ImplicitScene& scene,
  const RootGrid& grid, const SubdivisionParameters& parameters,
  const ParallelFor& parallelFor = SequentialFor, const ProgressCallback& progress = nullptr);

/// The subdivision on the best lattice placement. The root grid of
/// MakeRootGrid is shifted by less than the deepest cell, first by the shift
/// that keeps lattice planes and lines furthest from the meshes' creases
/// (LatticePlacement.h); while cells remain unresolved (and the cell limit
/// was not the cause) the next best shifts are tried, up to
/// `maximumPlacements`, and the run with the fewest unresolved cells is
/// kept. Progress rises monotonically over all placements (a run that
/// needs no retry may jump to 1 at its end).
struct PlacedSubdivision
{
  RootGrid Grid;
  SubdivisionResult Result;
  int PlacementsTried = 0;
  /// Unresolved cells of all pieces (= Result.UnresolvedCells for one piece).
  std::size_t UnresolvedCellsOfAllPieces = 0;
  /// Width of the finest cell MaximumDepth allows.
  double FinestCell = 0.0;
};

/// One piece of a run split among processes (ForestPartition.h): the root
/// cells are split so that the longest axis has up to sixteen trees per
/// piece (at least two; trees no smaller than four tolerance cells), this
/// piece subdivides its slab of trees and the ghost ring.
/// Decisions that must agree (another lattice placement, stop) use `Sum`
/// over the pieces, called the same number of times by every piece (an MPI
/// all-reduce). An abort is honoured after a placement, when `Sum` says
/// some piece asked for it, so that no piece is left waiting.
struct PieceOfRun
{
  int Piece = 0;
  int Pieces = 1;
  std::function<std::size_t(std::size_t)> Sum; ///< unset: this piece alone (identity)

  /// `x` summed over the pieces (this piece's own `x` when Sum is unset).
  std::size_t SumOverPieces(std::size_t x) const { return this->Sum ? this->Sum(x) : x; }
};

PlacedSubdivision RunOnBestLatticePlacement(const ImplicitScene& scene, const Box3& domain,
  const SubdivisionParameters& parameters, int maximumPlacements = LatticePlacements,
  const ParallelFor& parallelFor = SequentialFor, const ProgressCallback& progress = nullptr,
  const PieceOfRun& piece = PieceOfRun());

} // namespace tpc
