#include "SurfaceExtraction.h"

#include "EdgeCrossings.h"
#include "ExactCell.h"
#include "LoopTriangulation.h"

#include <algorithm>
#include <cmath>

namespace tpc
{
namespace
{
/// Gathers the final samples on the boundary of one leaf: the tiles of each
/// face from whichever side is finer (with their face refinements), every
/// leaf corner and refinement point on its faces and edges - the same points
/// every other cell touching them gathers.
class CellBoundaryBuilder
{
public:
  CellBoundaryBuilder(const AdaptiveOctree& tree, std::size_t cell)
    : Tree(tree)
    , Cell(cell)
    , Node(tree.Nodes[cell])
  {
  }

  CellBoundary Build()
  {
    CellBoundary b;
    const int depth = this->Tree.Grid.MaxDepth;
    const int shift = depth - this->Node.Level;
    b.Size = 1u << shift;
    for (int a = 0; a < 3; ++a)
    {
      b.Base[a] = this->Node.Ijk[a] << shift;
    }
    for (int c = 0; c < 8; ++c)
    {
      this->AddLeafCorner(b, this->Cell, c);
    }
    for (int f = 0; f < 6; ++f)
    {
      this->FaceTiles(b, f);
    }
    this->EdgeNeighborPoints(b);
    // Face-refinement points on every tile edge (T-junctions from refined
    // faces anywhere around this cell).
    std::vector<PointKey> extra;
    for (int f = 0; f < 6; ++f)
    {
      const int axis = f / 2;
      const int U = (axis + 1) % 3, V = (axis + 2) % 3;
      const std::uint32_t plane = b.Base[axis] + (f % 2 ? b.Size : 0);
      for (const FaceTile& t : b.Tiles[f])
      {
        // Bottom and top edges run along U, left and right along V.
        const std::uint32_t starts[4][2] = { { t.U0, t.V0 }, { t.U0, t.V1 }, { t.U0, t.V0 },
          { t.U1, t.V0 } };
        for (int k = 0; k < 4; ++k)
        {
          std::uint32_t p[3];
          p[axis] = plane;
          p[U] = starts[k][0];
          p[V] = starts[k][1];
          const int along = k < 2 ? U : V;
          this->Tree.RefinementPointsOn(p, along, k < 2 ? t.U1 : t.V1, extra);
        }
      }
    }
    for (const PointKey k : extra)
    {
      b.Points.emplace_back(k, this->Tree.Signs.Find(k) == 1);
    }
    return b;
  }

private:
  void AddLeafCorner(CellBoundary& b, std::size_t leaf, int corner) const
  {
    std::uint32_t p[3];
    CornerLattice(this->Tree.Grid, this->Tree.Nodes[leaf], corner, p);
    const PointKey key = MakePointKey(p[0], p[1], p[2]);
    b.Points.emplace_back(key, this->Tree.PointInside(leaf, key));
  }

  void AddTileCorners(CellBoundary& b, int axis, std::uint32_t plane, const FaceTile& t) const
  {
    for (int c = 0; c < 4; ++c)
    {
      const PointKey key = TileCorner(axis, plane, t, c);
      b.Points.emplace_back(key, this->Tree.Signs.Find(key) == 1);
    }
  }

  void CollectAdjacentLeaves(std::size_t node, int axisU, int bitU, int axisV, int bitV,
    std::vector<std::size_t>& out) const
  {
    const OctreeNode& n = this->Tree.Nodes[node];
    if (n.IsLeaf())
    {
      out.push_back(node);
      return;
    }
    for (int c = 0; c < 8; ++c)
    {
      if (((c >> axisU) & 1) == bitU && (axisV < 0 || ((c >> axisV) & 1) == bitV))
      {
        this->CollectAdjacentLeaves(static_cast<std::size_t>(n.FirstChild + c), axisU, bitU, axisV, bitV, out);
      }
    }
  }

  /// The neighbour displaced by `offset` at this cell's level, if it exists
  /// there and is refined (only then does it bring finer samples).
  std::int64_t RefinedNeighbor(const int offset[3]) const
  {
    const std::int64_t n = this->Neighbor(offset);
    if (n < 0)
    {
      return -1;
    }
    const OctreeNode& nn = this->Tree.Nodes[static_cast<std::size_t>(n)];
    return (nn.Level == this->Node.Level && !nn.IsLeaf()) ? n : -1;
  }

