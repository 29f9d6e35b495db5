#include "SurfaceExtraction.h"

#include "CellPatches.h"
#include "CertifiedError.h"
#include "CrackPatching.h"
#include "CrossingVertices.h"

#include <algorithm>
#include <cmath>
#include <optional>

namespace tpc
{
namespace
{
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

/// Cells whose patches the mesh holds (in a piece of a split run, ghost
/// cells take part in choosing each shared vertex's cell, as in the whole
/// run, but give no triangles).
std::vector<std::uint8_t> OwnCells(const AdaptiveOctree& tree, const std::vector<std::uint32_t>& cells)
{
  std::vector<std::uint8_t> own(cells.size());
  for (std::size_t i = 0; i < cells.size(); ++i)
  {
    own[i] = tree.RoleOf(tree.Nodes[cells[i]]) == TreeRole::Own;
  }
  return own;
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
/// Own cells whose loops did not close, and own cells that may hold
/// surface but got no patch (ExtractionResult).
void CountDefects(const AdaptiveOctree& tree, const std::vector<std::uint32_t>& cells,
  const std::vector<std::uint8_t>& own, const std::vector<BoundaryLoopSet>& loops,
  const std::vector<CellPatches>& patches, ExtractionResult& result)
{
  for (std::size_t i = 0; i < cells.size(); ++i)
  {
    result.InconsistentCells += own[i] && !loops[i].Consistent ? 1 : 0;
    // (An exact cell without triangles holds none of the input: nothing is missing.)
    result.CellsWithoutPatch +=
      own[i] && patches[i].Triangles.empty() && tree.Nodes[cells[i]].State != CellState::Exact ? 1 : 0;
  }
}

/// The error-bounded cells' bound: each one's certified error, or its
/// diagonal where that is smaller or the certificate failed (ExtractionResult).
void GatherCertifiedBound(const AdaptiveOctree& tree, const std::vector<std::uint32_t>& cells,
  const std::vector<double>& errors, ExtractionResult& result)
{
  for (std::size_t i = 0; i < cells.size(); ++i)
  {
    const OctreeNode& node = tree.Nodes[cells[i]];
    if (node.State == CellState::Surface && node.ErrorBounded && tree.RoleOf(node) == TreeRole::Own)
    {
      const double diagonal = tree.Grid.CellDiagonal(node.Level);
      // (A cell no larger than the tolerance keeps its diagonal's bound.)
      result.UncertifiedCells += errors[i] == HUGE_VAL && diagonal > tree.HausdorffTolerance ? 1 : 0;
      result.CellErrors.emplace_back(cells[i], errors[i]);
      result.CertifiedBound = std::max(result.CertifiedBound, std::min(errors[i], diagonal));
    }
  }
}
} // namespace

ExtractionResult ExtractSurface(const AdaptiveOctree& tree, const ImplicitScene& scene,
  const ParallelFor& parallelFor, const ProgressCallback& progress)
{
  // Progress: loops 40 %, vertex numbering 10 %, vertices 20 %, patches 25 %, writing 5 %.
  ExtractionResult result;
  TriangleMesh& mesh = result.Mesh;
  const auto& prims = scene.Primitives;
  const std::vector<std::uint32_t> cells = SurfaceLeaves(tree);
  const std::vector<std::uint8_t> own = OwnCells(tree, cells);

  // Pass 1: each cell's loops, sampled as its neighbours sample (crack patching).
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

  // Pass 2: one vertex per distinct crossing, placed by its first cell. (At
  // most one apex per loop follows: reserved now, so the points are written
  // where they stay.)
  std::size_t loopCount = 0;
  for (const BoundaryLoopSet& l : loops)
  {
    loopCount += l.LoopSizes.size();
  }
  CrossingVertices vertices;
  if (!vertices.Build(loops, parallelFor, ProgressRange(progress, 0.4, 0.5)))
  {
    result.Aborted = true;
    return result;
  }
  mesh.Points.reserve(vertices.Records().size() + loopCount);
  mesh.Normals.reserve(vertices.Records().size() + loopCount);
  if (!PlaceCrossingVertices(vertices, tree, cells, prims, mesh, parallelFor, ProgressRange(progress, 0.5, 0.7)))
  {
    result.Aborted = true;
    return result;
  }

  // Pass 3: each own cell's patches, and the error-bounded cells' errors.
  std::vector<CellPatches> patches(cells.size());
  std::vector<double> errors(cells.size(), 0.0);
  if (!ChunkedFor(cells.size(), Chunk, parallelFor, [&](std::size_t begin, std::size_t end) {
        for (std::size_t i = begin; i < end; ++i)
        {
          if (own[i] && tree.Nodes[cells[i]].State == CellState::Exact)
          {
            TriangulateExactCell(loops[i], vertices, mesh, patches[i]);
          }
          else if (own[i])
          {
            const OctreeNode& node = tree.Nodes[cells[i]];
            const bool bounded = node.State == CellState::Surface && node.ErrorBounded;
            const std::optional<QuadricCellError> surface = bounded
              ? BoundQuadricCell(tree.Expressions[cells[i]], tree.SceneExpression, prims,
                  tree.Grid.CellBox(node.Level, node.Ijk), tree.HausdorffTolerance)
              : std::nullopt;
            TriangulateCell(loops[i], node, *tree.Expressions[cells[i]], prims, tree.Grid, vertices, mesh,
              patches[i], surface ? &*surface : nullptr);
            errors[i] = !bounded ? 0.0 : surface ? CertifiedPatchError(*surface, patches[i], mesh) : HUGE_VAL;
          }
        }
      }, ProgressRange(progress, 0.7, 0.95)))
  {
    result.Aborted = true;
    return result;
  }
  CountDefects(tree, cells, own, loops, patches, result);
  GatherCertifiedBound(tree, cells, errors, result);

  // Pass 4: the output, written once.
  if (!WritePatches(patches, cells, mesh, parallelFor, ProgressRange(progress, 0.95, 1.0)))
  {
    result.Aborted = true;
    return result;
  }
  if (!tree.Roles.empty())
  {
    KeepUsedVertices(mesh);
  }
  return result;
}

} // namespace tpc
