// The vertices of the extracted surface on the cells' boundaries: one per
// distinct crossing of all loops, placed by one cell (the first in node
// order among the cells whose loops hold it - crease-fan cells first, which
// decide the CSG crease tiles they share - so that every piece of a split
// run places it alike: ForestPartition.h) on the exact field. (The surface
// leaves are listed in node order.)
#pragma once

#include "AdaptiveOctree.h"
#include "BoundaryLoops.h"
#include "DistinctRecords.h"
#include "Parallel.h"
#include "TriangleMesh.h"

#include <cstdint>
#include <vector>

namespace tpc
{

/// Of two cells sharing a CSG crease tile, whether cell `a` decides it
/// (CrackPatching.cxx) and places its vertex (CrossingVertices::Build) before
/// cell `b`: a crease-fan cell first (QuadricCellError.h), then node order.
/// (One rule for both, so the cell that decided a tile places its vertex.)
inline bool DecidesBefore(bool aCreaseFan, std::size_t a, bool bCreaseFan, std::size_t b)
{
  return aCreaseFan != bCreaseFan ? aCreaseFan : a < b;
}

class CrossingVertices
{
public:
  struct Record
  {
    Crossing Vertex;
    std::uint32_t CellIndex = 0; ///< index into the surface leaves
  };

  /// The distinct crossings of `loops` (one set per surface leaf), gathered
  /// in parallel (DistinctRecords.h); a vertex's id is its rank among them,
  /// and it is placed by the first of its cells in `decidesFirst` order, then
  /// in index order (the cell that decided a CSG crease tile, CrackPatching.h:
  /// crease-fan cells first). False when `progress` asked to stop.
  bool Build(const std::vector<BoundaryLoopSet>& loops, const std::vector<std::uint8_t>& decidesFirst,
    const ParallelFor& parallelFor, const ProgressCallback& progress);

  /// The id of a crossing of the loops.
  std::uint32_t IdOf(const Crossing& c) const;

  const std::vector<Record>& Records() const { return this->Distinct.Records; }

private:
  BucketedRecords<Record> Distinct;
};

/// Positions and normals of the crossing vertices (mesh.Points and Normals
/// from index 0), each placed by its cell: on its lattice sub-edge by root
/// finding on the exact field, exactly on the sub-edge's line and strictly
/// inside it (crossings of different sub-edges never coincide and a loop's
/// chords meet only at their ends: LoopTriangulation.h); exact cells' kinds
/// where the mesh crosses the lattice (ExactCell.h); bends last, from their
/// crossings. `cells` are the surface leaves. False when `progress` asked to
/// stop.
bool PlaceCrossingVertices(const CrossingVertices& vertices, const AdaptiveOctree& tree,
  const std::vector<std::uint32_t>& cells, const PrimitiveSet& primitives, TriangleMesh& mesh,
  const ParallelFor& parallelFor, const ProgressCallback& progress);

} // namespace tpc
