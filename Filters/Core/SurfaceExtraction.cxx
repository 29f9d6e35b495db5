#include "SurfaceExtraction.h"

#include "EdgeCrossings.h"
#include "SymmetricEigen.h"

#include <algorithm>
#include <cmath>

namespace tpc
{
namespace
{
/// A crossing is identified by the finest lattice sub-edge containing it:
/// its lower endpoint and axis. `Upper` is the other endpoint's coordinate on
/// that axis.
using EdgeKey = std::uint64_t;

struct Crossing
{
  EdgeKey Key = 0;
  std::uint32_t Upper = 0;
  bool LowerInside = false;
};

struct CellLoops
{
  std::vector<Crossing> Crossings; // loops, concatenated, in order
  std::vector<std::uint32_t> LoopSizes;
  bool Consistent = true;
};

struct FacePoint
{
  std::uint32_t U, V;
  bool Inside;
};

/// Walks the boundary of one leaf cell and returns its surface loops.
class CellBoundaryWalker
{
public:
  CellBoundaryWalker(const AdaptiveOctree& tree, std::size_t cell)
    : Tree(tree)
    , Cell(cell)
    , Node(tree.Nodes[cell])
  {
    this->Depth = tree.Grid.MaxDepth;
    this->Shift = this->Depth - this->Node.Level;
    this->Size = 1u << this->Shift;
    for (int a = 0; a < 3; ++a)
    {
      this->Base[a] = this->Node.Ijk[a] << this->Shift;
    }
  }

  CellLoops Run()
  {
    this->CollectPoints();
    std::vector<std::pair<Crossing, Crossing>> segments;
    for (int f = 0; f < 6; ++f)
    {
      this->FaceSegments(f, segments);
    }
    return AssembleLoops(segments);
  }

private:
  void AddLeafCorner(std::size_t leaf, int corner)
  {
    std::uint32_t p[3];
    CornerLattice(this->Tree.Grid, this->Tree.Nodes[leaf], corner, p);
    const PointKey key = MakePointKey(p[0], p[1], p[2]);
    this->Points.emplace_back(key, this->Tree.PointInside(leaf, key));
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

  /// The neighbour of this cell displaced by `offset` at the same level, if it
  /// exists there and is refined (only then does it bring finer points).
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

  void CollectPoints()
  {
    for (int c = 0; c < 8; ++c)
    {
      this->AddLeafCorner(this->Cell, c);
    }
    // Tiles of each face: the face itself, or the leaves of the refined
    // neighbour that touch it.
    for (int f = 0; f < 6; ++f)
    {
      const int axis = f / 2, side = f % 2;
      int offset[3] = { 0, 0, 0 };
      offset[axis] = side ? 1 : -1;
      this->Tiles[f].clear();
      const std::int64_t n = this->RefinedNeighbor(offset);
      if (n < 0)
      {
        this->Tiles[f].push_back(this->Cell);
        continue;
      }
      this->CollectAdjacentLeaves(static_cast<std::size_t>(n), axis, side ? 0 : 1, -1, 0, this->Tiles[f]);
      for (const std::size_t leaf : this->Tiles[f])
      {
        for (int c = 0; c < 8; ++c)
        {
          if (((c >> axis) & 1) == (side ? 0 : 1))
          {
            this->AddLeafCorner(leaf, c);
          }
        }
      }
    }
    // Edges: leaves of the refined diagonal neighbour that touch the edge line.
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
          this->AddLeafCorner(leaf, ((du ? 0 : 1) << u) | ((dv ? 0 : 1) << v) | (end << axis));
        }
      }
    }
    std::sort(this->Points.begin(), this->Points.end());
    this->Points.erase(std::unique(this->Points.begin(), this->Points.end(),
                         [](const auto& a, const auto& b) { return a.first == b.first; }),
      this->Points.end());
  }

