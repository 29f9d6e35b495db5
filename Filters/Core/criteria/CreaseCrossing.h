// Creases of an input mesh as polylines of the output (issue 17).
//
// A loop draws one chord across each face tile, so where a crease of the
// mesh (an edge between triangles meeting at 30 degrees or more) crosses a
// tile the chord cuts the crease's corner, and the output's crease is a
// saw-tooth of tilted triangles. A crease tile is drawn through the crossing
// of its sharpest edge instead: the chord a -> b becomes a -> x -> b, x where
// that edge meets the tile's plane (named and placed as exact cells name and
// place it, MeshArrangement.h), so the fans on both sides of the face have x
// as a vertex and the crease runs through the output's edges.
//
// A tile is a crease tile when one or more of the mesh's edges crossing the
// open tile bend by CreaseTileAngleDegrees or more (the angle between their
// triangles' normals). x is the sharpest one's crossing: the smallest cosine
// between its triangles' normals, ties broken by the edge's vertex indices
// (a total order on the edges). The other edges the trace crosses, however
// much they bend, are points of its halves, which the chords' deviation
// takes in (MeshCellError.h).
//
// Why 25 degrees, below a crease's 30, and why other bends are allowed. A
// CAD part's fillets and small holes are tessellated in steps of 20 to 30
// degrees; a tile drawn through its sharpest step lets the loop, and the fan
// from x, follow the fillet's edges instead of cutting across them, and a
// tile drawn through a crease with a fillet's step beside it follows both.
// Triangles on the benchmark's meshes at 1/64, 1/128, 1/256 (before: 30
// degrees, and every other edge on the tile below 10, which was to keep a
// scanned surface's sharp-looking noise out):
// - couplingdown 7 190 / 13 166 / 21 498 -> 6 286 / 11 552 / 18 960, its
//   30-degree output edges 1.77 -> 1.45 times the input's at 1/64;
// - armadillo (a scan) 9 278 / 22 614 / 50 474 -> 9 088 / 18 354 / 40 700:
//   loops through its sharp edges follow it closer, so cells may be larger
//   (allowing other bends alone, at 30 degrees: 8 730 / 18 870 / 42 744);
//   at 1/32 it gains (5 558 -> 6 346 in the corpus check): a coarse cell's
//   crease tiles add loop points more than they let it grow;
// - fandisk 3-4 % fewer, turbine within 1.1 %.
// At 20 degrees armadillo gained triangles at every eps (9 766 at 1/64); at
// 15 armadillo did, and couplingdown at 1/128 and 1/256.
//
// A narrow chamfer or step - two creases closer than the tile - is drawn
// through the sharper, and the other lies on a half (while such a tile was
// drawn straight, its chord's deviation was what most often split the cells
// along CAD parts' chamfers: couplingdown at 1/128, 567 of 739 such splits).
// The trace ends at the chord's ends a and b (the tile passed the face
// tests: one arc), so a -> x -> b follows it, within how far its two halves
// stray from the two chords (MeshCellError.h bounds that from the halves,
// which CreaseOnTile walks). Every sub-tile of a crease tile holding x is a
// crease tile through x too (the same edges, fewer of them: x is still the
// sharpest, and the quick test below passes there as well, x's two
// triangles being near the sub-tile); one without x holds pieces of one
// half, and is drawn through its own sharpest edge where it passes these
// tests itself, else straight - either way through points of that half:
// however crack patching refines a crease tile, the final loop runs through
// x and stays on the trace's halves. A cell whose loop runs through x may
// then be fanned from x (MeshEdgeFanPoint, LoopTriangulation.h): the crease
// becomes the fan's diagonal x -> x', one output edge per cell, where that
// patch is certified within the apex fan's own bound or a quarter of the
// tolerance (SurfaceExtraction.cxx).
//
// Both cells sharing a tile must draw it alike: each decides from the tile and
// the mesh alone, with exact side tests on the mesh's perturbed solid
// (MeshArrangement.h); every triangle meeting the tile is in both cells'
// triangle lists. (A quick test first reads the triangles each cell lists near
// the tile, which may differ: it only rules out tiles on which no two of them
// bend by CreaseTileAngleDegrees, with a cone narrower than half that angle,
// so that it never rules out a tile the exact decision would draw through x -
// a fixed cone set for 30 degrees left cracks at 20.) x's computed position
// must be strictly inside the tile too (the exact test is on the perturbed
// mesh: a crease crossing within rounding of a tile side would put the chords
// along the side, where the output is not embedded - a fuzzer found it); it is
// required as a property of x alone, on the side of every lattice plane the
// exact tests say (MeshArrangement::PlacedAsDecided), so that too is decided
// alike by both sides and for a tile and its sub-tiles. The extraction draws
// crease tiles between two cells of the same lone mesh leaf that are not exact
// (CrackPatching.h); an exact neighbour draws the whole trace, a polyline
// through x on the same halves.
#pragma once

#include "BoundaryLoops.h"
#include "CsgExpression.h"

#include <optional>
#include <vector>

namespace tpc
{

/// The angle between two triangles' normals from which their common edge is
/// a crease (the usual feature angle of vtkFeatureEdges and CAD viewers;
/// what the tests count).
constexpr double CreaseAngleDegrees = 30.0;
/// The angle between two triangles' normals from which their common edge
/// makes a tile it crosses a crease tile (header: why below a crease's).
constexpr double CreaseTileAngleDegrees = 25.0;

/// Tile `tile` of the lattice plane x_axis = `plane` as a crease tile of the
/// mesh of `leaf` (its triangle list holds every triangle meeting the tile);
/// nothing when it is not one.
std::optional<CreaseTile> CreaseOnTile(const CsgLeaf& leaf, const PrimitiveSet& primitives, const RootGrid& grid,
  int axis, LatticeIndex plane, const FaceTile& tile);

class FaceDecisionCache; // (FaceDecisionCache.h)

/// CreaseOnTile, or the decision `cache` keeps (FaceDecisionCache.h) where one
/// is given.
std::optional<CreaseTile> DecideCreaseTile(FaceDecisionCache* cache, const CsgLeaf& leaf,
  const PrimitiveSet& primitives, const RootGrid& grid, int axis, LatticeIndex plane, const FaceTile& tile);

/// Marks the crease tiles of every face of `boundary` (a cell of the mesh of
/// `leaf`) in boundary.Creases, with their halves (the subdivision's
/// prediction reads them: CreaseOnTile's walk is not repeated), where
/// `draws(f, k)` says that tile k of face f may be drawn so (both cells
/// sharing it agree); whether it marked any. `cache` (if given): the
/// decisions shared with the cells of the same pass.
template <typename Draws>
bool MarkCreaseTiles(CellBoundary& boundary, const CsgLeaf& leaf, const PrimitiveSet& primitives,
  const RootGrid& grid, const Draws& draws, FaceDecisionCache* cache = nullptr)
{
  bool marked = false;
  for (int f = 0; f < 6; ++f)
  {
    const int axis = f / 2;
    const LatticeIndex plane = boundary.Base[axis] + (f % 2 ? boundary.Size : 0);
    boundary.Creases[f].assign(boundary.Tiles[f].size(), std::nullopt);
    for (std::size_t k = 0; k < boundary.Tiles[f].size(); ++k)
    {
      if (draws(f, k))
      {
        boundary.Creases[f][k] = DecideCreaseTile(cache, leaf, primitives, grid, axis, plane, boundary.Tiles[f][k]);
        marked = marked || boundary.Creases[f][k];
      }
    }
  }
  return marked;
}

} // namespace tpc
