#include "ExactCell.h"

#include "MeshArrangement.h"

#include <algorithm>
#include <map>
#include <unordered_map>

namespace tpc
{
namespace
{

/// The sample points of a cell's boundary on each lattice line, sorted
/// along it, with their signs.
class BoundaryLines
{
public:
  using Samples = std::vector<std::pair<LatticeIndex, bool>>;

  explicit BoundaryLines(const CellBoundary& b)
  {
    for (const auto& point : b.Points)
    {
      LatticeIndex p[3];
      SplitPointKey(point.first, p);
      for (int a = 0; a < 3; ++a)
      {
        this->Lines[LineKey(p, a)].emplace_back(p[a], point.second);
      }
    }
    for (auto& line : this->Lines)
    {
      std::sort(line.second.begin(), line.second.end());
      line.second.erase(std::unique(line.second.begin(), line.second.end(),
                          [](const auto& x, const auto& y) { return x.first == y.first; }),
        line.second.end());
    }
  }
  const Samples* Line(const LatticeIndex lattice[3], int axis) const
  {
    const auto it = this->Lines.find(LineKey(lattice, axis));
    return it == this->Lines.end() ? nullptr : &it->second;
  }

private:
  std::unordered_map<LatticeKey, Samples, LatticeKeyHash> Lines;
};

/// Names arrangement points as the extraction's crossings.
struct Namer
{
  const MeshArrangement& Arrangement;
  const BoundaryLines& Lines;
  const TriangleList& Triangles;
  std::uint32_t Primitive;
  const RootGrid& Grid;

  Crossing Name(const ArrangementPoint& p) const
  {
    Crossing c;
    c.Tile = this->Primitive;
    switch (p.PointKind)
    {
      case ArrangementPoint::Kind::MeshVertex:
        c.Kind = CrossingKind::MeshVertex;
        c.Key = p.A;
        return c;
      case ArrangementPoint::Kind::EdgeOnPlane:
        c.Kind = CrossingKind::MeshEdge;
        c.Key = PlaneKey(p.Axis, p.Lattice[p.Axis]);
        c.Partner = (static_cast<std::uint64_t>(p.A) << 32) | p.B;
        return c;
      default:
        return this->OnSubEdge(p);
    }
  }

  /// A triangle's crossing with a lattice line of the boundary: the sub-edge
  /// between the samples around it, named by the sub-edge alone when the
  /// mesh crosses it once (as sampled cells name it).
  Crossing OnSubEdge(const ArrangementPoint& y) const
  {
    const int axis = y.Axis;
    const BoundaryLines::Samples* samples = this->Lines.Line(y.Lattice, axis);
    std::size_t upper = 0;
    if (samples)
    {
      const auto it = std::partition_point(samples->begin(), samples->end(),
        [&](const std::pair<LatticeIndex, bool>& s) { return this->Arrangement.Side(y, axis, s.first) > 0; });
      upper = static_cast<std::size_t>(it - samples->begin());
    }
    Crossing c;
    if (!samples || upper == 0 || upper == samples->size())
    {
      // Not between two samples (never expected): a vertex of its own, which
      // the loops of the cells around will not find - counted as
      // inconsistent there.
      c.Kind = CrossingKind::SubEdgeTriangle;
      c.Key = WithAxis(MakePointKey(y.Lattice[0], y.Lattice[1], y.Lattice[2]), axis);
      c.Tile = this->Primitive;
      c.Partner = y.A;
      return c;
    }
    LatticeIndex lo[3] = { y.Lattice[0], y.Lattice[1], y.Lattice[2] }, hi[3] = { lo[0], lo[1], lo[2] };
    lo[axis] = (*samples)[upper - 1].first;
    hi[axis] = (*samples)[upper].first;
    c.Key = WithAxis(MakePointKey(lo[0], lo[1], lo[2]), axis);
    c.Upper = hi[axis];
    c.LowerInside = (*samples)[upper - 1].second;
    const int crossings =
      this->Arrangement.Mesh().CountCrossings(this->Grid.Point(lo), this->Grid.Point(hi), axis, this->Triangles);
    if (crossings != 1)
    {
      c.Kind = CrossingKind::SubEdgeTriangle;
      c.Tile = this->Primitive;
      c.Partner = y.A;
    }
    return c;
  }
};

/// The tile sides strictly inside face f of the cell: for each of the face's
/// two axes, the lattice lines of constant coordinate on it that bound a
/// tile, with the intervals (along the other axis) where they do.
struct FaceTileSides
{
  int Axes[2] = { 0, 0 };
  std::map<LatticeIndex, std::vector<std::pair<LatticeIndex, LatticeIndex>>> Lines[2];