  void FaceSegments(int f, std::vector<std::pair<Crossing, Crossing>>& segments) const
  {
    const int axis = f / 2, side = f % 2;
    const int U = (axis + 1) % 3, V = (axis + 2) % 3;
    const std::uint32_t plane = this->Base[axis] + (side ? this->Size : 0);
    std::vector<FacePoint> byV, byU;
    for (const auto& pk : this->Points)
    {
      std::uint32_t p[3];
      SplitPointKey(pk.first, p);
      if (p[axis] == plane)
      {
        byV.push_back({ p[U], p[V], pk.second });
      }
    }
    byU = byV;
    std::sort(byV.begin(), byV.end(),
      [](const FacePoint& a, const FacePoint& b) { return a.V != b.V ? a.V < b.V : a.U < b.U; });
    std::sort(byU.begin(), byU.end(),
      [](const FacePoint& a, const FacePoint& b) { return a.U != b.U ? a.U < b.U : a.V < b.V; });

    std::vector<FacePoint> polygon;
    for (const std::size_t leaf : this->Tiles[f])
    {
      const OctreeNode& t = this->Tree.Nodes[leaf];
      const int tshift = this->Depth - t.Level;
      const std::uint32_t u0 = t.Ijk[U] << tshift, v0 = t.Ijk[V] << tshift;
      const std::uint32_t u1 = u0 + (1u << tshift), v1 = v0 + (1u << tshift);
      polygon.clear();
      // Counter-clockwise in (U, V): bottom, right, top, left; each side's
      // first point included, last excluded.
      auto rowRange = [&](std::uint32_t v, std::uint32_t ua, std::uint32_t ub) {
        auto lo = std::lower_bound(byV.begin(), byV.end(), FacePoint{ ua, v, false },
          [](const FacePoint& a, const FacePoint& b) { return a.V != b.V ? a.V < b.V : a.U < b.U; });
        auto hi = std::lower_bound(lo, byV.end(), FacePoint{ ub, v, false },
          [](const FacePoint& a, const FacePoint& b) { return a.V != b.V ? a.V < b.V : a.U < b.U; });
        return std::make_pair(lo, hi);
      };
      auto colRange = [&](std::uint32_t u, std::uint32_t va, std::uint32_t vb) {
        auto lo = std::lower_bound(byU.begin(), byU.end(), FacePoint{ u, va, false },
          [](const FacePoint& a, const FacePoint& b) { return a.U != b.U ? a.U < b.U : a.V < b.V; });
        auto hi = std::lower_bound(lo, byU.end(), FacePoint{ u, vb, false },
          [](const FacePoint& a, const FacePoint& b) { return a.U != b.U ? a.U < b.U : a.V < b.V; });
        return std::make_pair(lo, hi);
      };
      {
        auto r = rowRange(v0, u0, u1); // [u0, u1)
        polygon.insert(polygon.end(), r.first, r.second);
      }
      {
        auto r = colRange(u1, v0, v1); // [v0, v1)
        polygon.insert(polygon.end(), r.first, r.second);
      }
      {
        auto r = rowRange(v1, u0 + 1, u1 + 1); // (u0, u1], descending
        polygon.insert(polygon.end(), std::make_reverse_iterator(r.second), std::make_reverse_iterator(r.first));
      }
      {
        auto r = colRange(u0, v0 + 1, v1 + 1); // (v0, v1], descending
        polygon.insert(polygon.end(), std::make_reverse_iterator(r.second), std::make_reverse_iterator(r.first));
      }
      if (side == 0)
      {
        // Seen from outside the cell the low face is traversed the other way.
        std::reverse(polygon.begin(), polygon.end());
      }
      this->TileSegments(polygon, axis, plane, segments);
    }
  }

  /// One segment per run of inside points along the tile boundary, from the
  /// crossing entering the run to the crossing leaving it.
  static void TileSegments(const std::vector<FacePoint>& poly, int axis, std::uint32_t plane,
    std::vector<std::pair<Crossing, Crossing>>& segments)
  {
    const std::size_t m = poly.size();
    const int U = (axis + 1) % 3, V = (axis + 2) % 3;
    auto crossing = [&](std::size_t i) {
      const FacePoint& p = poly[i];
      const FacePoint& q = poly[(i + 1) % m];
      const int along = p.V == q.V ? U : V;
      const FacePoint& lower = (along == U ? p.U < q.U : p.V < q.V) ? p : q;
      const FacePoint& upper = &lower == &p ? q : p;
      std::uint32_t x[3];
      x[axis] = plane;
      x[U] = lower.U;
      x[V] = lower.V;
      Crossing c;
      c.Key = (MakePointKey(x[0], x[1], x[2]) << 2) | static_cast<EdgeKey>(along);
      c.Upper = along == U ? upper.U : upper.V;
      c.LowerInside = lower.Inside;
      return c;
    };
    for (std::size_t k = 0; k < m; ++k)
    {
      if (poly[k].Inside || !poly[(k + 1) % m].Inside)
      {
        continue;
      }
      std::size_t j = (k + 1) % m;
      while (poly[(j + 1) % m].Inside)
      {
        j = (j + 1) % m;
      }
      segments.emplace_back(crossing(k), crossing(j));
    }
  }

  static CellLoops AssembleLoops(std::vector<std::pair<Crossing, Crossing>>& segments)
  {
    CellLoops loops;
    std::sort(segments.begin(), segments.end(),
      [](const auto& a, const auto& b) { return a.first.Key < b.first.Key; });
    std::vector<bool> used(segments.size(), false);
    auto find = [&](EdgeKey k) -> std::size_t {
      auto it = std::lower_bound(segments.begin(), segments.end(), k,
        [](const auto& s, EdgeKey key) { return s.first.Key < key; });
      if (it == segments.end() || it->first.Key != k)
      {
        return segments.size();
      }
      return static_cast<std::size_t>(it - segments.begin());
    };
    for (std::size_t s = 0; s < segments.size(); ++s)
    {
      if (s > 0 && segments[s].first.Key == segments[s - 1].first.Key)
      {
        loops.Consistent = false; // a crossing starting two segments
      }
    }
    for (std::size_t s0 = 0; s0 < segments.size(); ++s0)
    {
      if (used[s0])
      {
        continue;
      }
      std::uint32_t size = 0;
      std::size_t s = s0;
      while (!used[s])
      {
        used[s] = true;
        loops.Crossings.push_back(segments[s].first);
        ++size;
        s = find(segments[s].second.Key);
        if (s == segments.size())
        {
          loops.Consistent = false;
          break;
        }
      }
      if (s != s0)
      {
        loops.Consistent = false;
      }
      loops.LoopSizes.push_back(size);
    }
    return loops;
  }

