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

/// The crease points tried as apexes, nearest the planes' point first.
constexpr std::size_t CreaseApexesTried = 4;

/// How far S's trace on the cell's faces strays from the loop `loop`
/// (header: The prediction): the covering pieces clipped to each face, at
/// their corners.
double TraceDeviation(const PolygonSet& covering, const Box3& cell, const std::vector<Vec3>& loop)
{
  double deviation = 0.0;
  for (int f = 0; f < 6; ++f)
  {
    const int axis = f / 2;
    Box3 face = cell;
    face.lo[axis] = face.hi[axis] = f % 2 ? cell.hi[axis] : cell.lo[axis];
    for (std::size_t i = 0; i < covering.size(); ++i)
    {
      if (!covering.Bounds(i).Overlaps(face))
      {
        continue;
      }
      BoundedVector<Vec3, 2 * ClippedCorners::capacity()> clipped;
      for (const Vec3& p : covering[i].Points)
      {
        clipped.push_back(p);
      }
      ClipToBox(clipped, face);
      for (const Vec3& p : clipped)
      {
        double nearest = HUGE_VAL;
        for (std::size_t k = 0; k < loop.size(); ++k)
        {
          nearest = std::min(nearest, SegmentDistance(p, loop[k], loop[(k + 1) % loop.size()]));
        }
        deviation = std::max(deviation, nearest);
      }
    }
  }
  return deviation;
}
/// The apexes on `creases` a fan may take in `cell`: on each segment, the
/// point nearest `planesPoint` among those 1/32 of the cell's width inside
/// it (as MeshCellApex keeps its own: strictly inside), nearest first.
/// (CreaseApexes, MeshCellError.h, clamps the nearest point into that box
/// instead, which may move it off the crease.)
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
  std::sort(candidates.begin(), candidates.end(), [](const auto& x, const auto& y) { return x.first < y.first; });
  std::vector<Vec3> apexes;
  for (std::size_t k = 0; k < candidates.size() && apexes.size() < CreaseApexesTried; ++k)
  {
    apexes.push_back(candidates[k].second);
  }
  return apexes;
}
} // namespace

bool MayPredictMeshBooleanFan(const CsgExpression& expression)
{
  if (!IsMeshBoolean(expression))
  {
    return false;
  }
  std::size_t listed = 0;
  for (const CsgLeaf& leaf : expression.Leaves())
  {
    listed += leaf.Triangles->size();
  }
  return listed <= BooleanFanTriangles;
}

bool MeshBooleanSurfaceForTolerance(
  const CsgExpression& expression, const PrimitiveSet& primitives, const Box3& cell, double tolerance,
  MeshBooleanSurface& surface)
{
  return MeshBooleanSurfaceInCell(
    expression, primitives, cell, BooleanPieceShare * tolerance, BooleanPieceBudget, surface);
}

std::optional<Vec3> PredictMeshBooleanFan(const CsgExpressionPtr& expression, const PrimitiveSet& primitives,
  const RootGrid& grid, const Box3& cell, const CellBoundary& boundary, double tolerance, double& predicted)
{
  predicted = HUGE_VAL;
  MeshBooleanSurface surface;
  std::vector<CreaseSegment> creases;
  if (!MeshBooleanSurfaceInCell(*expression, primitives, cell, BooleanPieceShare * tolerance, BooleanPieceBudget,
        surface, &creases) ||
    surface.OnSurface.empty())
  {
    return std::nullopt;
  }
  CellBoundary bent = boundary;
  MarkCsgCreaseTiles(bent, primitives, grid, [&](int, std::size_t) { return &expression; });
  const BoundaryLoopSet loops = TraceBoundaryLoops(bent);
  std::vector<Vec3> loop;
  if (loops.LoopSizes.size() != 1 || !loops.Consistent || loops.Crossings.size() < 3 ||
    !PlaceCsgLoopPoints(loops.Crossings, expression, primitives, grid, loop))
  {
    return std::nullopt;
  }
  const double delta = TraceDeviation(surface.Covering, cell, loop) + surface.Slack;
  if (!(delta < tolerance))
  {
    return std::nullopt;
  }
  // Around the point S's planes give where the meshes do not cross here;
  // else around a point of the crease where they do, nearest it first
  // (header: Creases).
  const Vec3 planesPoint = MeshCellApex(surface.OnSurface, cell);
  const std::vector<Vec3> apexes =
    creases.empty() ? std::vector<Vec3>{ planesPoint } : ApexesOnCreases(cell, creases, planesPoint);
  for (const Vec3& apex : apexes)
  {
    const std::vector<SourceTriangle> fan = ApexFan(loop, apex);
    if (!CreasesFollowed(creases, fan, BooleanCreaseReach * tolerance))
    {
      continue;
    }
    const HausdorffEstimate error = CertifiedSurfacePatchError(
      surface.OnSurface, surface.Covering, fan, surface.Slack, tolerance - delta, tolerance - delta, PredictionBudget);
    if (error.Upper + delta <= tolerance)
    {
      predicted = error.Upper + delta;
      return apex;
    }
  }
  return std::nullopt;
}

} // namespace tpc
