#include "SurfaceExtraction.h"

#include "EdgeCrossings.h"
#include "SymmetricEigen.h"

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
    std::int64_t ijk[3];
    for (int a = 0; a < 3; ++a)
    {
      ijk[a] = static_cast<std::int64_t>(this->Node.Ijk[a]) + offset[a];
    }
    const std::int64_t n = this->Tree.Find(this->Node.Level, ijk);
    if (n < 0)
    {
      return -1;
    }
    const OctreeNode& nn = this->Tree.Nodes[static_cast<std::size_t>(n)];
    return (nn.Level == this->Node.Level && !nn.IsLeaf()) ? n : -1;
  }

  /// Tiles of the face of `leaf` on face f's side, refined if it was.
  void AddFaceOfLeaf(CellBoundary& b, int f, std::size_t leaf, int leafFace) const
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
        this->AddTileCorners(b, axis, plane, t);
      }
      return;
    }
    const int shift = this->Tree.Grid.MaxDepth - q.Level;
    const std::uint32_t u0 = q.Ijk[(axis + 1) % 3] << shift, v0 = q.Ijk[(axis + 2) % 3] << shift;
    const FaceTile t{ u0, v0, u0 + (1u << shift), v0 + (1u << shift) };
    b.Tiles[f].push_back(t);
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
      this->AddFaceOfLeaf(b, f, this->Cell, f);
      return;
    }
    std::vector<std::size_t> leaves;
    this->CollectAdjacentLeaves(static_cast<std::size_t>(n), axis, side ? 0 : 1, -1, 0, leaves);
    for (const std::size_t leaf : leaves)
    {
      this->AddFaceOfLeaf(b, f, leaf, 2 * axis + (side ? 0 : 1));
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

// --- vertex placement ------------------------------------------------------

bool FanIsConsistent(const std::vector<Vec3>& pts, const std::vector<Vec3>& normals, const Vec3& c)
{
  const std::size_t m = pts.size();
  for (std::size_t k = 0; k < m; ++k)
  {
    const Vec3& a = pts[k];
    const Vec3& b = pts[(k + 1) % m];
    const Vec3 n = Cross(b - a, c - a);
    if (Dot(n, normals[k] + normals[(k + 1) % m]) <= 0.0)
    {
      return false;
    }
  }
  return true;
}

/// The loop's interior vertex: the point minimizing the distances to the
/// tangent planes at the crossings (recovers sharp CSG edges and corners, as
/// in Extended Marching Cubes), kept inside the cell; if its fan would fold,
/// the loop centroid pulled onto the surface, then the centroid itself.
Vec3 PlaceLoopVertex(const std::vector<Vec3>& pts, const std::vector<Vec3>& normals,
  const Box3& cell, const CsgExpression& expression, const PrimitiveSet& prims)
{
  Vec3 m;
  for (const Vec3& p : pts)
  {
    m += p;
  }
  m = m * (1.0 / static_cast<double>(pts.size()));

  double ata[3][3] = { { 0, 0, 0 }, { 0, 0, 0 }, { 0, 0, 0 } };
  double atb[3] = { 0, 0, 0 };
  for (std::size_t k = 0; k < pts.size(); ++k)
  {
    const Vec3& n = normals[k];
    const double d = Dot(n, pts[k] - m);
    for (int i = 0; i < 3; ++i)
    {
      for (int j = 0; j < 3; ++j)
      {
        ata[i][j] += n[i] * n[j];
      }
      atb[i] += n[i] * d;
    }
  }
  // Truncated pseudo-inverse: along flat directions stay at the centroid.
  Vec3 delta;
  SolveTruncated(ata, atb, 0.1, delta.x);
  const Vec3 qef = cell.Clamp(m + delta);
  if (FanIsConsistent(pts, normals, qef))
  {
    return qef;
  }
  Vec3 y = m;
  for (int it = 0; it < 4; ++it)
  {
    const Vec3 g = expression.Gradient(y, prims);
    const double gg = Dot(g, g);
    if (gg <= 0.0)
    {
      break;
    }
    y = cell.Clamp(y - g * (expression.Value(y, prims) / gg));
  }
  if (FanIsConsistent(pts, normals, y))
  {
    return y;
  }
  return m;
}

/// Faces of the cell (bit f, CubeTopology.h numbering) that a loop's crossing
/// lies on; all six for a bend (never triangulated without a centre).
unsigned FacesOf(const Crossing& c, const std::uint32_t base[3], std::uint32_t size)
{
  if (c.Tile != 0)
  {
    return 0x3F;
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

/// Marching Cubes' triangulation of a loop: a fan from one of its own points
/// (k - 2 triangles instead of the k of a fan around a centre), used where
/// the surface is smooth in the cell (every crossing normal within 25 degrees
/// of their mean: no crease or corner for a centre vertex to keep sharp).
/// A diagonal may not join two points on one face of the cell: it would lie in
/// the face, where the neighbour's patch may use the same two points. Among
/// the apexes whose triangles all face the way the surface normals do, the
/// one with the shortest diagonals. Returns -1 when there is none.
int LoopFanApex(const std::vector<Vec3>& pts, const std::vector<Vec3>& normals, const std::vector<unsigned>& faces)
{
  const std::size_t m = pts.size();
  Vec3 mean;
  for (const Vec3& n : normals)
  {
    mean += n;
  }
  mean = Normalized(mean);
  for (const Vec3& n : normals)
  {
    if (!(Dot(n, mean) >= 0.906)) // cos 25 degrees (also rejects zero normals)
    {
      return -1;
    }
  }
  int best = -1;
  double bestLength = HUGE_VAL;
  for (std::size_t s = 0; s < m; ++s)
  {
    double length = 0.0;
    bool valid = true;
    for (std::size_t i = 1; i + 1 < m && valid; ++i)
    {
      const std::size_t a = (s + i) % m, b = (s + i + 1) % m;
      valid = (i == 1 || (faces[s] & faces[a]) == 0) && (i + 2 == m || (faces[s] & faces[b]) == 0);
      const Vec3 n = Cross(pts[a] - pts[s], pts[b] - pts[s]);
      valid = valid && Dot(n, normals[s] + normals[a] + normals[b]) > 0.0 && Dot(n, mean) > 0.0;
      length += i > 1 ? Norm(pts[a] - pts[s]) : 0.0;
    }
    if (valid && length < bestLength)
    {
      best = static_cast<int>(s);
      bestLength = length;
    }
  }
  return best;
}

/// True when every loop point lies on the same face of the cell: the surface
/// there is a cap over that face, and a triangle through the loop points alone
/// would lie flat in the face, so the loop needs a vertex inside the cell.
bool LiesOnOneFace(const std::vector<Vec3>& pts, const Box3& cell)
{
  for (int a = 0; a < 3; ++a)
  {
    for (const double plane : { cell.lo[a], cell.hi[a] })
    {
      bool all = true;
      for (const Vec3& p : pts)
      {
        all = all && p[a] == plane;
      }
      if (all)
      {
        return true;
      }
    }
  }
  return false;
}
} // namespace

ExtractionResult ExtractSurface(const AdaptiveOctree& tree, const ImplicitScene& scene,
  const ParallelFor& parallelFor, const ProgressCallback& progress)
{
  // The per-cell loops run in chunks reporting progress (loops 40 %, vertex
  // sort 10 %, vertices 20 %, triangles 30 %), so that an abort stops them
  // within a chunk.
  constexpr std::size_t Chunk = 8192;
  ExtractionResult result;
  const RootGrid& grid = tree.Grid;
  const auto& prims = scene.Primitives;

  std::vector<std::uint32_t> cells;
  for (std::size_t n = 0; n < tree.Nodes.size(); ++n)
  {
    const OctreeNode& node = tree.Nodes[n];
    if (node.IsLeaf() && (node.State == CellState::Surface || node.State == CellState::Unresolved))
    {
      cells.push_back(static_cast<std::uint32_t>(n));
    }
  }

  // 1. Loops of every cell.
  std::vector<BoundaryLoopSet> loops(cells.size());
  if (!ChunkedFor(cells.size(), Chunk, parallelFor, [&](std::size_t begin, std::size_t end) {
    for (std::size_t i = begin; i < end; ++i)
    {
      CellBoundary boundary = CellBoundaryBuilder(tree, cells[i]).Build();
      loops[i] = TraceBoundaryLoops(boundary);
    }
  }, ProgressRange(progress, 0.0, 0.4)))
  {
    result.Aborted = true;
    return result;
  }

  // 2. One vertex per distinct crossing. The crossings are bucketed by a
  // hash of their edge key (in parallel, by blocks of cells), each bucket is
  // sorted and deduplicated on its own; a vertex's id is its bucket's offset
  // plus its rank there. (One global sort of tens of millions of records
  // takes seconds without an abort check.)
  struct Record
  {
    Crossing Vertex;
    std::uint32_t CellIndex;
  };
  constexpr std::size_t Blocks = 64, Buckets = 256;
  auto bucketOf = [](const Crossing& c) { return static_cast<std::size_t>((c.Key * 0x9E3779B97F4A7C15ULL) >> 56); };
  std::vector<std::vector<Record>> parts(Blocks * Buckets);
  parallelFor(Blocks, [&](std::size_t begin, std::size_t end) {
    for (std::size_t b = begin; b < end; ++b)
    {
      for (std::size_t i = cells.size() * b / Blocks; i < cells.size() * (b + 1) / Blocks; ++i)
      {
        for (const Crossing& c : loops[i].Crossings)
        {
          parts[b * Buckets + bucketOf(c)].push_back({ c, static_cast<std::uint32_t>(i) });
        }
      }
    }
  });
  // In a piece of a split run, ghost cells take part in choosing each shared
  // vertex's cell (as in the whole run) but give no triangles.
  std::vector<std::uint8_t> own(cells.size());
  for (std::size_t i = 0; i < cells.size(); ++i)
  {
    own[i] = tree.RoleOf(tree.Nodes[cells[i]]) == TreeRole::Own;
    result.InconsistentCells += loops[i].Consistent || !own[i] ? 0 : 1;
  }
  std::vector<std::vector<Record>> buckets(Buckets);
  if (!ChunkedFor(Buckets, 16, parallelFor, [&](std::size_t begin, std::size_t end) {
    for (std::size_t k = begin; k < end; ++k)
    {
      auto& bucket = buckets[k];
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
  }, ProgressRange(progress, 0.4, 0.5)))
  {
    result.Aborted = true;
    return result;
  }
  std::vector<std::size_t> bucketStart(Buckets + 1, 0);
  for (std::size_t k = 0; k < Buckets; ++k)
  {
    bucketStart[k + 1] = bucketStart[k] + buckets[k].size();
  }
  std::vector<Record> records(bucketStart[Buckets]);
  parallelFor(Buckets, [&](std::size_t begin, std::size_t end) {
    for (std::size_t k = begin; k < end; ++k)
    {
      std::copy(buckets[k].begin(), buckets[k].end(), records.begin() + static_cast<std::ptrdiff_t>(bucketStart[k]));
      std::vector<Record>().swap(buckets[k]);
    }
  });
  auto vertexOf = [&](const Crossing& c) {
    const std::size_t k = bucketOf(c);
    const auto first = records.begin() + static_cast<std::ptrdiff_t>(bucketStart[k]);
    const auto last = records.begin() + static_cast<std::ptrdiff_t>(bucketStart[k + 1]);
    auto it = std::lower_bound(first, last, c, [](const Record& r, const Crossing& key) { return r.Vertex < key; });
    return static_cast<std::uint32_t>(it - records.begin());
  };

  TriangleMesh& mesh = result.Mesh;
  mesh.Points.resize(records.size());
  mesh.Normals.resize(records.size());
  const bool placed = ChunkedFor(records.size(), 4 * Chunk, parallelFor, [&](std::size_t begin, std::size_t end) {
    for (std::size_t i = begin; i < end; ++i)
    {
      const Crossing& c = records[i].Vertex;
      if (c.Tile != 0)
      {
        continue; // bend vertices are placed from their crossings below
      }
      const int axis = static_cast<int>(c.Key & 3);
      std::uint32_t lo[3], hi[3];
      SplitPointKey(c.Key >> 2, lo);
      std::copy(lo, lo + 3, hi);
      hi[axis] = c.Upper;
      const CsgExpression& e = *tree.Expressions[cells[records[i].CellIndex]];
      const Vec3 p = FindEdgeCrossing(e, prims, grid.Point(lo), grid.Point(hi), c.LowerInside);
      mesh.Points[i] = p;
      mesh.Normals[i] = Normalized(e.Gradient(p, prims));
    }
  }, ProgressRange(progress, 0.5, 0.7));
  if (!placed)
  {
    result.Aborted = true;
    return result;
  }
  for (std::size_t i = 0; i < records.size(); ++i)
  {
    const Crossing& c = records[i].Vertex;
    if (c.Tile == 0)
    {
      continue;
    }
    // Between the run's two crossings, nudged off their line into its tile so
    // that bends of different tiles around the line do not coincide.
    Crossing first, last;
    first.Key = c.Key;
    last.Key = c.Partner;
    const Vec3 a = mesh.Points[vertexOf(first)], b = mesh.Points[vertexOf(last)];
    std::uint32_t corner[3], on[3];
    SplitPointKey((c.Tile - 1) >> 2, corner);
    SplitPointKey(c.Key >> 2, on);
    const int plane = static_cast<int>((c.Tile - 1) & 3), along = static_cast<int>(c.Key & 3);
    const int across = 3 - plane - along;
    Vec3 p = (a + b) * 0.5;
    p[across] += (on[across] == corner[across] ? 1e-3 : -1e-3) * Norm(b - a);
    mesh.Points[i] = p;
    mesh.Normals[i] = Normalized(mesh.Normals[vertexOf(first)] + mesh.Normals[vertexOf(last)]);
  }

  // 3. Triangulate each loop: a single triangle, or a fan around a vertex on
  // the surface inside the cell.
  struct CellTriangles
  {
    std::vector<Vec3> Centers;
    std::vector<std::array<std::uint32_t, 3>> Triangles; // center ids >= 2^31 are local
  };
  constexpr std::uint32_t LocalFlag = 1u << 31;
  std::vector<CellTriangles> local(cells.size());
  const bool triangulated = ChunkedFor(cells.size(), Chunk, parallelFor, [&](std::size_t begin, std::size_t end) {
    std::vector<std::uint32_t> ids;
    std::vector<Vec3> pts, normals;
    std::vector<unsigned> faces;
    for (std::size_t i = begin; i < end; ++i)
    {
      if (!own[i])
      {
        continue;
      }
      const OctreeNode& node = tree.Nodes[cells[i]];
      const Box3 box = grid.CellBox(node.Level, node.Ijk);
      const int shift = grid.MaxDepth - node.Level;
      std::uint32_t base[3];
      CornerLattice(grid, node, 0, base);
      std::size_t offset = 0;
      for (const std::uint32_t size : loops[i].LoopSizes)
      {
        ids.clear();
        pts.clear();
        normals.clear();
        faces.clear();
        for (std::uint32_t k = 0; k < size; ++k)
        {
          const Crossing& c = loops[i].Crossings[offset + k];
          const std::uint32_t id = vertexOf(c);
          ids.push_back(id);
          pts.push_back(mesh.Points[id]);
          normals.push_back(mesh.Normals[id]);
          faces.push_back(FacesOf(c, base, 1u << shift));
        }
        offset += size;
        if (size < 3)
        {
          continue; // only from inconsistent input; counted above
        }
        if (size == 3 && !LiesOnOneFace(pts, box))
        {
          local[i].Triangles.push_back({ ids[0], ids[1], ids[2] });
          continue;
        }
        const int apex = size > 3 ? LoopFanApex(pts, normals, faces) : -1;
        if (apex >= 0)
        {
          for (std::uint32_t k = 1; k + 1 < size; ++k)
          {
            local[i].Triangles.push_back({ ids[static_cast<std::size_t>(apex)],
              ids[(static_cast<std::size_t>(apex) + k) % size], ids[(static_cast<std::size_t>(apex) + k + 1) % size] });
          }
          continue;
        }
        const std::uint32_t center = LocalFlag | static_cast<std::uint32_t>(local[i].Centers.size());
        local[i].Centers.push_back(
          PlaceLoopVertex(pts, normals, box, *tree.Expressions[cells[i]], prims));
        for (std::uint32_t k = 0; k < size; ++k)
        {
          local[i].Triangles.push_back({ ids[k], ids[(k + 1) % size], center });
        }
      }
    }
  }, ProgressRange(progress, 0.7, 1.0));
  if (!triangulated)
  {
    result.Aborted = true;
    return result;
  }

  for (std::size_t i = 0; i < cells.size(); ++i)
  {
    const std::uint32_t base = static_cast<std::uint32_t>(mesh.Points.size());
    for (const Vec3& c : local[i].Centers)
    {
      mesh.Points.push_back(c);
      mesh.Normals.push_back(Vec3());
    }
    for (auto t : local[i].Triangles)
    {
      for (auto& v : t)
      {
        if (v & LocalFlag)
        {
          v = base + (v & ~LocalFlag);
        }
      }
      mesh.Triangles.push_back(t);
      mesh.TriangleCell.push_back(cells[i]);
    }
  }
  // Normals of loop vertices: area-weighted average of their fan.
  const std::size_t crossings = records.size();
  for (const auto& t : mesh.Triangles)
  {
    const Vec3 n = Cross(mesh.Points[t[1]] - mesh.Points[t[0]], mesh.Points[t[2]] - mesh.Points[t[0]]);
    for (const auto v : t)
    {
      if (v >= crossings)
      {
        mesh.Normals[v] += n;
      }
    }
  }
  for (std::size_t v = crossings; v < mesh.Normals.size(); ++v)
  {
    mesh.Normals[v] = Normalized(mesh.Normals[v]);
  }
  if (!tree.Roles.empty())
  {
    // Only the vertices of own cells' triangles.
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
  return result;
}

} // namespace tpc
