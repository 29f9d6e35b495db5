// Where to put the lattice so that no cell face grazes a crease.
//
// The octree's cells are bounded by lattice planes. A ridge or valley of a
// mesh lying (almost) in an axis plane - a roof ridge, a rim in a symmetry
// plane, common in CAD meshes with round coordinates - with a lattice plane a
// hair below it is cut by that plane along two lines closer than the finest
// lattice spacing: a sliver no face sample can split, at every depth, along
// the whole crease (and a face lying a hair from a plane cannot be told from
// it). They move away when the lattice is shifted by a fraction of a cell,
// so the driver ranks candidate shifts by the length of
// such creases each would graze and tries the best first
// (RunOnBestLatticePlacement). A crease edge grazes the planes normal to the
// axes it is flat along, so the length sums one term per axis, and the
// shifts along each axis are ranked on their own.
//
// Other near-coincidences (a crease passing a hair from a lattice line, met
// twice by it) are isolated points, as likely on any lattice; the driver's
// retries on the next shifts are what moves them.
#pragma once

#include "CsgExpression.h"
#include "Parallel.h"
#include "RootGrid.h"

#include <array>
#include <cstddef>
#include <vector>

namespace tpc
{

/// A ridge or valley almost parallel to the planes normal to one axis: the
/// range of its coordinate along that axis, and its length (the number of
/// cells it can spoil grows with it).
struct FlatCreaseEdge
{
  double Lo = 0.0;
  double Hi = 0.0;
  double Length = 0.0;
  /// Height above a plane per unit of separation of the plane's two traces.
  double BandPerSeparation = 0.0;
};

/// The mesh edges that can graze lattice planes, per axis: ridges and
/// valleys (both triangles on the same side along the axis) whose extent
/// along it is below `ridgeThickness`, and edges of faces lying in an axis
/// plane (within `planeThickness`).
struct LatticeCreases
{
  std::array<std::vector<FlatCreaseEdge>, 3> Ridges;
  std::array<std::vector<FlatCreaseEdge>, 3> InPlane;
};

LatticeCreases FindLatticeCreases(const PrimitiveSet& primitives, double ridgeThickness, double planeThickness,
  const ParallelFor& parallelFor = SequentialFor);

/// The spacings the penalty looks at.
struct LatticeSpacings
{
  double Surface = 1.0; ///< cells one level below the tolerance's (all along the surface)
  double Deepest = 1.0; ///< the deepest allowed cells
  double Finest = 1.0;  ///< the finest face-refinement samples (SampleDepth, RootGrid.h)
};

/// Those of the lattice `base` for the tolerance and depth given.
LatticeSpacings LatticeSpacingsOf(const RootGrid& base, double hausdorffTolerance, int maximumDepth);

/// Shifts priced along each axis (RankLatticeShifts), and how far above the
/// least a penalty still counts as a tie.
constexpr std::size_t LatticeShiftsPerAxis = 16;
constexpr double LatticeNearTie = 0.05;

/// The k-th shift along `axis` the ranking prices: none for k = 0, then a
/// low-discrepancy (Kronecker) sequence of fractions of `spacing`
/// (LatticeSpacings::Surface; MakeRootGrid leaves a margin of a cell).
double LatticeAxisShift(std::size_t k, int axis, double spacing);

/// Length of crease (in deepest cells) the lattice planes normal to `axis`
/// graze when one of them passes through `origin` (along that axis),
/// weighted by closeness; 0 when none comes close. A lattice's penalty is the
/// sum of its three axes' (each crease edge is counted along the axes it is
/// flat along).
double LatticeAxisPenalty(const LatticeCreases& creases, int axis, double origin, const LatticeSpacings& spacings);

/// Shifts (each component in [0, LatticeSpacings::Surface), to subtract from
/// the origin of `base`) best first, min(count, LatticeShiftsPerAxis) of
/// them (none for count <= 0): the k-th made of the k-th best shift along
/// each axis (near ties in the sequence's order), so the first is within
/// LatticeNearTie of the best of every combination tried and each next one
/// differs along every axis. The zero shift comes first among equals, so
/// scenes without meshes keep MakeRootGrid's lattice (and take the
/// sequence's next shifts in its order). Stops early, returning no shift,
/// when `progress` asks to abort.
std::vector<Vec3> RankLatticeShifts(const PrimitiveSet& primitives, const RootGrid& base,
  double hausdorffTolerance, int maximumDepth, int count, const ParallelFor& parallelFor = SequentialFor,
  const ProgressCallback& progress = nullptr);

} // namespace tpc