  /// The node displaced by `offset` at this cell's level, or the leaf
  /// holding that position; -1 outside the grid.
  std::int64_t Neighbor(const int offset[3]) const
  {
    std::int64_t ijk[3];
    for (int a = 0; a < 3; ++a)
    {
      ijk[a] = static_cast<std::int64_t>(this->Node.Ijk[a]) + offset[a];
    }
    return this->Tree.Find(this->Node.Level, ijk);
  }

  /// Tiles of the face of `leaf` on face f's side, refined if it was, with
  /// the leaf `across` them.
  void AddFaceOfLeaf(CellBoundary& b, int f, std::size_t leaf, int leafFace, std::int64_t across) const
  {
    const int axis = f / 2;
    const std::uint32_t plane = b.Base[axis] + (f % 2 ? b.Size : 0);
    const OctreeNode& q = this->Tree.Nodes[leaf];
    const auto it = this->Tree.FaceRefinements.find(FaceOf(this->Tree.Grid, q, leafFace));
    if (it != this->Tree.FaceRefinements.end())
    {
      for (const FaceTile& t : it->second)
      {
        b.Tiles[f].push_back(t);
        b.Across[f].push_back(across);
        this->AddTileCorners(b, axis, plane, t);
      }
      return;
    }
    const int shift = this->Tree.Grid.MaxDepth - q.Level;
    const std::uint32_t u0 = q.Ijk[(axis + 1) % 3] << shift, v0 = q.Ijk[(axis + 2) % 3] << shift;
    const FaceTile t{ u0, v0, u0 + (1u << shift), v0 + (1u << shift) };
    b.Tiles[f].push_back(t);
    b.Across[f].push_back(across);
    for (int c = 0; c < 8; ++c)
    {
      if (((c >> axis) & 1) == leafFace % 2)
      {
        this->AddLeafCorner(b, leaf, c);
      }
    }
  }

  void FaceTiles(CellBoundary& b, int f) const
  {
    const int axis = f / 2, side = f % 2;
    int offset[3] = { 0, 0, 0 };
    offset[axis] = side ? 1 : -1;
    const std::int64_t n = this->RefinedNeighbor(offset);
    if (n < 0)
    {
      this->AddFaceOfLeaf(b, f, this->Cell, f, this->Neighbor(offset));
      return;
    }
    std::vector<std::size_t> leaves;
    this->CollectAdjacentLeaves(static_cast<std::size_t>(n), axis, side ? 0 : 1, -1, 0, leaves);
    for (const std::size_t leaf : leaves)
    {
      this->AddFaceOfLeaf(b, f, leaf, 2 * axis + (side ? 0 : 1), static_cast<std::int64_t>(leaf));
    }
  }

  /// Corners of the finer leaves of the diagonal neighbours on this cell's edges.
  void EdgeNeighborPoints(CellBoundary& b) const
  {
    for (int e = 0; e < 12; ++e)
    {
      const int axis = e / 4, r = e % 4;
      const int u = (axis + 1) % 3, v = (axis + 2) % 3;
      const int du = r & 1, dv = (r >> 1) & 1;
      int offset[3] = { 0, 0, 0 };
      offset[u] = du ? 1 : -1;
      offset[v] = dv ? 1 : -1;
      const std::int64_t n = this->RefinedNeighbor(offset);
      if (n < 0)
      {
        continue;
      }
      std::vector<std::size_t> leaves;
      this->CollectAdjacentLeaves(static_cast<std::size_t>(n), u, du ? 0 : 1, v, dv ? 0 : 1, leaves);
      for (const std::size_t leaf : leaves)
      {
        for (int end = 0; end < 2; ++end)
        {
          this->AddLeafCorner(b, leaf, ((du ? 0 : 1) << u) | ((dv ? 0 : 1) << v) | (end << axis));
        }
      }
    }
  }

