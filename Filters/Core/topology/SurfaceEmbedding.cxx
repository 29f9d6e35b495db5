#include "SurfaceEmbedding.h"

#include "EmbeddedStars.h"
#include "SelfIntersection.h"

#include <algorithm>
#include <map>
#include <numeric>

namespace tpc
{
namespace
{
/// The consecutive triangles of each cell that has some (TriangleCell is in
/// node order).
struct CellTriangles
{
  std::vector<std::uint32_t> Cell;  ///< node of each run
  std::vector<std::uint32_t> First; ///< its first triangle; First[k + 1] ends it

  explicit CellTriangles(const TriangleMesh& mesh)
  {
    for (std::size_t t = 0; t < mesh.TriangleCell.size(); ++t)
    {
      if (t == 0 || mesh.TriangleCell[t] != mesh.TriangleCell[t - 1])
      {
        this->Cell.push_back(mesh.TriangleCell[t]);
        this->First.push_back(static_cast<std::uint32_t>(t));
      }
    }
    this->First.push_back(static_cast<std::uint32_t>(mesh.TriangleCell.size()));
  }
  /// Run of node `n`, or -1 when it has no triangles.
  std::int64_t RunOf(std::uint32_t n) const
  {
    const auto it = std::lower_bound(this->Cell.begin(), this->Cell.end(), n);
    return it != this->Cell.end() && *it == n ? it - this->Cell.begin() : -1;
  }
};

/// Leaves below node `m` touching the side of it given by `d` (per axis: -1
/// its high side, +1 its low side, 0 either).
void LeavesOnSide(const AdaptiveOctree& tree, std::size_t m, const int d[3], std::vector<std::uint32_t>& out)
{
  const OctreeNode& q = tree.Nodes[m];
  if (q.IsLeaf())
  {
    out.push_back(static_cast<std::uint32_t>(m));
    return;
  }
  for (int c = 0; c < 8; ++c)
  {
    bool touching = true;
    for (int a = 0; a < 3; ++a)
    {
      touching = touching && (d[a] == 0 || ((c >> a) & 1) == (d[a] > 0 ? 0 : 1));
    }
    if (touching)
    {
      LeavesOnSide(tree, static_cast<std::size_t>(q.FirstChild + c), d, out);
    }
  }
}

/// Every leaf other than n whose closed box touches leaf n's: the leaf (of
/// any level) holding each of the 26 neighbouring positions at n's level, or
/// the leaves of a refined neighbour on the side facing n.
std::vector<std::uint32_t> TouchingLeaves(const AdaptiveOctree& tree, std::uint32_t n)
{
  const OctreeNode& node = tree.Nodes[n];
  std::vector<std::uint32_t> out;
  for (int dz = -1; dz <= 1; ++dz)
  {
    for (int dy = -1; dy <= 1; ++dy)
    {
      for (int dx = -1; dx <= 1; ++dx)
      {
        const int d[3] = { dx, dy, dz };
        if (dx == 0 && dy == 0 && dz == 0)
        {
          continue;
        }
        std::int64_t ijk[3];
        for (int a = 0; a < 3; ++a)
        {
          ijk[a] = static_cast<std::int64_t>(node.Ijk[a]) + d[a];
        }
        const std::int64_t m = tree.Find(node.Level, ijk);
        if (m >= 0)
        {
          LeavesOnSide(tree, static_cast<std::size_t>(m), d, out);
        }
      }
    }
  }
  std::sort(out.begin(), out.end());
  out.erase(std::unique(out.begin(), out.end()), out.end());
  return out;
}

/// Failures found around one run of triangles.
struct RunFailures
{
  std::size_t ImproperPairs = 0, Degenerate = 0, Outside = 0, Tested = 0;
  std::vector<std::uint32_t> Cells;
};

/// The run's own triangles (each in its cell, not degenerate), their pairs,
/// and their pairs with the runs of touching leaves after it in node order
/// (each pair of runs is met from both sides; the first one tests it).
RunFailures CheckRun(const AdaptiveOctree& tree, const TriangleMesh& mesh, const EmbeddedStars& stars,
  const CellTriangles& runs, std::size_t k)
{
  RunFailures f;
  const std::uint32_t cell = runs.Cell[k];
  const OctreeNode& node = tree.Nodes[cell];
  const Box3 cellBox = tree.Grid.CellBox(node.Level, node.Ijk);
  for (std::uint32_t t = runs.First[k]; t < runs.First[k + 1]; ++t)
  {
    const auto& tri = mesh.Triangles[t];
    const Vec3 &a = mesh.Points[tri[0]], &b = mesh.Points[tri[1]], &c = mesh.Points[tri[2]];
    f.Outside += cellBox.Contains(a) && cellBox.Contains(b) && cellBox.Contains(c) ? 0 : 1;
    f.Degenerate += TriangleIsDegenerate(a, b, c) ? 1 : 0;
  }
  // (Boxes computed here rather than stored for the whole mesh: the check
  // adds no memory per cell to the run's budget beyond the stars' - a byte
  // per vertex, and while they are proven 16 bytes per triangle.)
  std::vector<Box3> own, other;
  for (std::uint32_t t = runs.First[k]; t < runs.First[k + 1]; ++t)
  {
    own.push_back(TriangleBox(mesh.Points.data(), mesh.Triangles[t]));
  }
  auto testPairs = [&](std::uint32_t begin, std::uint32_t end, std::uint32_t otherBegin, std::uint32_t otherEnd,
                     std::uint32_t otherCell, bool same) {
    other.clear();
    for (std::uint32_t t = otherBegin; t < otherEnd; ++t)
    {
      other.push_back(same ? own[t - begin] : TriangleBox(mesh.Points.data(), mesh.Triangles[t]));
    }
    bool failed = false;
    for (std::uint32_t t1 = begin; t1 < end; ++t1)
    {
      for (std::uint32_t t2 = same ? t1 + 1 : otherBegin; t2 < otherEnd; ++t2)
      {
        if (!own[t1 - begin].Overlaps(other[t2 - otherBegin]))
        {
          continue;
        }
        if (stars.ProveProper(mesh.Triangles[t1], mesh.Triangles[t2]))
        {
          continue;
        }
        ++f.Tested;
        if (TrianglesMeetImproperly(mesh.Points.data(), mesh.Triangles[t1], mesh.Triangles[t2]))
        {
          ++f.ImproperPairs;
          failed = true;
        }
      }
    }
    if (failed)
    {
      f.Cells.push_back(cell);
      f.Cells.push_back(otherCell);
    }
  };
  testPairs(runs.First[k], runs.First[k + 1], runs.First[k], runs.First[k + 1], cell, true);
  for (const std::uint32_t other : TouchingLeaves(tree, cell))
  {
    const std::int64_t j = other > cell ? runs.RunOf(other) : -1;
    if (j >= 0)
    {
      testPairs(runs.First[k], runs.First[k + 1], runs.First[j], runs.First[j + 1], other, false);
    }
  }
  if (f.Outside + f.Degenerate > 0)
  {
    f.Cells.push_back(cell);
  }
  return f;
}

/// Vertices with the coordinates of another (exact comparison), and the
/// cells of their triangles.
std::size_t CountCoincidentVertices(const TriangleMesh& mesh, std::vector<std::uint32_t>& cells,
  const ParallelFor& parallelFor, const ProgressCallback& progress, bool& aborted)
{
  std::vector<std::uint32_t> order(mesh.Points.size());
  std::iota(order.begin(), order.end(), 0u);
  auto less = [&](std::uint32_t a, std::uint32_t b) {
    const Vec3 &p = mesh.Points[a], &q = mesh.Points[b];
    return p[0] != q[0] ? p[0] < q[0] : p[1] != q[1] ? p[1] < q[1] : p[2] < q[2];
  };
  if (!ParallelSort(order, less, parallelFor, progress))
  {
    aborted = true;
    return 0;
  }
  std::vector<std::uint8_t> coincident(mesh.Points.size(), 0);
  std::size_t count = 0;
  for (std::size_t i = 1; i < order.size(); ++i)
  {
    if (!less(order[i - 1], order[i]))
    {
      ++count;
      coincident[order[i]] = coincident[order[i - 1]] = 1;
    }
  }
  for (std::size_t t = 0; count > 0 && t < mesh.Triangles.size(); ++t)
  {
    for (const auto v : mesh.Triangles[t])
    {
      if (coincident[v])
      {
        cells.push_back(mesh.TriangleCell[t]);
      }
    }
  }
  return count;
}
} // namespace

EmbeddingReport CheckEmbedding(const AdaptiveOctree& tree, const TriangleMesh& mesh,
  const ParallelFor& parallelFor, const ProgressCallback& progress)
{
  EmbeddingReport report;
  const CellTriangles runs(mesh);
  // (Pairs of triangles around a vertex whose star is proven embedded need
  // no test of their own: EmbeddedStars.h.)
  const EmbeddedStars stars(mesh.Points.data(), mesh.Points.size(), mesh.Triangles.data(), mesh.Triangles.size(),
    parallelFor);
  constexpr std::size_t Chunk = 4096;
  const std::size_t count = runs.Cell.size();
  std::vector<RunFailures> failures(std::min(count, Chunk)); // one chunk's
  const bool done = ForEachChunk(count, Chunk, parallelFor, [&](std::size_t begin, std::size_t end) {
    for (std::size_t k = begin; k < end; ++k)
    {
      failures[k % Chunk] = CheckRun(tree, mesh, stars, runs, k);
    }
  }, [&](std::size_t first, std::size_t last) {
    for (std::size_t k = first; k < last; ++k)
    {
      const RunFailures& f = failures[k % Chunk];
      report.ImproperPairs += f.ImproperPairs;
      report.DegenerateTriangles += f.Degenerate;
      report.TrianglesOutsideCells += f.Outside;
      report.PairsTested += f.Tested;
      report.Cells.insert(report.Cells.end(), f.Cells.begin(), f.Cells.end());
      std::vector<std::uint32_t>().swap(failures[k % Chunk].Cells);
    }
    return progress && progress(0.8 * static_cast<double>(last) / static_cast<double>(count));
  });
  if (!done)
  {
    report.Aborted = true;
    return report;
  }
  report.CoincidentVertices =
    CountCoincidentVertices(mesh, report.Cells, parallelFor, ProgressRange(progress, 0.8, 1.0), report.Aborted);
  std::sort(report.Cells.begin(), report.Cells.end());
  report.Cells.erase(std::unique(report.Cells.begin(), report.Cells.end()), report.Cells.end());
  return report;
}

namespace
{
/// A cell of an own tree touching a tree that is not the piece's own (or
/// the grid's outside, where no piece has triangles).
bool TouchesForeignTree(const AdaptiveOctree& tree, const OctreeNode& node)
{
  for (int d = 0; d < 27; ++d)
  {
    std::int64_t ijk[3];
    bool inside = true;
    for (int a = 0, code = d; a < 3; ++a, code /= 3)
    {
      ijk[a] = static_cast<std::int64_t>(node.Ijk[a]) + code % 3 - 1;
      inside = inside && ijk[a] >= 0 && (ijk[a] >> node.Level) < tree.Grid.Dims[a];
    }
    if (inside)
    {
      const int t = tree.Grid.TreeIndex(static_cast<int>(ijk[0] >> node.Level),
        static_cast<int>(ijk[1] >> node.Level), static_cast<int>(ijk[2] >> node.Level));
      if (tree.Roles[static_cast<std::size_t>(t)] != TreeRole::Own)
      {
        return true;
      }
    }
  }
  return false;
}
} // namespace

std::vector<double> SeamTriangles(const AdaptiveOctree& tree, const TriangleMesh& mesh)
{
  std::vector<double> out;
  if (tree.Roles.empty())
  {
    return out;
  }
  const CellTriangles runs(mesh);
  for (std::size_t k = 0; k < runs.Cell.size(); ++k)
  {
    if (!TouchesForeignTree(tree, tree.Nodes[runs.Cell[k]]))
    {
      continue;
    }
    for (std::uint32_t t = runs.First[k]; t < runs.First[k + 1]; ++t)
    {
      for (const auto v : mesh.Triangles[t])
      {
        out.insert(out.end(), mesh.Points[v].x, mesh.Points[v].x + 3);
      }
    }
  }
  return out;
}

std::size_t CountImproperSeamPairs(const std::vector<double>& a, const std::vector<double>& b)
{
  // One vertex per distinct coordinate triple of both sets.
  std::map<std::array<double, 3>, std::uint32_t> ids;
  std::vector<Vec3> points;
  auto triangles = [&](const std::vector<double>& coordinates) {
    std::vector<std::array<std::uint32_t, 3>> out(coordinates.size() / 9);
    for (std::size_t i = 0; i < coordinates.size() / 3; ++i)
    {
      const std::array<double, 3> p = { coordinates[3 * i], coordinates[3 * i + 1], coordinates[3 * i + 2] };
      const auto it = ids.emplace(p, static_cast<std::uint32_t>(points.size())).first;
      if (it->second == points.size())
      {
        points.emplace_back(p[0], p[1], p[2]);
      }
      out[i / 3][i % 3] = it->second;
    }
    return out;
  };
  const auto ta = triangles(a), tb = triangles(b);
  // The seam is a curve's neighbourhood: few triangles, a sort by x suffices.
  std::vector<Box3> boxB(tb.size());
  std::vector<std::uint32_t> order(tb.size());
  for (std::size_t j = 0; j < tb.size(); ++j)
  {
    boxB[j] = TriangleBox(points.data(), tb[j]);
    order[j] = static_cast<std::uint32_t>(j);
  }
  std::sort(order.begin(), order.end(), [&](std::uint32_t x, std::uint32_t y) { return boxB[x].lo[0] < boxB[y].lo[0]; });
  double widest = 0.0;
  for (const Box3& box : boxB)
  {
    widest = std::max(widest, box.Width(0));
  }
  std::size_t improper = 0;
  for (const auto& t1 : ta)
  {
    const Box3 box1 = TriangleBox(points.data(), t1);
    auto it = std::lower_bound(order.begin(), order.end(), box1.lo[0] - widest,
      [&](std::uint32_t j, double x) { return boxB[j].lo[0] < x; });
    for (; it != order.end() && boxB[*it].lo[0] <= box1.hi[0]; ++it)
    {
      improper += box1.Overlaps(boxB[*it]) && TrianglesMeetImproperly(points.data(), t1, tb[*it]) ? 1 : 0;
    }
  }
  return improper;
}

} // namespace tpc
