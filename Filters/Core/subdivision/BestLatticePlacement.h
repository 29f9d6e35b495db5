// The subdivision on the best of a few lattice placements, and the piece of
// a run split among processes that a subdivision computes.
//
// A surface feature that lies almost exactly on the lattice (a crease a hair
// from a lattice plane or line: it meets it in a sliver thinner than the
// finest lattice spacing) cannot be resolved on that lattice, but moves away
// on another placement (LatticePlacement.h); a genuine degeneracy (tangent
// contact) fails on every placement.
#pragma once

#include "RootGrid.h"
#include "TopologyPreservingSubdivision.h"

#include <cstddef>
#include <functional>

namespace tpc
{

/// How many lattice placements a driver may try.
constexpr int LatticePlacements = 3;

/// The subdivision on the best lattice placement. The root grid of
/// MakeRootGrid is shifted by less than a cell of the level below the
/// tolerance's (LatticeSpacings::Surface), first by the shift that keeps
/// lattice planes furthest from the meshes' creases (LatticePlacement.h);
/// while cells remain unresolved (and the cell limit was not the cause) the
/// ranking's next shifts, each moving the lattice along every axis, are
/// tried, up to `maximumPlacements`, and the run with the fewest unresolved
/// cells is kept. Progress rises monotonically over all placements (a run that
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
  /// The parameters the kept run was made with (a piece's: its depth below
  /// the split roots, its share of the cells, its trees' roles; after repair
  /// rounds, the cells they split first - Contour.cxx).
  SubdivisionParameters Parameters;
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

/// Frees a run's expressions (millions of them take about a second) in
/// chunks, each followed by a progress report of `at`; false when it asked to
/// stop.
bool ReleaseExpressions(AdaptiveOctree& octree, const ProgressCallback& progress, double at);

PlacedSubdivision RunOnBestLatticePlacement(const ImplicitScene& scene, const Box3& domain,
  const SubdivisionParameters& parameters, int maximumPlacements = LatticePlacements,
  const ParallelFor& parallelFor = SequentialFor, const ProgressCallback& progress = nullptr,
  const PieceOfRun& piece = PieceOfRun());

} // namespace tpc