  const AdaptiveOctree& Tree;
  std::size_t Cell;
  const OctreeNode& Node;
};

/// Faces of the cell (bit f, CubeTopology.h numbering) that a loop's crossing
/// lies on; all six for a bend (never a fan point).
unsigned FacesOf(const Crossing& c, const std::uint32_t base[3], std::uint32_t size)
{
  if (c.Kind == CrossingKind::Bend)
  {
    return 0x3F;
  }
  if (c.Kind == CrossingKind::MeshEdge)
  {
    const int axis = static_cast<int>(c.Key >> 32);
    const std::uint32_t plane = static_cast<std::uint32_t>(c.Key & 0xFFFFFFFFu);
    return (plane == base[axis] ? 1u : 0u) << (2 * axis) | (plane == base[axis] + size ? 1u : 0u) << (2 * axis + 1);
  }
  if (c.Kind == CrossingKind::MeshVertex)
  {
    return 0; // inside an exact cell
  }
  std::uint32_t p[3];
  SplitPointKey(c.Key >> 2, p);
  const int along = static_cast<int>(c.Key & 3);
  unsigned mask = 0;
  for (int a = 0; a < 3; ++a)
  {
    if (a != along)
    {
      mask |= (p[a] == base[a] ? 1u : 0u) << (2 * a);
      mask |= (p[a] == base[a] + size ? 1u : 0u) << (2 * a + 1);
    }
  }
  return mask;
}

/// The per-cell loops run in chunks reporting progress, so that an abort
/// stops them within a chunk.
constexpr std::size_t Chunk = 8192;

/// Leaves that meet the surface (passed the tests, were stopped, or are
/// exact), in node order.
std::vector<std::uint32_t> SurfaceLeaves(const AdaptiveOctree& tree)
{
  std::vector<std::uint32_t> cells;
  for (std::size_t n = 0; n < tree.Nodes.size(); ++n)
  {
    const OctreeNode& node = tree.Nodes[n];
    if (node.IsLeaf() &&
      (node.State == CellState::Surface || node.State == CellState::Unresolved || node.State == CellState::Exact))
    {
      cells.push_back(static_cast<std::uint32_t>(n));
    }
  }
  return cells;
}

/// One vertex per distinct crossing of all loops, and which cell places it
/// (the first in node order among the cells whose loops hold it, so that
/// every piece of a split run picks the same one: ForestPartition.h).
class CrossingVertices
{
public:
  struct Record
  {
    Crossing Vertex;
    std::uint32_t CellIndex; ///< index into the surface leaves
  };

  /// The crossings are bucketed by a hash of their edge key (in parallel, by
  /// blocks of cells), each bucket is sorted and deduplicated on its own; a
  /// vertex's id is its bucket's offset plus its rank there. (One global sort
  /// of tens of millions of records takes seconds without an abort check.)
  bool Build(const std::vector<BoundaryLoopSet>& loops, const ParallelFor& parallelFor,
    const ProgressCallback& progress)
  {
    std::vector<std::vector<Record>> parts(Blocks * Buckets);
    parallelFor(Blocks, [&](std::size_t begin, std::size_t end) {
      for (std::size_t b = begin; b < end; ++b)
      {
        for (std::size_t i = loops.size() * b / Blocks; i < loops.size() * (b + 1) / Blocks; ++i)
        {
          for (const Crossing& c : loops[i].Crossings)
          {
            parts[b * Buckets + BucketOf(c)].push_back({ c, static_cast<std::uint32_t>(i) });
          }
        }
      }
    });
    std::vector<std::vector<Record>> buckets(Buckets);
    if (!ChunkedFor(Buckets, 16, parallelFor, [&](std::size_t begin, std::size_t end) {
          for (std::size_t k = begin; k < end; ++k)
          {
            SortBucket(parts, k, buckets[k]);
          }
        }, progress))
    {
      return false;
    }
    this->BucketStart.assign(Buckets + 1, 0);
    for (std::size_t k = 0; k < Buckets; ++k)
    {
      this->BucketStart[k + 1] = this->BucketStart[k] + buckets[k].size();
    }
    this->Records.resize(this->BucketStart[Buckets]);
    parallelFor(Buckets, [&](std::size_t begin, std::size_t end) {
      for (std::size_t k = begin; k < end; ++k)
      {
        std::copy(buckets[k].begin(), buckets[k].end(),
          this->Records.begin() + static_cast<std::ptrdiff_t>(this->BucketStart[k]));
        std::vector<Record>().swap(buckets[k]);
      }
    });
    return true;
  }