  FaceTileSides(const CellBoundary& b, int f)
  {
    const int axis = f / 2;
    this->Axes[0] = (axis + 1) % 3;
    this->Axes[1] = (axis + 2) % 3;
    const LatticeIndex lo[2] = { b.Base[this->Axes[0]], b.Base[this->Axes[1]] };
    for (const FaceTile& t : b.Tiles[f])
    {
      const LatticeIndex u[2] = { t.U0, t.U1 }, v[2] = { t.V0, t.V1 };
      for (int s = 0; s < 2; ++s)
      {
        if (u[s] > lo[0] && u[s] < lo[0] + b.Size)
        {
          this->Lines[0][u[s]].emplace_back(t.V0, t.V1);
        }
        if (v[s] > lo[1] && v[s] < lo[1] + b.Size)
        {
          this->Lines[1][v[s]].emplace_back(t.U0, t.U1);
        }
      }
    }
  }
};

/// The points where the polygon edge x -> y on face f crosses tile sides,
/// in order from x.
std::vector<ArrangementPoint> TileSideCrossings(const MeshArrangement& arrangement, std::uint32_t t,
  const ArrangementPoint& x, const ArrangementPoint& y, int f, LatticeIndex plane, const FaceTileSides& sides)
{
  struct Hit
  {
    ArrangementPoint Point;
    int Axis;
    LatticeIndex Coordinate;
  };
  std::vector<Hit> hits;
  for (int j = 0; j < 2; ++j)
  {
    const int u = sides.Axes[j], v = sides.Axes[1 - j];
    for (const auto& line : sides.Lines[j])
    {
      if (arrangement.Side(x, u, line.first) == arrangement.Side(y, u, line.first))
      {
        continue;
      }
      LatticeIndex lattice[3] = { 0, 0, 0 };
      lattice[f / 2] = plane;
      lattice[u] = line.first;
      const ArrangementPoint z = ArrangementPoint::TriangleOnLine(t, v, lattice);
      // Only where the line bounds a tile (elsewhere it crosses a tile).
      const bool bounds = std::any_of(line.second.begin(), line.second.end(), [&](const auto& interval) {
        return arrangement.Side(z, v, interval.first) > 0 && arrangement.Side(z, v, interval.second) < 0;
      });
      if (bounds)
      {
        hits.push_back({ z, u, line.first });
      }
    }
  }
  std::sort(hits.begin(), hits.end(), [&](const Hit& a, const Hit& b) {
    return !(a.Axis == b.Axis && a.Coordinate == b.Coordinate) && arrangement.Before(x, a.Point, b.Axis, b.Coordinate);
  });
  std::vector<ArrangementPoint> out;
  for (const Hit& h : hits)
  {
    out.push_back(h.Point);
  }
  return out;
}
} // namespace

ExactPolygons ClipToExactCell(const CellBoundary& boundary, const CsgLeaf& leaf, const PrimitiveSet& primitives,
  const RootGrid& grid)
{
  const MeshSolid& mesh = primitives.Meshes[leaf.Primitive];
  const MeshArrangement arrangement(mesh, grid);
  const BoundaryLines lines(boundary);
  const Namer namer{ arrangement, lines, *leaf.Triangles, leaf.Primitive, grid };
  LatticeIndex lo[3], hi[3];
  for (int a = 0; a < 3; ++a)
  {
    lo[a] = boundary.Base[a];
    hi[a] = boundary.Base[a] + boundary.Size;
  }
  std::vector<FaceTileSides> sides;
  for (int f = 0; f < 6; ++f)
  {
    sides.emplace_back(boundary, f);
  }
  ExactPolygons out;
  for (const std::uint32_t t : *leaf.Triangles)
  {
    const std::vector<ClippedVertex> polygon = arrangement.ClipTriangle(t, lo, hi);
    const std::size_t first = out.Vertices.size();
    for (std::size_t i = 0; i < polygon.size(); ++i)
    {
      out.Vertices.push_back(namer.Name(polygon[i].Point));
      const int support = polygon[i].Support;
      if (support >= ClippedVertex::FaceSupport)
      {
        const int f = support - ClippedVertex::FaceSupport;
        const LatticeIndex plane = f % 2 ? hi[f / 2] : lo[f / 2];
        for (const ArrangementPoint& z : TileSideCrossings(
               arrangement, t, polygon[i].Point, polygon[(i + 1) % polygon.size()].Point, f, plane, sides[f]))
        {
          out.Vertices.push_back(namer.Name(z));
        }
      }
    }
    if (out.Vertices.size() > first)
    {
      if (leaf.Sigma < 0)
      {
        std::reverse(out.Vertices.begin() + static_cast<std::ptrdiff_t>(first), out.Vertices.end());
      }
      out.Sizes.push_back(static_cast<std::uint32_t>(out.Vertices.size() - first));
    }
  }
  return out;
}

void AddExactTileSegments(CellBoundary& boundary, const std::vector<ExactTile>& tiles, const PrimitiveSet& primitives,
  const RootGrid& grid)
{
  if (tiles.empty())
  {
    return;
  }
  const BoundaryLines lines(boundary);
  for (const ExactTile& exact : tiles)
  {
    const CsgLeaf& leaf = *exact.Leaf;
    const MeshArrangement arrangement(primitives.Meshes[leaf.Primitive], grid);
    const Namer namer{ arrangement, lines, *leaf.Triangles, leaf.Primitive, grid };
    const int f = exact.Face, axis = f / 2;
    const LatticeIndex plane = boundary.Base[axis] + (f % 2 ? boundary.Size : 0);
    const FaceTile& tile = boundary.Tiles[f][exact.Tile];
    const LatticeIndex lo[2] = { tile.U0, tile.V0 }, hi[2] = { tile.U1, tile.V1 };
    for (const std::uint32_t t : *leaf.Triangles)
    {
      ArrangementPoint from, to;
      if (arrangement.TraceOnRectangle(t, axis, plane, lo, hi, f % 2 ? 1 : -1, leaf.Sigma, from, to))
      {
        boundary.ExactSegments.emplace_back(namer.Name(from), namer.Name(to));
      }
    }
    boundary.ExactTile[f].resize(boundary.Tiles[f].size(), 0);
    boundary.ExactTile[f][exact.Tile] = 1;
  }
}

Vec3 ExactCrossingPosition(const Crossing& c, const PrimitiveSet& primitives, const RootGrid& grid)
{
  const MeshArrangement arrangement(primitives.Meshes[static_cast<std::size_t>(c.Tile)], grid);
  if (c.Kind == CrossingKind::MeshVertex)
  {
    return arrangement.Position(ArrangementPoint::Vertex(static_cast<std::uint32_t>(c.Key)));
  }
  if (c.Kind == CrossingKind::MeshEdge)
  {
    return arrangement.Position(ArrangementPoint::EdgeOnPlane(static_cast<std::uint32_t>(c.Partner >> 32),
      static_cast<std::uint32_t>(c.Partner & 0xFFFFFFFFu), PlaneAxis(c.Key), PlaneCoordinate(c.Key)));
  }
  // A triangle on a sub-edge crossed several times: on the line, strictly
  // inside the sub-edge (distinct crossings keep distinct positions).
  LatticeIndex lo[3];
  SplitPointKey(PointOf(c.Key), lo);
  const int axis = AxisOf(c.Key);
  Vec3 p = arrangement.Position(ArrangementPoint::TriangleOnLine(static_cast<std::uint32_t>(c.Partner), axis, lo));
  const double a = grid.Coordinate(axis, lo[axis]), b = grid.Coordinate(axis, c.Upper);
  p[axis] = std::clamp(p[axis], std::nextafter(a, b), std::nextafter(b, a));
  return p;
}

} // namespace tpc
