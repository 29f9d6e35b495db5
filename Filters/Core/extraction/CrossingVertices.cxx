#include "CrossingVertices.h"

#include "CsgCreaseCrossing.h"
#include "EdgeCrossings.h"
#include "ExactCell.h"

#include <algorithm>
#include <cassert>
#include <cmath>

namespace tpc
{
namespace
{
/// The per-vertex loop runs in chunks reporting progress, so that an abort
/// stops it within a chunk.
constexpr std::size_t Chunk = 4 * 8192;
constexpr std::size_t Blocks = 64, Buckets = 256;

std::size_t BucketOf(const CrossingVertices::Record& r)
{
  return HashKey(r.Vertex.Key) >> 56;
}

/// Bends (cells stopped by a limit only, BoundaryLoops.h): between the run's
/// two crossings, nudged off their line into the bend's tile so that bends
/// of different tiles around the line do not coincide.
void PlaceBendVertices(const CrossingVertices& vertices, TriangleMesh& mesh)
{
  for (std::size_t i = 0; i < vertices.Records().size(); ++i)
  {
    const Crossing& c = vertices.Records()[i].Vertex;
    if (c.Kind != CrossingKind::Bend)
    {
      continue;
    }
    Crossing first, last;
    first.Key = c.Key;
    last.Key = c.Partner;
    const Vec3 a = mesh.Points[vertices.IdOf(first)], b = mesh.Points[vertices.IdOf(last)];
    LatticeIndex corner[3], on[3];
    TileKeyCorner(c.Tile, corner);
    SplitPointKey(PointOf(c.Key), on);
    const int plane = TileKeyAxis(c.Tile), along = AxisOf(c.Key);
    const int across = 3 - plane - along;
    Vec3 p = (a + b) * 0.5;
    p[across] += (on[across] == corner[across] ? 1e-3 : -1e-3) * Norm(b - a);
    mesh.Points[i] = p;
    mesh.Normals[i] = Normalized(mesh.Normals[vertices.IdOf(first)] + mesh.Normals[vertices.IdOf(last)]);
  }
}
} // namespace

bool CrossingVertices::Build(const std::vector<BoundaryLoopSet>& loops, const std::vector<std::uint8_t>& decidesFirst,
  const ParallelFor& parallelFor, const ProgressCallback& progress)
{
  return GatherDistinct<Record>(Blocks, Buckets,
    [&loops](std::size_t b, const auto& out) {
      for (std::size_t i = loops.size() * b / Blocks; i < loops.size() * (b + 1) / Blocks; ++i)
      {
        for (const Crossing& c : loops[i].Crossings)
        {
          out(Record{ c, static_cast<std::uint32_t>(i) });
        }
      }
    },
    BucketOf,
    [&decidesFirst](const Record& a, const Record& b) {
      if (!a.Vertex.SameVertex(b.Vertex))
      {
        return a.Vertex < b.Vertex;
      }
      return DecidesBefore(decidesFirst[a.CellIndex] != 0, a.CellIndex, decidesFirst[b.CellIndex] != 0, b.CellIndex);
    },
    [](const Record& a, const Record& b) { return a.Vertex.SameVertex(b.Vertex); }, parallelFor, progress,
    this->Distinct);
}

std::uint32_t CrossingVertices::IdOf(const Crossing& c) const
{
  const std::size_t k = BucketOf(Record{ c, 0 });
  const auto& records = this->Distinct.Records;
  const auto first = records.begin() + static_cast<std::ptrdiff_t>(this->Distinct.BucketStart[k]);
  const auto last = records.begin() + static_cast<std::ptrdiff_t>(this->Distinct.BucketStart[k + 1]);
  auto it = std::lower_bound(first, last, c, [](const Record& r, const Crossing& key) { return r.Vertex < key; });
  return static_cast<std::uint32_t>(it - records.begin());
}

bool PlaceCrossingVertices(const CrossingVertices& vertices, const AdaptiveOctree& tree,
  const std::vector<std::uint32_t>& cells, const PrimitiveSet& prims, TriangleMesh& mesh,
  const ParallelFor& parallelFor, const ProgressCallback& progress)
{
  const auto& records = vertices.Records();
  // (Every point and normal is written below, bends' last: in parallel, the
  // threads first touch their pages, ReleasableArray.h.)
  mesh.Points.resize_for_overwrite(records.size());
  mesh.Normals.resize_for_overwrite(records.size());
  if (!ChunkedFor(records.size(), Chunk, parallelFor, [&](std::size_t begin, std::size_t end) {
    for (std::size_t i = begin; i < end; ++i)
    {
      const Crossing& c = records[i].Vertex;
      if (c.Kind == CrossingKind::Bend)
      {
        continue; // bend vertices are placed from their crossings (PlaceBendVertices)
      }
      const CsgExpressionPtr& e = tree.Expressions[cells[records[i].CellIndex]];
      if (c.Kind == CrossingKind::CsgCrease)
      {
        // Recomputed as the tile was decided (CsgCreaseCrossing.h: the same
        // function of the same cell's expression), normal halfway between
        // the two surfaces'. Should it ever fail, the tile's centre keeps
        // the loop simple and the patch in the cell, where the tolerance's
        // size bounds it.
        const auto vertex = CsgCreaseVertex(c, e, prims, tree.Grid);
        assert(vertex);
        mesh.Points[i] = vertex ? vertex->first : CsgCreaseTileCentre(c, tree.Grid);
        mesh.Normals[i] = vertex ? vertex->second : Vec3();
        continue;
      }
      mesh.Points[i] = c.Kind == CrossingKind::SubEdge ? PlaceSubEdgeCrossing(c, tree.Grid, *e, prims)
                                                       : ExactCrossingPosition(c, prims, tree.Grid);
      mesh.Normals[i] = Normalized(e->Gradient(mesh.Points[i], prims));
    }
  }, progress))
  {
    return false;
  }
  PlaceBendVertices(vertices, mesh);
  return true;
}

} // namespace tpc