  std::uint32_t IdOf(const Crossing& c) const
  {
    const std::size_t k = BucketOf(c);
    const auto first = this->Records.begin() + static_cast<std::ptrdiff_t>(this->BucketStart[k]);
    const auto last = this->Records.begin() + static_cast<std::ptrdiff_t>(this->BucketStart[k + 1]);
    auto it = std::lower_bound(first, last, c, [](const Record& r, const Crossing& key) { return r.Vertex < key; });
    return static_cast<std::uint32_t>(it - this->Records.begin());
  }

  std::vector<Record> Records;

private:
  static constexpr std::size_t Blocks = 64, Buckets = 256;
  static std::size_t BucketOf(const Crossing& c)
  {
    return static_cast<std::size_t>((c.Key * 0x9E3779B97F4A7C15ULL) >> 56);
  }
  static void SortBucket(std::vector<std::vector<Record>>& parts, std::size_t k, std::vector<Record>& bucket)
  {
    for (std::size_t b = 0; b < Blocks; ++b)
    {
      bucket.insert(bucket.end(), parts[b * Buckets + k].begin(), parts[b * Buckets + k].end());
      std::vector<Record>().swap(parts[b * Buckets + k]);
    }
    std::sort(bucket.begin(), bucket.end(), [](const Record& a, const Record& b) {
      return !a.Vertex.SameVertex(b.Vertex) ? a.Vertex < b.Vertex : a.CellIndex < b.CellIndex;
    });
    bucket.erase(std::unique(bucket.begin(), bucket.end(),
                   [](const Record& a, const Record& b) { return a.Vertex.SameVertex(b.Vertex); }),
      bucket.end());
  }

