// What the two cells sharing a face decide about it, decided once and shared.
//
// Crease tiles (CreaseCrossing.h). Both cells sharing a face tile ask whether
// it is a crease tile: in the subdivision's level that tests them, and again
// when the extraction traces their final loops - on armadillo at 1/64 each
// tile was decided 2.5 times, and CreaseOnTile was 6 % of the instructions.
// Each cell decides from the tile and the mesh alone, and alike
// (CreaseCrossing.h: both sides draw a tile alike - exact tests on the mesh,
// every triangle meeting the tile in both cells' lists).
//
// Face tilings (FaceRefinement.h). Each cell a level tests refines its six
// faces until their tiles pass the face tests, and the cell beside it, of the
// same level, refines the face they share (TileFaces, McCompatibility.cxx).
// Where a cell's surface is one mesh (its expression a lone mesh leaf,
// LoneMeshLeaf) the tiling is the face's and the mesh's alone: each tile's
// tests see the leaf pruned to the tile - the triangles of the cell's list
// that may meet it, in the list's order; both cells' lists hold every
// triangle meeting the face (they may differ by one that only grazes it
// within the triangle filter's slack, which the exact tests do not see) -
// and decide exactly on the triangles that meet it (FaceRefinement.cxx); the
// signs at the lattice points are exact. So both cells tile the face alike
// (TestFaceRefinement.cxx, TilingsOfOneMeshAreSharedByTheCellsOnBothSides,
// checks it face by face), and the second takes the first's tiling and
// learns the signs at its tiles' corners (a tiling was 8 % of armadillo's
// instructions at 1/128; shared, about 1 % fewer in all, for 1-4 % more
// memory at the peak at 1/256). The other points the first sampled while
// tiling go to its own sign table only (the second needs none of them).
// Where meshes meet, a tile's crossing counts may split it at other points
// with another cell's list (FaceRefinement.cxx): each such cell tiles its
// faces itself.
//
// So the first decision is every later asker's: whichever cell's thread makes
// it, the answer is the same, and the output does not depend on the threads.
// A decision is taken out by the second cell asking for it - the two sharing
// the face are all that ask in one pass (a cell asking again decides again,
// alike) - and the pass that asks holds the cache and clears it after (a
// subdivision level, the extraction's loops): it holds the decisions one
// cell has asked for and the other not yet, or never will (a neighbour of
// another level, one that failed before tiling, or outside the domain).
// (Kept until the end of the pass, the extraction's crease decisions were
// 20 % more memory at the peak, armadillo and the turbine at 1/256.)
#pragma once

#include "CellSignCache.h"
#include "CreaseCrossing.h"
#include "FaceRefinement.h"

#include <array>
#include <cstddef>
#include <cstdint>
#include <mutex>
#include <optional>
#include <unordered_map>
#include <utility>
#include <vector>

namespace tpc
{

class FaceDecisionCache
{
public:
  /// CreaseOnTile(leaf, primitives, grid, axis, plane, tile), decided once
  /// per mesh and tile for the two cells sharing the tile (the second asking
  /// takes the decision out); any number of threads may ask at once.
  std::optional<CreaseTile> DecideCrease(const CsgLeaf& leaf, const PrimitiveSet& primitives, const RootGrid& grid,
    int axis, LatticeIndex plane, const FaceTile& tile);

  /// Forgets every decision.
  void Clear();

private:
  friend FaceRefinementResult TileFace(FaceDecisionCache* cache, const CsgExpressionPtr& expression,
    const PrimitiveSet& primitives, const RootGrid& grid, int axis, LatticeIndex plane, const FaceTile& face,
    int maxLevels, CellSignCache& signs);

  /// A face or tile of one mesh: the leaf's primitive and sign (the tiling's
  /// tests read the leaf's side), the plane, the tile, and the levels a
  /// tiling may refine (0 for crease tiles).
  struct Key
  {
    std::uint32_t Primitive = 0;
    std::int8_t Sigma = 1;
    int Axis = 0;
    LatticeIndex Plane = 0;
    FaceTile Tile;
    int Levels = 0;
    bool operator==(const Key& o) const
    {
      return this->Primitive == o.Primitive && this->Sigma == o.Sigma && this->Axis == o.Axis &&
        this->Plane == o.Plane && this->Tile == o.Tile && this->Levels == o.Levels;
    }
  };
  struct KeyHash
  {
    std::size_t operator()(const Key& k) const;
  };

  /// Decisions of one kind, each taken out by its second asker; in shards of
  /// their own locks, so two threads seldom wait for each other.
  template <typename Value>
  class TakenOnce
  {
  public:
    /// The kept decision for `key`, taken out; else decide(), kept.
    /// (Decided without the lock; a thread deciding the same key meanwhile
    /// finds the same answer, and the first one kept stands - until the
    /// pass clears it, as one the other cell never asks for.)
    template <typename Decide>
    Value Take(const Key& key, const Decide& decide)
    {
      Shard& shard = this->Parts[KeyHash()(key) % Shards];
      {
        const std::lock_guard<std::mutex> lock(shard.Mutex);
        const auto found = shard.Values.find(key);
        if (found != shard.Values.end())
        {
          Value kept = std::move(found->second);
          shard.Values.erase(found);
          return kept;
        }
      }
      Value decided = decide();
      const std::lock_guard<std::mutex> lock(shard.Mutex);
      shard.Values.try_emplace(key, decided);
      return decided;
    }

    void Clear()
    {
      for (Shard& shard : this->Parts)
      {
        const std::lock_guard<std::mutex> lock(shard.Mutex);
        shard.Values.clear();
      }
    }

  private:
    struct Shard
    {
      std::mutex Mutex;
      std::unordered_map<Key, Value, KeyHash> Values;
    };
    static constexpr std::size_t Shards = 32;
    std::array<Shard, Shards> Parts;
  };

  /// A face's tiling and the signs at its tiles' corners, in the tiles'
  /// order, four per tile (TileCorner).
  struct Tiling
  {
    FaceRefinementResult Refinement;
    std::vector<bool> CornersInside;
  };

  TakenOnce<std::optional<CreaseTile>> Creases;
  TakenOnce<Tiling> Tilings;
};

/// RefineFace(expression, primitives, grid, axis, plane, face, maxLevels,
/// signs), decided once for the two cells sharing the face where `cache` is
/// given and `expression` is a lone mesh leaf - the second learns the signs
/// at the tiles' corners into its `signs` - else by the cell itself.
FaceRefinementResult TileFace(FaceDecisionCache* cache, const CsgExpressionPtr& expression,
  const PrimitiveSet& primitives, const RootGrid& grid, int axis, LatticeIndex plane, const FaceTile& face,
  int maxLevels, CellSignCache& signs);

} // namespace tpc
