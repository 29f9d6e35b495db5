// Crease tiles (CreaseCrossing.h) decided once and shared.
//
// Both cells sharing a face tile ask whether it is a crease tile: in the
// subdivision's level that tests them, and again when the extraction traces
// their final loops - on armadillo at 1/64 each tile was decided 2.5 times,
// and CreaseOnTile was 6 % of the instructions. Each cell decides from the
// tile and the mesh alone, and alike (CreaseCrossing.h: both sides draw a
// tile alike - exact tests on the mesh, every triangle meeting the tile in
// both cells' lists), so the first decision is every later asker's: whichever
// cell's thread makes it, the answer is the same, and the output does not
// depend on the threads. A decision is taken out by the second cell asking
// for it - the two sharing the tile are all that ask in one pass (a cell
// asking again decides again, alike) - and the pass that asks holds the cache
// and clears it after (a subdivision level, the extraction's loops): it holds
// the tiles one cell has asked for and the other not yet, or never will (a
// neighbour of another level, or outside the domain). (Kept until the end of
// the pass, the extraction's decisions were 20 % more memory at the peak,
// armadillo and the turbine at 1/256.)
#pragma once

#include "CreaseCrossing.h"

#include <array>
#include <cstddef>
#include <cstdint>
#include <mutex>
#include <optional>
#include <unordered_map>

namespace tpc
{

class CreaseTileCache
{
public:
  /// CreaseOnTile(leaf, primitives, grid, axis, plane, tile), decided once
  /// per mesh and tile for the two cells sharing the tile (the second asking
  /// takes the decision out); any number of threads may ask at once.
  std::optional<CreaseTile> Decide(const CsgLeaf& leaf, const PrimitiveSet& primitives, const RootGrid& grid,
    int axis, LatticeIndex plane, const FaceTile& tile);
  /// Forgets every decision.
  void Clear();

private:
  struct Key
  {
    std::uint32_t Primitive = 0;
    int Axis = 0;
    LatticeIndex Plane = 0;
    FaceTile Tile;
    bool operator==(const Key& o) const
    {
      return this->Primitive == o.Primitive && this->Axis == o.Axis && this->Plane == o.Plane && this->Tile == o.Tile;
    }
  };
  struct KeyHash
  {
    std::size_t operator()(const Key& k) const;
  };
  /// The decisions in shards of their own locks: two threads seldom wait
  /// for each other.
  struct Shard
  {
    std::mutex Mutex;
    std::unordered_map<Key, std::optional<CreaseTile>, KeyHash> Tiles;
  };
  static constexpr std::size_t Shards = 32;
  std::array<Shard, Shards> Parts;
};

} // namespace tpc