  std::vector<std::size_t> BucketStart;
};

/// A surface crossing on its lattice sub-edge, found on the exact field, then
/// put exactly on the sub-edge's line and strictly inside it: crossings of
/// different sub-edges never coincide and a loop's chords meet only at their
/// ends (LoopTriangulation.h).
Vec3 PlaceCrossing(const Crossing& c, const RootGrid& grid, const CsgExpression& expression,
  const PrimitiveSet& prims)
{
  const int axis = static_cast<int>(c.Key & 3);
  std::uint32_t lo[3], hi[3];
  SplitPointKey(c.Key >> 2, lo);
  std::copy(lo, lo + 3, hi);
  hi[axis] = c.Upper;
  const Vec3 a = grid.Point(lo), b = grid.Point(hi);
  const Vec3 found = FindEdgeCrossing(expression, prims, a, b, c.LowerInside);
  Vec3 p = a;
  p[axis] = std::clamp(found[axis], std::nextafter(a[axis], b[axis]), std::nextafter(b[axis], a[axis]));
  return p;
}

/// Positions and normals of the crossing vertices, each placed by its cell.
bool PlaceCrossingVertices(const CrossingVertices& vertices, const AdaptiveOctree& tree,
  const std::vector<std::uint32_t>& cells, const PrimitiveSet& prims, TriangleMesh& mesh,
  const ParallelFor& parallelFor, const ProgressCallback& progress)
{
  const auto& records = vertices.Records;
  mesh.Points.resize(records.size());
  mesh.Normals.resize(records.size());
  return ChunkedFor(records.size(), 4 * Chunk, parallelFor, [&](std::size_t begin, std::size_t end) {
    for (std::size_t i = begin; i < end; ++i)
    {
      const Crossing& c = records[i].Vertex;
      if (c.Kind == CrossingKind::Bend)
      {
        continue; // bend vertices are placed from their crossings (PlaceBendVertices)
      }
      const CsgExpression& e = *tree.Expressions[cells[records[i].CellIndex]];
      mesh.Points[i] = c.Kind == CrossingKind::SubEdge ? PlaceCrossing(c, tree.Grid, e, prims)
                                                       : ExactCrossingPosition(c, prims, tree.Grid);
      mesh.Normals[i] = Normalized(e.Gradient(mesh.Points[i], prims));
    }
  }, progress);
}

/// Bends (cells stopped by a limit only, BoundaryLoops.h): between the run's
/// two crossings, nudged off their line into the bend's tile so that bends
/// of different tiles around the line do not coincide.
void PlaceBendVertices(const CrossingVertices& vertices, TriangleMesh& mesh)
{
  for (std::size_t i = 0; i < vertices.Records.size(); ++i)
  {
    const Crossing& c = vertices.Records[i].Vertex;
    if (c.Kind != CrossingKind::Bend)
    {
      continue;
    }
    Crossing first, last;
    first.Key = c.Key;
    last.Key = c.Partner;
    const Vec3 a = mesh.Points[vertices.IdOf(first)], b = mesh.Points[vertices.IdOf(last)];
    std::uint32_t corner[3], on[3];
    SplitPointKey((c.Tile - 1) >> 2, corner);
    SplitPointKey(c.Key >> 2, on);
    const int plane = static_cast<int>((c.Tile - 1) & 3), along = static_cast<int>(c.Key & 3);
    const int across = 3 - plane - along;
    Vec3 p = (a + b) * 0.5;
    p[across] += (on[across] == corner[across] ? 1e-3 : -1e-3) * Norm(b - a);
    mesh.Points[i] = p;
    mesh.Normals[i] = Normalized(mesh.Normals[vertices.IdOf(first)] + mesh.Normals[vertices.IdOf(last)]);
  }
}

/// The triangles of one cell; apex ids at or above LocalFlag index Apexes.
struct CellPatches
{
  static constexpr std::uint32_t LocalFlag = 1u << 31;
  std::vector<Vec3> Apexes;
  std::vector<std::array<std::uint32_t, 3>> Triangles;
};

/// The loops of one cell; for an exact cell, its polygons (ExactCell.h).
/// Tiles shared with an exact cell are drawn exactly.
BoundaryLoopSet CellLoops(const AdaptiveOctree& tree, std::uint32_t cell, const PrimitiveSet& prims)
{
  CellBoundary boundary = CellBoundaryBuilder(tree, cell).Build();
  const CsgLeaf* own = tree.Nodes[cell].State == CellState::Exact ? LoneMeshLeaf(*tree.Expressions[cell]) : nullptr;
  if (own)
  {
    ExactPolygons polygons = ClipToExactCell(boundary, *own, prims, tree.Grid);
    BoundaryLoopSet set;
    set.Crossings = std::move(polygons.Vertices);
    set.LoopSizes = std::move(polygons.Sizes);
    return set;
  }
  std::vector<ExactTile> exact;
  for (int f = 0; f < 6; ++f)
  {
    for (std::size_t k = 0; k < boundary.Tiles[f].size(); ++k)
    {
      const std::int64_t across = boundary.Across[f][k];
      const CsgLeaf* leaf = across >= 0 && tree.Nodes[static_cast<std::size_t>(across)].State == CellState::Exact
        ? LoneMeshLeaf(*tree.Expressions[static_cast<std::size_t>(across)])
        : nullptr;
      if (leaf)
      {
        exact.push_back({ f, k, leaf });
      }
    }
  }
  AddExactTileSegments(boundary, exact, prims, tree.Grid);
  return TraceBoundaryLoops(boundary);
}

/// An exact cell's polygons (ExactCell.h), each a triangle or a fan around
/// its centroid (in its triangle's plane: the polygon is convex, and its
/// inserted tile-side points are collinear with their neighbours).
void TriangulateExactCell(const BoundaryLoopSet& polygons, const CrossingVertices& vertices,
  const TriangleMesh& mesh, CellPatches& out)
{
  std::size_t offset = 0;
  for (const std::uint32_t size : polygons.LoopSizes)
  {
    std::vector<std::uint32_t> id;
    Vec3 centroid;
    for (std::uint32_t k = 0; k < size; ++k)
    {
      id.push_back(vertices.IdOf(polygons.Crossings[offset + k]));
      centroid += mesh.Points[id.back()];
    }
    offset += size;
    if (size == 3)
    {
      out.Triangles.push_back({ id[0], id[1], id[2] });
      continue;
    }
    const std::uint32_t apex = CellPatches::LocalFlag | static_cast<std::uint32_t>(out.Apexes.size());
    out.Apexes.push_back(centroid * (1.0 / size));
    for (std::uint32_t k = 0; k < size; ++k)
    {
      out.Triangles.push_back({ id[k], id[(k + 1) % size], apex });
    }
  }
}

/// Spans every loop of one cell (LoopTriangulation.h), each apex in its own
/// loop's region of the cell.
void TriangulateCell(const BoundaryLoopSet& loops, const OctreeNode& node, const CsgExpression& expression,
  const PrimitiveSet& prims, const RootGrid& grid, const CrossingVertices& vertices, const TriangleMesh& mesh,
  CellPatches& out)
{
  const Box3 box = grid.CellBox(node.Level, node.Ijk);
  std::uint32_t base[3];
  CornerLattice(grid, node, 0, base);
  const std::uint32_t size = 1u << (grid.MaxDepth - node.Level);
  std::vector<std::vector<std::uint32_t>> ids;
  std::vector<std::vector<LoopPoint>> points;
  std::vector<Box3> boxes;
  std::size_t offset = 0;
  for (const std::uint32_t loopSize : loops.LoopSizes)
  {
    ids.emplace_back();
    points.emplace_back();
    Box3 b{ { HUGE_VAL, HUGE_VAL, HUGE_VAL }, { -HUGE_VAL, -HUGE_VAL, -HUGE_VAL } };
    for (std::uint32_t k = 0; k < loopSize; ++k)
    {
      const Crossing& c = loops.Crossings[offset + k];
      const std::uint32_t id = vertices.IdOf(c);
      ids.back().push_back(id);
      points.back().push_back({ mesh.Points[id], mesh.Normals[id], FacesOf(c, base, size) });
      for (int a = 0; a < 3; ++a)
      {
        b.lo[a] = std::min(b.lo[a], mesh.Points[id][a]);
        b.hi[a] = std::max(b.hi[a], mesh.Points[id][a]);
      }
    }
    boxes.push_back(b);
    offset += loopSize;
  }
  for (std::size_t l = 0; l < ids.size(); ++l)
  {
    const std::vector<std::uint32_t>& id = ids[l];
    const std::size_t k = id.size();
    if (k < 3)
    {
      continue; // only from inconsistent loops, counted by the caller
    }
    const Box3 region = ids.size() > 1 ? ApexRegion(boxes, l, box) : box;
    const LoopPatch patch = TriangulateLoop(points[l], region, node.PlaneSection, expression, prims);
    if (patch.Kind == LoopPatchKind::Triangle)
    {
      out.Triangles.push_back({ id[0], id[1], id[2] });
    }
    else if (patch.Kind == LoopPatchKind::LoopFan)
    {
      const std::size_t s = static_cast<std::size_t>(patch.FanPoint);
      for (std::size_t i = 1; i + 1 < k; ++i)
      {
        out.Triangles.push_back({ id[s], id[(s + i) % k], id[(s + i + 1) % k] });
      }
    }
    else
    {
      const std::uint32_t apex = CellPatches::LocalFlag | static_cast<std::uint32_t>(out.Apexes.size());
      out.Apexes.push_back(patch.Apex);
      for (std::size_t i = 0; i < k; ++i)
      {
        out.Triangles.push_back({ id[i], id[(i + 1) % k], apex });
      }
    }
  }
}

/// Appends every cell's apexes and triangles to the mesh, in cell order.
void AppendPatches(std::vector<CellPatches>& patches, const std::vector<std::uint32_t>& cells, TriangleMesh& mesh)
{
  for (std::size_t i = 0; i < cells.size(); ++i)
  {
    const std::uint32_t base = static_cast<std::uint32_t>(mesh.Points.size());
    for (const Vec3& c : patches[i].Apexes)
    {
      mesh.Points.push_back(c);
      mesh.Normals.push_back(Vec3());
    }
    for (auto t : patches[i].Triangles)
    {
      for (auto& v : t)
      {
        v = (v & CellPatches::LocalFlag) ? base + (v & ~CellPatches::LocalFlag) : v;
      }
      mesh.Triangles.push_back(t);
      mesh.TriangleCell.push_back(cells[i]);
    }
    std::vector<Vec3>().swap(patches[i].Apexes);
    std::vector<std::array<std::uint32_t, 3>>().swap(patches[i].Triangles);
  }
}

/// Normals of the apexes (ids from `firstApex` on): the area-weighted mean of
/// their fans' triangles.
void ApexNormals(TriangleMesh& mesh, std::size_t firstApex)
{
  for (const auto& t : mesh.Triangles)
  {
    const Vec3 n = Cross(mesh.Points[t[1]] - mesh.Points[t[0]], mesh.Points[t[2]] - mesh.Points[t[0]]);
    for (const auto v : t)
    {
      if (v >= firstApex)
      {
        mesh.Normals[v] += n;
      }
    }
  }
  for (std::size_t v = firstApex; v < mesh.Normals.size(); ++v)
  {
    mesh.Normals[v] = Normalized(mesh.Normals[v]);
  }
}

/// In a piece of a split run: only the vertices of own cells' triangles.
void KeepUsedVertices(TriangleMesh& mesh)
{
  std::vector<std::uint32_t> index(mesh.Points.size(), UINT32_MAX);
  for (const auto& t : mesh.Triangles)
  {
    for (const auto v : t)
    {
      index[v] = 0;
    }
  }
  std::uint32_t kept = 0;
  for (std::size_t v = 0; v < index.size(); ++v)
  {
    if (index[v] == 0)
    {
      index[v] = kept;
      mesh.Points[kept] = mesh.Points[v];
      mesh.Normals[kept] = mesh.Normals[v];
      ++kept;
    }
  }
  mesh.Points.resize(kept);
  mesh.Normals.resize(kept);
  for (auto& t : mesh.Triangles)
  {
    for (auto& v : t)
    {
      v = index[v];
    }
  }
}
} // namespace

ExtractionResult ExtractSurface(const AdaptiveOctree& tree, const ImplicitScene& scene,
  const ParallelFor& parallelFor, const ProgressCallback& progress)
{
  // Progress: loops 40 %, vertex numbering 10 %, vertices 20 %, triangles 30 %.
  ExtractionResult result;
  const auto& prims = scene.Primitives;
  const std::vector<std::uint32_t> cells = SurfaceLeaves(tree);

  std::vector<BoundaryLoopSet> loops(cells.size());
  if (!ChunkedFor(cells.size(), Chunk, parallelFor, [&](std::size_t begin, std::size_t end) {
        for (std::size_t i = begin; i < end; ++i)
        {
          loops[i] = CellLoops(tree, cells[i], prims);
        }
      }, ProgressRange(progress, 0.0, 0.4)))
  {
    result.Aborted = true;
    return result;
  }

  // In a piece of a split run, ghost cells take part in choosing each shared
  // vertex's cell (as in the whole run) but give no triangles.
  CrossingVertices vertices;
  if (!vertices.Build(loops, parallelFor, ProgressRange(progress, 0.4, 0.5)) ||
    !PlaceCrossingVertices(vertices, tree, cells, prims, result.Mesh, parallelFor, ProgressRange(progress, 0.5, 0.7)))
  {
    result.Aborted = true;
    return result;
  }
  PlaceBendVertices(vertices, result.Mesh);

  std::vector<std::uint8_t> own(cells.size());
  for (std::size_t i = 0; i < cells.size(); ++i)
  {
    own[i] = tree.RoleOf(tree.Nodes[cells[i]]) == TreeRole::Own;
  }
  std::vector<CellPatches> patches(cells.size());
  if (!ChunkedFor(cells.size(), Chunk, parallelFor, [&](std::size_t begin, std::size_t end) {
        for (std::size_t i = begin; i < end; ++i)
        {
          if (own[i] && tree.Nodes[cells[i]].State == CellState::Exact)
          {
            TriangulateExactCell(loops[i], vertices, result.Mesh, patches[i]);
          }
          else if (own[i])
          {
            TriangulateCell(loops[i], tree.Nodes[cells[i]], *tree.Expressions[cells[i]], prims, tree.Grid, vertices,
              result.Mesh, patches[i]);
          }
        }
      }, ProgressRange(progress, 0.7, 1.0)))
  {
    result.Aborted = true;
    return result;
  }
  for (std::size_t i = 0; i < cells.size(); ++i)
  {
    result.InconsistentCells += own[i] && !loops[i].Consistent ? 1 : 0;
    // (An exact cell without triangles holds none of the input: nothing is missing.)
    result.CellsWithoutPatch +=
      own[i] && patches[i].Triangles.empty() && tree.Nodes[cells[i]].State != CellState::Exact ? 1 : 0;
  }
  const std::size_t firstApex = result.Mesh.Points.size();
  AppendPatches(patches, cells, result.Mesh);
  ApexNormals(result.Mesh, firstApex);
  if (!tree.Roles.empty())
  {
    KeepUsedVertices(result.Mesh);
  }
  return result;
}

} // namespace tpc
