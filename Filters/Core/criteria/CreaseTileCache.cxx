#include "CreaseTileCache.h"

namespace tpc
{

std::size_t CreaseTileCache::KeyHash::operator()(const Key& k) const
{
  std::uint64_t h = 0;
  for (const std::uint64_t v : { std::uint64_t{ k.Primitive } << 2 | static_cast<std::uint64_t>(k.Axis), k.Plane,
         k.Tile.U0, k.Tile.V0, k.Tile.U1, k.Tile.V1 })
  {
    h = (h ^ v) * 0x9E3779B97F4A7C15ull;
  }
  return static_cast<std::size_t>(h ^ (h >> 29));
}

std::optional<CreaseTile> CreaseTileCache::Decide(const CsgLeaf& leaf, const PrimitiveSet& primitives,
  const RootGrid& grid, int axis, LatticeIndex plane, const FaceTile& tile)
{
  const Key key{ leaf.Primitive, axis, plane, tile };
  Shard& shard = this->Parts[KeyHash()(key) % Shards];
  {
    const std::lock_guard<std::mutex> lock(shard.Mutex);
    const auto found = shard.Tiles.find(key);
    if (found != shard.Tiles.end())
    {
      // (The other cell sharing the tile: taken out. A cell asking again
      // decides again, alike.)
      std::optional<CreaseTile> kept = std::move(found->second);
      shard.Tiles.erase(found);
      return kept;
    }
  }
  // (Decided without the lock; a thread deciding the same tile meanwhile
  // finds the same answer, and the first one kept stands.)
  std::optional<CreaseTile> decided = CreaseOnTile(leaf, primitives, grid, axis, plane, tile);
  const std::lock_guard<std::mutex> lock(shard.Mutex);
  shard.Tiles.emplace(key, decided);
  return decided;
}

void CreaseTileCache::Clear()
{
  for (Shard& shard : this->Parts)
  {
    const std::lock_guard<std::mutex> lock(shard.Mutex);
    shard.Tiles.clear();
  }
}

} // namespace tpc