  const AdaptiveOctree& Tree;
  std::size_t Cell;
  const OctreeNode& Node;
  int Depth = 0, Shift = 0;
  std::uint32_t Size = 1;
  std::uint32_t Base[3] = { 0, 0, 0 };
  std::vector<std::pair<PointKey, bool>> Points;
  std::vector<std::size_t> Tiles[6];
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
  const Box3& cell, const CsgExpression& expression, const std::vector<Quadric>& prims)
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
} // namespace

ExtractionResult ExtractSurface(
  const AdaptiveOctree& tree, const ImplicitScene& scene, const ParallelFor& parallelFor)
{
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
  std::vector<CellLoops> loops(cells.size());
  parallelFor(cells.size(), [&](std::size_t begin, std::size_t end) {
    for (std::size_t i = begin; i < end; ++i)
    {
      loops[i] = CellBoundaryWalker(tree, cells[i]).Run();
    }
  });

  // 2. One vertex per distinct crossing.
  struct Record
  {
    EdgeKey Key;
    std::uint32_t CellIndex;
    std::uint32_t Upper;
    bool LowerInside;
  };
  std::vector<Record> records;
  for (std::size_t i = 0; i < cells.size(); ++i)
  {
    result.InconsistentCells += loops[i].Consistent ? 0 : 1;
    for (const Crossing& c : loops[i].Crossings)
    {
      records.push_back({ c.Key, static_cast<std::uint32_t>(i), c.Upper, c.LowerInside });
    }
  }
  std::sort(records.begin(), records.end(), [](const Record& a, const Record& b) {
    return a.Key != b.Key ? a.Key < b.Key : a.CellIndex < b.CellIndex;
  });
  records.erase(std::unique(records.begin(), records.end(),
                  [](const Record& a, const Record& b) { return a.Key == b.Key; }),
    records.end());

  TriangleMesh& mesh = result.Mesh;
  mesh.Points.resize(records.size());
  mesh.Normals.resize(records.size());
  parallelFor(records.size(), [&](std::size_t begin, std::size_t end) {
    for (std::size_t i = begin; i < end; ++i)
    {
      const Record& r = records[i];
      const int axis = static_cast<int>(r.Key & 3);
      std::uint32_t lo[3], hi[3];
      SplitPointKey(r.Key >> 2, lo);
      std::copy(lo, lo + 3, hi);
      hi[axis] = r.Upper;
      const CsgExpression& e = *tree.Expressions[cells[r.CellIndex]];
      const Vec3 p = FindEdgeCrossing(e, prims, grid.Point(lo), grid.Point(hi), r.LowerInside);
      mesh.Points[i] = p;
      mesh.Normals[i] = Normalized(e.Gradient(p, prims));
    }
  });
  auto vertexOf = [&](EdgeKey k) {
    auto it = std::lower_bound(records.begin(), records.end(), k,
      [](const Record& r, EdgeKey key) { return r.Key < key; });
    return static_cast<std::uint32_t>(it - records.begin());
  };

  // 3. Triangulate each loop: a single triangle, or a fan around a vertex on
  // the surface inside the cell.
  struct CellTriangles
  {
    std::vector<Vec3> Centers;
    std::vector<std::array<std::uint32_t, 3>> Triangles; // center ids >= 2^31 are local
  };
  constexpr std::uint32_t LocalFlag = 1u << 31;
  std::vector<CellTriangles> local(cells.size());
  parallelFor(cells.size(), [&](std::size_t begin, std::size_t end) {
    std::vector<std::uint32_t> ids;
    std::vector<Vec3> pts, normals;
    for (std::size_t i = begin; i < end; ++i)
    {
      const OctreeNode& node = tree.Nodes[cells[i]];
      const Box3 box = grid.CellBox(node.Level, node.Ijk);
      std::size_t offset = 0;
      for (const std::uint32_t size : loops[i].LoopSizes)
      {
        ids.clear();
        pts.clear();
        normals.clear();
        for (std::uint32_t k = 0; k < size; ++k)
        {
          const std::uint32_t id = vertexOf(loops[i].Crossings[offset + k].Key);
          ids.push_back(id);
          pts.push_back(mesh.Points[id]);
          normals.push_back(mesh.Normals[id]);
        }
        offset += size;
        if (size < 3)
        {
          continue; // only from inconsistent input; counted above
        }
        if (size == 3)
        {
          local[i].Triangles.push_back({ ids[0], ids[1], ids[2] });
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
  });

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
  return result;
}

} // namespace tpc
