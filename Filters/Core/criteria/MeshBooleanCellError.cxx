#include "MeshBooleanCellError.h"

#include "CsgCreaseCrossing.h"
#include "MeshCellError.h"

#include <algorithm>
#include <cmath>
#include <vector>

namespace tpc
{
namespace
{
/// Pieces the prediction's branch and bound may examine per direction (a
/// cell whose bound needs more is split instead, as in MeshCellError.cxx).
constexpr std::size_t PredictionBudget = 1024;

/// How far S's trace on the cell's faces strays from the loops `loops`
/// (header: The prediction): the covering pieces clipped to each face, at
/// their corners.
double TraceDeviation(const PolygonSet& covering, const Box3& cell, const std::vector<std::vector<Vec3>>& loops)
{
  const auto fromLoop = [&](const Vec3& p) {
    double nearest = HUGE_VAL;
    for (const std::vector<Vec3>& loop : loops)
    {
      for (std::size_t k = 0; k < loop.size(); ++k)
      {
        nearest = std::min(nearest, SegmentDistance(p, loop[k], loop[(k + 1) % loop.size()]));
      }
    }
    return nearest;
  };
  double deviation = 0.0;
  for (int f = 0; f < 6; ++f)
  {
    const int axis = f / 2;
    Box3 face = cell;
    face.lo[axis] = face.hi[axis] = f % 2 ? cell.hi[axis] : cell.lo[axis];
    deviation = std::max(deviation, LargestOverClippedCorners(covering, face, fromLoop));
  }
  return deviation;
}
} // namespace

bool IsCertifiableMeshBoolean(const CsgExpression& expression)
{
  const std::vector<CsgLeaf> leaves = MeshBooleanLeaves(expression);
  std::size_t listed = 0;
  for (const CsgLeaf& leaf : leaves)
  {
    listed += leaf.Triangles->size();
  }
  return !leaves.empty() && listed <= BooleanFanTriangles;
}

std::vector<Vec3> ApexesOnCreases(const Box3& cell, const std::vector<CreaseSegment>& creases, const Vec3& planesPoint)
{
  const Box3 inner = cell.Shrunk(1.0 / 32.0);
  std::vector<std::pair<double, Vec3>> candidates;
  for (const CreaseSegment& c : creases)
  {
    Vec3 a = c.A, b = c.B;
    if (!ClipSegment(a, b, inner))
    {
      continue;
    }
    const Vec3 ab = b - a;
    const double length2 = Dot(ab, ab);
    const double t = length2 > 0.0 ? std::clamp(Dot(planesPoint - a, ab) / length2, 0.0, 1.0) : 0.0;
    const Vec3 onCrease = a + ab * t;
    candidates.emplace_back(Norm(onCrease - planesPoint), onCrease);
  }
  // (Ties by position, so that equal points - segments sharing an end - are
  // neighbours: each is kept once.)
  std::sort(candidates.begin(), candidates.end(), [](const auto& x, const auto& y) {
    return x.first != y.first ? x.first < y.first
                              : std::lexicographical_compare(x.second.x, x.second.x + 3, y.second.x, y.second.x + 3);
  });
  std::vector<Vec3> apexes;
  for (std::size_t k = 0; k < candidates.size() && apexes.size() < CreaseApexesTried; ++k)
  {
    if (apexes.empty() || Norm(candidates[k].second - apexes.back()) != 0.0)
    {
      apexes.push_back(candidates[k].second);
    }
  }
  return apexes;
}

namespace
{
/// The apexes each loop's fan may take, tried in order (header: Creases;
/// Several loops): a lone loop's as above; with several, each loop's
/// planes' point in its room (LoopApex) or the crease points nearest it
/// there.
std::vector<std::vector<Vec3>> ApexCandidates(const MeshBooleanSurface& surface,
  const std::vector<CreaseSegment>& creases, const Box3& cell, const std::vector<std::vector<Vec3>>& loops)
{
  if (loops.size() == 1)
  {
    const Vec3 planesPoint = MeshCellApex(surface.OnSurface, cell);
    return { creases.empty() ? std::vector<Vec3>{ planesPoint } : ApexesOnCreases(cell, creases, planesPoint) };
  }
  const std::vector<ApexRoom> rooms = ApexRooms(loops, cell);
  std::vector<std::vector<Vec3>> candidates(loops.size());
  for (std::size_t l = 0; l < loops.size(); ++l)
  {
    const Vec3 planesPoint = LoopApex(surface.OnSurface, rooms[l], loops[l]);
    candidates[l] = InRoomOnly(ApexesOnCreases(rooms[l].Region, creases, planesPoint), rooms[l]);
    if (candidates[l].empty())
    {
      candidates[l].push_back(planesPoint);
    }
  }
  return candidates;
}
} // namespace

std::vector<Vec3> PredictMeshBooleanFan(const CsgExpressionPtr& expression, const PrimitiveSet& primitives,
  const RootGrid& grid, const Box3& cell, const CellBoundary& boundary, double tolerance, double& predicted)
{
  predicted = HUGE_VAL;
  MeshBooleanSurface surface;
  std::vector<CreaseSegment> creases;
  if (!MeshBooleanSurfaceInCell(*expression, primitives, cell, BooleanPieceShare * tolerance, BooleanPieceBudget,
        surface, &creases) ||
    surface.OnSurface.empty())
  {
    return {};
  }
  CellBoundary bent = boundary;
  MarkCsgCreaseTiles(bent, primitives, grid, [&](int, std::size_t) { return &expression; });
  const BoundaryLoopSet loops = TraceBoundaryLoops(bent);
  if (loops.LoopSizes.empty() || !loops.Consistent)
  {
    return {};
  }
  const std::vector<std::vector<Crossing>> each = EachLoop(loops);
  std::vector<std::vector<Vec3>> points(each.size());
  for (std::size_t l = 0; l < points.size(); ++l)
  {
    if (each[l].size() < 3 || !PlaceCsgLoopPoints(each[l], expression, primitives, grid, points[l]))
    {
      return {};
    }
  }
  const double delta = TraceDeviation(surface.Covering, cell, points) + surface.Slack;
  if (!(delta < tolerance))
  {
    return {};
  }
  // Around the point S's planes give where the meshes do not cross here;
  // else around a point of the crease where they do, nearest it first
  // (header: Creases) - each loop around its own (Several loops), the k-th
  // try taking each loop's k-th candidate, or its last.
  for (const std::vector<Vec3>& apexes :
    KthApexSets(ApexCandidates(surface, creases, cell, points), CreaseApexesTried))
  {
    const std::vector<SourceTriangle> fan = ApexFans(points, apexes);
    if (!CreasesFollowed(creases, fan, BooleanCreaseReach * tolerance))
    {
      continue;
    }
    // (Its bound is only compared with the tolerance - the extraction
    // certifies the final fans on their own - so any bound within it will do:
    // PolygonHausdorff.h, Settled pieces.)
    const HausdorffEstimate error = CertifiedSurfacePatchError(surface.OnSurface, surface.Covering, fan,
      surface.Slack, tolerance - delta, tolerance - delta, PredictionBudget, nullptr, tolerance - delta);
    if (error.Upper + delta <= tolerance)
    {
      predicted = error.Upper + delta;
      return apexes;
    }
  }
  return {};
}

} // namespace tpc
