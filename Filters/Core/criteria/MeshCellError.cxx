#include "MeshCellError.h"

#include "CreaseCrossing.h"
#include "CreaseFollowing.h"
#include "EdgeCrossings.h"
#include "ExactCellCriterion.h"
#include "FaceRefinement.h"
#include "MeshArrangement.h"
#include "MeshSolid.h"
#include "SlabBound.h"
#include "SymmetricEigen.h"
#include "UnionFind.h"

#include <algorithm>
#include <cfloat>
#include <cmath>

namespace tpc
{
namespace
{
/// Pieces the subdivision's prediction may examine per direction (a cell
/// whose bound needs more is split instead: smaller cells are cheaper).
constexpr std::size_t PredictionBudget = 1024;

/// The face of the cell holding both crossings, or -1.
int CommonFace(const Crossing& p, const Crossing& q, const CellBoundary& boundary)
{
  const unsigned common =
    CrossingFaces(p, boundary.Base, boundary.Size) & CrossingFaces(q, boundary.Base, boundary.Size);
  for (int f = 0; f < 6; ++f)
  {
    if (common & (1u << f))
    {
      return f;
    }
  }
  return -1;
}

/// delta of the chord from loop point `end` to the crease x of a crease
/// tile: the farthest the trace's half ending at `end` strays from it (the
/// final loop's points between them lie on that half, CreaseCrossing.h);
/// +inf when it is not clear which half ends there (`end` lies on the last
/// segment of its half, up to rounding, and far from the other's).
double CreaseChordDeviation(const CreaseTile& crease, const Vec3& end)
{
  double exitDistance[2];
  for (int s = 0; s < 2; ++s)
  {
    const std::vector<Vec3>& half = crease.Sides[s];
    const Vec3& last = half.size() > 1 ? half[half.size() - 2] : crease.Position;
    exitDistance[s] = SegmentDistance(end, last, half.back());
  }
  const int s = exitDistance[0] <= exitDistance[1] ? 0 : 1;
  if (!(exitDistance[1 - s] > 1e3 * exitDistance[s]))
  {
    return HUGE_VAL;
  }
  double deviation = 0.0;
  for (std::size_t k = 0; k + 1 < crease.Sides[s].size(); ++k)
  {
    deviation = std::max(deviation, SegmentDistance(crease.Sides[s][k], end, crease.Position));
  }
  return deviation;
}

/// Whether tile t of a face normal to `axis` holds the sub-edge of crossing
/// `c` (on its boundary): the tile of a chord, decided on lattice keys.
bool HoldsSubEdge(const FaceTile& t, int axis, const Crossing& c)
{
  if (c.Kind != CrossingKind::SubEdge)
  {
    return false;
  }
  LatticeIndex lo[3];
  SplitPointKey(PointOf(c.Key), lo);
  LatticeIndex hi[3] = { lo[0], lo[1], lo[2] };
  hi[AxisOf(c.Key)] = c.Upper;
  const int u = (axis + 1) % 3, v = (axis + 2) % 3;
  return lo[u] >= t.U0 && hi[u] <= t.U1 && lo[v] >= t.V0 && hi[v] <= t.V1;
}

/// The box of tile t of face f.
Box3 TileBox(const RootGrid& grid, const CellBoundary& boundary, int f, const FaceTile& t)
{
  const int axis = f / 2;
  const LatticeIndex plane = boundary.Base[axis] + (f % 2 ? boundary.Size : 0);
  return { grid.Point(TileCorner(axis, plane, t, 0)), grid.Point(TileCorner(axis, plane, t, 3)) };
}

/// Whether some polygon of `surface` is within `reach` of `p` (its box
/// first: a lower bound of the distance).
bool WithinReach(const PolygonSet& surface, const Vec3& p, double reach)
{
  for (std::size_t i = 0; i < surface.size(); ++i)
  {
    if (surface.Bounds(i).Distance2(p) <= reach * reach && surface.Distance(p, i) <= reach)
    {
      return true;
    }
  }
  return false;
}

/// Whether a point of the fan `fan` (triangle k over chord k, whose delta
/// with the slack is chordDelta[k]) is proven to fail both of the
/// prediction's bounds before their branch and bound (header: Probes): its
/// centroid or an edge's midpoint farther from S_C than the tolerance minus
/// chordDelta[k], plus twice the slack.
bool FanPointStrays(const PolygonSet& surface, const std::vector<SourceTriangle>& fan,
  const std::vector<double>& chordDelta, double slack, double tolerance)
{
  for (std::size_t k = 0; k < fan.size(); ++k)
  {
    const SourceTriangle& t = fan[k];
    const double reach = tolerance - chordDelta[k] + 2.0 * slack;
    for (const Vec3& x : { (t[0] + t[1] + t[2]) * (1.0 / 3.0), (t[0] + t[1]) * 0.5, (t[1] + t[2]) * 0.5,
           (t[2] + t[0]) * 0.5 })
    {
      if (!WithinReach(surface, x, reach))
      {
        return true;
      }
    }
  }
  return false;
}
} // namespace

PolygonSet SurfaceInCell(const CsgLeaf& leaf, const PrimitiveSet& primitives,
  const Box3& cell)
{
  PolygonSet surface;
  SurfaceInCell(leaf, primitives, cell, surface);
  return surface;
}

void SurfaceInCell(const CsgLeaf& leaf, const PrimitiveSet& primitives, const Box3& cell, PolygonSet& surface,
  TriangleList* triangles)
{
  const MeshSolid& mesh = primitives.Meshes[leaf.Primitive];
  if (triangles)
  {
    triangles->clear();
    triangles->reserve(leaf.Triangles->size());
  }
  surface.Recycle(leaf.Triangles->size());
  surface.SetSlackMagnitude(SlackMagnitude(leaf, primitives, cell));
  // (Most triangles of a cell lie in it whole, three corners each; those
  // cut by its faces have up to nine, and room for four on average keeps a
  // large cell's corners from being copied as they grow.)
  surface.reserve(leaf.Triangles->size(), 4 * leaf.Triangles->size());
  for (const std::uint32_t t : *leaf.Triangles)
  {
    ClippedCorners clipped{ mesh.Vertex(t, 0), mesh.Vertex(t, 1), mesh.Vertex(t, 2) };
    ClipToBox(clipped, cell);
    if (!clipped.empty())
    {
      surface.Add(clipped.data(), clipped.size());
      if (triangles)
      {
        triangles->push_back(t);
      }
    }
  }
}

namespace
{
/// The point nearest to the planes of the polygons of `surface` whose index
/// `keep` accepts (MeshCellApex), kept `margin` of `box`'s width inside it.
template <typename Keep>
Vec3 LeastSquaresApex(const PolygonSet& surface, const Box3& box, double margin, const Keep& keep)
{
  Vec3 centroid;
  double weight = 0.0;
  for (std::size_t i = 0; i < surface.size(); ++i)
  {
    if (!keep(i))
    {
      continue;
    }
    const ConvexPolygon q = surface[i];
    const double w = q.TwiceArea;
    for (const Vec3& p : q.Points)
    {
      centroid += p * (w / q.Points.size());
    }
    weight += w;
  }
  centroid = weight > 0.0 ? centroid * (1.0 / weight) : box.Center();
  // Relative weights: the system does not depend on the scene's scale (the
  // eigen-solver's thresholds are absolute).
  double ata[3][3] = { { 0, 0, 0 }, { 0, 0, 0 }, { 0, 0, 0 } };
  double atb[3] = { 0, 0, 0 };
  for (std::size_t i = 0; i < surface.size(); ++i)
  {
    if (!keep(i))
    {
      continue;
    }
    const ConvexPolygon q = surface[i];
    const Vec3& n = q.Normal;
    const double w = weight > 0.0 ? q.TwiceArea / weight : 1.0, d = Dot(n, q.Points[0] - centroid);
    for (int a = 0; a < 3; ++a)
    {
      for (int b = 0; b < 3; ++b)
      {
        ata[a][b] += w * n[a] * n[b];
      }
      atb[a] += w * n[a] * d;
    }
  }
  Vec3 delta;
  SolveTruncated(ata, atb, 0.05, delta.x);
  return box.Shrunk(margin).Clamp(centroid + delta);
}

/// How far inside its room's region (relative to its width) the apex of one
/// of several loops is kept (header: Several loops): far less than a lone
/// loop's 1/32 of the cell - a loop whose sheet is a small corner of the
/// mesh cut off by the cell's faces has its planes' point within 1/32 of a
/// face, and clamping it there bends its fan off the sheet's plane (a tilted
/// bar at 1/64: six output creases off the bar's edges).
constexpr double LoopApexMargin = 1.0 / 1024.0;

/// The crease apexes tried for a cell of several loops (CreaseApexSets): the
/// k-th try takes each loop's k-th candidate.
constexpr std::size_t SeveralLoopsCreaseTries = 4;

} // namespace

Vec3 MeshCellApex(const PolygonSet& surface, const Box3& cell)
{
  return LeastSquaresApex(surface, cell, 1.0 / 32.0, [](std::size_t) { return true; });
}

Vec3 LoopApex(const PolygonSet& surface, const ApexRoom& room, const std::vector<Vec3>& loop)
{
  // (Each polygon asked once: the least squares read the choice twice.)
  std::vector<char> inRoom(surface.size());
  for (std::size_t i = 0; i < surface.size(); ++i)
  {
    const PointSpan corners = surface[i].Points;
    const Vec3 c = MeanOf(corners.begin(), corners.size());
    inRoom[i] = room.Region.Contains(c) &&
      std::all_of(room.Below.begin(), room.Below.end(),
        [&](const SeparatingPlane& plane) { return Dot(plane.Normal, c) < plane.Offset; });
  }
  const Vec3 apex = LeastSquaresApex(surface, room.Region, LoopApexMargin, [&](std::size_t i) { return inRoom[i]; });
  return KeptInRoom(apex, MeanOf(loop.data(), loop.size()), room);
}

double ChordDeviation(const PolygonSet& surface, const Box3& tile, const Vec3& a, const Vec3& b)
{
  return LargestOverClippedCorners(surface, tile, [&](const Vec3& p) { return SegmentDistance(p, a, b); });
}

double SlackMagnitude(const CsgLeaf& leaf, const PrimitiveSet& primitives, const Box3& cell)
{
  return std::max(primitives.Meshes[leaf.Primitive].Bounds().Magnitude(), cell.Magnitude());
}

double RoundingSlackFor(double magnitude, double size)
{
  return 16384.0 * DBL_EPSILON * magnitude + 1e-12 * size;
}

double RoundingSlack(const CsgLeaf& leaf, const PrimitiveSet& primitives, const Box3& cell)
{
  return RoundingSlackFor(SlackMagnitude(leaf, primitives, cell), cell.Diagonal());
}

HausdorffEstimate CertifiedMeshPatchError(const PolygonSet& surface,
  const std::vector<SourceTriangle>& patch, double slack, double enough, double giveUp, std::size_t budget,
  const std::vector<double>* patchOffsets, double anyBoundWithin)
{
  return CertifiedSurfacePatchError(
    surface, surface, patch, slack, enough, giveUp, budget, patchOffsets, anyBoundWithin);
}

HausdorffEstimate CertifiedSurfacePatchError(const PolygonSet& onSurface, const PolygonSet& covering,
  const std::vector<SourceTriangle>& patch, double slack, double enough, double giveUp, std::size_t budget,
  const std::vector<double>* patchOffsets, double anyBoundWithin)
{
  HausdorffEstimate error{ HUGE_VAL, 0.0 };
  if (onSurface.empty() || patch.empty())
  {
    return error;
  }
  const double anyWithin = anyBoundWithin - slack; // (of the distances, as enough and giveUp)
  const HausdorffEstimate toSurface = OneSidedHausdorff(
    patch, onSurface, enough - slack, giveUp - slack, budget, { patchOffsets, nullptr }, nullptr, anyWithin);
  error.Lower = toSurface.Lower;
  if (!(toSurface.Upper + slack <= giveUp))
  {
    return error;
  }
  std::vector<SourceTriangle> pieces;
  for (const ConvexPolygon& q : covering)
  {
    AppendAsSources(q.Points.begin(), q.Points.size(), pieces);
  }
  PolygonSet targets;
  targets.SetSlackMagnitude(covering.GetSlackMagnitude()); // (the patch lies in the same cell)
  targets.reserve(patch.size(), 3 * patch.size());
  for (const SourceTriangle& t : patch)
  {
    targets.Add({ t[0], t[1], t[2] });
  }
  const HausdorffEstimate toPatch =
    OneSidedHausdorff(pieces, targets, enough - slack, giveUp - slack, budget, { nullptr, patchOffsets }, nullptr,
      std::max(toSurface.Lower, anyWithin)); // (error.Lower takes the maximum with the former, error.Upper with
                                             // toSurface.Upper, at least it)
  error.Lower = std::max(error.Lower, toPatch.Lower);
  const double upper = std::max(toSurface.Upper, toPatch.Upper) + slack;
  error.Upper = upper <= giveUp ? upper : HUGE_VAL;
  return error;
}

std::vector<Vec3> CreaseApexes(const Box3& cell, const std::vector<CreaseSegment>& creases, const Vec3& apex)
{
  const Box3 inner = cell.Shrunk(1.0 / 32.0);
  std::vector<std::pair<double, Vec3>> candidates;
  for (const CreaseSegment& c : creases)
  {
    const Vec3 ab = c.B - c.A;
    const double length2 = Dot(ab, ab);
    const double t = length2 > 0.0 ? std::clamp(Dot(apex - c.A, ab) / length2, 0.0, 1.0) : 0.0;
    const Vec3 onCrease = inner.Clamp(c.A + ab * t);
    candidates.emplace_back(Norm(onCrease - apex), onCrease);
  }
  // (Ties by position, so that equal points are neighbours: each is kept once.)
  std::sort(candidates.begin(), candidates.end(), [](const auto& a, const auto& b) {
    return a.first != b.first ? a.first < b.first
                              : std::lexicographical_compare(a.second.x, a.second.x + 3, b.second.x, b.second.x + 3);
  });
  std::vector<Vec3> apexes;
  for (const auto& [distance, point] : candidates)
  {
    if (apexes.empty() || Norm(point - apexes.back()) != 0.0)
    {
      apexes.push_back(point);
    }
  }
  return apexes;
}

std::vector<std::vector<Vec3>> CreaseApexSets(const Box3& cell, const std::vector<CreaseSegment>& creases,
  const std::vector<std::vector<Vec3>>& loops, const std::vector<Vec3>& apexes)
{
  std::vector<std::vector<Vec3>> sets;
  if (loops.size() == 1)
  {
    for (const Vec3& apex : CreaseApexes(cell, creases, apexes[0]))
    {
      sets.push_back({ apex });
    }
    return sets;
  }
  // (Where no loop has a crease point in its room, no set: the fans around
  // the loops' own apexes are the ones that missed.)
  const std::vector<ApexRoom> rooms = ApexRooms(loops, cell);
  std::vector<std::vector<Vec3>> perLoop(loops.size());
  bool any = false;
  for (std::size_t l = 0; l < loops.size(); ++l)
  {
    perLoop[l] = InRoomOnly(CreaseApexes(rooms[l].Region, creases, apexes[l]), rooms[l]);
    any = any || !perLoop[l].empty();
    if (perLoop[l].empty())
    {
      perLoop[l].push_back(apexes[l]);
    }
  }
  return any ? KthApexSets(perLoop, SeveralLoopsCreaseTries) : std::vector<std::vector<Vec3>>();
}

bool PredictCreaseApex(const PolygonSet& surface, const Box3& cell, const std::vector<CreaseSegment>& creases,
  double reach, double slack, double tolerance, AdaptiveOctree::MeshCellPrediction& prediction)
{
  const double delta = prediction.Delta;
  if (prediction.Loops.empty() || !(delta < tolerance))
  {
    return false;
  }
  for (const std::vector<Vec3>& apexes : CreaseApexSets(cell, creases, prediction.Loops, prediction.Apexes))
  {
    const std::vector<SourceTriangle> fan = ApexFans(prediction.Loops, apexes);
    if (!CreasesFollowed(creases, fan, reach))
    {
      continue;
    }
    const HausdorffEstimate error = CertifiedMeshPatchError(surface, fan, slack, tolerance - delta,
      tolerance - delta, PredictionBudget, nullptr, PredictionPrecision * tolerance);
    if (error.Upper + delta <= tolerance)
    {
      prediction.Apexes = apexes;
      prediction.Creases = AdaptiveOctree::MeshCellPrediction::CreaseFans::ApexFanFollows;
      prediction.Bound = error.Upper + delta;
      prediction.OwnFanError = error.Upper;
      prediction.Attained = error.Lower;
      return true;
    }
  }
  return false;
}

std::vector<SourceTriangle> ApexFan(const std::vector<Vec3>& loop, const Vec3& apex)
{
  std::vector<SourceTriangle> fan;
  for (std::size_t k = 0; k < loop.size(); ++k)
  {
    fan.push_back({ loop[k], loop[(k + 1) % loop.size()], apex });
  }
  return fan;
}

std::vector<SourceTriangle> ApexFans(const std::vector<std::vector<Vec3>>& loops, const std::vector<Vec3>& apexes)
{
  std::vector<SourceTriangle> fans;
  for (std::size_t l = 0; l < loops.size(); ++l)
  {
    const std::vector<SourceTriangle> fan = ApexFan(loops[l], apexes[l]);
    fans.insert(fans.end(), fan.begin(), fan.end());
  }
  return fans;
}

bool PlaceLoopPoints(const CsgExpression& expression, const PrimitiveSet& primitives, const RootGrid& grid,
  const std::vector<Crossing>& loop, std::vector<Vec3>& points)
{
  const CsgLeaf* leaf = LoneMeshLeaf(expression);
  points.assign(loop.size(), Vec3());
  if (!leaf)
  {
    return false;
  }
  const MeshArrangement arrangement(primitives.Meshes[leaf->Primitive], grid);
  for (std::size_t k = 0; k < loop.size(); ++k)
  {
    const Crossing& c = loop[k];
    if (c.Kind == CrossingKind::MeshEdge)
    {
      points[k] = arrangement.Position(ArrangementPoint::EdgeOnPlane(static_cast<std::uint32_t>(c.Partner >> 32),
        static_cast<std::uint32_t>(c.Partner & 0xFFFFFFFFu), PlaneAxis(c.Key), PlaneCoordinate(c.Key)));
    }
    else if (c.Kind == CrossingKind::SubEdge)
    {
      points[k] = PlaceSubEdgeCrossing(c, grid, expression, primitives);
    }
    else
    {
      return false;
    }
  }
  return true;
}

bool MeasureChords(const PolygonSet& surface, const RootGrid& grid, const CellBoundary& boundary,
  const std::vector<Crossing>& loop, const std::vector<Vec3>& points, double stopAbove,
  std::vector<ChordTile>& chords)
{
  const std::size_t m = loop.size();
  chords.clear();
  double delta = 0.0;
  for (std::size_t k = 0; k < m && delta <= stopAbove; ++k)
  {
    const int f = CommonFace(loop[k], loop[(k + 1) % m], boundary);
    if (f < 0)
    {
      return false;
    }
    const Crossing &p = loop[k], &q = loop[(k + 1) % m];
    const Vec3 &a = points[k], &b = points[(k + 1) % m];
    const int axis = f / 2;
    ChordTile chord;
    chord.Face = f;
    for (std::size_t t = 0; t < boundary.Tiles[f].size(); ++t)
    {
      const FaceTile& tile = boundary.Tiles[f][t];
      if (p.Kind == CrossingKind::MeshEdge || q.Kind == CrossingKind::MeshEdge)
      {
        // The crease tile whose crease crossing this is (marked in
        // boundary.Creases with its halves).
        const bool fromCrease = p.Kind == CrossingKind::MeshEdge;
        const Crossing& x = fromCrease ? p : q;
        const std::optional<CreaseTile>* crease =
          t < boundary.Creases[f].size() ? &boundary.Creases[f][t] : nullptr;
        if (crease && *crease && (*crease)->X.SameVertex(x))
        {
          chord.Tile = t;
          chord.Deviation = CreaseChordDeviation(**crease, fromCrease ? b : a);
          break;
        }
      }
      else if (HoldsSubEdge(tile, axis, p) && HoldsSubEdge(tile, axis, q))
      {
        chord.Tile = t;
        chord.Deviation = ChordDeviation(surface, TileBox(grid, boundary, f, tile), a, b);
        break;
      }
    }
    if (!(chord.Deviation >= 0.0))
    {
      return false; // (a NaN from degenerate input would fall out of max and the offsets' order)
    }
    chords.push_back(chord);
    delta = std::max(delta, chord.Deviation);
  }
  return true;
}

int RefineChordTiles(const CsgExpressionPtr& expression, const PrimitiveSet& primitives, const RootGrid& grid,
  const PolygonSet& surface, bool creaseTiles, double threshold, int levels, CellSignCache& signs,
  CellBoundary& boundary)
{
  const CsgLeaf* leaf = LoneMeshLeaf(*expression);
  if (!leaf)
  {
    return 0;
  }
  // (The crease tiles are marked on entry; again after each round that
  // split tiles.)
  int splits = 0;
  for (int round = 0; round < ChordRefinementRounds; ++round)
  {
    const BoundaryLoopSet loops = TraceBoundaryLoops(boundary);
    std::vector<Vec3> points;
    std::vector<ChordTile> chords;
    if (loops.LoopSizes.size() != 1 || !loops.Consistent ||
      !PlaceLoopPoints(*expression, primitives, grid, loops.Crossings, points) ||
      !MeasureChords(surface, grid, boundary, loops.Crossings, points, HUGE_VAL, chords))
    {
      return splits;
    }
    // The tiles to split, each once, highest index first so that erasing
    // one leaves the others' indices.
    std::vector<std::pair<int, std::size_t>> wide;
    for (const ChordTile& c : chords)
    {
      if (c.Tile == ChordTile::NoTile)
      {
        continue;
      }
      const FaceTile& t = boundary.Tiles[c.Face][c.Tile];
      // (Crease tiles stay whole: header, Chords refined.)
      const bool creaseTile = c.Tile < boundary.Creases[c.Face].size() && boundary.Creases[c.Face][c.Tile];
      if (c.Deviation > threshold && !creaseTile && t.U1 - t.U0 >= 2 && t.V1 - t.V0 >= 2)
      {
        wide.emplace_back(c.Face, c.Tile);
      }
    }
    std::sort(wide.begin(), wide.end());
    wide.erase(std::unique(wide.begin(), wide.end()), wide.end());
    int splitNow = 0;
    for (auto w = wide.rbegin(); w != wide.rend(); ++w)
    {
      const int f = w->first, axis = f / 2;
      const LatticeIndex plane = boundary.Base[axis] + (f % 2 ? boundary.Size : 0);
      const FaceTile t = boundary.Tiles[f][w->second];
      const LatticeIndex um = t.U0 + (t.U1 - t.U0) / 2, vm = t.V0 + (t.V1 - t.V0) / 2;
      std::vector<FaceTile> quadrants;
      bool passed = true;
      for (const FaceTile& q : { FaceTile{ t.U0, t.V0, um, vm }, FaceTile{ um, t.V0, t.U1, vm },
             FaceTile{ t.U0, vm, um, t.V1 }, FaceTile{ um, vm, t.U1, t.V1 } })
      {
        const FaceRefinementResult r = RefineFace(expression, primitives, grid, axis, plane, q, levels, signs);
        passed = passed && !r.Tiles.empty();
        quadrants.insert(quadrants.end(), r.Tiles.begin(), r.Tiles.end());
      }
      if (!passed)
      {
        continue;
      }
      std::vector<FaceTile>& tiles = boundary.Tiles[f];
      tiles.erase(tiles.begin() + static_cast<std::ptrdiff_t>(w->second));
      tiles.insert(tiles.end(), quadrants.begin(), quadrants.end());
      if (w->second < boundary.Creases[f].size())
      {
        boundary.Creases[f].clear(); // (marked again on the finer tiles)
      }
      for (const FaceTile& q : quadrants)
      {
        for (int c = 0; c < 4; ++c)
        {
          const PointKey key = TileCorner(axis, plane, q, c);
          boundary.Points.emplace_back(key, signs.Inside(key));
        }
      }
      ++splitNow;
    }
    splits += splitNow;
    if (splitNow == 0)
    {
      break;
    }
    if (creaseTiles)
    {
      MarkCreaseTiles(boundary, *leaf, primitives, grid, [](int, std::size_t) { return true; });
    }
  }
  return splits;
}

namespace
{
/// The largest distance from an apex of `apexes` to S_C `surface`: a
/// distance the fans attain (a lower bound of E(P)).
double ApexesAttained(const PolygonSet& surface, const std::vector<Vec3>& apexes)
{
  double attained = 0.0;
  for (const Vec3& apex : apexes)
  {
    double nearest = HUGE_VAL;
    for (std::size_t i = 0; i < surface.size(); ++i)
    {
      // (A polygon whose box is farther than the nearest so far is too.)
      if (!(surface.Bounds(i).Distance2(apex) >= nearest * nearest))
      {
        nearest = std::min(nearest, surface.Distance(apex, i));
      }
    }
    attained = std::max(attained, nearest < HUGE_VAL ? nearest : 0.0);
  }
  return attained;
}

/// Whether one of the fans over `loops` around the sets of crease points
/// CreaseApexSets gives for `apexes` follows every crease of `creases`
/// within `reach` (header: Creases first).
bool CreaseApexFanFollows(const Box3& cell, const std::vector<CreaseSegment>& creases, double reach,
  const std::vector<std::vector<Vec3>>& loops, const std::vector<Vec3>& apexes)
{
  const std::vector<std::vector<Vec3>> others = CreaseApexSets(cell, creases, loops, apexes);
  return std::any_of(others.begin(), others.end(),
    [&](const std::vector<Vec3>& set) { return CreasesFollowed(creases, ApexFans(loops, set), reach); });
}
} // namespace

double PredictedMeshCellError(const CsgExpression& expression, const PrimitiveSet& primitives,
  const RootGrid& grid, const Box3& cell, const CellBoundary& boundary, const BoundaryLoopSet& loops,
  double tolerance, AdaptiveOctree::MeshCellPrediction& prediction, const PolygonSet* given,
  const TriangleList* givenTriangles, bool probesFirst, const std::vector<CreaseSegment>* creases,
  bool sceneOfOneMesh)
{
  prediction = AdaptiveOctree::MeshCellPrediction();
  const CsgLeaf* leaf = LoneMeshLeaf(expression);
  if (!leaf || loops.LoopSizes.empty() || !loops.Consistent ||
    *std::min_element(loops.LoopSizes.begin(), loops.LoopSizes.end()) < 3)
  {
    return HUGE_VAL;
  }
  PolygonSet computed;
  TriangleList computedTriangles;
  if (!given)
  {
    SurfaceInCell(*leaf, primitives, cell, computed, &computedTriangles);
  }
  const PolygonSet& surface = given ? *given : computed;
  const TriangleList* surfaceTriangles = given ? givenTriangles : &computedTriangles;
  // Each loop's points, and delta_k: each chord against the trace on its
  // tile (on a crease tile, against its half of the trace), loop by loop in
  // the fan's order.
  const std::vector<std::vector<Crossing>> each = EachLoop(loops);
  std::vector<std::vector<Vec3>> points(each.size());
  std::vector<double> chordDelta;
  double delta = 0.0;
  for (std::size_t l = 0; l < points.size(); ++l)
  {
    const std::vector<Crossing>& loop = each[l];
    std::vector<ChordTile> chords;
    if (!PlaceLoopPoints(expression, primitives, grid, loop, points[l]) ||
      !MeasureChords(surface, grid, boundary, loop, points[l], tolerance, chords))
    {
      return HUGE_VAL;
    }
    for (std::size_t k = 0; k < loop.size(); ++k)
    {
      chordDelta.push_back(k < chords.size() ? chords[k].Deviation : HUGE_VAL);
      delta = std::max(delta, chordDelta.back());
    }
    if (!(delta < tolerance))
    {
      return HUGE_VAL;
    }
  }
  const double slack = RoundingSlack(*leaf, primitives, cell);
  delta += slack; // (the final points lie on S up to rounding)
  if (!(delta < tolerance))
  {
    return HUGE_VAL;
  }
  for (double& d : chordDelta)
  {
    d += slack;
  }
  prediction.Delta = delta;
  // The apexes: S_C's for a lone loop; each loop's own in its room where
  // there are several (header: Several loops).
  std::vector<Vec3> apexes;
  if (points.size() == 1)
  {
    apexes.push_back(MeshCellApex(surface, cell));
  }
  else
  {
    const std::vector<ApexRoom> rooms = ApexRooms(points, cell);
    for (std::size_t l = 0; l < points.size(); ++l)
    {
      apexes.push_back(LoopApex(surface, rooms[l], points[l]));
    }
  }
  const std::vector<SourceTriangle> fan = ApexFans(points, apexes);
  if (probesFirst && FanPointStrays(surface, fan, chordDelta, slack, tolerance))
  {
    prediction.ProbeStrayed = true;
    return HUGE_VAL;
  }
  if (probesFirst && creases && !creases->empty())
  {
    using CreaseFans = AdaptiveOctree::MeshCellPrediction::CreaseFans;
    const double reach = CreaseReach * tolerance;
    prediction.Creases = CreasesFollowed(*creases, fan, reach) ? CreaseFans::ApexFanFollows
      : CreaseApexFanFollows(cell, *creases, reach, points, apexes) ? CreaseFans::OtherFanFollows
                                                                     : CreaseFans::NoneFollows;
    if (prediction.Creases == CreaseFans::NoneFollows)
    {
      return HUGE_VAL;
    }
  }
  // Where S_C and the fan face one way, the slab they lie in - or its local
  // heights - bound E(P), or sheet by sheet where S_C is several (header: Slab
  // bound); else, or where those bounds are too wide, the branch and bound.
  const MeshSolid& mesh = primitives.Meshes[leaf->Primitive];
  const bool slabApplies = surfaceTriangles && sceneOfOneMesh && mesh.EveryEdgeHasTwoTriangles();
  const double within = tolerance - delta;
  const OwnChords own{ &points, &chordDelta, HUGE_VAL, false, cell };
  double slab = slabApplies ? SlabPatchError(mesh, *surfaceTriangles, surface, fan, delta, slack, own, within, within)
                            : HUGE_VAL;
  if (slabApplies && !(slab <= within) && points.size() > 1)
  {
    std::vector<std::vector<SourceTriangle>> fans; // (the fan's triangles loop by loop: ApexFans)
    for (std::size_t l = 0, first = 0; l < points.size(); first += points[l].size(), ++l)
    {
      fans.emplace_back(fan.begin() + static_cast<std::ptrdiff_t>(first),
        fan.begin() + static_cast<std::ptrdiff_t>(first + points[l].size()));
    }
    slab = std::min(
      slab, SheetwiseSlabError(mesh, *surfaceTriangles, surface, cell, points, own, fans, delta, slack, within, within));
  }
  if (slab + delta <= tolerance)
  {
    prediction.Loops = std::move(points);
    prediction.Apexes = std::move(apexes);
    prediction.Attained = ApexesAttained(surface, prediction.Apexes);
    prediction.OwnFanError = slab;
    prediction.Bound = slab + delta;
    return prediction.Bound;
  }
  const double anyWithin = sceneOfOneMesh ? PredictionPrecision * tolerance : 0.0;
  const HausdorffEstimate error = CertifiedMeshPatchError(
    surface, fan, slack, tolerance - delta, tolerance - delta, PredictionBudget, nullptr, anyWithin);
  prediction.Loops = std::move(points);
  prediction.Apexes = std::move(apexes);
  prediction.Attained = error.Lower;
  prediction.OwnFanError = error.Upper;
  prediction.Bound = error.Upper == HUGE_VAL ? HUGE_VAL : error.Upper + delta;
  // E(P) + delta failed: the per-chord bound (header), where the chords'
  // deviations differ and the fan's attained distance leaves room for the
  // smallest. (It bounds E(P) too - the offsets are >= 0 - but OwnFanError
  // stays unproven, +inf: the extraction reads it as how close the apex fan
  // itself is, MeshCellFromLoopPoint.)
  const double leastDelta = *std::min_element(chordDelta.begin(), chordDelta.end());
  if (prediction.Bound == HUGE_VAL && leastDelta < delta && error.Lower + leastDelta < tolerance)
  {
    prediction.Bound =
      CertifiedMeshPatchError(surface, fan, slack, tolerance, tolerance, PredictionBudget, &chordDelta, anyWithin)
        .Upper;
  }
  return prediction.Bound;
}

namespace
{
/// The least |n[axis]| of the unit normal n of a triangle crossing a cell
/// edge for SpokeStrays to use the crossing (header, Spokes).
constexpr double WellCrossed = 1e-3;

/// The most sheets of S_C whose apexes SheetSpokesStray finds (a pass over
/// S_C each): a large cell of many sheets - the turbine's blades side by
/// side - rarely has fans within the tolerance, and the one apex's spokes
/// split it as before.
constexpr std::uint32_t MostSheetsAsked = 8;

/// S_C's sheets (header: Spokes): each polygon's sheet, in S_C's order.
struct SurfaceSheets
{
  std::vector<std::uint32_t> SheetOf; ///< each one's sheet, 0 .. Count - 1
  std::uint32_t Count = 0;
};

/// S_C's polygons' triangles `meeting` (the listed ones that meet the cell,
/// in the list's order: SurfaceInCell's `triangles`) joined into sheets
/// across mesh edges that meet the closed cell.
SurfaceSheets SheetsInCell(const MeshSolid& mesh, const TriangleList& meeting, const Box3& cell)
{
  SurfaceSheets sheets;
  // (Pruning keeps its parent's order, so the list - and the part of it
  // that meets the cell - is in order, and SheetSpokesStray finds a
  // triangle's sheet by bisection; were it not, no sheets are told apart.)
  if (!std::is_sorted(meeting.begin(), meeting.end()))
  {
    return sheets;
  }
  // Each triangle's place in the list, by its number: a lookup per edge
  // (open addressing, at most half full), where a bisection per edge was
  // most of the time of this function in a large cell. (A table over the
  // whole mesh would be as fast, but kept per thread it would hold four
  // bytes a triangle of the largest mesh ever asked about.)
  int bits = 4;
  while ((std::size_t{ 1 } << bits) < 2 * meeting.size())
  {
    ++bits;
  }
  const std::size_t mask = (std::size_t{ 1 } << bits) - 1;
  const auto slotOf = [&](std::uint32_t t) {
    return static_cast<std::size_t>((static_cast<std::uint64_t>(t) * 0x9E3779B97F4A7C15ull) >> (64 - bits));
  };
  std::vector<std::pair<std::uint32_t, std::uint32_t>> places(mask + 1, { MeshSolid::NoTriangle, 0 });
  for (std::size_t i = 0; i < meeting.size(); ++i)
  {
    std::size_t k = slotOf(meeting[i]);
    while (places[k].first != MeshSolid::NoTriangle)
    {
      k = (k + 1) & mask;
    }
    places[k] = { meeting[i], static_cast<std::uint32_t>(i) };
  }
  const auto placeOf = [&](std::uint32_t t, std::uint32_t& place) {
    for (std::size_t k = slotOf(t);; k = (k + 1) & mask)
    {
      if (places[k].first == t)
      {
        place = places[k].second;
        return true;
      }
      if (places[k].first == MeshSolid::NoTriangle)
      {
        return false;
      }
    }
  };
  UnionFind joined(meeting.size());
  for (std::size_t i = 0; i < meeting.size(); ++i)
  {
    for (int k = 0; k < 3; ++k)
    {
      const std::uint32_t u = mesh.Across(meeting[i], k);
      std::uint32_t j = 0;
      Vec3 a = mesh.Vertex(meeting[i], k), b = mesh.Vertex(meeting[i], (k + 1) % 3);
      // (An end in the closed cell is an edge meeting it - ClipSegment
      // says so too, at more cost: in a large cell most edges have both.)
      if (u != MeshSolid::NoTriangle && placeOf(u, j) &&
        (cell.Contains(a) || cell.Contains(b) || ClipSegment(a, b, cell)))
      {
        joined.Join(static_cast<std::uint32_t>(i), j);
      }
    }
  }
  std::vector<std::uint32_t> number(meeting.size(), UINT32_MAX);
  for (std::size_t i = 0; i < meeting.size(); ++i)
  {
    std::uint32_t& sheet = number[joined.Find(static_cast<std::uint32_t>(i))];
    sheet = sheet == UINT32_MAX ? sheets.Count++ : sheet;
    sheets.SheetOf.push_back(sheet);
  }
  return sheets;
}

/// The polygons of S_C `surface` that may lie within `reach` of a point of
/// the cell's loops `loops`: all but those whose boxes lie deeper inside
/// `cell` than off + 2 reach, off the largest distance of a loop point to
/// its nearest face's plane. (A loop point p lies within off of some face's
/// plane, a point x of such a box farther than off + 2 reach from it: x and
/// p are more than 2 reach apart across it - twice, so that the
/// comparisons' rounding, far smaller, cannot matter.) In a large cell most
/// of S_C's polygons are inside, and SheetOfLoop looked at every one for
/// every point.
std::vector<std::uint32_t> PolygonsNearLoops(
  const PolygonSet& surface, const std::vector<std::vector<Vec3>>& loops, const Box3& cell, double reach)
{
  double off = 0.0; // (the loop points' largest distance to the nearest face)
  for (const std::vector<Vec3>& loop : loops)
  {
    for (const Vec3& p : loop)
    {
      double nearest = HUGE_VAL;
      for (int a = 0; a < 3; ++a)
      {
        nearest = std::min({ nearest, std::fabs(p[a] - cell.lo[a]), std::fabs(cell.hi[a] - p[a]) });
      }
      off = std::max(off, nearest);
    }
  }
  const double inside = off + 2.0 * reach;
  std::vector<std::uint32_t> near;
  for (std::size_t i = 0; i < surface.size(); ++i)
  {
    const Box3& b = surface.Bounds(i);
    bool deep = true;
    for (int a = 0; a < 3; ++a)
    {
      deep = deep && b.lo[a] - cell.lo[a] > inside && cell.hi[a] - b.hi[a] > inside;
    }
    if (!deep)
    {
      near.push_back(static_cast<std::uint32_t>(i));
    }
  }
  return near;
}

/// The sheet of S_C `surface` (its polygons' sheets `sheets`) every point of
/// `loop` lies on within `reach` - the one sheet near each - or NoSheet.
/// `near`: the polygons that may be within `reach` of it (PolygonsNearLoops).
std::uint32_t SheetOfLoop(const PolygonSet& surface, const SurfaceSheets& sheets, const std::vector<Vec3>& loop,
  double reach, const std::vector<std::uint32_t>& near)
{
  constexpr std::uint32_t NoSheet = UINT32_MAX;
  std::uint32_t found = NoSheet;
  for (const Vec3& p : loop)
  {
    bool onOne = false;
    for (const std::uint32_t i : near)
    {
      if (surface.Bounds(i).Distance2(p) <= reach * reach && surface.Distance(p, i) <= reach)
      {
        if (found != NoSheet && sheets.SheetOf[i] != found)
        {
          return NoSheet;
        }
        found = sheets.SheetOf[i];
        onOne = true;
      }
    }
    if (!onOne)
    {
      return NoSheet;
    }
  }
  return found;
}

/// Whether no mesh vertex in the closed `cell` is a corner of triangles of
/// two sheets (`sheets`, over S_C's triangles `meeting`).
bool SheetsApartInCell(
  const MeshSolid& mesh, const TriangleList& meeting, const SurfaceSheets& sheets, const Box3& cell)
{
  std::vector<std::pair<std::uint32_t, std::uint32_t>> corners; // (vertex, sheet)
  for (std::size_t i = 0; i < meeting.size(); ++i)
  {
    for (int k = 0; k < 3; ++k)
    {
      if (cell.Contains(mesh.Vertex(meeting[i], k)))
      {
        corners.emplace_back(mesh.Triangles()[meeting[i]][k], sheets.SheetOf[i]);
      }
    }
  }
  std::sort(corners.begin(), corners.end());
  for (std::size_t i = 1; i < corners.size(); ++i)
  {
    if (corners[i].first == corners[i - 1].first && corners[i].second != corners[i - 1].second)
    {
      return false;
    }
  }
  return true;
}

} // namespace

double SheetwiseSlabError(const MeshSolid& mesh, const TriangleList& surfaceTriangles, const PolygonSet& surface,
  const Box3& cell, const std::vector<std::vector<Vec3>>& loops, const OwnChords& chords,
  const std::vector<std::vector<SourceTriangle>>& fans, double chordReach, double slack, double enough,
  double giveUp)
{
  std::size_t chordCount = 0;
  for (const std::vector<Vec3>& loop : loops)
  {
    chordCount += loop.size();
  }
  if (surfaceTriangles.size() != surface.size() || fans.size() != loops.size() ||
    (chords.Deltas && chords.Deltas->size() != chordCount))
  {
    return HUGE_VAL;
  }
  const SurfaceSheets sheets = SheetsInCell(mesh, surfaceTriangles, cell);
  if (sheets.Count < 2 || sheets.Count > loops.size() || !SheetsApartInCell(mesh, surfaceTriangles, sheets, cell))
  {
    return HUGE_VAL;
  }
  std::vector<std::uint32_t> sheetOf(loops.size());
  std::vector<bool> hasLoop(sheets.Count, false);
  const std::vector<std::uint32_t> near = PolygonsNearLoops(surface, loops, cell, slack);
  for (std::size_t l = 0; l < loops.size(); ++l)
  {
    sheetOf[l] = SheetOfLoop(surface, sheets, loops[l], slack, near);
    if (sheetOf[l] >= sheets.Count)
    {
      return HUGE_VAL;
    }
    hasLoop[sheetOf[l]] = true;
  }
  if (std::find(hasLoop.begin(), hasLoop.end(), false) != hasLoop.end())
  {
    return HUGE_VAL;
  }
  // Each sheet with its loops, their fans and chords, bounded on its own.
  double largest = 0.0;
  for (std::uint32_t s = 0; s < sheets.Count; ++s)
  {
    PolygonSet part;
    part.SetSlackMagnitude(surface.GetSlackMagnitude());
    TriangleList partTriangles;
    for (std::size_t i = 0; i < surface.size(); ++i)
    {
      if (sheets.SheetOf[i] == s)
      {
        part.AddCopy(surface, i);
        partTriangles.push_back(surfaceTriangles[i]);
      }
    }
    std::vector<std::vector<Vec3>> partLoops;
    std::vector<double> partDeltas;
    std::vector<SourceTriangle> partFan;
    for (std::size_t l = 0, first = 0; l < loops.size(); first += loops[l].size(), ++l)
    {
      if (sheetOf[l] == s)
      {
        partLoops.push_back(loops[l]);
        if (chords.Deltas)
        {
          partDeltas.insert(partDeltas.end(), chords.Deltas->begin() + first,
            chords.Deltas->begin() + first + loops[l].size());
        }
        partFan.insert(partFan.end(), fans[l].begin(), fans[l].end());
      }
    }
    const OwnChords own{ &partLoops, chords.Deltas ? &partDeltas : nullptr, chords.Delta, chords.Refined, cell };
    largest = std::max(
      largest, SlabPatchError(mesh, partTriangles, part, partFan, chordReach, slack, own, enough, giveUp));
    if (!(largest <= giveUp))
    {
      return HUGE_VAL; // (a bound of some sheets only proves nothing of E(P))
    }
  }
  return largest;
}

namespace
{
/// Whether an apex `apexOf(t)` or a point of a spoke to it from the crossing
/// of a cell edge that S crosses once (t the crossed triangle) strays farther
/// than `reach` from S_C (header: Spokes).
template <typename ApexOf>
bool SpokeFromApexStrays(const CsgLeaf& leaf, const PrimitiveSet& primitives, const Box3& cell,
  unsigned insideCorners, const PolygonSet& surface, double reach, const ApexOf& apexOf)
{
  const MeshSolid& mesh = primitives.Meshes[leaf.Primitive];
  for (int axis = 0; axis < 3; ++axis)
  {
    for (int c = 0; c < 8; ++c)
    {
      const int d = c | (1 << axis);
      if (c == d || ((insideCorners >> c) & 1u) == ((insideCorners >> d) & 1u))
      {
        continue; // (each edge once, from its lower corner; only edges with a sign change)
      }
      Vec3 x;
      std::uint32_t crossed = 0;
      if (!mesh.CrossingPoint(cell.Corner(c), cell.Corner(d), axis, *leaf.Triangles, x, &crossed) ||
        std::fabs(mesh.Normal(crossed)[axis]) < WellCrossed)
      {
        continue; // (crossed more than once, or nearly along a triangle: header, Spokes)
      }
      const Vec3 apex = apexOf(crossed);
      for (const double s : { 0.25, 0.5, 0.75 })
      {
        if (!WithinReach(surface, apex + (x - apex) * s, reach))
        {
          return true;
        }
      }
    }
  }
  return false;
}
} // namespace

bool SpokeStrays(const CsgLeaf& leaf, const PrimitiveSet& primitives, const Box3& cell, unsigned insideCorners,
  const PolygonSet& surface, double tolerance)
{
  if (surface.empty() || !leaf.Triangles)
  {
    return false;
  }
  // (The slack covers the rounding of the crossings, the apex and the
  // distances here and in the prediction, as there: header, Rounding.)
  const double reach = tolerance + RoundingSlack(leaf, primitives, cell);
  const Vec3 apex = MeshCellApex(surface, cell);
  return !WithinReach(surface, apex, reach) ||
    SpokeFromApexStrays(leaf, primitives, cell, insideCorners, surface, reach, [&](std::uint32_t) { return apex; });
}

bool SheetSpokesStray(const CsgLeaf& leaf, const PrimitiveSet& primitives, const Box3& cell, unsigned insideCorners,
  const PolygonSet& surface, const TriangleList& surfaceTriangles, double tolerance)
{
  if (surfaceTriangles.size() != surface.size())
  {
    return true;
  }
  const SurfaceSheets sheets = SheetsInCell(primitives.Meshes[leaf.Primitive], surfaceTriangles, cell);
  if (sheets.Count <= 1 || sheets.Count > MostSheetsAsked)
  {
    return true;
  }
  const double reach = tolerance + RoundingSlack(leaf, primitives, cell);
  std::vector<Vec3> apexes(sheets.Count);
  for (std::uint32_t s = 0; s < sheets.Count; ++s)
  {
    apexes[s] =
      LeastSquaresApex(surface, cell, LoopApexMargin, [&](std::size_t i) { return sheets.SheetOf[i] == s; });
    if (!WithinReach(surface, apexes[s], reach))
    {
      return true;
    }
  }
  const Vec3 apex = MeshCellApex(surface, cell);
  return SpokeFromApexStrays(leaf, primitives, cell, insideCorners, surface, reach, [&](std::uint32_t t) {
    const auto i = std::lower_bound(surfaceTriangles.begin(), surfaceTriangles.end(), t);
    const bool found = i != surfaceTriangles.end() && *i == t;
    return found ? apexes[sheets.SheetOf[static_cast<std::size_t>(i - surfaceTriangles.begin())]] : apex;
  });
}

bool FinalLoopRefines(const std::vector<Vec3>& own, const std::vector<Vec3>& final, const Box3& cell)
{
  if (own.empty() || final.size() < own.size())
  {
    return false;
  }
  // (Crossings named by a finer sub-edge are placed on the same triangle's
  // plane, then kept strictly inside their sub-edge: equal up to an ulp.)
  const double tolerance = 64.0 * DBL_EPSILON * cell.Magnitude();
  const auto same = [&](const Vec3& x, const Vec3& y) {
    for (int a = 0; a < 3; ++a)
    {
      if (!(std::fabs(x[a] - y[a]) <= tolerance))
      {
        return false;
      }
    }
    return true;
  };
  const std::size_t n = final.size();
  std::size_t start = 0;
  while (start < n && !same(final[start], own[0]))
  {
    ++start;
  }
  if (start == n)
  {
    return false;
  }
  std::size_t next = 1;
  for (std::size_t k = 1; k < n && next < own.size(); ++k)
  {
    next += same(final[(start + k) % n], own[next]) ? 1 : 0;
  }
  return next == own.size();
}

bool SameLoop(const std::vector<Vec3>& own, const std::vector<Vec3>& final)
{
  const std::size_t n = own.size();
  if (n == 0 || final.size() != n)
  {
    return false;
  }
  const auto equal = [](const Vec3& x, const Vec3& y) { return x[0] == y[0] && x[1] == y[1] && x[2] == y[2]; };
  const auto start = std::find_if(final.begin(), final.end(), [&](const Vec3& p) { return equal(p, own[0]); });
  if (start == final.end())
  {
    return false;
  }
  const std::size_t offset = static_cast<std::size_t>(start - final.begin());
  for (std::size_t k = 1; k < n; ++k)
  {
    if (!equal(final[(offset + k) % n], own[k]))
    {
      return false;
    }
  }
  return true;
}

} // namespace tpc
