// Cells split because a run's final surface found them wanting, for the
// subdivision's next run on the same lattice (Contour.h: Repair rounds).
//
// The subdivision decides a cell's size before its final patch exists: crack
// patching draws the patch over the finest samples on its faces, which its
// neighbours' sizes decide, and the exact embedding check looks at all the
// patches together. Two findings can only come after the extraction:
// - a cell larger than the tolerance whose final patch's certificate
//   (CertifiedError.h, MeshCellError.h) exceeds the tolerance or fails: the
//   prediction it was accepted on bounds the fan over loops that refine its
//   own, and crack patching's final loop need not refine it where a finer
//   neighbour's tiling replaced its own (QuadricCellError.h: Where the final
//   loop does not refine L);
// - a cell whose patch meets another patch improperly (SurfaceEmbedding.h).
// Such a cell is named here by its level and lattice position, and the next
// run splits it before its tests (its SplitReason PatchNotCertified or
// PatchNotEmbedded); every other cell is decided as before, its children
// and their neighbours by their own tests. Nothing here is trusted: the next
// run's surface is certified and checked anew, and the guarantee is decided
// on it alone. The pieces of a split run gather the cells every piece named
// (Serialize), since each ghost ring holds cells another piece owns: all
// pieces split the same cells (Contour.cxx: RepairCellsFoundWanting).
#pragma once

#include "RootGrid.h"
#include "SplitReason.h"

#include <cstdint>
#include <vector>

namespace tpc
{

struct CellToSplit
{
  std::uint8_t Level = 0;
  LatticeIndex Ijk[3] = { 0, 0, 0 };
  SplitReason Reason = SplitReason::PatchNotCertified;
};

/// The cells a next run splits before their tests, looked up by position.
class CellsToSplit
{
public:
  /// Adds `cell` (a cell already named keeps its first reason).
  void Add(const CellToSplit& cell);
  bool Empty() const { return this->Cells.empty(); }
  std::size_t Size() const { return this->Cells.size(); }
  /// The request for the cell at `level`, `ijk`, or null.
  const CellToSplit* Find(int level, const LatticeIndex ijk[3]) const;
  /// Five numbers a cell (level, position, reason), for the pieces of a
  /// split run to exchange (PieceExchange::GatherAll): a lattice index has
  /// at most LatticeBits (42) bits, exact in a double.
  std::vector<double> Serialize() const;
  /// Adds every cell of a Serialize()d list.
  void AddSerialized(const std::vector<double>& cells);

private:
  std::vector<CellToSplit> Cells; ///< sorted by level, then position
};

} // namespace tpc
