#include "CellPatches.h"

#include "LoopTriangulation.h"

#include <algorithm>
#include <cmath>

namespace tpc
{
namespace
{
/// The per-cell loop runs in chunks reporting progress.
constexpr std::size_t Chunk = 8192;

/// Cell i's apexes and triangles written at their offsets, apex normals
/// summed over the cell's triangles in order (an apex is in its own cell's
/// triangles only).
void WriteCellPatches(const CellPatches& patches, std::uint32_t cell, std::size_t firstApex,
  std::size_t firstTriangle, TriangleMesh& mesh)
{
  std::copy(patches.Apexes.begin(), patches.Apexes.end(), mesh.Points.begin() + firstApex);
  std::fill(mesh.Normals.begin() + firstApex, mesh.Normals.begin() + firstApex + patches.Apexes.size(), Vec3());
  for (std::size_t k = 0; k < patches.Triangles.size(); ++k)
  {
    Triangle t = patches.Triangles[k];
    for (auto& v : t)
    {
      v = (v & CellPatches::LocalFlag) ? static_cast<std::uint32_t>(firstApex) + (v & ~CellPatches::LocalFlag) : v;
    }
    mesh.Triangles[firstTriangle + k] = t;
    mesh.TriangleCell[firstTriangle + k] = cell;
    const Vec3 n = Cross(mesh.Points[t[1]] - mesh.Points[t[0]], mesh.Points[t[2]] - mesh.Points[t[0]]);
    for (const std::uint32_t v : t)
    {
      if (v >= firstApex)
      {
        mesh.Normals[v] += n;
      }
    }
  }
  for (std::size_t v = firstApex; v < firstApex + patches.Apexes.size(); ++v)
  {
    mesh.Normals[v] = Normalized(mesh.Normals[v]);
  }
}

/// The `count` crossings from `crossings` as a loop's points (position,
/// normal, the faces of the cell `box`, with low corner `base` and edge
/// `size` on the lattice, holding them as placed, whether a mesh edge's
/// crossing), appended to `points`, and their vertex ids to `ids`.
void GatherLoop(const Crossing* crossings, std::size_t count, const CrossingVertices& vertices,
  const TriangleMesh& mesh, const Box3& box, const LatticeIndex base[3], LatticeIndex size,
  std::vector<std::uint32_t>& ids, std::vector<LoopPoint>& points)
{
  for (std::size_t k = 0; k < count; ++k)
  {
    const Crossing& c = crossings[k];
    const std::uint32_t id = vertices.IdOf(c);
    const bool onMeshEdge = c.Kind == CrossingKind::MeshEdge;
    ids.push_back(id);
    points.push_back({ mesh.Points[id], mesh.Normals[id],
      FacesAsPlaced(CrossingFaces(c, base, size), onMeshEdge, mesh.Points[id], box), onMeshEdge });
  }
}

/// How far `p` is from `room`: from its region, plus how far beyond each cut
/// (0 inside the room's closure).
double DistanceToRoom(const Vec3& p, const ApexRoom& room)
{
  double d = Norm(p - room.Region.Clamp(p));
  for (const SeparatingPlane& plane : room.Below)
  {
    d += std::max(0.0, Dot(plane.Normal, p) - plane.Offset);
  }
  return d;
}

/// The apex of `apexes` (none if null) each loop of `rooms` is fanned
/// around: a lone loop's lone apex; with several loops, each takes the apex
/// nearest its room (the prediction placed one in each loop's room over the
/// cell's own loops; the final loops hold more points, so their rooms may
/// differ a little), unless two take the same one (then none does). Null
/// where a loop has none.
std::vector<const Vec3*> ApexesOfLoops(const std::vector<Vec3>* apexes, const std::vector<ApexRoom>& rooms)
{
  std::vector<const Vec3*> chosen(rooms.size(), nullptr);
  if (!apexes || apexes->size() != rooms.size())
  {
    return chosen;
  }
  for (std::size_t l = 0; l < rooms.size(); ++l)
  {
    double nearest = HUGE_VAL;
    for (const Vec3& apex : *apexes)
    {
      const double d = rooms.size() == 1 ? 0.0 : DistanceToRoom(apex, rooms[l]);
      if (d < nearest)
      {
        nearest = d;
        chosen[l] = &apex;
      }
    }
  }
  for (std::size_t l = 0; l < rooms.size(); ++l)
  {
    for (std::size_t m = l + 1; m < rooms.size(); ++m)
    {
      if (chosen[l] == chosen[m])
      {
        return std::vector<const Vec3*>(rooms.size(), nullptr);
      }
    }
  }
  return chosen;
}

/// Marching Cubes' fan of the loop `id` from its point s: k - 2 triangles.
void AppendLoopFan(const std::vector<std::uint32_t>& id, std::size_t s, CellPatches& out)
{
  const std::size_t k = id.size();
  for (std::size_t i = 1; i + 1 < k; ++i)
  {
    out.Triangles.push_back({ id[s], id[(s + i) % k], id[(s + i + 1) % k] });
  }
}
} // namespace

void TriangulateCell(const BoundaryLoopSet& loops, const OctreeNode& node, const CsgExpression& expression,
  const PrimitiveSet& prims, const RootGrid& grid, const CrossingVertices& vertices, const TriangleMesh& mesh,
  CellPatches& out, const QuadricCellError* surface, const std::vector<Vec3>* meshApexes)
{
  const Box3 box = grid.CellBox(node.Level, node.Ijk);
  LatticeIndex base[3];
  CornerLattice(grid, node, 0, base);
  const LatticeIndex size = LatticeIndex(1) << (grid.MaxDepth - node.Level);
  std::vector<std::vector<std::uint32_t>> ids;
  std::vector<std::vector<LoopPoint>> points;
  std::size_t offset = 0;
  for (const std::uint32_t loopSize : loops.LoopSizes)
  {
    ids.emplace_back();
    points.emplace_back();
    GatherLoop(
      loops.Crossings.data() + offset, loopSize, vertices, mesh, box, base, size, ids.back(), points.back());
    offset += loopSize;
  }
  // (A lone loop's room is the whole cell: its points are copied out only
  // where several loops share the cell, as before rooms.)
  std::vector<std::vector<Vec3>> positions(points.size() > 1 ? points.size() : 0);
  for (std::size_t l = 0; l < positions.size(); ++l)
  {
    for (const LoopPoint& p : points[l])
    {
      positions[l].push_back(p.Position);
    }
  }
  const std::vector<ApexRoom> rooms =
    points.size() > 1 ? ApexRooms(positions, box) : std::vector<ApexRoom>(points.size(), ApexRoom{ box, {} });
  const std::vector<const Vec3*> apexes = ApexesOfLoops(meshApexes, rooms);
  for (std::size_t l = 0; l < ids.size(); ++l)
  {
    const std::vector<std::uint32_t>& id = ids[l];
    const std::size_t k = id.size();
    if (k < 3)
    {
      continue; // only from inconsistent loops, counted by the caller
    }
    const LoopPatch patch =
      TriangulateLoop(points[l], rooms[l], node.PlaneSection, expression, prims, surface, apexes[l]);
    if (patch.Kind == LoopPatchKind::Triangle)
    {
      out.Triangles.push_back({ id[0], id[1], id[2] });
    }
    else if (patch.Kind == LoopPatchKind::LoopFan)
    {
      AppendLoopFan(id, static_cast<std::size_t>(patch.FanPoint), out);
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

bool TriangulateCellFromLoopPoint(const BoundaryLoopSet& loops, const OctreeNode& node, const RootGrid& grid,
  const CrossingVertices& vertices, const TriangleMesh& mesh, CellPatches& out, bool& fromMeshEdge)
{
  fromMeshEdge = false;
  if (loops.LoopSizes.size() != 1 || loops.LoopSizes[0] < 4 || !loops.Consistent)
  {
    return false;
  }
  LatticeIndex base[3];
  CornerLattice(grid, node, 0, base);
  const LatticeIndex size = LatticeIndex(1) << (grid.MaxDepth - node.Level);
  if (std::any_of(loops.Crossings.begin(), loops.Crossings.end(), [](const Crossing& c) {
        return c.Kind != CrossingKind::SubEdge && c.Kind != CrossingKind::MeshEdge;
      }))
  {
    return false; // a bend (a cell stopped by a limit), a sub-edge an exact neighbour crosses twice
  }
  std::vector<std::uint32_t> ids;
  std::vector<LoopPoint> points;
  GatherLoop(loops.Crossings.data(), loops.Crossings.size(), vertices, mesh, grid.CellBox(node.Level, node.Ijk),
    base, size, ids, points);
  fromMeshEdge = std::any_of(points.begin(), points.end(), [](const LoopPoint& p) { return p.OnMeshEdge; });
  const int s = fromMeshEdge ? MeshEdgeFanPoint(points) : LoopFanPoint(points);
  if (s < 0)
  {
    return false;
  }
  out = CellPatches();
  AppendLoopFan(ids, static_cast<std::size_t>(s), out);
  return true;
}

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

bool WritePatches(std::vector<CellPatches>& patches, const std::vector<std::uint32_t>& cells, TriangleMesh& mesh,
  const ParallelFor& parallelFor, const ProgressCallback& progress)
{
  // Count, prefix sum.
  std::vector<std::size_t> firstApex(cells.size() + 1), firstTriangle(cells.size() + 1);
  firstApex[0] = mesh.Points.size();
  firstTriangle[0] = mesh.Triangles.size();
  for (std::size_t i = 0; i < cells.size(); ++i)
  {
    firstApex[i + 1] = firstApex[i] + patches[i].Apexes.size();
    firstTriangle[i + 1] = firstTriangle[i] + patches[i].Triangles.size();
  }
  // (Each cell writes its own apexes' points and normals and its triangles:
  // in parallel, the threads first touch their pages, ReleasableArray.h.)
  mesh.Points.resize_for_overwrite(firstApex.back());
  mesh.Normals.resize_for_overwrite(firstApex.back());
  mesh.Triangles.resize_for_overwrite(firstTriangle.back());
  mesh.TriangleCell.resize(firstTriangle.back());
  // Write.
  return ChunkedFor(cells.size(), Chunk, parallelFor, [&](std::size_t begin, std::size_t end) {
    for (std::size_t i = begin; i < end; ++i)
    {
      WriteCellPatches(patches[i], cells[i], firstApex[i], firstTriangle[i], mesh);
      patches[i] = CellPatches();
    }
  }, progress);
}

} // namespace tpc
