#include "FaceDecisionCache.h"

#include "ExactCellCriterion.h"

namespace tpc
{

std::size_t FaceDecisionCache::KeyHash::operator()(const Key& k) const
{
  std::uint64_t h = 0;
  for (const std::uint64_t v : { std::uint64_t{ k.Primitive } << 2 | static_cast<std::uint64_t>(k.Axis),
         static_cast<std::uint64_t>(k.Levels) << 1 | (k.Sigma < 0 ? 1u : 0u), k.Plane, k.Tile.U0, k.Tile.V0,
         k.Tile.U1, k.Tile.V1 })
  {
    h = (h ^ v) * 0x9E3779B97F4A7C15ull;
  }
  return static_cast<std::size_t>(h ^ (h >> 29));
}

std::optional<CreaseTile> FaceDecisionCache::DecideCrease(const CsgLeaf& leaf, const PrimitiveSet& primitives,
  const RootGrid& grid, int axis, LatticeIndex plane, const FaceTile& tile)
{
  // (The leaf's sign is not in the key: a crease tile is the mesh's.)
  return this->Creases.Take(Key{ leaf.Primitive, 1, axis, plane, tile, 0 },
    [&] { return CreaseOnTile(leaf, primitives, grid, axis, plane, tile); });
}

FaceRefinementResult TileFace(FaceDecisionCache* cache, const CsgExpressionPtr& expression,
  const PrimitiveSet& primitives, const RootGrid& grid, int axis, LatticeIndex plane, const FaceTile& face,
  int maxLevels, CellSignCache& signs)
{
  const CsgLeaf* leaf = cache ? LoneMeshLeaf(*expression) : nullptr;
  if (!leaf)
  {
    return RefineFace(expression, primitives, grid, axis, plane, face, maxLevels, signs);
  }
  FaceDecisionCache::Tiling t = cache->Tilings.Take(
    FaceDecisionCache::Key{ leaf->Primitive, leaf->Sigma, axis, plane, face, maxLevels }, [&] {
      FaceDecisionCache::Tiling first;
      first.Refinement = RefineFace(expression, primitives, grid, axis, plane, face, maxLevels, signs);
      for (const FaceTile& r : first.Refinement.Tiles)
      {
        for (int c = 0; c < 4; ++c)
        {
          first.CornersInside.push_back(signs.Inside(TileCorner(axis, plane, r, c)));
        }
      }
      return first;
    });
  for (std::size_t r = 0; r < t.Refinement.Tiles.size(); ++r)
  {
    for (int c = 0; c < 4; ++c)
    {
      signs.Learn(TileCorner(axis, plane, t.Refinement.Tiles[r], c), t.CornersInside[4 * r + c]);
    }
  }
  return std::move(t.Refinement);
}

void FaceDecisionCache::Clear()
{
  this->Creases.Clear();
  this->Tilings.Clear();
}

} // namespace tpc
