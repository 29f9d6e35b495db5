#include "BoundaryLoops.h"

#include <algorithm>
#include <iterator>

namespace tpc
{
namespace
{
struct FacePoint
{
  LatticeIndex U, V;
  bool Inside;
};

bool ByVU(const FacePoint& a, const FacePoint& b)
{
  return a.V != b.V ? a.V < b.V : a.U < b.U;
}

bool ByUV(const FacePoint& a, const FacePoint& b)
{
  return a.U != b.U ? a.U < b.U : a.V < b.V;
}

using Segment = std::pair<Crossing, Crossing>;

/// One segment per run of inside points along the tile polygon, from the
/// crossing entering the run to the crossing leaving it.
void TileSegments(const std::vector<FacePoint>& poly, int axis, LatticeIndex plane,
  const FaceTile& tile, std::vector<Segment>& segments)
{
  const std::size_t m = poly.size();
  const int U = (axis + 1) % 3, V = (axis + 2) % 3;
  auto crossing = [&](std::size_t i) {
    const FacePoint& p = poly[i];
    const FacePoint& q = poly[(i + 1) % m];
    const int along = p.V == q.V ? U : V;
    const bool pLower = along == U ? p.U < q.U : p.V < q.V;
    const FacePoint& lower = pLower ? p : q;
    const FacePoint& upper = pLower ? q : p;
    LatticeIndex x[3];
    x[axis] = plane;
    x[U] = lower.U;
    x[V] = lower.V;
    Crossing c;
    c.Key = WithAxis(MakePointKey(x[0], x[1], x[2]), along);
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
    const Crossing in = crossing(k), out = crossing(j);
    const int along = AxisOf(in.Key);
    LatticeIndex a[3], b[3];
    SplitPointKey(PointOf(in.Key), a);
    SplitPointKey(PointOf(out.Key), b);
    const bool sameLine = AxisOf(in.Key) == AxisOf(out.Key) && a[(along + 1) % 3] == b[(along + 1) % 3] &&
      a[(along + 2) % 3] == b[(along + 2) % 3];
    if (!sameLine)
    {
      segments.emplace_back(in, out);
      continue;
    }
    // Both cells sharing the tile must name the bend alike, and they walk the
    // tile in opposite directions: use the ordered pair of crossings.
    Crossing bend;
    bend.Kind = CrossingKind::Bend;
    bend.Key = std::min(in.Key, out.Key);
    bend.Tile = TileKey(axis, plane, tile);
    bend.Partner = std::max(in.Key, out.Key);
    segments.emplace_back(in, bend);
    segments.emplace_back(bend, out);
  }
}

/// Scratch of one thread's traces (a cell's tests trace its loops several
/// times; fresh vectors each time were a tenth of the tracing).
struct TraceScratch
{
  std::vector<FacePoint> OnFace[6];
  std::vector<FacePoint> ByU, Polygon;
};

/// The boundary's sample points on each face, in (u, v) of its plane.
void PointsByFace(const CellBoundary& b, TraceScratch& scratch)
{
  for (std::vector<FacePoint>& face : scratch.OnFace)
  {
    face.clear();
  }
  for (const auto& pk : b.Points)
  {
    LatticeIndex p[3];
    SplitPointKey(pk.first, p);
    for (int axis = 0; axis < 3; ++axis)
    {
      const int U = (axis + 1) % 3, V = (axis + 2) % 3;
      for (int side = 0; side < 2; ++side)
      {
        if (p[axis] == b.Base[axis] + (side ? b.Size : 0))
        {
          scratch.OnFace[2 * axis + side].push_back({ p[U], p[V], pk.second });
        }
      }
    }
  }
}

void FaceSegments(const CellBoundary& b, int f, TraceScratch& scratch, std::vector<Segment>& segments)
{
  const int axis = f / 2, side = f % 2;
  const LatticeIndex plane = b.Base[axis] + (side ? b.Size : 0);
  std::vector<FacePoint>& byV = scratch.OnFace[f];
  if (std::all_of(byV.begin(), byV.end(), [&](const FacePoint& p) { return p.Inside == byV[0].Inside; }))
  {
    return; // (no tile's polygon changes sign: no segment; exact tiles' are in ExactSegments)
  }
  std::vector<FacePoint>& byU = scratch.ByU;
  byU.assign(byV.begin(), byV.end());
  std::sort(byV.begin(), byV.end(), ByVU);
  std::sort(byU.begin(), byU.end(), ByUV);
  auto row = [&](LatticeIndex v, LatticeIndex ua, LatticeIndex ub) { // u in [ua, ub)
    auto lo = std::lower_bound(byV.begin(), byV.end(), FacePoint{ ua, v, false }, ByVU);
    auto hi = std::lower_bound(lo, byV.end(), FacePoint{ ub, v, false }, ByVU);
    return std::make_pair(lo, hi);
  };
  auto col = [&](LatticeIndex u, LatticeIndex va, LatticeIndex vb) { // v in [va, vb)
    auto lo = std::lower_bound(byU.begin(), byU.end(), FacePoint{ u, va, false }, ByUV);
    auto hi = std::lower_bound(lo, byU.end(), FacePoint{ u, vb, false }, ByUV);
    return std::make_pair(lo, hi);
  };

  std::vector<FacePoint>& polygon = scratch.Polygon;
  for (std::size_t k = 0; k < b.Tiles[f].size(); ++k)
  {
    if (k < b.ExactTile[f].size() && b.ExactTile[f][k])
    {
      continue; // drawn exactly: b.ExactSegments
    }
    const FaceTile& t = b.Tiles[f][k];
    const LatticeIndex u0 = t.U0, v0 = t.V0, u1 = t.U1, v1 = t.V1;
    polygon.clear();
    // Counter-clockwise in (u, v): bottom, right, top, left; each side's first
    // point included, its last excluded.
    auto r = row(v0, u0, u1);
    polygon.insert(polygon.end(), r.first, r.second);
    r = col(u1, v0, v1);
    polygon.insert(polygon.end(), r.first, r.second);
    r = row(v1, u0 + 1, u1 + 1);
    polygon.insert(polygon.end(), std::make_reverse_iterator(r.second), std::make_reverse_iterator(r.first));
    r = col(u0, v0 + 1, v1 + 1);
    polygon.insert(polygon.end(), std::make_reverse_iterator(r.second), std::make_reverse_iterator(r.first));
    if (side == 0)
    {
      // Seen from outside the cell the low face is traversed the other way.
      std::reverse(polygon.begin(), polygon.end());
    }
    if (polygon.size() >= 3)
    {
      const std::size_t first = segments.size();
      TileSegments(polygon, axis, plane, t, segments);
      // A crease tile's one chord runs through the crease (CreaseCrossing.h,
      // CsgCreaseCrossing.h).
      if (k < b.Creases[f].size() && b.Creases[f][k] && segments.size() == first + 1 &&
        segments[first].first.Kind != CrossingKind::Bend && segments[first].second.Kind != CrossingKind::Bend)
      {
        const Crossing out = segments[first].second;
        segments[first].second = b.Creases[f][k]->X;
        segments.emplace_back(b.Creases[f][k]->X, out);
      }
    }
  }
}

/// The faces of the cell with low corner `base` and edge `size` that lie in
/// the lattice plane x_axis = `plane`: its low face's bit, its high face's,
/// or none.
unsigned FacesInPlane(int axis, LatticeIndex plane, const LatticeIndex base[3], LatticeIndex size)
{
  return (plane == base[axis] ? 1u : 0u) << (2 * axis) | (plane == base[axis] + size ? 1u : 0u) << (2 * axis + 1);
}
} // namespace

unsigned CrossingFaces(const Crossing& c, const LatticeIndex base[3], LatticeIndex size)
{
  if (c.Kind == CrossingKind::Bend)
  {
    return 0x3F;
  }
  if (c.Kind == CrossingKind::MeshEdge)
  {
    return FacesInPlane(PlaneAxis(c.Key), PlaneCoordinate(c.Key), base, size);
  }
  if (c.Kind == CrossingKind::MeshVertex)
  {
    return 0; // inside an exact cell
  }
  if (c.Kind == CrossingKind::CsgCrease)
  {
    const int axis = TileKeyAxis(c.Tile);
    LatticeIndex corner[3];
    TileKeyCorner(c.Tile, corner);
    return FacesInPlane(axis, corner[axis], base, size);
  }
  LatticeIndex p[3];
  SplitPointKey(PointOf(c.Key), p);
  const int along = AxisOf(c.Key);
  unsigned mask = 0;
  for (int a = 0; a < 3; ++a)
  {
    if (a != along)
    {
      mask |= FacesInPlane(a, p[a], base, size);
    }
  }
  return mask;
}

BoundaryLoopSet TraceBoundaryLoops(CellBoundary& b)
{
  std::sort(b.Points.begin(), b.Points.end());
  b.Points.erase(std::unique(b.Points.begin(), b.Points.end(),
                   [](const auto& x, const auto& y) { return x.first == y.first; }),
    b.Points.end());
  thread_local TraceScratch scratch;
  thread_local std::vector<Segment> segments;
  segments.assign(b.ExactSegments.begin(), b.ExactSegments.end());
  PointsByFace(b, scratch);
  for (int f = 0; f < 6; ++f)
  {
    FaceSegments(b, f, scratch, segments);
  }

  BoundaryLoopSet loops;
  loops.Crossings.reserve(segments.size());
  std::sort(segments.begin(), segments.end(),
    [](const Segment& x, const Segment& y) { return x.first < y.first; });
  for (std::size_t s = 1; s < segments.size(); ++s)
  {
    if (segments[s].first.SameVertex(segments[s - 1].first))
    {
      loops.Consistent = false; // a crossing starting two segments
    }
  }
  auto find = [&](const Crossing& c) {
    auto it = std::lower_bound(segments.begin(), segments.end(), c,
      [](const Segment& s, const Crossing& key) { return s.first < key; });
    return (it == segments.end() || !it->first.SameVertex(c)) ? segments.size()
                                                              : static_cast<std::size_t>(it - segments.begin());
  };
  std::vector<bool> used(segments.size(), false);
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
      s = find(segments[s].second);
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

std::vector<std::vector<Crossing>> EachLoop(const BoundaryLoopSet& loops)
{
  std::vector<std::vector<Crossing>> each;
  auto first = loops.Crossings.begin();
  for (const std::uint32_t size : loops.LoopSizes)
  {
    each.emplace_back(first, first + size);
    first += size;
  }
  return each;
}

} // namespace tpc
